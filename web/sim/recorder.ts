// Recordings, in the simulation worker: each frame is stepped, drawn and encoded next to the view
// (web/sim/encode.ts, loaded with the first recording), and only the finished file goes to the
// page. While one is made, the worker holds back every message but acks and cancels, so nothing
// moves the run or the view under it.
import type { RecordHost } from './encode';
import { inLaterTask, post, run, timedAdvance } from './host';
import { draw, seekNow, setPlaying, stepped, tell } from './pace';
import type { ToWorker } from './protocol';
import { Cancelled, type RecordSettings } from './record';

/** The recording under way, and how to stop it. */
let recording: { id: number; stop: AbortController } | null = null;
/**
 * What came in during a recording, other than acks and cancels: kept in order and handled
 * once it ends. Holding rather than refusing keeps the page's requests (a hover pick, a play from
 * a course page) meaningful, and nothing can move the run or resize the view under the recording.
 */
const held: ToWorker[] = [];
/** Messages a recording does not hold back (pings never wait): the page's panels follow it, and Cancel stops it. */
const DURING_RECORDING = new Set<ToWorker['type']>(['ack', 'record-cancel']);

/** True when `msg` waits for the recording under way; it is then kept for after it. */
export function holdsBack(msg: ToWorker): boolean {
  if (!recording || DURING_RECORDING.has(msg.type)) return false;
  held.push(msg);
  return true;
}

/** Stops the recording `id`, or drops it if it has not started (it then ends as cancelled). */
export function cancelRecording(id: number) {
  if (recording?.id === id) {
    recording.stop.abort();
    return;
  }
  // Cancelled before it started: it never will.
  const waiting = held.findIndex((m) => m.type === 'record' && m.id === id);
  if (waiting >= 0) {
    held.splice(waiting, 1);
    post({ type: 'record-failed', id, message: 'cancelled', cancelled: true });
  }
}

/** The run and the view, as the recorder steps and copies them. */
const recordHost: RecordHost = {
  steps: () => run.sim?.steps() ?? 0,
  async advance(count) {
    const s = run.sim;
    if (!s) throw new Error('the simulation stopped');
    if (timedAdvance(s, count) === undefined) throw new Error('the run could not be stepped');
    stepped();
    // The GIF encoder never waits on anything: without this task boundary the worker would read
    // no message until the recording ended. Here the page's Cancel and acks get in.
    await new Promise<void>((resolve) => inLaterTask(resolve));
    return { steps: s.steps(), finished: s.finished() };
  },
  async captureFrame() {
    draw();
    const v = run.viewer;
    if (!v) throw new Error('the view is gone');
    let bitmap: ImageBitmap;
    try {
      // In the task that drew: WebGL keeps no drawing buffer past it.
      bitmap = v.capture();
    } catch (e) {
      throw new Error(`the view could not be captured: ${String(e)}`);
    }
    // The page follows the recording (step counter, panels) as fast as it takes frames.
    tell();
    return bitmap;
  },
};

/**
 * Records the view from the step the run stands at, as the page's dialog asked (it has already
 * resized the view to the recording's scale), and sends back the file or why there is none. Then
 * the messages held meanwhile are handled with `handle`, in order.
 */
export async function record(id: number, settings: RecordSettings, handle: (msg: ToWorker) => void) {
  recording = { id, stop: new AbortController() };
  try {
    setPlaying(false);
    // A seek the page asked for before recording is where the recording starts.
    seekNow();
    if (!run.sim || !run.viewer) throw new Error('nothing is drawn yet');
    const progress = (done: number, total: number) => post({ type: 'record-progress', id, done, total });
    // The encoders (GIF, WebM) are fetched with the first recording, not with the worker.
    const { encode } = await import('./encode');
    const { blob, from, to } = await encode(recordHost, settings, recording.stop.signal, progress);
    post({ type: 'recorded', id, blob, from, to });
  } catch (e) {
    post({ type: 'record-failed', id, message: e instanceof Error ? e.message : String(e), cancelled: e instanceof Cancelled });
  } finally {
    recording = null;
    // A held 'record' starts the next recording, which holds what follows it.
    while (!recording && held.length > 0) handle(held.shift()!);
  }
}
