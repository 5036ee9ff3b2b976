// What the page and the simulation worker agree on about a recording: its settings, its frames,
// what it yields, and how a cancelled one ends. The recording is made in the worker, where the
// view is drawn (web/sim/encode.ts); the page's dialog (web/features/record/) sends the settings and
// receives the file.
import type { FromWorker, ToWorker } from './protocol';

export type RecordFormat = 'png' | 'webm' | 'gif';

export interface RecordSettings {
  format: RecordFormat;
  /** Steps to record, from the step in view. */
  steps: number;
  /** Steps between two frames. */
  every: number;
  /** Drawing-buffer multiple, 1 (the canvas's own resolution) or 2: the page resizes the view to it before recording. */
  scale: number;
  /** Frames per second of the video or GIF. */
  fps: number;
  /** What is drawn over the view in every frame (each optional). */
  overlays?: Overlays;
}

/** A legend entry drawn over a recording: a swatch of the colour (round for an agent) and the name. */
export interface LegendEntry {
  name: string;
  color: string;
  round: boolean;
}

/** Drawn over a recording's frames: the step counter, the scenario's title, the colour legend. */
export interface Overlays {
  step: boolean;
  title: string | null;
  legend: LegendEntry[] | null;
}

/** A finished recording: the file, and the steps it shows (the name's range). */
export interface Recorded {
  blob: Blob;
  from: number;
  to: number;
}

/**
 * The frames of a recording of `steps` steps every `every`: one per interval, the first showing the
 * step in view. A video frame stands for the time until the next, so frame i shows step
 * from + i·every and the video's duration covers the `steps` steps (the file name's range).
 */
export function frameCount(steps: number, every: number): number {
  return Math.max(1, Math.floor(steps / every));
}

/** Raised by the recorder when the user cancels. */
export class Cancelled extends Error {}

/** Frames done, of the recording's total: what the dialog's progress bar shows. */
export type Progress = (done: number, total: number) => void;

/** The recordings a simulation client asked its worker for, by id, until each settles. */
export class Recordings {
  private id = 0;
  private readonly waiting = new Map<number, { progress: Progress; resolve: (r: Recorded) => void; reject: (e: Error) => void }>();

  /**
   * Starts one with `send`; rejects with Cancelled as soon as `signal` aborts, without waiting for
   * the worker (it may be inside a long step), and tells the worker to stop.
   */
  start(settings: RecordSettings, signal: AbortSignal, progress: Progress, send: (msg: ToWorker) => void): Promise<Recorded> {
    if (signal.aborted) return Promise.reject(new Cancelled());
    const id = ++this.id;
    return new Promise((resolve, reject) => {
      const abort = () => {
        this.waiting.delete(id);
        send({ type: 'record-cancel', id });
        reject(new Cancelled());
      };
      signal.addEventListener('abort', abort, { once: true });
      const settle = () => signal.removeEventListener('abort', abort);
      this.waiting.set(id, {
        progress,
        resolve: (r) => {
          settle();
          resolve(r);
        },
        reject: (e) => {
          settle();
          reject(e);
        },
      });
      send({ type: 'record', id, settings });
    });
  }

  /** The worker's news of a recording. */
  receive(msg: Extract<FromWorker, { type: 'record-progress' | 'recorded' | 'record-failed' }>) {
    const r = this.waiting.get(msg.id);
    if (msg.type === 'record-progress') {
      r?.progress(msg.done, msg.total);
      return;
    }
    this.waiting.delete(msg.id);
    if (msg.type === 'recorded') r?.resolve({ blob: msg.blob, from: msg.from, to: msg.to });
    else r?.reject(msg.cancelled ? new Cancelled() : new Error(msg.message));
  }

  /** Every recording under way fails: the worker is gone. */
  fail(message: string) {
    for (const r of this.waiting.values()) r.reject(new Error(message));
    this.waiting.clear();
  }
}
