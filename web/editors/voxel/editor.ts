// A 3-D shape editor for the cubic lattice. Click a face to add a unit on it (or the floor to start
// a layer); the Remove tool, Alt-click, a right-click or a long press on touch removes one. Drag to
// turn the view, right- or Shift-drag to pan, wheel or pinch to zoom. A layer slice shows only the
// layers up to k, or layer k alone, to reach inside. Keyboard: arrows move a cursor, Page Up/Down
// change its layer, Space or Enter toggles a unit there. Undo and redo; the same shape as text
// (cubic layers, read and written by the core). Shapes are applied through the page, which has the
// core validate them: a refused shape stays on screen with the core's reason.
import { History } from '../../page/store';
import { bindGestures } from '../../render/gestures';
import { clear } from '../../widgets/dom';
import { message } from '../../wasm';
import { type SliceMode, type Tool, type VoxelControls, voxelControls } from './controls';
import { voxelKey } from './keys';
import { type EditCursor, VoxelView } from './view';
import { type Box, type Cell, PAD } from './units';
import * as U from './units';

export interface VoxelSubject {
  /** What is being edited, for labels and messages ("the initial shape"). */
  label: string;
  /** The shape as cubic text, or '' for none yet. */
  text: string;
  /** Applies a shape; returns the core's complaint, or null when it was accepted. */
  apply(text: string): Promise<string | null>;
}

const LONG_PRESS_MS = 550;
/** A drag turns the view once it has moved this many pixels, so a shaky click stays a click. */
const DRAG_SLOP = 4;

export class VoxelEditor {
  private subject: VoxelSubject = { label: 'the shape', text: '', apply: async () => null };
  private units = new Set<string>();
  private readonly history = new History<string[]>(200);
  private tool: Tool = 'add';
  private sliceMode: SliceMode = 'all';
  private level = 0;
  /** The editing box in shape coordinates: origin (x, y) and size; z always starts at 0. */
  private box: Box = { ox: -PAD, oy: -PAD, w: 6, h: 6, d: 3 };
  /** The box drawn in 3-D, its camera and what is under the pointer. */
  private readonly view: VoxelView;
  private pointerCursor: EditCursor | null = null;
  private keyCursor: Cell = [0, 0, 0];
  private focused = false;
  private gestures: { destroy(): void } | null = null;
  /** The editor's controls and canvas. */
  private readonly ui: VoxelControls;

  constructor(
    private readonly root: HTMLElement,
    idPrefix: string,
  ) {
    this.ui = voxelControls(idPrefix, this.tool, {
      setTool: (tool) => this.setTool(tool),
      undo: () => this.undo(),
      redo: () => this.redo(),
      fit: () => this.fit(),
      slice: (mode) => this.setSlice(mode, this.level),
      level: (level) => this.setSlice(this.sliceMode === 'all' ? 'below' : this.sliceMode, level),
      useText: () => this.useText(),
    });
    clear(root);
    root.append(...this.ui.nodes);

    this.view = new VoxelView(
      this.ui,
      () => this.cursor(),
      () => this.fit(),
    );
    this.bind();
    this.view.resize();
  }

  /** Edits another shape (the initial one, a target's): forgets the undo history. */
  load(subject: VoxelSubject) {
    this.subject = subject;
    this.history.clear();
    this.ui.error.textContent = '';
    this.ui.textError.textContent = '';
    this.units = this.read(subject.text) ?? new Set();
    this.view.refit();
    this.rebuild();
    this.placeKeyCursor();
    this.fit();
  }

  /**
   * Shows a shape that changed elsewhere (undo, a preset, a link). A drawing the core refused is
   * kept until the scenario's own shape changes.
   */
  setText(text: string) {
    if (text === this.subject.text) return;
    this.subject = { ...this.subject, text };
    const units = this.read(text);
    if (!units || U.formatUnits(units) === U.formatUnits(this.units)) return;
    this.units = units;
    this.history.clear();
    this.ui.error.textContent = '';
    this.rebuild();
  }

  /** The shape now on screen as cubic text, or '' when it is empty. */
  shapeText(): string {
    return U.formatUnits(this.units);
  }

  destroy() {
    this.view.destroy();
    this.gestures?.destroy();
    clear(this.root);
  }

  // ---- state --------------------------------------------------------------------------------

  private read(text: string): Set<string> | null {
    try {
      return U.readUnits(text);
    } catch (e) {
      this.ui.textError.textContent = message(e);
      return null;
    }
  }

  private setTool(tool: Tool) {
    this.tool = tool;
    for (const b of this.ui.toolButtons) b.setAttribute('aria-checked', String(b.dataset.tool === tool));
    this.pointerCursor = null;
    this.request();
  }

  private setSlice(mode: SliceMode, level: number) {
    this.sliceMode = mode;
    this.level = Math.max(0, Math.min(this.box.d - 1, Math.round(level)));
    this.keyCursor[2] = mode === 'one' ? this.level : mode === 'below' ? Math.min(this.keyCursor[2], this.level) : this.keyCursor[2];
    this.pointerCursor = null;
    this.rebuild();
  }

  /** Records the shape for undo, changes it and applies it. */
  private edit(change: (units: Set<string>) => void) {
    const next = new Set(this.units);
    change(next);
    if (next.size === this.units.size && [...next].every((k) => this.units.has(k))) return;
    this.history.push([...this.units]);
    this.units = U.settle(next);
    this.rebuild();
    this.push();
  }

  private undo() {
    this.restore(this.history.undo([...this.units]));
  }

  private redo() {
    this.restore(this.history.redo([...this.units]));
  }

  private restore(units: string[] | null) {
    if (!units) return;
    this.units = new Set(units);
    this.rebuild();
    this.push();
  }

  private push() {
    if (this.units.size === 0) {
      this.ui.error.textContent = `${U.cap(this.subject.label)} is empty: add at least two units (the drawing is kept).`;
      return;
    }
    void this.subject.apply(U.formatUnits(this.units)).then((problem) => {
      this.ui.error.textContent = problem ? `${problem} (the drawing is kept; fix it and it is applied)` : '';
    });
  }

  private useText() {
    this.ui.textError.textContent = '';
    const units = this.read(this.ui.text.value);
    if (!units) return;
    this.edit((u) => {
      u.clear();
      for (const k of units) u.add(k);
    });
    this.fit();
  }

  // ---- the synthetic lattice the renderer draws ---------------------------------------------

  /** Recomputes the box around the units, the cells drawn and the status. */
  private rebuild() {
    const old = this.box;
    const box = U.boxAround(this.units);
    this.box = box;
    this.level = Math.min(this.level, box.d - 1);
    this.keyCursor = this.clampCell(this.keyCursor);

    const { w, h, d } = box;
    const cells = new Uint8Array(w * h * d);
    const ghost: number[] = [];
    for (const k of this.units) {
      const [x, y, z] = U.unkey(k);
      const i = this.index([x, y, z]);
      if (this.visibleLayer(z)) cells[i] = this.sliceMode !== 'all' && z === this.level ? 2 : 1;
      else ghost.push(i);
    }
    this.view.show([w, h, d], cells, { ghost, ground: this.sliceMode === 'one' ? this.level : 0 }, [old.ox - box.ox, old.oy - box.oy]);
    this.syncControls();
  }

  private syncControls() {
    const n = this.units.size;
    const [w, h, d] = U.extent(this.units);
    this.ui.status.textContent = `${U.cap(this.subject.label)}: ${n} unit${n === 1 ? '' : 's'}${n ? ` · ${w} × ${h} × ${d}` : ''}`;
    this.ui.undoButton.disabled = !this.history.canUndo;
    this.ui.redoButton.disabled = !this.history.canRedo;
    this.ui.sliceSelect.value = this.sliceMode;
    this.ui.levelInput.max = String(this.box.d - 1);
    this.ui.levelInput.value = String(this.level);
    this.ui.levelInput.disabled = this.sliceMode === 'all';
    this.ui.levelOut.textContent = this.sliceMode === 'all' ? '' : `layer ${this.level + 1} of ${this.box.d}`;
    this.ui.canvas.dataset.units = String(n);
    if (document.activeElement !== this.ui.text) this.ui.text.value = U.formatUnits(this.units);
  }

  private visibleLayer(z: number): boolean {
    return this.sliceMode === 'all' || (this.sliceMode === 'below' ? z <= this.level : z === this.level);
  }

  private index(cell: Cell): number {
    return U.indexIn(this.box, cell);
  }

  private cellOf(i: number): Cell {
    return U.cellIn(this.box, i);
  }

  private clampCell(cell: Cell): Cell {
    return U.clampIn(this.box, cell);
  }

  // ---- drawing ------------------------------------------------------------------------------

  private request() {
    this.view.request();
  }

  /** The cursor drawn: the pointer's, else the keyboard's while the view has the focus. */
  private cursor(): EditCursor | null {
    if (this.pointerCursor) return this.pointerCursor;
    if (!this.focused) return null;
    return { cell: this.index(this.keyCursor), kind: this.units.has(U.key(...this.keyCursor)) ? 'remove' : 'add' };
  }

  private fit() {
    const b = this.box;
    const bounds = U.unitBounds(this.units);
    if (bounds) {
      const { lo, hi } = bounds;
      this.view.fitBox([lo[0] - b.ox - 0.5, lo[1] - b.oy - 0.5, 0], [hi[0] - b.ox + 0.5, hi[1] - b.oy + 0.5, hi[2] + 0.5], 0.92);
    } else {
      this.view.fitBox([0, 0, 0], [b.w, b.h, 1], 1.08);
    }
  }

  // ---- picking and editing ------------------------------------------------------------------

  /** What a click at (sx, sy) would do: add a unit in an empty cell or remove the one hit. */
  private target(sx: number, sy: number, remove: boolean): { cell: number; kind: 'add' | 'remove' } | null {
    const b = this.box;
    const hit = this.view.pick(sx, sy);
    if (remove) return hit ? { cell: hit.cell, kind: 'remove' } : null;
    let cell = -1;
    if (hit) {
      cell = hit.front;
    } else {
      const floor = this.sliceMode === 'one' ? this.level : 0;
      const p = this.view.floor(sx, sy, floor);
      if (p) {
        const x = Math.floor(p[0]);
        const y = Math.floor(p[1]);
        if (x >= 0 && y >= 0 && x < b.w && y < b.h) cell = (floor * b.h + y) * b.w + x;
      }
    }
    if (cell < 0) return null;
    const z = this.cellOf(cell)[2];
    if (!this.visibleLayer(z)) return null;
    return { cell, kind: 'add' };
  }

  private act(t: { cell: number; kind: 'add' | 'remove' }) {
    const c = this.cellOf(t.cell);
    this.keyCursor = c;
    this.pointerCursor = null;
    this.edit((u) => (t.kind === 'add' ? u.add(U.key(...c)) : u.delete(U.key(...c))));
  }

  private toggleAtCursor(removeOnly = false) {
    const c = this.keyCursor;
    if (!this.visibleLayer(c[2])) {
      this.ui.error.textContent = `Layer ${c[2] + 1} is hidden by the slice.`;
      return;
    }
    const k = U.key(...c);
    if (this.units.has(k)) this.edit((u) => u.delete(k));
    else if (!removeOnly) this.edit((u) => u.add(k));
  }

  /** The cursor starts just above the middle of the shape. */
  private placeKeyCursor() {
    this.keyCursor = this.clampCell(U.aboveMiddle(this.units));
  }

  /** Arrow keys move the cursor along the lattice axis nearest to the screen direction. */
  private moveCursor(right: number, upScreen: number) {
    const step = U.screenStep(this.view.yaw(), right, upScreen);
    const c = this.keyCursor;
    this.keyCursor = this.clampCell([c[0] + step[0], c[1] + step[1], c[2]]);
    this.request();
  }

  private bind() {
    const c = this.ui.canvas;
    this.gestures = bindGestures(
      c,
      {
        press: () => c.focus({ preventScroll: true }),
        drag: (dx, dy, kind) => {
          this.pointerCursor = null;
          this.view.drag(dx, dy, kind === 'orbit');
        },
        zoom: (factor, at) => {
          this.view.zoom(factor, at.x, at.y);
        },
        tap: (at, button, mods) => {
          const removing = this.tool === 'remove' || mods.altKey || button === 2;
          const t = this.target(at.x, at.y, removing);
          if (t) this.act(t);
          else if (removing) this.ui.hint.textContent = 'Nothing to remove there.';
        },
        // A long press on touch or pen removes the unit under it.
        longPress: (at) => {
          const t = this.target(at.x, at.y, true);
          if (t) this.act(t);
        },
        hover: (at, mods) => {
          const t = this.target(at.x, at.y, this.tool === 'remove' || mods.altKey);
          this.pointerCursor = t;
          this.ui.hint.textContent = t ? this.describe(t) : '';
          this.request();
        },
        leave: () => {
          this.pointerCursor = null;
          this.ui.hint.textContent = '';
          this.request();
        },
      },
      { dragSlop: DRAG_SLOP, longPressMs: LONG_PRESS_MS },
    );
    c.addEventListener('focus', () => {
      this.focused = true;
      this.request();
    });
    c.addEventListener('blur', () => {
      this.focused = false;
      this.request();
    });
    c.addEventListener('keydown', (e) => this.key(e));
  }

  private key(e: KeyboardEvent) {
    const handled = voxelKey(e, {
      undo: () => this.undo(),
      redo: () => this.redo(),
      turn: (dx, dy) => this.view.drag(dx, dy, true),
      move: (right, up) => this.moveCursor(right, up),
      layer: (by) => {
        const c = this.keyCursor;
        this.keyCursor = this.clampCell([c[0], c[1], c[2] + by]);
        if (this.sliceMode === 'one') this.setSlice('one', this.keyCursor[2]);
        this.request();
      },
      toggle: (removeOnly) => this.toggleAtCursor(removeOnly),
      slice: (by) => this.setSlice(this.sliceMode === 'all' ? 'below' : this.sliceMode, (this.sliceMode === 'all' ? this.box.d - 1 : this.level) + by),
      zoom: (factor) => this.view.zoom(factor, 0, 0),
      fit: () => this.fit(),
    });
    if (!handled) return;
    const c = this.keyCursor;
    this.ui.hint.textContent = `cursor (${c[0]}, ${c[1]}, layer ${c[2] + 1})${this.units.has(U.key(...c)) ? ': a unit' : ''}`;
  }

  private describe(t: { cell: number; kind: 'add' | 'remove' }): string {
    const [x, y, z] = this.cellOf(t.cell);
    return `${t.kind === 'add' ? 'add a unit' : 'remove the unit'} at (${x}, ${y}), layer ${z + 1}`;
  }
}
