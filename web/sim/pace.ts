// The simulation worker's pace: its play loop, moved here unchanged from worker.ts. It steps the
// run at the requested speed, draws at most once per animation frame, reading the model's buffers
// in place, and sends the page a frame of what its panels show, flow-controlled: the next is sent
// only after the page has taken the last, so a fast simulation never floods the page. Timing here
// paces the run; it never enters the model.
import { panic_message, type Sim, type Viewer } from '../pkg/kumiki_wasm.js';
import type { Frame, Verdict } from '../contract.gen';
import type { Drawn, WorkerTiming } from '../types';
import type { RenderStats } from '../view.gen';
import type { FromWorker } from './protocol';

const scope = self as unknown as DedicatedWorkerGlobalScope;
export const post = (msg: FromWorker, transfer: Transferable[] = []) => scope.postMessage(msg, transfer);

/** Longest stretch of stepping between looks at the message queue. */
export const SLICE_MS = 12;
/**
 * The state hash costs a pass over the state: while playing it is refreshed at most this often,
 * and no more often than keeps it under HASH_SHARE of the time (a 16 M-cell AMAS takes 0.1 s to
 * hash, which every 250 ms would take as much as its stepping).
 */
const HASH_EVERY_MS = 250;
const HASH_SHARE = 0.05;
/**
 * While playing, the longest between two frames: a step that would end past it waits until the
 * next animation frame has drawn. A worker's animation frames run only when its task queue is
 * idle, so a run that steps without pause (a large lattice, a slow machine) would otherwise never
 * be drawn, and one whose steps are long would be drawn a step or more late.
 */
const FRAME_GAP_MS = 100;
/** The longest stepping holds for an animation frame that does not come. */
const HOLD_MAX_MS = 1000;

/** The run and the view the worker holds, and what the page asked to see of them. */
export const run = {
  sim: null as Sim | null,
  viewer: null as Viewer | null,
  overlay: null as string | null,
  /** The metric the page charts, and about how many points it draws. */
  chartMetric: null as string | null,
  chartPoints: 400,
};

let playing = false;
let stepsPerSecond = 30;
let awaitingAck = false;
/** The page has not been told of the state as it stands. */
let dirty = false;
/** The state changed since the view last drew it. */
let changed = false;
let drawScheduled = false;
/** When the last frame was drawn, or a hold stopped waiting for one: the next is due FRAME_GAP_MS after. */
let lastDrawAt = 0;
/** Stepping waits for the pending draw's animation frame. */
let holding = false;
/** The page is shown: a hidden page gets no animation frames, so stepping never waits for one. */
let visible = true;
/** What the last draw reported, for the next frame. */
let drawn: RenderStats | null = null;
/** While playing, the hash is not refreshed before this time. */
let nextHashAt = 0;
let budget = 0;
let lastTick = 0;
let msPerStep = 1;
let rateWindow: { t: number; steps: number }[] = [];
let tickScheduled = false;
/** The run's end was judged by its exercise's goal (once per end reached). */
let goalJudged = false;
/** A step to go back (or forward) to; seeks that arrive together are done once, for the last. */
let seekTo: number | null = null;

/** A step to follow (the first run of a comparison reached it); null when there is none. */
let followTo: number | null = null;

/** Calls waiting for a later task: after the messages already queued, and unthrottled (a timer is not). */
const later: (() => void)[] = [];
const channel = new MessageChannel();
channel.port1.onmessage = () => later.shift()?.();
export function inLaterTask(f: () => void) {
  later.push(f);
  channel.port2.postMessage(null);
}
export function schedule() {
  if (!tickScheduled) {
    tickScheduled = true;
    inLaterTask(() => {
      tickScheduled = false;
      tick();
    });
  }
}

export function guard<T>(context: 'load' | 'apply' | 'step', f: () => T): T | undefined {
  try {
    return f();
  } catch (e) {
    const panic = memory.panicMessage();
    if (panic) {
      run.sim = null;
      playing = false;
      post({ type: 'panic', message: panic });
    } else {
      post({ type: 'error', message: e instanceof Error ? e.message : String(e), context });
    }
    return undefined;
  }
}

function measuredRate(): number {
  if (rateWindow.length < 2) return 0;
  const a = rateWindow[0];
  const b = rateWindow[rateWindow.length - 1];
  return b.t > a.t ? ((b.steps - a.steps) * 1000) / (b.t - a.t) : 0;
}

export function sendFrame(force = false) {
  if (!run.sim || (awaitingAck && !force)) return;
  const s = run.sim;
  const frame = guard('step', (): Frame => {
    const now = performance.now();
    const hashed = !playing || now >= nextHashAt;
    const frame = s.frame(hashed, run.chartMetric ?? undefined, run.chartPoints) as Frame;
    if (hashed) nextHashAt = now + Math.max(HASH_EVERY_MS, (performance.now() - now) / HASH_SHARE);
    return frame;
  });
  if (!frame) return;
  const range = run.overlay ? run.viewer?.overlay_range() : undefined;
  const shown: Drawn = {
    stepsPerSecond: playing ? measuredRate() : 0,
    overlayRange: range ? [range[0], range[1]] : null,
    scene: drawn,
    work: work(),
  };
  awaitingAck = true;
  dirty = false;
  post({ type: 'frame', frame, drawn: shown });
  if (frame.finished && !goalJudged) {
    goalJudged = true;
    judge(s);
  } else if (!frame.finished) goalJudged = false;
}

/** Milliseconds spent in the model's steps since the worker started. */
let stepMs = 0;
/** The wasm instance in use (the page's module, or its rules module: worker.ts switches): its memory and panic. */
export const memory = { wasm: null as WebAssembly.Memory | null, panicMessage: panic_message as () => string | undefined };

function work(): WorkerTiming {
  const [frames, uploadMs, drawMs] = run.viewer ? run.viewer.timing() : [0, 0, 0];
  return { stepMs, frames, uploadMs, drawMs, wasmBytes: memory.wasm?.buffer.byteLength ?? 0 };
}

/** Draws the lattice as it stands, now. */
export function draw() {
  if (!run.viewer || !run.sim) return;
  const v = run.viewer;
  const s = run.sim;
  if (changed) v.state_changed();
  changed = false;
  const stats = guard('step', () => v.draw_sim(s, run.overlay ?? undefined) as RenderStats | null);
  if (stats === undefined) return;
  // What was drawn changed (marks hid the ghost, a hover highlighted cells): the page is told.
  if (JSON.stringify(stats) !== JSON.stringify(drawn)) dirty = true;
  drawn = stats;
}

const frameTimer: (f: () => void) => void =
  typeof scope.requestAnimationFrame === 'function' ? (f) => scope.requestAnimationFrame(f) : (f) => setTimeout(f, 16);

/** Draws at the next animation frame, then tells the page (once it took the last frame). */
export function redraw() {
  if (drawScheduled) return;
  drawScheduled = true;
  frameTimer(() => {
    drawScheduled = false;
    lastDrawAt = performance.now();
    draw();
    if (dirty) sendFrame();
    else post({ type: 'drew', work: work() });
    if (holding) {
      holding = false;
      schedule();
    }
  });
}

/** A draw is pending and the next step would end past its due time: stepping makes way for it. */
function drawOverdue(): boolean {
  return drawScheduled && visible && performance.now() + msPerStep - lastDrawAt > FRAME_GAP_MS;
}

/** Stops stepping until the pending draw's animation frame, or for HOLD_MAX_MS if none comes. */
function hold() {
  if (holding) return;
  holding = true;
  setTimeout(() => {
    if (!holding) return;
    holding = false;
    // Step another FRAME_GAP_MS before waiting again.
    lastDrawAt = performance.now();
    schedule();
  }, HOLD_MAX_MS);
}

/** The run's state changed: draw it and tell the page. */
export function touched() {
  changed = true;
  dirty = true;
  redraw();
}

/** The page should hear of the state again (the chart it asks for changed). */
export function untold() {
  dirty = true;
  redraw();
}

/** Sends the page a frame if it has not heard of the state as it stands. */
export function tell() {
  if (dirty) sendFrame();
}

/** The state changed under the view (the recorder stepped it): drawn at the next capture. */
export function stepped() {
  changed = true;
  dirty = true;
}

/** Posts the exercise's verdict on the run as it stands, and why a rule's script stopped it (the rule, the line, the cap). */
export function judge(s: Sim) {
  const result = guard('step', () => s.check_goal() as Verdict | undefined);
  if (result) post({ type: 'goal', met: result.met, because: result.because, steps: s.steps(), credit: result.credit ?? [] });
  if (s.stopped()) post({ type: 'error', message: `The run stopped: ${s.stopped()}`, context: 'step' });
}

export function setPlaying(on: boolean) {
  if (playing === on) return;
  playing = on && !!run.sim && !run.sim.finished();
  budget = 0;
  lastTick = performance.now();
  rateWindow = [];
  post({ type: 'playing', playing });
  if (!playing) touched();
  schedule();
}

/** A new run was loaded: it stands still, drawn afresh, and its first frame goes out at once. */
export function started() {
  playing = false;
  followTo = null;
  post({ type: 'playing', playing: false });
  awaitingAck = false;
  drawn = null;
  changed = true;
  draw();
  sendFrame(true);
}

/** The page took the last frame. */
export function acknowledged() {
  awaitingAck = false;
  if (dirty) redraw();
}

export function setSpeed(rate: number) {
  stepsPerSecond = rate;
  budget = 0;
  lastTick = performance.now();
}

export function setVisible(shown: boolean) {
  visible = shown;
  schedule();
}

/** Goes to `step` (back by replaying, forward up to the furthest step reached), paused. */
export function seek(step: number) {
  setPlaying(false);
  followTo = null;
  seekTo = step;
  schedule();
}

/** Follows the first run of a comparison to `step`, paused. */
export function follow(step: number) {
  setPlaying(false);
  seekTo = null;
  followTo = step;
  schedule();
}

/** Plays (a comparison's second run stops following). */
export function play() {
  followTo = null;
  setPlaying(true);
}

/** Steps `count` steps now, paused. */
export function stepNow(s: Sim, count: number) {
  setPlaying(false);
  followTo = null;
  guard('step', () => s.advance(count));
  touched();
}

/** Goes to the step a seek asked for, if one is waiting. False if the run was lost doing it. */
export function seekNow(): boolean {
  if (!run.sim || seekTo === null) return !!run.sim;
  const s = run.sim;
  const step = seekTo;
  seekTo = null;
  if (guard('step', () => s.seek(step)) === undefined && !run.sim) return false;
  touched();
  return true;
}

/** Steps the run `count` steps, timing them for the page and for the pace; undefined if it failed. */
export function timedAdvance(s: Sim, count: number): number | undefined {
  const t0 = performance.now();
  const n = guard('step', () => s.advance(count));
  const dt = performance.now() - t0;
  stepMs += dt;
  if (n) msPerStep = 0.7 * msPerStep + 0.3 * (dt / n);
  return n;
}

/**
 * Steps toward the step to follow for at most a slice, back by seeking, forward by stepping; a run
 * that ends first stays at its end. True while there is more to do.
 */
function followNow(): boolean {
  if (!run.sim || followTo === null) return false;
  const s = run.sim;
  const target = followTo;
  if (target < s.steps()) {
    followTo = null;
    seekTo = target;
    seekNow();
    return false;
  }
  const start = performance.now();
  let moved = false;
  while (s.steps() < target && !s.finished() && performance.now() - start < SLICE_MS) {
    const n = timedAdvance(s, Math.min(target - s.steps(), Math.max(1, Math.floor(2 / Math.max(msPerStep, 1e-4)))));
    if (!n) break;
    moved = true;
  }
  if (!run.sim) return false;
  if (moved) touched();
  const more = s.steps() < target && !s.finished();
  if (!more) followTo = null;
  return more;
}

function tick() {
  if (followNow()) {
    schedule();
    return;
  }
  if (!seekNow()) return;
  if (playing && run.sim) {
    const s = run.sim;
    const start = performance.now();
    const unlimited = !Number.isFinite(stepsPerSecond);
    budget = unlimited ? Infinity : Math.min(budget + ((start - lastTick) * stepsPerSecond) / 1000, stepsPerSecond + 1);
    lastTick = start;
    let taken = 0;
    while (budget >= 1 && performance.now() - start < SLICE_MS && !drawOverdue()) {
      const want = unlimited
        ? Math.max(1, Math.floor(2 / Math.max(msPerStep, 1e-4)))
        : Math.min(Math.floor(budget), Math.max(1, Math.floor(2 / Math.max(msPerStep, 1e-4))));
      const n = timedAdvance(s, want);
      if (n === undefined) return;
      taken += n;
      budget -= n;
      if (n < want) break;
    }
    if (!run.sim) return;
    if (taken > 0) {
      touched();
      rateWindow.push({ t: performance.now(), steps: s.steps() });
      while (rateWindow.length > 2 && rateWindow[rateWindow.length - 1].t - rateWindow[0].t > 2000) rateWindow.shift();
    }
    if (s.finished()) {
      playing = false;
      post({ type: 'playing', playing: false });
      draw();
      sendFrame(true);
    }
  }
  if (playing) {
    if (drawOverdue()) {
      hold();
    } else if (Number.isFinite(stepsPerSecond) && budget < 1) {
      setTimeout(schedule, Math.max(1, Math.min(50, ((1 - budget) * 1000) / stepsPerSecond)));
    } else {
      schedule();
    }
  }
}
