// The simulation worker's pace: its play loop. It steps the run at the requested speed, draws at
// most once per animation frame (at max speed, once per frame the page frees: stepping never
// waits), reading the model's buffers in place, and sends the page a frame of what its panels
// show, flow-controlled: the next is sent only after the page has taken the last, so a fast
// simulation never floods the page. Timing here paces the run; it never enters the model.
import type { Sim } from '../pkg/kumiki_wasm.js';
import type { Frame, Verdict } from '../contract.gen';
import type { Drawn } from '../types';
import type { RenderStats } from '../view.gen';
import { guard, inLaterTask, msPerStep, panicked, post, run, SLICE_MS, scope, stepsPerCall, timedAdvance, work } from './host';
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
/**
 * At max speed, the least time between two drawn frames while the run steps. Stepping never
 * waits for a frame there: the worker's own animation frames come only while its task queue is
 * idle, so it asks the page for one (the page's animation frame says the compositor takes a new
 * frame) and draws the state as it then stands, skipping the steps between. Each drawn frame of a
 * large lattice costs the software rasteriser far more than the worker, on the same cores.
 */
const MAX_SPEED_FRAME_GAP_MS = 200;

let playing = false;
let stepsPerSecond = 30;
let awaitingAck = false;
/** The page has not been told of the state as it stands. */
let dirty = false;
/** The state changed since the view last drew it. */
let changed = false;
let drawScheduled = false;
/** The page was asked for a frame (at max speed) and has not yet said one is free. */
let frameAsked = false;
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
let rateWindow: { t: number; steps: number }[] = [];
let tickScheduled = false;
/** The run's end was judged by its exercise's goal (once per end reached). */
let goalJudged = false;
/** A step to go back (or forward) to; seeks that arrive together are done once, for the last. */
let seekTo: number | null = null;

/** A step to follow (the first run of a comparison reached it); null when there is none. */
let followTo: number | null = null;

export function schedule() {
  if (!tickScheduled) {
    tickScheduled = true;
    inLaterTask(() => {
      tickScheduled = false;
      tick();
    });
  }
}

panicked.stop = () => {
  playing = false;
};

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

/** Playing at max speed: stepping never waits for a frame, the page says when one is free. */
function atMaxSpeed(): boolean {
  return playing && !Number.isFinite(stepsPerSecond);
}

/** Draws at the next animation frame (at max speed, the next the page says is free), then tells the page (once it took the last frame). */
export function redraw() {
  drawScheduled = true;
  requestDraw();
}

/** The worker's animation frame was asked for and has not come. */
let frameRequested = false;

/** Makes sure a pending draw will come: from the page's frame at max speed, else from the worker's. */
function requestDraw() {
  if (!drawScheduled) return;
  if (atMaxSpeed()) askFrame();
  else if (!frameRequested) {
    frameRequested = true;
    frameTimer(() => {
      frameRequested = false;
      drawDue();
    });
  }
}

/** Draws the pending draw, if it is still pending, and tells the page. */
function drawDue() {
  if (!drawScheduled) return;
  drawScheduled = false;
  lastDrawAt = performance.now();
  draw();
  if (dirty) sendFrame();
  else post({ type: 'drew', work: work() });
  if (holding) {
    holding = false;
    schedule();
  }
}

/**
 * At max speed, asks the page for a frame once a draw is pending, the page is shown and the last
 * frame is MAX_SPEED_FRAME_GAP_MS old (a camera move alone draws at once: it uploads nothing).
 */
function askFrame() {
  if (frameAsked || !drawScheduled || !visible || !atMaxSpeed()) return;
  if (changed && performance.now() - lastDrawAt < MAX_SPEED_FRAME_GAP_MS) return;
  frameAsked = true;
  post({ type: 'frame-wanted' });
}

/** The page's animation frame came after the worker asked for one: the view is drawn now. */
export function frameFree() {
  frameAsked = false;
  // Play stopped or slowed since: the worker's own animation frame draws.
  if (atMaxSpeed()) drawDue();
  else requestDraw();
}

/** A draw is pending and the next step would end past its due time: stepping makes way for it. */
function drawOverdue(): boolean {
  return !atMaxSpeed() && drawScheduled && visible && performance.now() + msPerStep() - lastDrawAt > FRAME_GAP_MS;
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
  requestDraw();
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
  requestDraw();
}

export function setVisible(shown: boolean) {
  visible = shown;
  requestDraw();
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
    const n = timedAdvance(s, Math.min(target - s.steps(), stepsPerCall()));
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
      const want = unlimited ? stepsPerCall() : Math.min(Math.floor(budget), stepsPerCall());
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
