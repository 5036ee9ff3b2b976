// The session: the page's one way to the scenario in view. The scenario itself is held by the wasm
// `Draft` (crate/core/src/draft.rs) in the simulation worker, beside the run built from it: what
// checking a scenario learns (its shapes laid on the lattice) stays in the wasm instance that
// checked it, so the run is built from the checked scenario without reading or checking it again.
// An opening or an edit is one call here, one message to the worker and one call into its wasm; the
// answer says whether it was refused and why, and the run it started comes back as 'loaded' with
// the scenario's canonical text, its layout and its comparison. The session keeps what the page
// shows of it (that text, parsed once; the layout; the latest frame), the undo history, and the
// scenario that survives a reload; panels read it and listen to its events.
import type { Comparison, Frame, Layout } from '../contract.gen';
import { sameLattice } from '../render/geometry';
import type { Proposed } from '../sim/protocol';
import type { Drawn } from '../types';
import { Events } from './events';
import { History, noteOpening, openedScenario, saveScenario } from './store';

export interface SessionEvents {
  /** A run was loaded; `shapeChanged` when its lattice or size differs from the last one. */
  loaded: { layout: Layout; shapeChanged: boolean };
  /** A frame of the run arrived. */
  frame: Frame;
  /** The run recorded a change to its own scenario (a clicked disturbance). */
  recorded: string;
  /** Undo or redo may have become possible or impossible. */
  history: null;
  /** The worker started or stopped playing. */
  playing: boolean;
  /** A scenario other than a link's replaced the one in view (the address's link no longer names it). */
  replaced: null;
}

export interface OpenOptions {
  /** The scenario replaced can be brought back by undo (default true). */
  record?: boolean;
  /** A scenario that cannot run is refused without a message (default false). */
  quiet?: boolean;
  /**
   * Told why a scenario cannot run, instead of the page's banner (an editor shows it beside
   * itself): briefly, and whole (empty when that says no more).
   */
  onProblem?: (brief: string, full: string) => void;
  /**
   * It opens a scenario (a link, the gallery, the course page, the exercise editor, undo) rather
   * than editing the one in view: an exercise's locks do not hold it back (default false).
   */
  opens?: boolean;
  /** It is the address's link: the link stays in the address (default false). */
  fromLink?: boolean;
  /** Called with the scenario's canonical text once its run has loaded. */
  onLoaded?: (text: string) => void;
}

/** What the session asks of the simulation worker's side (web/sim/client.ts). */
export interface ScenarioOwner {
  /** Opens scenario text in the worker's Draft; `keepLocks` holds it to the exercise in view. */
  open(text: string, keepLocks: boolean, ask: boolean): Promise<Proposed>;
  /** Sets dotted paths of the scenario in view (`changes`: a JSON object from path to value). */
  edit(changes: string): Promise<Proposed>;
  /** Builds the large scenario proposed in answer to request `id`, once the page agreed to it. */
  build(id: number): void;
  /** Starts the scenario in view again from step 0. */
  reset(): void;
  /** The share-link payload of the scenario in view, or of it named `name` (a hand-in). */
  link(name?: string): Promise<string>;
  /** What is wrong with an exercise goal for the scenario in view and its model's `metrics`. */
  goalProblem(goal: string, metrics: string[]): Promise<string | null>;
}

/** What the page does for the session: say why a scenario was refused, and open large ones. */
export interface SessionHost {
  /** A refusal, briefly, with the whole message when it says more. */
  refused(brief: string, full: string): void;
  /** A proposal too large to check at once: `start` builds it, now or once the user agrees. */
  large(cells: number, start: () => void): void;
}

/** A request of the page whose run has not loaded yet. */
interface Pending {
  /** The request's number: its run's 'loaded' carries it. */
  id: number;
  record: boolean;
  fromLink: boolean;
  onLoaded?: (text: string) => void;
}

export class Session {
  /** The scenario the run was started from (canonical JSON); clicked disturbances are added to it. */
  scenario = '';
  layout: Layout | null = null;
  frame: Frame | null = null;
  /** What the worker drew and measured with the latest frame. */
  drawn: Drawn | null = null;
  /** The run plays. */
  playing = false;
  /** The scenario in view's comparison, as its worker derived it. */
  comparison: Comparison = { kind: 'none' };
  private readonly history = new History();
  private readonly events = new Events<SessionEvents>();
  private parsed: { text: string; doc: Record<string, unknown> } | null = null;
  /** The request whose run loads next, if the page made one. */
  private pending: Pending | null = null;
  /** The scenario being opened; saved for reloads once it has drawn a frame. */
  private opening: string | null = null;

  constructor(
    private readonly owner: ScenarioOwner | null = null,
    private readonly host: SessionHost | null = null,
  ) {}

  on<K extends keyof SessionEvents>(event: K, listener: (value: SessionEvents[K]) => void) {
    this.events.on(event, listener);
  }

  private emit<K extends keyof SessionEvents>(event: K, value: SessionEvents[K]) {
    this.events.emit(event, value);
  }

  /** The scenario as an object, parsed once per text. Callers that change it copy it first. */
  doc(): Record<string, unknown> {
    if (this.parsed?.text !== this.scenario) this.parsed = { text: this.scenario, doc: JSON.parse(this.scenario || '{}') as Record<string, unknown> };
    return this.parsed.doc;
  }

  // ---- what the page asks ---------------------------------------------------------------------

  /**
   * Opens a scenario text: checked first, so a bad one never replaces a good run. Resolves to
   * whether it was accepted (a large one runs once the page has agreed to it; its run's 'loaded'
   * tells when).
   */
  async open(text: string, options: OpenOptions = {}): Promise<boolean> {
    return this.proceed(await this.need().open(text, !options.opens, true), options, text);
  }

  /**
   * Changes dotted paths of the scenario in view (`stages.0.target`), all at once: the result is
   * checked once, as a whole, and held to the exercise's locks. Resolves to the problem (told to
   * `onProblem` too, never to the banner), or null when the change runs.
   */
  edit(changes: Record<string, unknown>, options: OpenOptions = {}): Promise<string | null> {
    return this.editText(JSON.stringify(changes), options);
  }

  /**
   * Sets one dotted path to `valueJson`: JSON, or else taken as text. The JSON is read by the
   * core, so a number keeps every digit typed. Resolves to the problem, or null.
   */
  set(path: string, valueJson: string, options: OpenOptions = {}): Promise<string | null> {
    let value = valueJson;
    try {
      JSON.parse(valueJson);
    } catch {
      value = JSON.stringify(valueJson);
    }
    return this.editText(`{${JSON.stringify(path)}:${value}}`, options);
  }

  private async editText(changes: string, options: OpenOptions): Promise<string | null> {
    let problem: string | null = null;
    const onProblem = (brief: string, full: string) => {
      problem = brief;
      options.onProblem?.(brief, full);
    };
    // A refused edit is the caller's to show: beside the field, or in the banner in its words.
    this.proceed(await this.need().edit(changes), { ...options, onProblem });
    return problem;
  }

  /** Starts the scenario in view again from step 0. */
  reset() {
    if (this.scenario) this.need().reset();
  }

  /** The share-link payload of the scenario in view, or of it named `name` (a student's hand-in). */
  link(name?: string): Promise<string> {
    return this.need().link(name);
  }

  /** What is wrong with a goal: its syntax, or a metric or scenario field the model does not have. */
  goalProblem(goal: string, metrics: string[]): Promise<string | null> {
    return this.need().goalProblem(goal, metrics);
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

  private need(): ScenarioOwner {
    if (!this.owner) throw new Error('the session has no simulation to hold its scenario');
    return this.owner;
  }

  /**
   * Runs what an opening (of `text`) or an edit proposed, or says why it cannot run: its own
   * problem in brief, with the whole of it a click away when it says more.
   */
  private proceed(proposal: Proposed, { record = true, quiet = false, onProblem, fromLink = false, onLoaded }: OpenOptions, text?: string): boolean {
    if (proposal.problem) {
      if (onProblem) onProblem(proposal.problem, proposal.in_full ?? '');
      else if (!quiet) this.host?.refused(proposal.problem, proposal.in_full ?? '');
      return false;
    }
    this.pending = { id: proposal.id, record, fromLink, onLoaded };
    // A scenario that stops the page as it opens (too large for the device) is offered after a
    // reload, not opened again: it is noted until it has drawn.
    const opening = proposal.text ?? text;
    if (proposal.large_cells > 0) {
      const build = () => {
        if (opening) noteOpening(opening);
        this.need().build(proposal.id);
      };
      if (this.host) this.host.large(proposal.large_cells, build);
      else build();
    } else if (opening) noteOpening(opening);
    return true;
  }

  // ---- what the worker reports ----------------------------------------------------------------

  /**
   * The worker loaded a run of `text`: the page's request `id` (an opening, an edit), or 0 (a
   * reset, a restart).
   */
  loaded(id: number, layout: Layout, text: string, comparison: Comparison) {
    const pending = this.pending?.id === id ? this.pending : null;
    if (pending) this.pending = null;
    if (pending) {
      if (pending.record) this.remember(this.scenario, text);
      if (!pending.fromLink) this.emit('replaced', null);
    }
    const shapeChanged = !sameLattice(this.layout, layout);
    this.layout = layout;
    this.scenario = text;
    this.comparison = comparison;
    this.opening = text;
    this.emit('loaded', { layout, shapeChanged });
    pending?.onLoaded?.(text);
  }

  /** A request could not run after all (the worker refused or was stopped): the scenario in view stays. */
  failed() {
    this.pending = null;
    openedScenario();
  }

  /** A large scenario the user chose not to open: the one in view stays, and no link names it. */
  declined() {
    this.pending = null;
    this.emit('replaced', null);
  }

  setFrame(frame: Frame, drawn: Drawn | null = null) {
    if (this.opening !== null) {
      // It opened and drew: now it may be restored after a reload.
      saveScenario(this.opening);
      openedScenario();
      this.opening = null;
    }
    this.frame = frame;
    this.drawn = drawn;
    this.emit('frame', frame);
  }

  setPlaying(on: boolean) {
    this.playing = on;
    this.emit('playing', on);
  }

  /** The run changed its scenario (a clicked disturbance): undo brings back the one before. */
  recorded(text: string, comparison: Comparison) {
    this.remember(this.scenario, text);
    this.scenario = text;
    this.comparison = comparison;
    saveScenario(text);
    this.emit('recorded', text);
  }

  /** Notes that `previous` is being replaced by `next`, so undo can bring it back. */
  remember(previous: string, next: string) {
    if (previous && next !== previous) this.history.push(previous);
    this.emit('history', null);
  }
}
