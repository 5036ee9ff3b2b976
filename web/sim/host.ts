// What the simulation worker's parts share: the run and the view it holds, the wasm instance in
// use, posting to the page, a later task, calls into wasm that report what went wrong, and the
// steps timed for the page's figures and the play loop's pace (web/sim/pace.ts).
import { panic_message, type Sim, type Viewer } from '../pkg/kumiki_wasm.js';
import type { WorkerTiming } from '../types';
import type { FromWorker } from './protocol';

export const scope = self as unknown as DedicatedWorkerGlobalScope;
export const post = (msg: FromWorker, transfer: Transferable[] = []) => scope.postMessage(msg, transfer);

/** Longest stretch of stepping between looks at the message queue. */
export const SLICE_MS = 12;

/** The run and the view the worker holds, and what the page asked to see of them. */
export const run = {
  sim: null as Sim | null,
  viewer: null as Viewer | null,
  overlay: null as string | null,
  /** The metric the page charts, and about how many points it draws. */
  chartMetric: null as string | null,
  chartPoints: 400,
};

/** The wasm instance in use (the page's module, or its rules module: worker.ts switches): its memory and panic. */
export const memory = { wasm: null as WebAssembly.Memory | null, panicMessage: panic_message as () => string | undefined };

/** Calls waiting for a later task: after the messages already queued, and unthrottled (a timer is not). */
const later: (() => void)[] = [];
const channel = new MessageChannel();
channel.port1.onmessage = () => later.shift()?.();
export function inLaterTask(f: () => void) {
  later.push(f);
  channel.port2.postMessage(null);
}

/** What stops after a panic besides the run (the play loop sets it). */
export const panicked = { stop: () => {} };

export function guard<T>(context: 'load' | 'apply' | 'step', f: () => T): T | undefined {
  try {
    return f();
  } catch (e) {
    const panic = memory.panicMessage();
    if (panic) {
      run.sim = null;
      panicked.stop();
      post({ type: 'panic', message: panic });
    } else {
      post({ type: 'error', message: e instanceof Error ? e.message : String(e), context });
    }
    return undefined;
  }
}

/** Milliseconds spent in the model's steps since the worker started. */
let stepMs = 0;
/** About how long a step takes now. */
let perStep = 1;
export const msPerStep = () => perStep;
/** How many steps one call into the run should take: about 2 ms of them, at least one. */
export const stepsPerCall = () => Math.max(1, Math.floor(2 / Math.max(perStep, 1e-4)));

/** Steps the run `count` steps, timing them for the page and for the pace; undefined if it failed. */
export function timedAdvance(s: Sim, count: number): number | undefined {
  const t0 = performance.now();
  const n = guard('step', () => s.advance(count));
  const dt = performance.now() - t0;
  stepMs += dt;
  if (n) perStep = 0.7 * perStep + 0.3 * (dt / n);
  return n;
}

/** The worker's timing so far, for the page's figures. */
export function work(): WorkerTiming {
  const [frames, uploadMs, drawMs] = run.viewer ? run.viewer.timing() : [0, 0, 0];
  return { stepMs, frames, uploadMs, drawMs, wasmBytes: memory.wasm?.buffer.byteLength ?? 0 };
}
