// The page's side of the simulation worker. It restarts the worker after a panic, with the last
// scenario that loaded, so the page stays usable. The worker holds the scenario in view (its
// Draft) beside the run: this client is the session's way to it (web/page/session.ts).
import type { Comparison, Credit, Facts, Frame, Layout } from '../contract.gen';
import type { ScenarioOwner } from '../page/session';
import type { Drawn, WorkerTiming } from '../types';
import { wasmModule } from '../wasm';
import type { CameraMove, ClickState, FromWorker, Picked, Proposed, RendererChoice, ToWorker, ViewMarks } from './protocol';
import { type Progress, type Recorded, type RecordSettings, Recordings } from './record';

export interface SimEvents {
  /** A run started: of the request `id` (0: a reset, a restart, a follower's scenario). */
  loaded(id: number, layout: Layout, scenario: string, comparison: Comparison): void;
  frame(frame: Frame, drawn: Drawn): void;
  playing(playing: boolean): void;
  /** A click was recorded in the scenario. */
  scenario(scenario: string, comparison: Comparison): void;
  error(message: string, context: 'load' | 'apply' | 'step'): void;
  panic(message: string): void;
  /** The exercise's goal judged on the run: when it ends, or when asked with `check`. */
  goal(met: boolean, because: string, steps: number, credit: Credit[]): void;
  /** The worker has not answered for `ms` milliseconds (`ms` is 0 once it answers again). */
  stalled(ms: number): void;
  /** The worker's view started drawing with this renderer. */
  viewer(kind: 'webgl2' | 'canvas2d'): void;
  /** The view was drawn again (a camera move), with the worker's timing so far. */
  drew(work: WorkerTiming): void;
}

/** Canvases for a (new) worker's view: each worker needs fresh ones, a canvas transfers once. */
export type ViewCanvases = () => { canvas: OffscreenCanvas; annotations: OffscreenCanvas; prefer: RendererChoice };

/** How long the worker may leave a ping unanswered before the page says so. */
const STALL_MS = 4000;

export class SimClient implements ScenarioOwner {
  private worker!: Worker;
  /** The scenario of the last run that loaded: a restarted worker opens it again. */
  private lastGood: string | null = null;
  private requestId = 0;
  /** Openings and edits waiting for their proposal. */
  private proposals = new Map<number, (proposed: Proposed) => void>();
  private inspectId = 0;
  private inspectWaiters = new Map<number, (facts: Facts) => void>();
  private answers = new Map<number, (value: unknown) => void>();
  private askId = 0;
  private readonly recordings = new Recordings();
  private canvases: ViewCanvases | null = null;
  private viewState: { size: { width: number; height: number; dpr: number } | null; marks: ViewMarks | null } = { size: null, marks: null };
  private speed = 30;
  private overlay: string | null = null;
  private chart: { metric: string | null; points: number } = { metric: null, points: 400 };
  private pingId = 0;
  /** When the oldest unanswered ping was sent; null when every ping has been answered. */
  private unanswered: number | null = null;
  private stalledFor = 0;
  /** The latest frame the worker sent. */
  private last: Frame | null = null;
  /** The second run of a comparison, kept at this run's step (web/features/compare/). */
  private follower: SimClient | null = null;
  /** The run this one follows, when it is the second run of a comparison. */
  private leader: SimClient | null = null;
  /** The worker is playing. */
  private playingNow = false;
  /** The worker stopped playing since its last frame: a frame that says it ended, ended a play. */
  private stoppedPlaying = false;

  constructor(private readonly on: SimEvents) {
    this.start();
    setInterval(() => this.watch(), 1000);
    document.addEventListener('visibilitychange', () => this.send({ type: 'visible', visible: !document.hidden }));
  }

  /**
   * Pairs this run with the second run of a comparison (null: no longer): the second gets this
   * one's speed, overlay and chart, follows its step count (forward by stepping, back by seeking)
   * and pauses with it. Once this run has ended, play and step move the second one alone, to its
   * own end.
   */
  pair(follower: SimClient | null) {
    if (this.follower) this.follower.leader = null;
    this.follower = follower;
    this.reportPlaying();
    if (!follower) return;
    follower.leader = this;
    follower.setSpeed(this.speed);
    follower.setOverlay(this.overlay);
    follower.setChart(this.chart.metric, this.chart.points);
    if (this.last) follower.follow(this.last.steps);
  }

  /** Playing, as the page's Play button shows it: this run, or its follower going on alone. */
  private reportPlaying() {
    this.on.playing(this.playingNow || !!this.follower?.playingNow);
  }

  /** This run has ended and its follower has not: play and step are the follower's. */
  private get followerAlone(): boolean {
    return !!this.follower && !!this.last?.finished && !this.follower.last?.finished;
  }

  /** The watchdog: one ping at a time; a ping left unanswered too long is reported. */
  private watch() {
    const now = performance.now();
    if (this.unanswered === null) {
      this.unanswered = now;
      this.send({ type: 'ping', id: ++this.pingId });
    } else if (now - this.unanswered > STALL_MS) {
      this.stalledFor = now - this.unanswered;
      this.on.stalled(this.stalledFor);
    }
  }

  /**
   * Any message shows the worker's thread runs: a stall shown is over, and an unanswered ping is
   * timed from now. (Without this, a stall noticed just as a long task ended would be reported
   * after that task's own message, and would take its place in the banner.)
   */
  private heard() {
    if (this.unanswered !== null) this.unanswered = performance.now();
    if (this.stalledFor) {
      this.stalledFor = 0;
      this.on.stalled(0);
    }
  }

  /** Ends a worker that does not answer and starts again with the last scenario that loaded. */
  recover() {
    this.restart();
  }

  private start() {
    this.worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: 'kumiki-sim' });
    this.worker.onmessage = (e: MessageEvent<FromWorker>) => this.receive(e.data);
    this.worker.onerror = (e) => this.on.error(`the simulation worker failed: ${e.message}`, 'step');
    const worker = this.worker;
    // The page compiles the module once; a failure is reported where the page loads its own copy.
    wasmModule().then(
      (module) => worker.postMessage({ type: 'module', module } satisfies ToWorker),
      () => {},
    );
    this.send({ type: 'speed', stepsPerSecond: this.speed });
    this.send({ type: 'overlay', field: this.overlay });
    this.send({ type: 'chart', ...this.chart });
    this.send({ type: 'visible', visible: !document.hidden });
    this.attachView();
  }

  /** Gives the worker its view: now, and again after every restart. */
  useView(canvases: ViewCanvases) {
    this.canvases = canvases;
    this.attachView();
  }

  private attachView() {
    if (!this.canvases) return;
    const { canvas, annotations, prefer } = this.canvases();
    this.worker.postMessage({ type: 'view', canvas, annotations, prefer } satisfies ToWorker, [canvas, annotations]);
    // The new view starts with the size and marks the page last gave.
    const { size, marks } = this.viewState;
    if (size) this.send({ type: 'resize', ...size });
    if (marks) this.send({ type: 'marks', marks });
  }

  resize(width: number, height: number, dpr: number) {
    this.viewState.size = { width, height, dpr };
    this.send({ type: 'resize', width, height, dpr });
  }
  setMarks(marks: ViewMarks) {
    this.viewState.marks = marks;
    this.send({ type: 'marks', marks });
  }
  camera(move: CameraMove) {
    this.send({ type: 'camera', move });
  }
  /** What is under a point of the view (CSS pixels). */
  pick(x: number, y: number): Promise<Picked> {
    return this.ask((id) => ({ type: 'pick', id, x, y })) as Promise<Picked>;
  }
  /** The code of one cell as the run stands. */
  code(cell: number): Promise<number> {
    return this.ask((id) => ({ type: 'code', id, cell })) as Promise<number>;
  }
  /** The middle occupied cell (in memory order), or -1. */
  middle(): Promise<number> {
    return this.ask((id) => ({ type: 'middle', id })) as Promise<number>;
  }
  /**
   * Records the view: the worker pauses the run, steps it, draws and encodes each frame, and
   * sends back the file. Rejects with Cancelled as soon as `signal` aborts (see Recordings).
   */
  record(settings: RecordSettings, signal: AbortSignal, progress: Progress): Promise<Recorded> {
    return this.recordings.start(settings, signal, progress, (msg) => this.send(msg));
  }
  /** Asks the worker `message` (given its id) and resolves to its 'answer' (null if it restarted first). */
  ask(message: (id: number) => ToWorker): Promise<unknown> {
    const id = ++this.askId;
    return new Promise((resolve) => {
      this.answers.set(id, resolve);
      this.send(message(id));
    });
  }

  private send(msg: ToWorker) {
    this.worker.postMessage(msg);
  }

  private receive(msg: FromWorker) {
    this.heard();
    switch (msg.type) {
      case 'ready':
        return;
      case 'goal':
        this.on.goal(msg.met, msg.because, msg.steps, msg.credit);
        return;
      case 'pong':
        this.unanswered = null;
        return;
      case 'proposed': {
        const waiter = this.proposals.get(msg.proposal.id);
        this.proposals.delete(msg.proposal.id);
        waiter?.(msg.proposal);
        return;
      }
      case 'loaded':
        this.lastGood = msg.scenario;
        this.on.loaded(msg.id, msg.layout, msg.scenario, msg.comparison);
        return;
      case 'frame': {
        this.last = msg.frame;
        const follower = this.follower;
        // Once this run has ended, the follower is held back to its step only if it is behind;
        // if this run ended playing, the follower plays on alone to its own end.
        if (follower && (!msg.frame.finished || (follower.last?.steps ?? 0) < msg.frame.steps)) follower.follow(msg.frame.steps);
        if (follower && msg.frame.finished && this.stoppedPlaying && !follower.last?.finished) follower.play();
        this.stoppedPlaying = false;
        this.on.frame(msg.frame, msg.drawn);
        return;
      }
      case 'playing':
        if (this.playingNow && !msg.playing) this.stoppedPlaying = true;
        this.playingNow = msg.playing;
        if (this.leader) this.leader.reportPlaying();
        else this.reportPlaying();
        return;
      case 'scenario':
        this.lastGood = msg.scenario;
        this.on.scenario(msg.scenario, msg.comparison);
        return;
      case 'viewer':
        return this.on.viewer(msg.kind);
      case 'drew':
        return this.on.drew(msg.work);
      case 'frame-wanted':
        requestAnimationFrame(() => this.send({ type: 'frame-free' }));
        return;
      case 'answer': {
        const waiter = this.answers.get(msg.id);
        this.answers.delete(msg.id);
        waiter?.(msg.value);
        return;
      }
      case 'record-progress':
      case 'recorded':
      case 'record-failed':
        this.recordings.receive(msg);
        return;
      case 'inspected': {
        const waiter = this.inspectWaiters.get(msg.id);
        this.inspectWaiters.delete(msg.id);
        waiter?.(msg.facts);
        return;
      }
      case 'error':
        return this.on.error(msg.message, msg.context);
      case 'panic':
        this.on.panic(msg.message);
        this.restart();
        return;
    }
  }

  /** A fresh worker with the last scenario that loaded. */
  private restart() {
    this.worker.terminate();
    this.inspectWaiters.clear();
    for (const waiter of this.answers.values()) waiter(null);
    this.answers.clear();
    // Requests the worker never answered are refused, so no caller waits for ever.
    for (const [id, waiter] of this.proposals) waiter({ id, problem: 'the simulation stopped and was restarted', in_full: null, large_cells: 0, text: null });
    this.proposals.clear();
    this.recordings.fail('the simulation stopped and was restarted');
    this.unanswered = null;
    if (this.stalledFor) {
      this.stalledFor = 0;
      this.on.stalled(0);
    }
    this.start();
    if (this.lastGood) this.load(this.lastGood);
  }

  /** Opens a scenario and runs it, whatever its size, answering nobody (a restart, a follower). */
  load(scenario: string) {
    this.last = null;
    this.send({ type: 'open', id: 0, text: scenario, keepLocks: false, ask: false });
  }

  private propose(message: (id: number) => ToWorker): Promise<Proposed> {
    const id = ++this.requestId;
    return new Promise((resolve) => {
      this.proposals.set(id, resolve);
      this.send(message(id));
    });
  }

  open(text: string, keepLocks: boolean, ask: boolean): Promise<Proposed> {
    return this.propose((id) => ({ type: 'open', id, text, keepLocks, ask }));
  }
  edit(changes: string): Promise<Proposed> {
    return this.propose((id) => ({ type: 'edit', id, changes }));
  }
  build(id: number) {
    this.send({ type: 'build', id });
  }
  reset() {
    this.last = null;
    this.send({ type: 'reset' });
  }
  /** The share-link payload of the scenario in view; named `name` with a `record` (when, checks, hints, the answer), its hand-in link. */
  link(name?: string, record?: { made: string; checks: number; hints: number; answer?: string }): Promise<string> {
    const handin = record && JSON.stringify(record);
    return this.ask((id) => (handin ? { type: 'handin', id, name: name ?? '', record: handin } : { type: 'link', id, name: name ?? null })).then((value) => {
      if (typeof value === 'string') return value;
      throw new Error((value as { error?: string } | null)?.error ?? 'the simulation stopped before it made the link');
    });
  }
  goalProblem(goal: string, metrics: string[]): Promise<string | null> {
    return this.ask((id) => ({ type: 'goal-problem', id, goal, metrics })) as Promise<string | null>;
  }
  /** Whether the exercise in view lets each of `tools` (its action's kind and its label) be clicked. */
  clicks(tools: { kind: string; label: string }[]): Promise<ClickState[]> {
    return this.ask((id) => ({ type: 'clicks', id, tools })) as Promise<ClickState[]>;
  }
  play() {
    if (this.followerAlone) this.follower?.play();
    this.send({ type: 'play' });
  }
  pause() {
    this.follower?.pause();
    this.send({ type: 'pause' });
  }
  step(count = 1) {
    if (this.followerAlone) this.follower?.step(count);
    this.send({ type: 'step', count });
  }
  /** Goes to `step` and stays paused (a run ending first stays at its end). */
  follow(step: number) {
    this.send({ type: 'follow', step });
  }
  /** Asks for the exercise's verdict on the run as it stands. */
  check() {
    this.send({ type: 'check' });
  }
  /** Goes to an earlier (or, up to the furthest reached, later) step of the run. */
  seek(step: number) {
    this.send({ type: 'seek', step });
  }
  setSpeed(stepsPerSecond: number) {
    this.speed = stepsPerSecond;
    this.follower?.setSpeed(stepsPerSecond);
    this.send({ type: 'speed', stepsPerSecond });
  }
  setOverlay(field: string | null) {
    this.overlay = field;
    this.follower?.setOverlay(field);
    this.send({ type: 'overlay', field });
  }
  /** Which metric the chart shows, and about how many points it draws: frames carry its record. */
  setChart(metric: string | null, points: number) {
    this.chart = { metric, points };
    this.follower?.setChart(metric, points);
    this.send({ type: 'chart', metric, points });
  }
  apply(action: Record<string, unknown>) {
    this.send({ type: 'apply', action: JSON.stringify(action) });
  }
  ack() {
    this.send({ type: 'ack' });
  }
  crash() {
    this.send({ type: 'crash' });
  }
  inspect(cell: number): Promise<Facts> {
    const id = ++this.inspectId;
    return new Promise((resolve) => {
      this.inspectWaiters.set(id, resolve);
      this.send({ type: 'inspect', cell, id });
    });
  }
}
