// Messages between the page and the simulation worker. The worker also draws the lattice: the
// page transfers its canvases once ('view') and then sends sizes, gestures and marks; frames
// carry only what the panels show, never the lattice's buffers. A recording ('record') is made in
// the worker too: only its progress and the finished file come back. While it runs, the worker
// takes only 'ack' and 'record-cancel' (and answers pings); every other message waits, in order,
// until the recording ends, so nothing moves the run or the view under the recording.
import type { Comparison, Credit, Facts, Frame, Layout } from '../contract.gen';
import type { Marks as ViewMarks } from '../view.gen';
import type { Drawn, WorkerTiming } from '../types';
import type { RecordSettings } from './record';

export type { Picked, Marks as ViewMarks } from '../view.gen';

/**
 * Scenarios whose shapes span more cells than this are not checked at once: the page is told
 * their size first, to show a notice while they are checked and built, and to ask about the
 * memory of one that needs much (web/page/opening.ts); and the page's own thread never reads one.
 * Checking costs about 0.2 µs a cell natively and about twice that in wasm: 2^18 cells stay well
 * under 0.1 s on a busy machine; the largest (4096 × 4096, 64 times more) take seconds.
 */
export const LARGE_CELLS = 1 << 18;

export type RendererChoice = 'webgl2' | 'canvas2d' | 'auto';

export type CameraMove = { op: 'drag'; dx: number; dy: number; orbit: boolean } | { op: 'zoom'; factor: number; x: number; y: number } | { op: 'fit' };

/**
 * The worker's answer to an opening or an edit of the scenario in view (its Draft's proposal): why
 * it was refused, or that it runs. One too large to check at once waits for 'build' when asked to
 * (`large_cells`, with its text so that the page can note it before it is built).
 */
export interface Proposed {
  /** The request's number. */
  id: number;
  /** Why it was refused, briefly; null when it runs. */
  problem: string | null;
  /** The whole of the problem, when it says more. */
  in_full: string | null;
  /** The cells of its largest shape when it is too large to check at once; else 0. */
  large_cells: number;
  /** Its text, when it is large; else null (the run's 'loaded' carries it). */
  text: string | null;
}

/** What the exercise in view says of one click tool (its Draft's `click_problem` and `clicks_left`). */
export interface ClickState {
  /** Why a click of it may not be made, in words to show where the click is made; null when it may. */
  problem: string | null;
  /** How many more of its kind the exercise lets a student add; null when no exercise counts them. */
  left: number | null;
}

export type ToWorker =
  /** The wasm module the page compiled: the worker starts with it, without compiling its own. */
  | { type: 'module'; module: WebAssembly.Module }
  /**
   * Opens scenario text in place of the scenario in view (`keepLocks`: held to its exercise's
   * locks). Answered 'proposed'; then, unless it was refused, or is large and `ask` is set (it
   * then waits for 'build'), 'loaded'.
   */
  | { type: 'open'; id: number; text: string; keepLocks: boolean; ask: boolean }
  /** Sets dotted paths of the scenario in view (`changes`: a JSON object from path to value); answered like 'open'. */
  | { type: 'edit'; id: number; changes: string }
  /** Builds the large scenario proposed in answer to `id`, once the page agreed to it. */
  | { type: 'build'; id: number }
  /** Starts the scenario in view again from step 0 (nothing is read or checked again). */
  | { type: 'reset' }
  /** The share-link payload of the scenario in view (named `name`, a hand-in), as an 'answer'. */
  | { type: 'link'; id: number; name: string | null }
  /** The hand-in link of the exercise in view, named `name`, with its record (`record`: JSON), as an 'answer' (or `{ error }`). */
  | { type: 'handin'; id: number; name: string; record: string }
  /** What is wrong with an exercise goal for the scenario in view, as an 'answer' (null: nothing). */
  | { type: 'goal-problem'; id: number; goal: string; metrics: string[] }
  /** Whether the exercise in view lets each click tool be used, as an 'answer': a `ClickState` each. */
  | { type: 'clicks'; id: number; tools: { kind: string; label: string }[] }
  | { type: 'play' }
  | { type: 'pause' }
  | { type: 'step'; count: number }
  | { type: 'seek'; step: number }
  /**
   * Goes to `step` and stays paused there: forward by stepping (as far as the run goes), back by
   * seeking. The second run of a comparison follows the first's step count with it; follows that
   * arrive together are done once, for the last.
   */
  | { type: 'follow'; step: number }
  | { type: 'check' }
  | { type: 'speed'; stepsPerSecond: number }
  | { type: 'overlay'; field: string | null }
  | { type: 'chart'; metric: string | null; points: number }
  | { type: 'apply'; action: string }
  | { type: 'inspect'; cell: number; id: number }
  | { type: 'ack' }
  /** The page's animation frame came after the worker asked for one ('frame-wanted'): it draws now. */
  | { type: 'frame-free' }
  | { type: 'crash' }
  | { type: 'ping'; id: number }
  /** Whether the page is shown (a hidden page draws nothing, so the run need not wait for it). */
  | { type: 'visible'; visible: boolean }
  | { type: 'view'; canvas: OffscreenCanvas; annotations: OffscreenCanvas; prefer: RendererChoice }
  | { type: 'resize'; width: number; height: number; dpr: number }
  | { type: 'camera'; move: CameraMove }
  | { type: 'marks'; marks: ViewMarks }
  | { type: 'pick'; id: number; x: number; y: number }
  | { type: 'code'; id: number; cell: number }
  | { type: 'middle'; id: number }
  | { type: 'record'; id: number; settings: RecordSettings }
  /**
   * Every model's rule slots (`SlotDoc[]`, the rules module's `rule_slots`), as an 'answer'. The
   * worker fetches and starts its rules module for it, and keeps the run in view where it is.
   */
  | { type: 'rule-slots'; id: number }
  /** Why `source` cannot be slot `slot` of `model`'s script, as an 'answer' `{problem}` (null: it can); the rules module checks it. */
  | { type: 'check-rule'; id: number; model: string; slot: string; source: string }
  /** Stops the recording `id`, or drops it if it has not started; it ends with 'record-failed'. */
  | { type: 'record-cancel'; id: number };

export type FromWorker =
  | { type: 'ready' }
  | { type: 'proposed'; proposal: Proposed }
  /** A run started: of the page's request `id` (0 for a reset or a restart), with its scenario's canonical text. */
  | { type: 'loaded'; id: number; layout: Layout; scenario: string; comparison: Comparison }
  /** The run as it stands (generated from the core's record) and what the worker drew and measured. */
  | { type: 'frame'; frame: Frame; drawn: Drawn }
  | { type: 'playing'; playing: boolean }
  /** A click was recorded in the scenario (and, in the past, forked the run). */
  | { type: 'scenario'; scenario: string; comparison: Comparison }
  | { type: 'inspected'; id: number; cell: number; facts: Facts }
  | { type: 'error'; message: string; context: 'load' | 'apply' | 'step' }
  | { type: 'panic'; message: string }
  | { type: 'pong'; id: number }
  /** The exercise's verdict on the run: met, why, and the points of each credit part (`Credit`) when it gives some. */
  | { type: 'goal'; met: boolean; because: string; steps: number; credit: Credit[] }
  | { type: 'viewer'; kind: 'webgl2' | 'canvas2d' }
  /** The view was drawn again with nothing new for the panels (a camera move). */
  | { type: 'drew'; work: WorkerTiming }
  /** Playing at max speed, the worker asks to be told ('frame-free') at the page's next animation frame. */
  | { type: 'frame-wanted' }
  | { type: 'answer'; id: number; value: unknown }
  | { type: 'record-progress'; id: number; done: number; total: number }
  /** A recording finished: the file, and the steps it shows. */
  | { type: 'recorded'; id: number; blob: Blob; from: number; to: number }
  | { type: 'record-failed'; id: number; message: string; cancelled: boolean };
