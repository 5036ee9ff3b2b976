// The session store: the scenario in view (canonical JSON), the undo history of its changes, the
// run's layout and its latest frame. The worker owns the live run; main.ts writes here what it
// reports, and the panels read the session and listen to its events instead of to each other.
import { sameLattice } from './render/geometry';
import { History } from './store';
import type { Layout } from './contract.gen';
import type { Frame } from './types';

export interface SessionEvents {
  /** A run was loaded; `shapeChanged` when its lattice or size differs from the last one. */
  loaded: { layout: Layout; shapeChanged: boolean };
  /** A frame of the run arrived. */
  frame: Frame;
  /** The run recorded a change to its own scenario (a clicked disturbance). */
  recorded: string;
  /** Undo or redo may have become possible or impossible. */
  history: null;
}

type Listener<K extends keyof SessionEvents> = (value: SessionEvents[K]) => void;

export class Session {
  /** The scenario the run was started from (canonical JSON); clicked disturbances are added to it. */
  scenario = '';
  layout: Layout | null = null;
  frame: Frame | null = null;
  private readonly history = new History();
  private readonly listeners: { [K in keyof SessionEvents]: Listener<K>[] } = { loaded: [], frame: [], recorded: [], history: [] };
  private parsed: { text: string; doc: Record<string, unknown> } | null = null;

  on<K extends keyof SessionEvents>(event: K, listener: Listener<K>) {
    this.listeners[event].push(listener);
  }

  private emit<K extends keyof SessionEvents>(event: K, value: SessionEvents[K]) {
    for (const listener of this.listeners[event]) listener(value);
  }

  /** The scenario as an object, parsed once per text. Callers that change it copy it first. */
  doc(): Record<string, unknown> {
    if (this.parsed?.text !== this.scenario) this.parsed = { text: this.scenario, doc: JSON.parse(this.scenario || '{}') as Record<string, unknown> };
    return this.parsed.doc;
  }

  /** The worker loaded a run of `json`. */
  loaded(layout: Layout, json: string) {
    const shapeChanged = !sameLattice(this.layout, layout);
    this.layout = layout;
    this.scenario = json;
    this.emit('loaded', { layout, shapeChanged });
  }

  setFrame(frame: Frame) {
    this.frame = frame;
    this.emit('frame', frame);
  }

  /** The run changed its scenario (a clicked disturbance): undo brings back the one before. */
  recorded(json: string) {
    this.remember(this.scenario, json);
    this.scenario = json;
    this.emit('recorded', json);
  }

  /** Notes that `previous` is being replaced by `next`, so undo can bring it back. */
  remember(previous: string, next: string) {
    if (previous && next !== previous) this.history.push(previous);
    this.emit('history', null);
  }

  /** The scenario before the current one, or null; the current one becomes redo's. */
  undo(): string | null {
    const prev = this.history.undo(this.scenario);
    this.emit('history', null);
    return prev;
  }

  redo(): string | null {
    const next = this.history.redo(this.scenario);
    this.emit('history', null);
    return next;
  }

  get canUndo() {
    return this.history.canUndo;
  }
  get canRedo() {
    return this.history.canRedo;
  }
}
