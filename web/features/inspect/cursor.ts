// The keyboard way to click a cell in the main view. With the view focused, C shows a cursor
// cell; the arrows move it (Page Up and Page Down change the layer of a cubic lattice), Enter or
// Space applies the selected tool there, through the same path as a pointer click, and Escape
// (or C again) hides it. While the cursor is hidden the arrows keep their meaning (step, step
// back), and Shift/Alt+arrows still turn and pan the view.
import { coordOf, is3d } from '../../render/geometry';
import type { Layout } from '../../contract.gen';

export interface CursorHooks {
  layout(): Layout | null;
  /** The middle occupied cell of the run in view (-1: none), to start on the structure. */
  middle(): Promise<number>;
  /** Shows the cursor (or hides it, for -1) in the view. */
  show(cell: number): void;
  /** Clicks a cell with the selected tool, as the pointer does. */
  click(cell: number): void;
  /** Says where the cursor is (for screen readers). */
  announce(cell: number): void;
}

const MOVES: Record<string, [number, number, number]> = {
  ArrowLeft: [-1, 0, 0],
  ArrowRight: [1, 0, 0],
  ArrowUp: [0, -1, 0],
  ArrowDown: [0, 1, 0],
  PageUp: [0, 0, 1],
  PageDown: [0, 0, -1],
};

export class KeyCursor {
  /** The cursor's cell, or -1 when it is hidden. */
  cell = -1;

  constructor(
    wrap: HTMLElement,
    private readonly hooks: CursorHooks,
  ) {
    // On the view's container, so it survives the canvas being replaced when the renderer changes;
    // the view's own Shift/Alt+arrow keys stop before they get here.
    wrap.addEventListener('keydown', (e) => {
      if (!(e.target instanceof HTMLCanvasElement) || e.ctrlKey || e.metaKey || e.altKey || e.shiftKey) return;
      if (this.key(e.key)) {
        e.preventDefault();
        e.stopPropagation();
      }
    });
  }

  /** Hides the cursor (a new scenario was loaded, or its lattice changed). */
  hide() {
    if (this.cell < 0) return;
    this.cell = -1;
    this.hooks.show(-1);
  }

  /** Handles a key on the focused view; true when it was the cursor's. */
  private key(key: string): boolean {
    const layout = this.hooks.layout();
    if (!layout) return false;
    if (key === 'c' || key === 'C') {
      if (this.cell >= 0) {
        this.hide();
        this.hooks.announce(-1);
      } else {
        void this.start(layout).then((cell) => {
          this.place(cell);
          this.hooks.announce(cell);
        });
      }
      return true;
    }
    if (this.cell < 0) return false;
    if (key === 'Escape') {
      this.hide();
      this.hooks.announce(-1);
      return true;
    }
    if (key === 'Enter' || key === ' ') {
      this.hooks.click(this.cell);
      return true;
    }
    const move = MOVES[key];
    if (!move || (move[2] !== 0 && !is3d(layout))) return false;
    const [w, h, d] = layout.dims;
    const [cx, cy, cz] = coordOf(layout.dims, this.cell);
    const [x, y, z] = [cx + move[0], cy + move[1], cz + move[2]];
    // At an edge the cursor stays, and says so again.
    if (x >= 0 && y >= 0 && z >= 0 && x < w && y < h && z < Math.max(1, d)) this.place((z * h + y) * w + x);
    this.hooks.announce(this.cell);
    return true;
  }

  private place(cell: number) {
    this.cell = cell;
    this.hooks.show(cell);
  }

  /** Where the cursor appears: on the structure (its middle cell in memory order), else the middle. */
  private async start(layout: Layout): Promise<number> {
    const middle = await this.hooks.middle();
    if (middle >= 0) return middle;
    const [w, h] = layout.dims;
    return Math.floor(h / 2) * w + Math.floor(w / 2);
  }
}
