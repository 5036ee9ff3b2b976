// The page without a browser, for the features' unit tests: the shell's markup (static/index.html)
// in a DOM library's document, the real page context (session, events, tabs, banner, preferences)
// and the real core. What the simulation worker does is done here, in this thread, with the same
// wasm calls (web/sim/worker.ts): the Draft checks each opening and edit, the run starts from it and
// its frames come back. Only the drawing is left out: the view is a stand-in that keeps its marks.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import type { Comparison, Frame, Proposal, SlotDoc, Verdict } from '../../web/contract.gen';
import type { Feature, PageContext, PageEvents } from '../../web/page/context';
import { EarlyInput } from '../../web/page/early';
import { Events } from '../../web/page/events';
import { Session } from '../../web/page/session';
import { sessionHost, workerEvents } from '../../web/page/shell';
import { loadPrefs } from '../../web/page/store';
import { Tabs } from '../../web/page/tabs';
import * as wasm from '../../web/pkg/kumiki_wasm.js';
import * as rulesWasm from '../../web/pkg/kumiki_wasm_rules.js';
import type { View } from '../../web/render/view';
import type { SimClient, SimEvents } from '../../web/sim/client';
import type { ClickState, Proposed, ToWorker } from '../../web/sim/protocol';
import { Banner } from '../../web/widgets/banner';
import type { Catalogue } from '../../web/wasm';

const root = (path: string) => resolve(__dirname, '../..', path);

let started = false;
/** The page's wasm module, started once in this thread. */
export function startCore() {
  if (started) return;
  wasm.initSync({ module: readFileSync(root('web/pkg/kumiki_wasm_bg.wasm')) });
  started = true;
}

let rulesStarted = false;
/** The page's rules module (the simulation with the script engine), started once in this thread. */
export function startRules(): typeof rulesWasm {
  if (!rulesStarted) rulesWasm.initSync({ module: readFileSync(root('web/pkg/kumiki_wasm_rules_bg.wasm')) });
  rulesStarted = true;
  return rulesWasm;
}

/**
 * A 2-D context that draws nothing: the DOM library has no canvas, and the features' charts and
 * editors only need one to exist.
 */
function noCanvas() {
  const context = (canvas: HTMLCanvasElement): unknown =>
    new Proxy(
      {},
      {
        get: (_, key) => (key === 'canvas' ? canvas : key === 'measureText' ? () => ({ width: 0 }) : () => undefined),
        set: () => true,
      },
    );
  HTMLCanvasElement.prototype.getContext = function (this: HTMLCanvasElement) {
    return context(this);
  } as never;
  (globalThis as Record<string, unknown>).Path2D ??= class {
    constructor() {
      // biome-ignore lint/correctness/noConstructorReturn: a path that records nothing, whatever is drawn on it.
      return new Proxy(this, { get: () => () => undefined });
    }
  };
}

/** The shell's markup: static/index.html's body, without its script. */
function shell() {
  const html = readFileSync(root('static/index.html'), 'utf8');
  document.body.innerHTML = /<body>([\s\S]*)<\/body>/.exec(html)?.[1] ?? '';
}

/** A tick of the event loop: the worker's next message. */
const later = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

/**
 * The simulation worker's side, in this thread: its Draft and its run, in the page's module, or in
 * its rules module for a test of scenarios with rule scripts (`rules`; the worker itself switches
 * to it when such a scenario opens, which the browser tests check).
 */
class Worker {
  private readonly module: typeof wasm;
  readonly draft: wasm.Draft;
  sim: wasm.Sim | null = null;
  /** Messages the page sent that a test may look at: 'edit' with its changes, 'open' with its text. */
  readonly sent: string[] = [];
  chart: string | null = null;
  private waiting: { id: number; text: string } | null = null;
  private id = 0;

  constructor(
    private readonly on: () => SimEvents,
    rules: boolean,
  ) {
    this.module = rules ? (startRules() as unknown as typeof wasm) : wasm;
    this.draft = new this.module.Draft(1 << 18);
  }

  /** The worker's answers to the questions only its rules module answers ('rule-slots', 'check-rule'). */
  async ask(message: (id: number) => ToWorker): Promise<unknown> {
    const msg = message(0);
    await later();
    if (msg.type === 'rule-slots') return startRules().rule_slots() as SlotDoc[];
    if (msg.type !== 'check-rule') throw new Error(`the test's worker answers no '${msg.type}'`);
    this.sent.push(`check-rule ${msg.model}.${msg.slot}`);
    return { problem: startRules().check_rule(msg.model, msg.slot, msg.source) ?? null };
  }

  private answer(id: number, proposal: Proposal, ask: boolean): Proposed {
    const large = proposal.large_cells > 0;
    if (!proposal.problem) {
      if (!large) void later().then(() => this.start(id, () => this.module.Sim.start(this.draft), proposal.text));
      else if (ask) this.waiting = { id, text: proposal.text };
      else void later().then(() => this.buildLarge(id, proposal.text));
    }
    return { id, problem: proposal.problem ?? null, in_full: proposal.in_full ?? null, large_cells: proposal.large_cells, text: large ? proposal.text : null };
  }

  private buildLarge(id: number, text: string) {
    this.start(id, () => {
      const sim = new this.module.Sim(text);
      this.draft.ran(sim);
      return sim;
    });
  }

  private start(id: number, make: () => wasm.Sim, text?: string) {
    this.sim?.free();
    this.sim = make();
    const comparison = this.draft.comparison() as Comparison;
    this.on().loaded(id, this.sim.layout(), text ?? this.sim.scenario_json(), comparison);
    this.frame();
  }

  /** Sends the page a frame of the run as it stands. */
  frame() {
    if (!this.sim) return;
    const frame = this.sim.frame(true, this.chart ?? undefined, 400) as Frame;
    this.on().frame(frame, { stepsPerSecond: 0, overlayRange: null, scene: null, work: { stepMs: 0, frames: 0, uploadMs: 0, drawMs: 0, wasmBytes: 0 } });
  }

  async open(text: string, keepLocks: boolean, ask: boolean): Promise<Proposed> {
    this.sent.push(`open ${text.length > 80 ? `${text.slice(0, 80)}…` : text}`);
    await later();
    return this.answer(++this.id, this.draft.open(text, keepLocks) as Proposal, ask);
  }

  async edit(changes: string): Promise<Proposed> {
    this.sent.push(`edit ${changes}`);
    await later();
    return this.answer(++this.id, this.draft.edit_all(changes) as Proposal, true);
  }

  build(id: number) {
    const waiting = this.waiting;
    if (waiting?.id === id) void later().then(() => this.buildLarge(id, waiting.text));
  }

  reset() {
    void later().then(() => this.start(0, () => this.module.Sim.start(this.draft)));
  }

  async link(name?: string, record?: Record<string, unknown>): Promise<string> {
    if (!record) return this.draft.link(name);
    this.sent.push(`handin ${name}`);
    await later();
    return this.draft.handin(name ?? '', JSON.stringify(record));
  }

  /** The exercise's verdict on the run as it stands, as the worker's 'check' answers it. */
  check() {
    void later().then(() => {
      const sim = this.sim;
      const verdict = sim?.check_goal() as Verdict | undefined;
      if (sim && verdict) this.on().goal(verdict.met, verdict.because, sim.steps(), verdict.credit ?? []);
    });
  }

  async goalProblem(goal: string, metrics: string[]): Promise<string | null> {
    return this.draft.goal_problem(goal, metrics) ?? null;
  }

  async clicks(tools: { kind: string; label: string }[]): Promise<ClickState[]> {
    this.sent.push(`clicks ${tools.map((t) => t.kind).join(',')}`);
    await later();
    return tools.map((t) => ({ problem: this.draft.click_problem(t.kind, t.label) ?? null, left: this.draft.clicks_left(t.kind) ?? null }));
  }

  /** A click tool's action, applied now and recorded in the scenario in view, as the worker does. */
  apply(action: Record<string, unknown>) {
    this.sent.push(`apply ${JSON.stringify(action)}`);
    void later().then(() => {
      const sim = this.sim;
      if (!sim) return;
      try {
        sim.apply(JSON.stringify(action));
      } catch (e) {
        this.on().error(e instanceof Error ? e.message : String(e), 'apply');
        return;
      }
      this.draft.ran(sim);
      this.on().scenario(sim.scenario_json(), this.draft.comparison() as Comparison);
      this.frame();
    });
  }

  step(count: number) {
    this.sim?.advance(count);
    this.frame();
  }

  setChart(metric: string | null) {
    this.chart = metric;
  }

  async inspect(cell: number) {
    return this.sim?.inspect(cell) ?? {};
  }

  async code(cell: number) {
    return this.sim?.cell_code(cell) ?? 0;
  }
}

/** The view, without its canvases: it keeps the marks the features set. */
function fakeView(): View {
  return {
    marks: { arrows: true, labels: true, hover: -1, highlight: [], selected: -1, ghost: true, bonds: true },
    is3d: false,
    overlayRange: null,
    rendererKind: 'canvas2d',
    companion: null,
    request() {},
    fit() {},
    zoom() {},
    setLayout() {},
    setFrame() {},
    setCaptureScale() {},
    useRenderer: async () => 'canvas2d',
  } as unknown as View;
}

export interface TestPage {
  page: PageContext;
  worker: Worker;
  /** Waits until `ready()` holds, checking after each tick of the event loop. */
  until(ready: () => boolean, what?: string): Promise<void>;
}

/**
 * The page with `features` mounted, the shell's markup and the real core; nothing opened yet. With
 * `rules`, the worker's side runs the rules module (scenarios with scripts run).
 */
export function testPage(features: Feature[], { rules = false }: { rules?: boolean } = {}): TestPage {
  startCore();
  noCanvas();
  localStorage.clear();
  shell();
  const events = new Events<PageEvents>();
  const prefs = loadPrefs();
  const banner = new Banner();
  // Large scenarios open at once: their notice and question are the browser tests'.
  const large = { active: false, loaded() {}, failed() {}, begin: (_cells: number, build: () => void) => build() };
  const worker = new Worker(() => on, rules);
  const sim = new Proxy(worker, {
    get: (target, key) => (key in target ? Reflect.get(target, key) : () => undefined),
  }) as unknown as SimClient;
  const session = new Session(worker, sessionHost(banner, large));
  const page: PageContext = {
    session,
    sim,
    view: fakeView(),
    banner,
    prefs,
    persistPrefs: () => {},
    tabs: new Tabs(prefs, () => {}, events),
    events,
    embedded: false,
    early: new EarlyInput(),
    useRenderer: async () => {},
  };
  const on = workerEvents(() => page, large);
  for (const f of features) if (f.tab) page.tabs.add(f.name, f.tab);
  for (const f of features) f.mount(page);
  const until = async (ready: () => boolean, what = 'the page') => {
    const start = Date.now();
    while (Date.now() - start < 30_000) {
      if (ready()) return;
      await later();
    }
    throw new Error(`${what} did not come`);
  };
  return { page, worker, until };
}

/** The built-in scenarios and lessons as the page fetches them (web/pkg/catalog.json: scripts/catalog.mjs). */
export const catalog = JSON.parse(readFileSync(root('web/pkg/catalog.json'), 'utf8')) as Catalogue;

/** A built-in scenario's text. */
export const preset = (name: string): string => catalog.presetText[name] ?? '';
/** A lesson's text. */
export const lesson = (name: string): string => catalog.lessonText[name] ?? '';
