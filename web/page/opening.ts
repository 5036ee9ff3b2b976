// Large scenarios: one estimated to need much memory opens only once the user agrees, and while
// one is checked and built the page shows a notice with an indeterminate bar and a way to stop.
// Checking a scenario lays out its shapes, which for a 4096 × 4096 lattice takes seconds. The
// simulation worker's Draft (web/sim/worker.ts) counts a scenario's cells from its text, nothing
// built, and answers one over LARGE_CELLS before checking it; the page asks or shows the notice,
// then lets the worker build it. Its changes (a new seed, a field) go the same way.
import { byId, markup } from '../widgets/dom';
import * as core from '../wasm';
import dialog from './large-ask.html?raw';

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

/** The notice shown while the worker opens a large scenario. */
export class LargeOpening {
  private pending = false;
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
    document.body.append(markup(dialog));
    byId('opening-stop').addEventListener('click', () => {
      this.failed();
      stop();
    });
  }

  /** True while the worker is opening a large scenario. */
  get active(): boolean {
    return this.pending;
  }

  /**
   * Starts opening a large scenario (its largest shape spans `cells`) in the worker: shows the
   * notice until it has loaded. `start` lets the worker build it, at once or once the user agrees.
   */
  begin(cells: number, start: () => void) {
    const mb = memoryEstimateMb(cells);
    // One over the page's limits is refused by the worker at once: nothing to ask about.
    if (mb > ASK_ABOVE_MB && cells > this.agreed && cells <= core.pageShapeCells()) {
      this.ask(cells, mb, () => {
        this.agreed = cells;
        this.open(cells);
        start();
      });
      return;
    }
    this.open(cells);
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

  private open(cells: number) {
    this.cells = cells;
    this.pending = true;
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

  /** The worker loaded it: the notice goes. */
  loaded() {
    this.end();
  }

  /** The worker refused it or was stopped: the scenario in view stays. */
  failed() {
    this.end();
  }

  private end() {
    this.pending = false;
    clearInterval(this.timer);
    this.box.hidden = true;
  }
}
