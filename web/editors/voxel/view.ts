// The voxel editor's 3-D view: the box around the shape drawn by crate/view on this thread (its
// own wasm Viewer on the editor's canvas), its camera, and what is under the pointer.
import type { Scene } from '../../contract.gen';
import type { Picked } from '../../sim/protocol';
import { message, newViewer, type Viewer } from '../../wasm';
import type { VoxelControls } from './controls';
import { editorLayout } from './units';

/** An editing cursor drawn over the view: where a unit would be added or removed. */
export type EditCursor = { cell: number; kind: 'add' | 'remove' };

export class VoxelView {
  /** Draws the box in 3-D and owns its camera (crate/view, on this thread). */
  private viewer: Viewer | null = null;
  private dims: [number, number, number] = [6, 6, 3];
  private cells: Uint8Array = new Uint8Array(6 * 6 * 3);
  private world: Scene = { ghost: [], ground: 0 };
  private cssWidth = 1;
  private scheduled = false;
  /** The camera was fitted once the view had a size: later resizes keep it. */
  private fitted = false;
  private destroyed = false;
  private readonly resizeObserver: ResizeObserver;

  /** `cursor` says which cursor to draw; `fit` frames the shape (the editor knows its bounds). */
  constructor(
    private readonly ui: VoxelControls,
    private readonly cursor: () => EditCursor | null,
    private readonly fit: () => void,
  ) {
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(ui.wrap);
    try {
      this.viewer = newViewer(ui.canvas.transferControlToOffscreen(), 'auto');
      ui.canvas.dataset.renderer = this.viewer.kind();
      this.viewer.set_layout(editorLayout(this.dims));
    } catch (e) {
      ui.error.textContent = `The 3-D view cannot start: ${message(e)}`;
    }
  }

  /** Draws `cells` of a box of `dims` (moved by `shift` cells from the last), with a scene's ghost and ground. */
  show(dims: [number, number, number], cells: Uint8Array, world: Scene, shift: [number, number]) {
    // Keep what is on screen in place when the box grows or shrinks on the low side.
    this.viewer?.shift_target(shift[0], shift[1], 0);
    if (this.dims.join() !== dims.join()) {
      this.dims = dims;
      this.viewer?.set_layout(editorLayout(dims));
    }
    this.cells = cells;
    this.world = world;
    this.ui.canvas.dataset.visible = String(cells.reduce((s, c) => s + (c ? 1 : 0), 0));
    this.request();
  }

  /** The next fit frames the shape anew, whatever the size. */
  refit() {
    this.fitted = false;
  }

  /** Frames the box from `lo` to `hi` (lattice coordinates) with `margin`. */
  fitBox(lo: number[], hi: number[], margin: number) {
    this.viewer?.fit_box(new Float64Array(lo), new Float64Array(hi), margin);
    this.fitted = this.cssWidth > 1;
    this.request();
  }

  drag(dx: number, dy: number, orbit: boolean) {
    this.viewer?.drag(dx, dy, orbit);
    this.request();
  }

  zoom(factor: number, x: number, y: number) {
    this.viewer?.zoom(factor, x, y);
    this.request();
  }

  /** The camera's turn about the vertical, in radians. */
  yaw(): number {
    return this.viewer?.yaw() ?? 0;
  }

  /** The unit hit at a point of the view and the empty cell in front of its face. */
  pick(sx: number, sy: number): Picked['hit'] {
    return this.viewer ? (this.viewer.pick_cells(this.cells, sx, sy) as Picked).hit : null;
  }

  /** Where a point of the view meets the plane at height `z`, in cells; null when it misses. */
  floor(sx: number, sy: number, z: number): [number, number] | null {
    const p = this.viewer?.hit_plane_z(sx, sy, z);
    return p ? [p[0], p[1]] : null;
  }

  /** Draws at the next animation frame. */
  request() {
    if (this.scheduled) return;
    this.scheduled = true;
    requestAnimationFrame(() => {
      this.scheduled = false;
      this.draw();
    });
  }

  private draw() {
    const v = this.viewer;
    if (!v || this.destroyed) return;
    try {
      v.set_marks({ arrows: false, labels: false, cursor: this.cursor() });
      this.ui.canvas.dataset.scene = JSON.stringify(v.draw_cells(this.cells, this.world));
    } catch (e) {
      this.ui.error.textContent = `The 3-D view cannot draw: ${message(e)}`;
    }
  }

  resize() {
    const rect = this.ui.wrap.getBoundingClientRect();
    const w = Math.max(1, rect.width);
    const h = Math.max(1, rect.height);
    this.cssWidth = w;
    this.viewer?.resize(w, h, Math.min(2, window.devicePixelRatio || 1));
    if (!this.fitted && w > 1) this.fit();
    this.request();
  }

  destroy() {
    this.destroyed = true;
    this.resizeObserver.disconnect();
    this.viewer?.free();
    this.viewer = null;
  }
}
