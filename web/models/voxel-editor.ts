// A 3-D shape editor for the cubic lattice. Click a face to add a unit on it (or the floor to start
// a layer); the Remove tool, Alt-click, a right-click or a long press on touch removes one. Drag to
// turn the view, right- or Shift-drag to pan, wheel or pinch to zoom. A layer slice shows only the
// layers up to k, or layer k alone, to reach inside. Keyboard: arrows move a cursor, Page Up/Down
// change its layer, Space or Enter toggles a unit there. Undo and redo; the same shape as text
// (cubic layers, read and written by the core). Shapes are applied through the page, which has the
// core validate them: a refused shape stays on screen with the core's reason.
import { bindGestures } from '../render/gestures';
import type { Picked } from '../sim/protocol';
import type { Layout, Scene } from '../contract.gen';
import { History } from '../store';
import { clear, el } from '../ui/dom';
import { formatShape, message, newViewer, parseShape, type Viewer } from '../wasm';

export interface VoxelSubject {
  /** What is being edited, for labels and messages ("the initial shape"). */
  label: string;
  /** The shape as cubic text, or '' for none yet. */
  text: string;
  /** Applies a shape; returns the core's complaint, or null when it was accepted. */
  apply(text: string): string | null;
}

type Tool = 'add' | 'remove';
type SliceMode = 'all' | 'below' | 'one';
type Cell = [number, number, number];

/** Free cells shown around the shape on each side, and above it. */
const PAD = 2;
const LONG_PRESS_MS = 550;
/** A drag turns the view once it has moved this many pixels, so a shaky click stays a click. */
const DRAG_SLOP = 4;
const UNIT_COLOR = '#5b8fd0';
const LAYER_COLOR = '#2fb7a4';

const key = (x: number, y: number, z: number) => `${x},${y},${z}`;
const unkey = (k: string): Cell => k.split(',').map(Number) as Cell;

export class VoxelEditor {
  private subject: VoxelSubject = { label: 'the shape', text: '', apply: () => null };
  private units = new Set<string>();
  private readonly history = new History<string[]>(200);
  private tool: Tool = 'add';
  private sliceMode: SliceMode = 'all';
  private level = 0;
  /** The editing box in shape coordinates: origin (x, y) and size; z always starts at 0. */
  private box = { ox: -PAD, oy: -PAD, w: 6, h: 6, d: 3 };
  /** Draws the box in 3-D and owns its camera (crate/view, on this thread). */
  private viewer: Viewer | null = null;
  private layout: Layout;
  private cells: Uint8Array;
  private cssWidth = 1;
  private world: Scene = { ghost: [], ground: 0 };
  private pointerCursor: { cell: number; kind: 'add' | 'remove' } | null = null;
  private keyCursor: Cell = [0, 0, 0];
  private focused = false;
  private scheduled = false;
  private fitted = false;
  private gestures: { destroy(): void } | null = null;
  private readonly canvas: HTMLCanvasElement;
  private readonly wrap: HTMLElement;
  private readonly status: HTMLElement;
  private readonly error: HTMLElement;
  private readonly hint: HTMLElement;
  private readonly undoButton: HTMLButtonElement;
  private readonly redoButton: HTMLButtonElement;
  private readonly toolButtons: HTMLButtonElement[] = [];
  private readonly sliceSelect: HTMLSelectElement;
  private readonly levelInput: HTMLInputElement;
  private readonly levelOut: HTMLOutputElement;
  private readonly text: HTMLTextAreaElement;
  private readonly textError: HTMLElement;
  private readonly resizeObserver: ResizeObserver;
  private destroyed = false;

  constructor(
    private readonly root: HTMLElement,
    idPrefix: string,
  ) {
    const id = idPrefix;
    const toolGroup = el('div', { class: 'tools', role: 'radiogroup', 'aria-label': 'Editing tool' });
    for (const [tool, label, aria] of [
      ['add', 'Add', 'Add: a click on a face adds a unit there'],
      ['remove', 'Remove', 'Remove: a click on a unit removes it'],
    ] as const) {
      const b = el('button', { type: 'button', role: 'radio', 'aria-checked': String(tool === this.tool), 'aria-label': aria, text: label, 'data-tool': tool });
      b.addEventListener('click', () => this.setTool(tool));
      toolGroup.append(b);
      this.toolButtons.push(b);
    }
    const button = (label: string, aria: string, f: () => void, extra: Record<string, string> = {}) => {
      // The spoken name holds the visible one (WCAG 2.5.3); a longer explanation is the title.
      const b = el('button', {
        type: 'button',
        text: label,
        ...(aria.toLowerCase().includes(label.toLowerCase()) ? { 'aria-label': aria } : { title: aria }),
        ...extra,
      });
      b.addEventListener('click', f);
      return b;
    };
    this.undoButton = button('Undo', 'Undo the last shape edit', () => this.undo(), { 'aria-keyshortcuts': 'Control+Z' });
    this.redoButton = button('Redo', 'Redo the shape edit', () => this.redo(), { 'aria-keyshortcuts': 'Control+Shift+Z' });
    const fit = button('Fit', 'Fit the shape in the editor view', () => this.fit(), { class: 'voxel-fit' });

    this.sliceSelect = el('select', { id: `${id}-slice`, 'aria-label': 'Layers shown' });
    for (const [value, label] of [
      ['all', 'all layers'],
      ['below', 'layers up to'],
      ['one', 'one layer'],
    ]) {
      this.sliceSelect.append(el('option', { value, text: label }));
    }
    this.sliceSelect.addEventListener('change', () => this.setSlice(this.sliceSelect.value as SliceMode, this.level));
    this.levelInput = el('input', { id: `${id}-level`, type: 'range', min: 0, max: 2, step: 1, value: 0, 'aria-label': 'Layer (from the ground up)' });
    this.levelOut = el('output', { for: this.levelInput.id, class: 'level-out' });
    this.levelInput.addEventListener('input', () => this.setSlice(this.sliceMode === 'all' ? 'below' : this.sliceMode, Number(this.levelInput.value)));

    this.canvas = el('canvas', {
      class: 'voxel-canvas',
      tabindex: 0,
      role: 'application',
      'aria-label':
        'Shape in 3-D. Click a face to add a unit, Alt-click or right-click or long-press to remove; drag to turn, Shift-drag to pan, wheel or pinch to zoom. Keys: arrows move the cursor, Page Up and Page Down change its layer, Space or Enter toggles a unit, Delete removes, Shift+arrows turn the view, brackets change the shown layer.',
    });
    this.wrap = el('div', { class: 'voxel-wrap' }, this.canvas, fit);
    this.hint = el('p', { class: 'voxel-hint', 'aria-hidden': 'true' });
    this.wrap.append(this.hint);
    this.status = el('p', { class: 'hint', role: 'status', 'aria-live': 'polite' });
    const help = el('p', {
      class: 'hint',
      text: 'Click a face to add a unit, the floor to start a layer. Alt-click, right-click or long-press removes. Drag to turn, Shift-drag to pan, wheel or pinch to zoom. Keys: arrows, Page Up/Down, Space.',
    });
    this.error = el('p', { class: 'error', role: 'status', 'aria-live': 'polite' });

    this.text = el('textarea', { id: `${id}-text`, rows: 7, spellcheck: 'false' });
    this.textError = el('p', { class: 'error', role: 'status', 'aria-live': 'polite' });
    const useText = button('Use text', 'Replace the shape with the text', () => this.useText());
    const details = el(
      'details',
      { class: 'voxel-text' },
      el('summary', { text: 'As text (import / export)' }),
      el('p', { class: 'hint', text: 'Square layers from the ground up, separated by a line ---; # is a unit, . is empty.' }),
      el('label', { for: this.text.id, class: 'sr-only', text: 'Shape as text' }),
      this.text,
      el('div', { class: 'row-buttons' }, useText),
      this.textError,
    );

    clear(root);
    root.append(
      el('div', { class: 'row-buttons voxel-toolbar' }, toolGroup, this.undoButton, this.redoButton),
      el(
        'div',
        { class: 'row-buttons voxel-slice' },
        el('label', { for: this.sliceSelect.id, text: 'Show' }),
        this.sliceSelect,
        this.levelInput,
        this.levelOut,
      ),
      this.wrap,
      this.error,
      this.status,
      help,
      details,
    );

    this.layout = editorLayout([6, 6, 3]);
    this.cells = new Uint8Array(6 * 6 * 3);
    this.bind();
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(this.wrap);
    try {
      this.viewer = newViewer(this.canvas.transferControlToOffscreen(), 'auto');
      this.canvas.dataset.renderer = this.viewer.kind();
      this.viewer.set_layout(this.layout);
    } catch (e) {
      this.error.textContent = `The 3-D view cannot start: ${message(e)}`;
    }
    this.resize();
  }

  /** Edits another shape (the initial one, a target's): forgets the undo history. */
  load(subject: VoxelSubject) {
    this.subject = subject;
    this.history.clear();
    this.error.textContent = '';
    this.textError.textContent = '';
    this.units = this.read(subject.text) ?? new Set();
    this.fitted = false;
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
    if (!units || formatUnits(units) === formatUnits(this.units)) return;
    this.units = units;
    this.history.clear();
    this.error.textContent = '';
    this.rebuild();
  }

  /** The shape now on screen as cubic text, or '' when it is empty. */
  shapeText(): string {
    return formatUnits(this.units);
  }

  destroy() {
    this.destroyed = true;
    this.resizeObserver.disconnect();
    this.gestures?.destroy();
    this.viewer?.free();
    this.viewer = null;
    clear(this.root);
  }

  // ---- state --------------------------------------------------------------------------------

  private read(text: string): Set<string> | null {
    if (!text.trim()) return new Set();
    try {
      const s = parseShape('cubic', text);
      const out = new Set<string>();
      for (let z = 0; z < s.d; z++) for (let y = 0; y < s.h; y++) for (let x = 0; x < s.w; x++) if (s.cells[(z * s.h + y) * s.w + x]) out.add(key(x, y, z));
      return out;
    } catch (e) {
      this.textError.textContent = message(e);
      return null;
    }
  }

  private setTool(tool: Tool) {
    this.tool = tool;
    for (const b of this.toolButtons) b.setAttribute('aria-checked', String(b.dataset.tool === tool));
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
    this.units = settle(next);
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
      this.error.textContent = `${cap(this.subject.label)} is empty: add at least two units (the drawing is kept).`;
      return;
    }
    const problem = this.subject.apply(formatUnits(this.units));
    this.error.textContent = problem ? `${problem} (the drawing is kept; fix it and it is applied)` : '';
  }

  private useText() {
    this.textError.textContent = '';
    const units = this.read(this.text.value);
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
    let x0 = Infinity;
    let y0 = Infinity;
    let x1 = -Infinity;
    let y1 = -Infinity;
    let z1 = -1;
    for (const k of this.units) {
      const [x, y, z] = unkey(k);
      x0 = Math.min(x0, x);
      y0 = Math.min(y0, y);
      x1 = Math.max(x1, x);
      y1 = Math.max(y1, y);
      z1 = Math.max(z1, z);
    }
    if (!this.units.size) [x0, y0, x1, y1, z1] = [0, 0, 3, 3, -1];
    const old = this.box;
    const box = { ox: x0 - PAD, oy: y0 - PAD, w: x1 - x0 + 1 + 2 * PAD, h: y1 - y0 + 1 + 2 * PAD, d: z1 + 1 + PAD };
    // Keep what is on screen in place when the box grows or shrinks on the low side.
    this.viewer?.shift_target(old.ox - box.ox, old.oy - box.oy, 0);
    this.box = box;
    this.level = Math.min(this.level, box.d - 1);
    this.keyCursor = this.clampCell(this.keyCursor);

    const { w, h, d } = box;
    const cells = new Uint8Array(w * h * d);
    const ghost: number[] = [];
    for (const k of this.units) {
      const [x, y, z] = unkey(k);
      const i = this.index([x, y, z]);
      if (this.visibleLayer(z)) cells[i] = this.sliceMode !== 'all' && z === this.level ? 2 : 1;
      else ghost.push(i);
    }
    if (this.layout.dims.join() !== [w, h, d].join()) {
      this.layout = editorLayout([w, h, d]);
      this.viewer?.set_layout(this.layout);
    }
    this.cells = cells;
    this.world = { ghost, ground: this.sliceMode === 'one' ? this.level : 0 };
    this.syncControls();
    this.request();
  }

  private syncControls() {
    const n = this.units.size;
    const [w, h, d] = this.extent();
    this.status.textContent = `${cap(this.subject.label)}: ${n} unit${n === 1 ? '' : 's'}${n ? ` · ${w} × ${h} × ${d}` : ''}`;
    this.undoButton.disabled = !this.history.canUndo;
    this.redoButton.disabled = !this.history.canRedo;
    this.sliceSelect.value = this.sliceMode;
    this.levelInput.max = String(this.box.d - 1);
    this.levelInput.value = String(this.level);
    this.levelInput.disabled = this.sliceMode === 'all';
    this.levelOut.textContent = this.sliceMode === 'all' ? '' : `layer ${this.level + 1} of ${this.box.d}`;
    this.canvas.dataset.units = String(n);
    this.canvas.dataset.visible = String(this.cells.reduce((s, c) => s + (c ? 1 : 0), 0));
    if (document.activeElement !== this.text) this.text.value = formatUnits(this.units);
  }

  private extent(): Cell {
    if (!this.units.size) return [0, 0, 0];
    const cs = [...this.units].map(unkey);
    const span = (a: number) => Math.max(...cs.map((c) => c[a])) - Math.min(...cs.map((c) => c[a])) + 1;
    return [span(0), span(1), span(2)];
  }

  private visibleLayer(z: number): boolean {
    return this.sliceMode === 'all' || (this.sliceMode === 'below' ? z <= this.level : z === this.level);
  }

  private index([x, y, z]: Cell): number {
    const b = this.box;
    return (z * b.h + (y - b.oy)) * b.w + (x - b.ox);
  }

  private cellOf(i: number): Cell {
    const b = this.box;
    return [(i % b.w) + b.ox, (Math.floor(i / b.w) % b.h) + b.oy, Math.floor(i / (b.w * b.h))];
  }

  private clampCell([x, y, z]: Cell): Cell {
    const b = this.box;
    return [Math.max(b.ox, Math.min(b.ox + b.w - 1, x)), Math.max(b.oy, Math.min(b.oy + b.h - 1, y)), Math.max(0, Math.min(b.d - 1, z))];
  }

  // ---- drawing ------------------------------------------------------------------------------

  private request() {
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
    let cursor = this.pointerCursor;
    if (!cursor && this.focused) cursor = { cell: this.index(this.keyCursor), kind: this.units.has(key(...this.keyCursor)) ? 'remove' : 'add' };
    try {
      v.set_marks({ arrows: false, labels: false, cursor: cursor ?? null });
      this.canvas.dataset.scene = JSON.stringify(v.draw_cells(this.cells, this.world));
    } catch (e) {
      this.error.textContent = `The 3-D view cannot draw: ${message(e)}`;
    }
  }

  private resize() {
    const rect = this.wrap.getBoundingClientRect();
    const w = Math.max(1, rect.width);
    const h = Math.max(1, rect.height);
    this.cssWidth = w;
    this.viewer?.resize(w, h, Math.min(2, window.devicePixelRatio || 1));
    if (!this.fitted && w > 1) this.fit();
    this.request();
  }

  private fit() {
    const b = this.box;
    const cs = [...this.units].map(unkey);
    if (cs.length) {
      const lo = [0, 1, 2].map((a) => Math.min(...cs.map((c) => c[a])));
      const hi = [0, 1, 2].map((a) => Math.max(...cs.map((c) => c[a])) + 1);
      this.viewer?.fit_box(
        new Float64Array([lo[0] - b.ox - 0.5, lo[1] - b.oy - 0.5, 0]),
        new Float64Array([hi[0] - b.ox + 0.5, hi[1] - b.oy + 0.5, hi[2] + 0.5]),
        0.92,
      );
    } else {
      this.viewer?.fit_box(new Float64Array([0, 0, 0]), new Float64Array([b.w, b.h, 1]), 1.08);
    }
    this.fitted = this.cssWidth > 1;
    this.request();
  }

  // ---- picking and editing ------------------------------------------------------------------

  /** What a click at (sx, sy) would do: add a unit in an empty cell or remove the one hit. */
  private target(sx: number, sy: number, remove: boolean): { cell: number; kind: 'add' | 'remove' } | null {
    const b = this.box;
    const v = this.viewer;
    if (!v) return null;
    const hit = (v.pick_cells(this.cells, sx, sy) as Picked).hit;
    if (remove) return hit ? { cell: hit.cell, kind: 'remove' } : null;
    let cell = -1;
    if (hit) {
      cell = hit.front;
    } else {
      const floor = this.sliceMode === 'one' ? this.level : 0;
      const p = v.hit_plane_z(sx, sy, floor);
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
    this.edit((u) => (t.kind === 'add' ? u.add(key(...c)) : u.delete(key(...c))));
  }

  private toggleAtCursor(removeOnly = false) {
    const c = this.keyCursor;
    if (!this.visibleLayer(c[2])) {
      this.error.textContent = `Layer ${c[2] + 1} is hidden by the slice.`;
      return;
    }
    const k = key(...c);
    if (this.units.has(k)) this.edit((u) => u.delete(k));
    else if (!removeOnly) this.edit((u) => u.add(k));
  }

  /** The cursor starts just above the middle of the shape. */
  private placeKeyCursor() {
    const cs = [...this.units].map(unkey);
    if (!cs.length) {
      this.keyCursor = [0, 0, 0];
      return;
    }
    const mid = cs[Math.floor(cs.length / 2)];
    const top = Math.max(...cs.filter((c) => c[0] === mid[0] && c[1] === mid[1]).map((c) => c[2]));
    this.keyCursor = this.clampCell([mid[0], mid[1], top + 1]);
  }

  /** Arrow keys move the cursor along the lattice axis nearest to the screen direction. */
  private moveCursor(right: number, upScreen: number) {
    const yaw = this.viewer?.yaw() ?? 0;
    // Screen right is (-sin yaw, cos yaw) in the ground plane; screen up (away) is -(cos, sin).
    const rx = -Math.sin(yaw);
    const ry = Math.cos(yaw);
    const ax = -Math.cos(yaw);
    const ay = -Math.sin(yaw);
    const dx = right * rx + upScreen * ax;
    const dy = right * ry + upScreen * ay;
    const step: Cell = Math.abs(dx) >= Math.abs(dy) ? [Math.sign(dx), 0, 0] : [0, Math.sign(dy), 0];
    const c = this.keyCursor;
    this.keyCursor = this.clampCell([c[0] + step[0], c[1] + step[1], c[2]]);
    this.request();
  }

  private bind() {
    const c = this.canvas;
    this.gestures = bindGestures(
      c,
      {
        press: () => c.focus({ preventScroll: true }),
        drag: (dx, dy, kind) => {
          this.pointerCursor = null;
          this.viewer?.drag(dx, dy, kind === 'orbit');
          this.request();
        },
        zoom: (factor, at) => {
          this.viewer?.zoom(factor, at.x, at.y);
          this.request();
        },
        tap: (at, button, mods) => {
          const removing = this.tool === 'remove' || mods.altKey || button === 2;
          const t = this.target(at.x, at.y, removing);
          if (t) this.act(t);
          else if (removing) this.hint.textContent = 'Nothing to remove there.';
        },
        // A long press on touch or pen removes the unit under it.
        longPress: (at) => {
          const t = this.target(at.x, at.y, true);
          if (t) this.act(t);
        },
        hover: (at, mods) => {
          const t = this.target(at.x, at.y, this.tool === 'remove' || mods.altKey);
          this.pointerCursor = t;
          this.hint.textContent = t ? this.describe(t) : '';
          this.request();
        },
        leave: () => {
          this.pointerCursor = null;
          this.hint.textContent = '';
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
    const mod = e.ctrlKey || e.metaKey;
    if (mod && (e.key.toLowerCase() === 'z' || e.key.toLowerCase() === 'y')) {
      if (e.shiftKey || e.key.toLowerCase() === 'y') this.redo();
      else this.undo();
    } else if (mod || e.altKey) {
      return;
    } else if (e.shiftKey && e.key.startsWith('Arrow')) {
      const d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] }[e.key] ?? [0, 0];
      this.viewer?.drag(d[0] * 24, d[1] * 24, true);
      this.request();
    } else {
      switch (e.key) {
        case 'ArrowLeft':
          this.moveCursor(-1, 0);
          break;
        case 'ArrowRight':
          this.moveCursor(1, 0);
          break;
        case 'ArrowUp':
          this.moveCursor(0, 1);
          break;
        case 'ArrowDown':
          this.moveCursor(0, -1);
          break;
        case 'PageUp':
        case 'PageDown': {
          const c = this.keyCursor;
          this.keyCursor = this.clampCell([c[0], c[1], c[2] + (e.key === 'PageUp' ? 1 : -1)]);
          if (this.sliceMode === 'one') this.setSlice('one', this.keyCursor[2]);
          this.request();
          break;
        }
        case ' ':
        case 'Enter':
          this.toggleAtCursor();
          break;
        case 'Delete':
        case 'Backspace':
          this.toggleAtCursor(true);
          break;
        case '[':
        case ']':
          this.setSlice(
            this.sliceMode === 'all' ? 'below' : this.sliceMode,
            (this.sliceMode === 'all' ? this.box.d - 1 : this.level) + (e.key === ']' ? 1 : -1),
          );
          break;
        case '+':
        case '=':
          this.viewer?.zoom(1.25, 0, 0);
          this.request();
          break;
        case '-':
          this.viewer?.zoom(0.8, 0, 0);
          this.request();
          break;
        case '0':
          this.fit();
          break;
        default:
          return;
      }
    }
    e.preventDefault();
    e.stopPropagation();
    const c = this.keyCursor;
    this.hint.textContent = `cursor (${c[0]}, ${c[1]}, layer ${c[2] + 1})${this.units.has(key(...c)) ? ': a unit' : ''}`;
  }

  private describe(t: { cell: number; kind: 'add' | 'remove' }): string {
    const [x, y, z] = this.cellOf(t.cell);
    return `${t.kind === 'add' ? 'add a unit' : 'remove the unit'} at (${x}, ${y}), layer ${z + 1}`;
  }
}

/** Lowers a shape so that its lowest layer is the ground (layers are written from the ground up). */
function settle(units: Set<string>): Set<string> {
  let low = Infinity;
  for (const k of units) low = Math.min(low, unkey(k)[2]);
  if (!Number.isFinite(low) || low === 0) return units;
  const out = new Set<string>();
  for (const k of units) {
    const [x, y, z] = unkey(k);
    out.add(key(x, y, z - low));
  }
  return out;
}

/** The cubic text of a set of units, trimmed to their box; '' for none. */
function formatUnits(units: Set<string>): string {
  if (!units.size) return '';
  const cs = [...units].map(unkey);
  const lo = [0, 1, 2].map((a) => Math.min(...cs.map((c) => c[a])));
  const hi = [0, 1, 2].map((a) => Math.max(...cs.map((c) => c[a])));
  const [w, h, d] = [0, 1, 2].map((a) => hi[a] - lo[a] + 1);
  const cells = new Array<number>(w * h * d).fill(0);
  for (const [x, y, z] of cs) cells[((z - lo[2]) * h + (y - lo[1])) * w + (x - lo[0])] = 1;
  return formatShape('cubic', { w, h, d, cells });
}

function editorLayout(dims: [number, number, number]): Layout {
  return {
    lattice: 'cubic',
    dims,
    cells: [
      { code: 1, name: 'unit', color: UNIT_COLOR },
      { code: 2, name: 'unit in the chosen layer', color: LAYER_COLOR },
    ],
    agents: [],
    events: [],
    fields: [],
    tools: [],
    cell_labels: false,
    chart: '',
    goal: true,
  };
}

function cap(s: string): string {
  return s.charAt(0).toUpperCase() + s.slice(1);
}
