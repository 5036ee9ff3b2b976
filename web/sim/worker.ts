// The simulation worker: owns the wasm Sim and the lattice view (a wasm Viewer drawing on the
// page's transferred OffscreenCanvas), runs steps at the requested pace and draws at most once
// per animation frame, reading the model's buffers in place. What the page's panels show goes
// out as frames, flow-controlled: the next is sent only after the page has taken the last, so a
// fast simulation never floods the page. Timing here paces the run; it never enters the model.
// Recordings are made here too (web/sim/encode.ts): each frame is stepped, drawn and encoded next
// to the view, and only the finished file goes to the page.
import init, { Sim, Viewer, panic_message, simulate_panic } from '../pkg/kumiki_wasm.js';
import type { Check, Facts, Metrics, Scene } from '../contract.gen';
import type { ChartBand, Frame } from '../types';
import type { RenderStats } from '../view.gen';
import type { FromWorker, ToWorker } from './protocol';
import { encode, type RecordHost } from './encode';
import { Cancelled, type RecordSettings } from './record';

const scope = self as unknown as DedicatedWorkerGlobalScope;
const post = (msg: FromWorker, transfer: Transferable[] = []) => scope.postMessage(msg, transfer);

/** Longest stretch of stepping between looks at the message queue. */
const SLICE_MS = 12;
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

let sim: Sim | null = null;
let viewer: Viewer | null = null;
let maxSteps = 0;
let playing = false;
let stepsPerSecond = 30;
let overlay: string | null = null;
/** The metric the page charts, and about how many points it draws. */
let chartMetric: string | null = null;
let chartPoints = 400;
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
function inLaterTask(f: () => void) {
  later.push(f);
  channel.port2.postMessage(null);
}
function schedule() {
  if (!tickScheduled) {
    tickScheduled = true;
    inLaterTask(() => {
      tickScheduled = false;
      tick();
    });
  }
}

function guard<T>(context: 'load' | 'apply' | 'step', f: () => T): T | undefined {
  try {
    return f();
  } catch (e) {
    const panic = panic_message();
    if (panic) {
      sim = null;
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

function sendFrame(force = false) {
  if (!sim || (awaitingAck && !force)) return;
  const s = sim;
  const frame = guard('step', (): Frame => {
    let hash: string | null = null;
    const now = performance.now();
    if (!playing || now >= nextHashAt) {
      hash = s.hash();
      nextHashAt = now + Math.max(HASH_EVERY_MS, (performance.now() - now) / HASH_SHARE);
    }
    const scene = s.scene_if_changed() as Scene | null;
    const range = overlay ? viewer?.overlay_range() : undefined;
    return {
      steps: s.steps(),
      furthest: s.furthest(),
      maxSteps,
      finished: s.finished(),
      completed: s.completed(),
      hash,
      metrics: s.metrics() as Metrics,
      stepsPerSecond: playing ? measuredRate() : 0,
      scene,
      chart: chartMetric ? chartBand(s, chartMetric) : null,
      overlayRange: range ? [range[0], range[1]] : null,
      drawn,
      work: work(),
    };
  });
  if (!frame) return;
  const transfer: Transferable[] = [];
  if (frame.chart) transfer.push(frame.chart.steps.buffer, frame.chart.min.buffer, frame.chart.max.buffer);
  awaitingAck = true;
  dirty = false;
  post({ type: 'frame', frame }, transfer);
  if (frame.finished && !goalJudged) {
    goalJudged = true;
    judge(s);
  } else if (!frame.finished) goalJudged = false;
}

/** Milliseconds spent in the model's steps since the worker started. */
let stepMs = 0;
/** The wasm instance's memory, once started. */
let memory: WebAssembly.Memory | null = null;

function work(): Frame['work'] {
  const [frames, uploadMs, drawMs] = viewer ? viewer.timing() : [0, 0, 0];
  return { stepMs, frames, uploadMs, drawMs, wasmBytes: memory?.buffer.byteLength ?? 0 };
}

/** Draws the lattice as it stands, now. */
function draw() {
  if (!viewer || !sim) return;
  const v = viewer;
  const s = sim;
  if (changed) v.frame_changed();
  changed = false;
  const stats = guard('step', () => v.draw_sim(s, overlay ?? undefined) as RenderStats | null);
  if (stats === undefined) return;
  // What was drawn changed (marks hid the ghost, a hover highlighted cells): the page is told.
  if (JSON.stringify(stats) !== JSON.stringify(drawn)) dirty = true;
  drawn = stats;
}

const frameTimer: (f: () => void) => void =
  typeof scope.requestAnimationFrame === 'function' ? (f) => scope.requestAnimationFrame(f) : (f) => setTimeout(f, 16);

/** Draws at the next animation frame, then tells the page (once it took the last frame). */
function redraw() {
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
function touched() {
  changed = true;
  dirty = true;
  redraw();
}

/** The charted metric's record of every step so far, merged to about one point per pixel. */
function chartBand(s: Sim, metric: string): ChartBand {
  const flat = s.chart(metric, chartPoints);
  const n = flat.length / 3;
  return { metric, steps: flat.slice(0, n), min: flat.slice(n, 2 * n), max: flat.slice(2 * n), span: s.chart_span() };
}

/** Posts the exercise's verdict on the run as it stands; nothing for a scenario with no exercise. */
function judge(s: Sim) {
  const result = guard('step', () => s.check_goal() as Check | undefined);
  if (result) post({ type: 'goal', met: result.met, because: result.because, steps: s.steps() });
}

function setPlaying(on: boolean) {
  if (playing === on) return;
  playing = on && !!sim && !sim.finished();
  budget = 0;
  lastTick = performance.now();
  rateWindow = [];
  post({ type: 'playing', playing });
  if (!playing) touched();
  schedule();
}

/** Goes to the step a seek asked for, if one is waiting. False if the run was lost doing it. */
function seekNow(): boolean {
  if (!sim || seekTo === null) return !!sim;
  const s = sim;
  const step = seekTo;
  seekTo = null;
  if (guard('step', () => s.seek(step)) === undefined && !sim) return false;
  touched();
  return true;
}

/** Steps the run `count` steps, timing them for the page and for the pace; undefined if it failed. */
function timedAdvance(s: Sim, count: number): number | undefined {
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
  if (!sim || followTo === null) return false;
  const s = sim;
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
  if (!sim) return false;
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
  if (playing && sim) {
    const s = sim;
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
    if (!sim) return;
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

function handle(msg: ToWorker) {
  switch (msg.type) {
    case 'load': {
      playing = false;
      followTo = null;
      const created = guard('load', () => new Sim(msg.scenario));
      if (!created) return;
      sim?.free();
      sim = created;
      maxSteps = created.max_steps();
      post({ type: 'loaded', layout: created.layout(), scenario: created.scenario_json() });
      post({ type: 'playing', playing: false });
      awaitingAck = false;
      drawn = null;
      attachLayout();
      changed = true;
      draw();
      sendFrame(true);
      return;
    }
    case 'play':
      followTo = null;
      setPlaying(true);
      return;
    case 'pause':
      setPlaying(false);
      return;
    case 'step': {
      if (!sim) return;
      const s = sim;
      setPlaying(false);
      followTo = null;
      guard('step', () => s.advance(msg.count));
      touched();
      return;
    }
    case 'check':
      if (sim) judge(sim);
      return;
    case 'seek':
      if (!sim) return;
      setPlaying(false);
      followTo = null;
      seekTo = msg.step;
      schedule();
      return;
    case 'follow':
      if (!sim) return;
      setPlaying(false);
      seekTo = null;
      followTo = msg.step;
      schedule();
      return;
    case 'speed':
      stepsPerSecond = msg.stepsPerSecond;
      budget = 0;
      lastTick = performance.now();
      return;
    case 'overlay':
      overlay = msg.field;
      touched();
      return;
    case 'chart':
      chartMetric = msg.metric;
      chartPoints = Math.max(1, Math.min(4096, Math.round(msg.points)));
      dirty = true;
      redraw();
      return;
    case 'apply': {
      if (!sim) return;
      const s = sim;
      const ok = guard('apply', () => {
        s.apply(msg.action);
        return true;
      });
      if (ok) {
        post({ type: 'scenario', scenario: s.scenario_json() });
        touched();
      }
      return;
    }
    case 'inspect': {
      if (!sim) return;
      const s = sim;
      const facts = guard('step', () => s.inspect(msg.cell) as Facts);
      if (facts) post({ type: 'inspected', id: msg.id, cell: msg.cell, facts });
      return;
    }
    case 'ack':
      awaitingAck = false;
      if (dirty) redraw();
      return;
    case 'crash':
      guard('step', () => simulate_panic());
      return;
    case 'ping':
      return;
    case 'visible':
      visible = msg.visible;
      schedule();
      return;
    case 'view': {
      viewer?.free();
      viewer = null;
      const created = guard('load', () => new Viewer(msg.canvas, msg.annotations, msg.prefer));
      if (!created) return;
      viewer = created;
      post({ type: 'viewer', kind: viewer.kind() as 'webgl2' | 'canvas2d' });
      attachLayout();
      touched();
      return;
    }
    case 'resize':
      viewer?.resize(msg.width, msg.height, msg.dpr);
      redraw();
      return;
    case 'camera': {
      const v = viewer;
      if (!v) return;
      const m = msg.move;
      if (m.op === 'drag') v.drag(m.dx, m.dy, m.orbit);
      else if (m.op === 'zoom') v.zoom(m.factor, m.x, m.y);
      else v.fit();
      redraw();
      return;
    }
    case 'marks':
      viewer?.set_marks(msg.marks);
      redraw();
      return;
    case 'pick': {
      const v = viewer;
      const s = sim;
      const value = v && s ? guard('step', () => v.pick_sim(s, msg.x, msg.y)) : null;
      post({ type: 'answer', id: msg.id, value: value ?? { cell: -1, code: 0, hit: null } });
      return;
    }
    case 'code':
      post({ type: 'answer', id: msg.id, value: sim ? sim.cell_code(msg.cell) : 0 });
      return;
    case 'middle':
      post({ type: 'answer', id: msg.id, value: sim ? sim.middle_occupied() : -1 });
      return;
    case 'record':
      void record(msg.id, msg.settings);
      return;
    case 'record-cancel': {
      if (recording?.id === msg.id) {
        recording.stop.abort();
        return;
      }
      // Cancelled before it started: it never will.
      const waiting = held.findIndex((m) => m.type === 'record' && m.id === msg.id);
      if (waiting >= 0) {
        held.splice(waiting, 1);
        post({ type: 'record-failed', id: msg.id, message: 'cancelled', cancelled: true });
      }
      return;
    }
  }
}

// ---- recording ----------------------------------------------------------------------------------

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

/** The run and the view, as the recorder steps and copies them. */
const recordHost: RecordHost = {
  steps: () => sim?.steps() ?? 0,
  async advance(count) {
    const s = sim;
    if (!s) throw new Error('the simulation stopped');
    if (timedAdvance(s, count) === undefined) throw new Error('the run could not be stepped');
    changed = true;
    dirty = true;
    // The GIF encoder never waits on anything: without this task boundary the worker would read
    // no message until the recording ended. Here the page's Cancel and acks get in.
    await new Promise<void>((resolve) => inLaterTask(resolve));
    return { steps: s.steps(), finished: s.finished() };
  },
  async captureFrame() {
    draw();
    const v = viewer;
    if (!v) throw new Error('the view is gone');
    let bitmap: ImageBitmap;
    try {
      // In the task that drew: WebGL keeps no drawing buffer past it.
      bitmap = v.capture();
    } catch (e) {
      throw new Error(`the view could not be captured: ${String(e)}`);
    }
    // The page follows the recording (step counter, panels) as fast as it takes frames.
    if (dirty) sendFrame();
    return bitmap;
  },
};

/**
 * Records the view from the step the run stands at, as the page's dialog asked (it has already
 * resized the view to the recording's scale), and sends back the file or why there is none.
 */
async function record(id: number, settings: RecordSettings) {
  recording = { id, stop: new AbortController() };
  try {
    setPlaying(false);
    // A seek the page asked for before recording is where the recording starts.
    seekNow();
    if (!sim || !viewer) throw new Error('nothing is drawn yet');
    const progress = (done: number, total: number) => post({ type: 'record-progress', id, done, total });
    const { blob, from, to } = await encode(recordHost, settings, recording.stop.signal, progress);
    post({ type: 'recorded', id, blob, from, to });
  } catch (e) {
    post({ type: 'record-failed', id, message: e instanceof Error ? e.message : String(e), cancelled: e instanceof Cancelled });
  } finally {
    recording = null;
    // A held 'record' starts the next recording, which holds what follows it.
    while (!recording && held.length > 0) handleReporting(held.shift()!);
  }
}

/** Tells the view the run's lattice and legends. */
function attachLayout() {
  const v = viewer;
  const s = sim;
  if (v && s) guard('load', () => v.set_layout_of(s));
}

const queue: ToWorker[] = [];
let ready = false;
/** Handles a message now, or holds it until the recording under way ends. */
function take(msg: ToWorker) {
  if (recording && !DURING_RECORDING.has(msg.type)) held.push(msg);
  else handleReporting(msg);
}

/**
 * Handles a message; if that throws, the page is told why. Messages handled in a batch (those
 * queued before start, those held by a recording) are each handled whatever the one before did.
 */
function handleReporting(msg: ToWorker) {
  try {
    handle(msg);
  } catch (e) {
    post({ type: 'error', message: `the '${msg.type}' request failed: ${e instanceof Error ? e.message : String(e)}`, context: 'step' });
  }
}
scope.onmessage = (e: MessageEvent<ToWorker>) => {
  // Answered at once, even before the wasm is ready: the page's watchdog asks whether this
  // thread still takes messages at all.
  if (e.data.type === 'ping') post({ type: 'pong', id: e.data.id });
  else if (e.data.type === 'module') start(e.data.module);
  else if (ready) take(e.data);
  else queue.push(e.data);
};

/** Starts with the page's compiled module (compiled once, for both threads). */
function start(module: WebAssembly.Module) {
  init({ module_or_path: module })
    .then((exports) => {
      memory = exports.memory;
      ready = true;
      post({ type: 'ready' });
      for (const m of queue.splice(0)) take(m);
    })
    .catch((e: unknown) => post({ type: 'error', message: `the simulation could not start: ${String(e)}`, context: 'load' }));
}
