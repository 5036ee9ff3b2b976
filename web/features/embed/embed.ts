// Kumiki in a course page: `?embed` shows only the view, the run controls and the exercise panel,
// and the page that frames it drives it with postMessage. Every message in either direction is an
// object `{ source: 'kumiki', type, ... }`. Commands are taken only from the framing window, and
// only when their shape is exactly right; anything else is ignored. Nothing in a message is ever
// run as code or written into the page as HTML. docs/embed.md documents the API.
import type { Frame } from '../../contract.gen';

export type EmbedCommand =
  | { type: 'load'; link: string }
  | { type: 'play' }
  | { type: 'pause' }
  | { type: 'step'; count: number }
  | { type: 'reset' }
  | { type: 'check' };

/** Largest `count` a `step` command may ask for at once. */
export const MAX_STEP = 1_000_000;
/** Longest link a `load` command may carry (the page's own link limit is far below). */
const MAX_LINK = 1 << 20;
/** `step` events are sent at most this often while the run plays. */
const STEP_EVENT_MS = 250;

/**
 * A command from the host, or null when the message is not one: wrong envelope, unknown type,
 * extra or missing fields, wrong kinds, or out-of-range values.
 */
export function parseCommand(data: unknown): EmbedCommand | null {
  if (typeof data !== 'object' || data === null || Array.isArray(data)) return null;
  const m = data as Record<string, unknown>;
  if (m.source !== 'kumiki' || typeof m.type !== 'string') return null;
  const keys = Object.keys(m).filter((k) => k !== 'source' && k !== 'type');
  switch (m.type) {
    case 'play':
    case 'pause':
    case 'reset':
    case 'check':
      return keys.length === 0 ? { type: m.type } : null;
    case 'step': {
      if (keys.some((k) => k !== 'count')) return null;
      const count = m.count ?? 1;
      return typeof count === 'number' && Number.isInteger(count) && count >= 1 && count <= MAX_STEP ? { type: 'step', count } : null;
    }
    case 'load':
      if (keys.length !== 1 || keys[0] !== 'link' || typeof m.link !== 'string' || m.link.length === 0 || m.link.length > MAX_LINK) return null;
      return { type: 'load', link: m.link };
    default:
      return null;
  }
}

/**
 * The share-link payload (`k1.…`) of what a host sent: a whole Kumiki URL, its `#…` fragment, or
 * the payload itself.
 */
export function linkPayload(link: string): string {
  const hash = link.indexOf('#');
  return (hash >= 0 ? link.slice(hash + 1) : link).trim();
}

/** What the embed needs from the page. */
export interface EmbedHost {
  /** Opens a share-link payload; resolves to null when it opened, or to the reason it did not. */
  load(payload: string): Promise<string | null>;
  play(): void;
  pause(): void;
  step(count: number): void;
  reset(): void;
  check(): void;
}

export type EmbedEvent =
  | { type: 'ready'; version: string; step: number; hash: string | null }
  | { type: 'step'; step: number; hash: string; finished: boolean; completed: boolean }
  | { type: 'finished'; step: number; hash: string | null; completed: boolean; metrics: Frame['metrics'] }
  | { type: 'goal-checked'; met: boolean; why: string; step: number }
  | { type: 'handin'; link: string; name: string }
  | { type: 'error'; command: string; message: string };

/** The embedded page's side of the API: it takes the host's commands and tells it what happens. */
export class Embed {
  private readied = false;
  private lastStepEvent = Number.NEGATIVE_INFINITY;
  /** The step and hash of the last `step` event: a new scenario's step 0 is news too. */
  private lastStepSent = '';
  private trailing: ReturnType<typeof setTimeout> | null = null;
  private finishedAt = -1;

  constructor(
    private readonly host: EmbedHost,
    private readonly version: string,
    private readonly parent: Window = window.parent,
  ) {
    window.addEventListener('message', (e) => this.receive(e));
  }

  private post(event: EmbedEvent) {
    // The events carry only the public scenario's state (step, hash, metrics, verdict), so any
    // course page may hear them: the embedding site is not known in advance.
    this.parent.postMessage({ source: 'kumiki', ...event }, '*');
  }

  private receive(e: MessageEvent) {
    if (e.source !== this.parent || this.parent === window) return;
    const command = parseCommand(e.data);
    if (!command) return;
    switch (command.type) {
      case 'load':
        void this.host.load(linkPayload(command.link)).then((problem) => {
          if (problem) this.post({ type: 'error', command: 'load', message: problem });
          else this.forgetLastStep();
        });
        return;
      case 'play':
        return this.host.play();
      case 'pause':
        return this.host.pause();
      case 'step':
        return this.host.step(command.count);
      case 'reset':
        return this.host.reset();
      case 'check':
        return this.host.check();
    }
  }

  /** A scenario was loaded: its step 0 is news even when the state equals the last one sent. */
  private forgetLastStep() {
    if (this.trailing) clearTimeout(this.trailing);
    this.trailing = null;
    this.lastStepSent = '';
    this.finishedAt = -1;
  }

  /** A frame the page has received: `ready` on the first, then throttled `step` events and `finished`. */
  frame(frame: Frame) {
    if (!this.readied) {
      this.readied = true;
      this.post({ type: 'ready', version: this.version, step: frame.steps, hash: frame.hash ?? null });
    }
    // A step event carries the state hash of its step; while the run plays the worker sends one
    // at most every 250 ms, and every frame while paused has one.
    const key = `${frame.steps}:${frame.hash}`;
    if (frame.hash && key !== this.lastStepSent) {
      const now = performance.now();
      const send = () => {
        this.trailing = null;
        this.lastStepEvent = performance.now();
        this.lastStepSent = key;
        this.post({ type: 'step', step: frame.steps, hash: frame.hash!, finished: frame.finished, completed: frame.completed });
      };
      if (this.trailing) clearTimeout(this.trailing);
      if (now - this.lastStepEvent >= STEP_EVENT_MS) send();
      else this.trailing = setTimeout(send, STEP_EVENT_MS - (now - this.lastStepEvent));
    }
    if (frame.finished && this.finishedAt !== frame.steps) {
      this.finishedAt = frame.steps;
      this.post({ type: 'finished', step: frame.steps, hash: frame.hash ?? null, completed: frame.completed, metrics: frame.metrics });
    } else if (!frame.finished) {
      this.finishedAt = -1;
    }
  }

  /** The exercise's verdict, when a run ends or on Check. */
  goal(met: boolean, why: string, step: number) {
    this.post({ type: 'goal-checked', met, why, step });
  }

  /** The student pressed Hand in: the course page may collect the link itself. */
  handin(link: string, name: string) {
    this.post({ type: 'handin', link, name });
  }
}
