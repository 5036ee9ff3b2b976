// The simulation worker: owns the scenario in view (the wasm Draft), the run built from it (Sim)
// and the lattice view (a wasm Viewer drawing on the page's transferred OffscreenCanvas). An
// opening or an edit is checked once by the Draft, and the run is built from the checked scenario
// it holds: nothing is read or checked again. The play loop and the frames are web/sim/pace.ts's (with web/sim/host.ts, what they share);
// recordings are web/sim/recorder.ts's. It starts with the page's module (kumiki_wasm); a scenario
// that carries rule scripts switches it, for good, to the rules module (kumiki_wasm_rules, the same
// calls with the script engine), fetched then and never for a scenario without scripts.
import * as pageModule from '../pkg/kumiki_wasm.js';
import type { Comparison, Facts, Proposal } from '../contract.gen';
import { guard, memory, post, run } from './host';
import { acknowledged, follow, frameFree, judge, play, redraw, seek, setPlaying, setSpeed, setVisible, started, stepNow, touched, untold } from './pace';
import { clickStates } from './clicks';
import { LARGE_CELLS, type Proposed, type ToWorker } from './protocol';
import { cancelRecording, holdsBack, record } from './recorder';
import { needsRules } from './rules';

/** The calls the worker makes of its wasm module: the page's module's, which the rules module has too. */
type Wasm = typeof pageModule;
type RulesWasm = typeof import('../pkg/kumiki_wasm_rules.js');
/** The module in use. */
let wasm: Wasm = pageModule;
/** The rules module, once asked for: fetched and started once. */
let rulesWasm: Promise<RulesWasm> | null = null;
/** The rules module's memory, once started. */
let rulesMemory: WebAssembly.Memory | null = null;
/** The scenario in view's text, to open it again in the rules module's Draft when the worker switches. */
let inView: string | null = null;
/** The page's canvases and what it last asked of the view, to draw again with the rules module's Viewer. */
type ViewAsked = { view: Extract<ToWorker, { type: 'view' }> | null; resize: ToWorker | null; marks: ToWorker | null };
let viewAsked: ViewAsked = { view: null, resize: null, marks: null };

const scope = self as unknown as DedicatedWorkerGlobalScope;

/** The scenario in view, made once the module has started. */
let draft: pageModule.Draft | null = null;
/** A large scenario proposed and waiting for the page to agree to it: its request and text. */
let waiting: { id: number; text: string } | null = null;

/** Answers an opening or an edit; runs it unless it was refused, or is large and the page asks first. */
function proposed(id: number, proposal: Proposal | undefined, ask: boolean) {
  waiting = null;
  if (!proposal) return;
  const large = proposal.large_cells > 0;
  const answer: Proposed = {
    id,
    problem: proposal.problem ?? null,
    in_full: proposal.in_full ?? null,
    large_cells: proposal.large_cells,
    text: large ? proposal.text : null,
  };
  post({ type: 'proposed', proposal: answer });
  if (proposal.problem) return;
  if (!large) startRun(id, () => wasm.Sim.start(needDraft()), proposal.text);
  else if (ask) waiting = { id, text: proposal.text };
  else buildLarge(id, proposal.text);
}

/** Checks and builds a large scenario (this takes a while), which then becomes the one in view. */
function buildLarge(id: number, text: string) {
  startRun(id, () => {
    const sim = new wasm.Sim(text);
    needDraft().ran(sim);
    return sim;
  });
}

/** Replaces the run with `make()`'s and tells the page: its layout, its text and its comparison. */
function startRun(id: number, make: () => pageModule.Sim, text?: string) {
  const created = guard('load', make);
  if (!created) return;
  run.sim?.free();
  run.sim = created;
  inView = text ?? created.scenario_json();
  const comparison = guard('load', () => needDraft().comparison() as Comparison) ?? { kind: 'none' };
  post({ type: 'loaded', id, layout: created.layout(), scenario: inView, comparison });
  if (run.viewer) attachLayout();
  else attachAsked();
  started();
}

function needDraft(): pageModule.Draft {
  draft ??= new wasm.Draft(LARGE_CELLS);
  return draft;
}

/** Tells the view the run's lattice and legends. */
function attachLayout() {
  const v = run.viewer;
  const s = run.sim;
  if (v && s) guard('load', () => v.set_layout_of(s));
}

function handle(msg: ToWorker) {
  switch (msg.type) {
    case 'open':
      return proposed(
        msg.id,
        guard('load', () => needDraft().open(msg.text, msg.keepLocks) as Proposal),
        msg.ask,
      );
    case 'edit':
      return proposed(
        msg.id,
        guard('load', () => needDraft().edit_all(msg.changes) as Proposal),
        true,
      );
    case 'build':
      if (waiting?.id === msg.id) buildLarge(msg.id, waiting.text);
      waiting = null;
      return;
    case 'reset':
      if (run.sim) startRun(0, () => wasm.Sim.start(needDraft()));
      return;
    case 'link': {
      // A name too long for a hand-in is the caller's to show, not the banner's.
      let value: unknown;
      try {
        value = needDraft().link(msg.name ?? undefined);
      } catch (e) {
        value = { error: e instanceof Error ? e.message : String(e) };
      }
      post({ type: 'answer', id: msg.id, value });
      return;
    }
    case 'handin': {
      let value: unknown;
      try {
        value = needDraft().handin(msg.name, msg.record);
      } catch (e) {
        value = { error: e instanceof Error ? e.message : String(e) };
      }
      post({ type: 'answer', id: msg.id, value });
      return;
    }
    case 'goal-problem':
      post({ type: 'answer', id: msg.id, value: needDraft().goal_problem(msg.goal, msg.metrics) ?? null });
      return;
    case 'clicks':
      post({ type: 'answer', id: msg.id, value: clickStates(run.sim, needDraft(), msg.tools) });
      return;
    case 'play':
      return play();
    case 'pause':
      return setPlaying(false);
    case 'step':
      if (run.sim) stepNow(run.sim, msg.count);
      return;
    case 'check':
      if (run.sim) judge(run.sim);
      return;
    case 'seek':
      if (run.sim) seek(msg.step);
      return;
    case 'follow':
      if (run.sim) follow(msg.step);
      return;
    case 'speed':
      return setSpeed(msg.stepsPerSecond);
    case 'overlay':
      run.overlay = msg.field;
      return touched();
    case 'chart':
      run.chartMetric = msg.metric;
      run.chartPoints = Math.max(1, Math.min(4096, Math.round(msg.points)));
      return untold();
    case 'apply':
      return apply(msg.action);
    case 'inspect': {
      const s = run.sim;
      const facts = s ? guard('step', () => s.inspect(msg.cell) as Facts) : undefined;
      if (facts) post({ type: 'inspected', id: msg.id, cell: msg.cell, facts });
      return;
    }
    case 'ack':
      return acknowledged();
    case 'frame-free':
      return frameFree();
    case 'crash':
      guard('step', () => wasm.simulate_panic());
      return;
    case 'rule-slots':
      void answerWithRules(msg.id, (rules) => rules.rule_slots());
      return;
    case 'check-rule':
      void answerWithRules(msg.id, (rules) => ({ problem: rules.check_rule(msg.model, msg.slot, msg.source) ?? null }));
      return;
    case 'ping':
    case 'module':
      return;
    case 'visible':
      return setVisible(msg.visible);
    case 'view':
      viewAsked = { view: msg, resize: null, marks: null };
      if (run.sim) return attachView(msg);
      // The first run starts the view (startRun): the renderer starts while the page takes in the run.
      run.viewer?.free();
      run.viewer = null;
      return;
    case 'resize':
      viewAsked.resize = msg;
      run.viewer?.resize(msg.width, msg.height, msg.dpr);
      return redraw();
    case 'camera': {
      const v = run.viewer;
      if (!v) return;
      const m = msg.move;
      if (m.op === 'drag') v.drag(m.dx, m.dy, m.orbit);
      else if (m.op === 'zoom') v.zoom(m.factor, m.x, m.y);
      else v.fit();
      return redraw();
    }
    case 'marks':
      viewAsked.marks = msg;
      run.viewer?.set_marks(msg.marks);
      return redraw();
    case 'pick': {
      const v = run.viewer;
      const s = run.sim;
      const value = v && s ? guard('step', () => v.pick_sim(s, msg.x, msg.y)) : null;
      post({ type: 'answer', id: msg.id, value: value ?? { cell: -1, code: 0, hit: null } });
      return;
    }
    case 'code':
      post({ type: 'answer', id: msg.id, value: run.sim ? run.sim.cell_code(msg.cell) : 0 });
      return;
    case 'middle':
      post({ type: 'answer', id: msg.id, value: run.sim ? run.sim.middle_occupied() : -1 });
      return;
    case 'record':
      void record(msg.id, msg.settings, handleReporting);
      return;
    case 'record-cancel':
      return cancelRecording(msg.id);
  }
}

/** Applies a click tool's action now and records it in the scenario in view. */
function apply(action: string) {
  const s = run.sim;
  if (!s) return;
  const ok = guard('apply', () => {
    s.apply(action);
    return true;
  });
  if (!ok) return;
  const d = needDraft();
  d.ran(s);
  const comparison = guard('step', () => d.comparison() as Comparison) ?? { kind: 'none' };
  inView = s.scenario_json();
  post({ type: 'scenario', scenario: inView, comparison });
  touched();
}

/** Draws on the page's canvases from now on (a new renderer, or a restarted worker). */
function attachView(msg: Extract<ToWorker, { type: 'view' }>) {
  run.viewer?.free();
  run.viewer = null;
  const created = guard('load', () => new wasm.Viewer(msg.canvas, msg.annotations, msg.prefer));
  if (!created) return;
  run.viewer = created;
  post({ type: 'viewer', kind: created.kind() as 'webgl2' | 'canvas2d' });
  attachLayout();
  touched();
}

const queue: ToWorker[] = [];
let ready = false;
/** Handles a message now, or holds it until the recording under way ends. */
function take(msg: ToWorker) {
  if (holdsBack(msg)) return;
  if (wasm === pageModule && needsRules(msg)) {
    // Held, with every message after it, until the rules module has started and holds the scenario.
    ready = false;
    queue.unshift(msg);
    void switchToRules();
    return;
  }
  handleReporting(msg);
}

/** The rules module, fetched and started the first time it is asked for. */
function loadRules(): Promise<RulesWasm> {
  rulesWasm ??= import('../pkg/kumiki_wasm_rules.js').then(async (rules) => {
    rulesMemory = (await rules.default()).memory;
    return rules;
  });
  return rulesWasm;
}

/** Answers a Rules room's question with the rules module's free functions (the run is not moved). */
async function answerWithRules(id: number, ask: (rules: RulesWasm) => unknown) {
  let value: unknown;
  try {
    value = ask(await loadRules());
  } catch (e) {
    value = { error: e instanceof Error ? e.message : String(e) };
  }
  post({ type: 'answer', id, value });
}

/**
 * Moves the scenario in view, its view and the messages held since to the rules module: its Draft
 * opens the scenario in view again (its text carries its exercise and its locks), its Viewer draws
 * on the page's canvases. The run in view is dropped: the message held (an opening or an edit)
 * starts the next one.
 */
async function switchToRules() {
  let rules: RulesWasm;
  try {
    rules = await loadRules();
  } catch (e) {
    queue.shift();
    post({ type: 'error', message: `the rule scripts' engine could not load: ${String(e)}`, context: 'load' });
    return drain();
  }
  run.sim?.free();
  run.sim = null;
  run.viewer?.free();
  run.viewer = null;
  draft?.free();
  draft = null;
  wasm = rules as unknown as Wasm;
  memory.wasm = rulesMemory;
  memory.panicMessage = rules.panic_message;
  if (inView) guard('load', () => needDraft().open(inView ?? '', false));
  attachAsked();
  drain();
}

/** Draws on the canvases the page gave last, at the size and with the marks it asked for since. */
function attachAsked() {
  const { view, resize, marks } = viewAsked;
  if (!view) return;
  attachView(view);
  if (resize) handle(resize);
  if (marks) handle(marks);
}

/** Handles the messages held while the module started. */
function drain() {
  ready = true;
  // One at a time: a message may switch the module, and those after it wait again.
  while (ready && queue.length > 0) take(queue.shift() as ToWorker);
}

/** Handles a message, telling the page why if it throws: each of a batch (queued, held) is handled. */
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
  pageModule
    .default({ module_or_path: module })
    .then((exports) => {
      memory.wasm = exports.memory;
      post({ type: 'ready' });
      drain();
    })
    .catch((e: unknown) => post({ type: 'error', message: `the simulation could not start: ${String(e)}`, context: 'load' }));
}
