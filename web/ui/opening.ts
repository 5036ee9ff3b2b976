// Large scenarios open in the simulation worker first, and one estimated to need much memory
// only once the user agrees. Checking a scenario lays out its shapes, which for a 4096 × 4096
// lattice takes seconds; on the main thread that would freeze the page. The scenario in view
// (web/wasm.ts, Draft) therefore checks only scenarios whose shapes span up to LARGE_CELLS cells
// (counted from the text, nothing built); a larger one is sent straight to the worker, which checks
// it while it builds its run, and the page shows a notice with an indeterminate bar and a way to
// stop until the worker answers. Its changes (a new seed, a field) are checked by the worker in
// turn.
import { byId } from './dom';
import * as core from '../wasm';

/**
 * Above this many cells the main thread does not check a scenario. Checking costs about 0.2 µs a
 * cell natively and about twice that in wasm: 2^18 cells stay well under 0.1 s on the main thread
 * of a busy machine; the largest (4096 × 4096, 64 times more) take seconds.
 */
export const LARGE_CELLS = 1 << 18;

/**
 * Memory a scenario adds to the page, per cell of its largest shape, measured in headless
 * Chromium (renderer plus GPU process, resident, after playing 10 s, over the default page's) on
 * 2026-11-27: an AMAS target of 2000 × 2000 added 128 MB (34 B a cell: the run, its one keyframe,
 * the view's copy and textures) and the page's largest, 4096 × 4088, 282 MB (18 B a cell: too
 * large for a keyframe; `npm run bench` prints it). The larger share is the estimate, so it errs
 * high. AMAS reaches by far the largest lattices of the four models.
 */
const BYTES_PER_CELL = 34;
/** The page's own memory, measured the same way with the default scenario: renderer and GPU process. */
const PAGE_MB = 350;
/** Above this many megabytes of its own, a scenario is opened only once the user agrees. */
export const ASK_ABOVE_MB = 128;

/** Megabytes a scenario is estimated to add to the page, from its text (nothing built). */
export function memoryEstimateMb(cells: number): number {
  return (cells * BYTES_PER_CELL) / 2 ** 20;
}

/** The notice shown while the worker opens a large scenario, and what to do once it has. */
export class LargeOpening {
  private pending: ((json: string) => void) | null = null;
  private started = 0;
  private timer: ReturnType<typeof setInterval> | undefined;
  private readonly box = byId('opening');
  private readonly text = byId('opening-text');
  private cells = 0;

  /** The largest scenario (in cells) the user agreed to open: its edits are not asked again. */
  private agreed = 0;

  /**
   * `stop` ends the opening (the worker is restarted with the last good scenario); `declined`
   * follows a "no" to opening a scenario that needs much memory (nothing was started).
   */
  constructor(
    stop: () => void,
    private readonly declined: () => void,
  ) {
    byId('opening-stop').addEventListener('click', () => {
      this.failed();
      stop();
    });
  }

  /** True while the worker is opening a large scenario. */
  get active(): boolean {
    return this.pending !== null;
  }

  /**
   * Starts opening a large scenario (its largest shape spans `cells`) in the worker: shows the
   * notice and keeps `opened` for when the worker has loaded it (it gets the worker's canonical
   * JSON). `start` sends it to the worker, at once or once the user agrees.
   */
  begin(cells: number, opened: (json: string) => void, start: () => void) {
    const mb = memoryEstimateMb(cells);
    // One over the page's limits is refused by the worker at once: nothing to ask about.
    if (mb > ASK_ABOVE_MB && cells > this.agreed && cells <= core.pageShapeCells()) {
      this.ask(cells, mb, () => {
        this.agreed = cells;
        this.open(cells, opened);
        start();
      });
      return;
    }
    this.open(cells, opened);
    start();
  }

  /**
   * Asks before opening a scenario estimated to need more than ASK_ABOVE_MB: the estimate, and
   * two answers. Declined (or dismissed), nothing is opened and the scenario in view stays.
   */
  private ask(cells: number, mb: number, agree: () => void) {
    const dialog = byId<HTMLDialogElement>('large-ask');
    byId('large-ask-text').textContent =
      `This scenario is large: ${cells.toLocaleString('en-US')} cells. Kumiki estimates it needs about ${Math.round(mb).toLocaleString('en-US')} MB of memory, on top of about ${PAGE_MB} MB for the page itself. On a small device (a classroom Chromebook, a phone) that can close the tab.`;
    dialog.returnValue = '';
    const answered = () => {
      dialog.removeEventListener('close', answered);
      if (dialog.returnValue === 'open') agree();
      else this.declined();
    };
    dialog.addEventListener('close', answered);
    dialog.showModal();
  }

  private open(cells: number, opened: (json: string) => void) {
    this.cells = cells;
    this.pending = opened;
    this.started = performance.now();
    this.show();
    clearInterval(this.timer);
    this.timer = setInterval(() => this.show(), 1000);
    this.box.hidden = false;
    return true;
  }

  private show() {
    const seconds = Math.floor((performance.now() - this.started) / 1000);
    this.text.textContent = `This scenario is large (${this.cells.toLocaleString('en-US')} cells); opening it…${seconds ? ` ${seconds} s` : ''}`;
  }

  /** The worker loaded it: runs what was kept for then, and hides the notice. */
  loaded(json: string) {
    const opened = this.pending;
    this.end();
    opened?.(json);
  }

  /** The worker refused it or was stopped: the scenario in view stays. */
  failed() {
    this.end();
  }

  private end() {
    this.pending = null;
    clearInterval(this.timer);
    this.box.hidden = true;
  }
}
