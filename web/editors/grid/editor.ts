// A shape editor for the square and hex lattices: paint or erase cells by dragging (mouse, pen or
// one finger; the gestures come from render/gestures.ts), move a cursor with the arrow keys and
// toggle with Space, resize, trim, undo and redo, and edit the same shape as text. Shapes are read
// and written by the core's own rules.
import type { Cells as Shape } from '../../contract.gen';
import { History } from '../../page/store';
import { bindGestures, type Point } from '../../render/gestures';
import { clear, el } from '../../widgets/dom';
import { Geometry, formatShape, message, parseShape } from '../../wasm';
import { drawGrid } from './draw';

export interface GridEditorOptions {
  lattice: 'square' | 'hex';
  label: string;
  text: string;
  /** Applies the shape; returns the core's complaint, or null when it was accepted. */
  apply(text: string): Promise<string | null>;
  /** A fixed strip drawn below the shape (AMAS's supply row), not part of the text. */
  below?: { label: string; color: string };
  maxSide?: number;
}

type Tool = 'paint' | 'erase';

/** The editor's canvas is at most this many CSS pixels on a side. */
const MAX_CANVAS_PX = 2048;

/** Editors made so far, for unique element ids. */
let editors = 0;

export class GridEditor {
  private shape: Shape;
  private readonly history = new History<Shape>(200);
  private tool: Tool = 'paint';
  private cursor = 0;
  private stroke: { erase: boolean; last: number; changed: boolean } | null = null;
  private readonly canvas: HTMLCanvasElement;
  private readonly text: HTMLTextAreaElement;
  private readonly error: HTMLElement;
  private readonly status: HTMLElement;
  private readonly widthInput: HTMLInputElement;
  private readonly heightInput: HTMLInputElement;
  private readonly undoButton: HTMLButtonElement;
  private readonly redoButton: HTMLButtonElement;
  private readonly resizeObserver: ResizeObserver;
  private gestures: { destroy(): void } | null = null;
  private scale = 10;
  /** The shape's lattice geometry at its current size (see `geometry()`). */
  private geo: Geometry | null = null;
  private readonly maxSide: number;

  constructor(
    private readonly root: HTMLElement,
    private readonly opts: GridEditorOptions,
  ) {
    this.maxSide = opts.maxSide ?? 200;
    this.shape = this.read(opts.text) ?? { w: 8, h: 6, d: 1, cells: new Array(48).fill(0) };
    const id = `grid-${++editors}`;
    const toolGroup = el('div', { class: 'tools', role: 'radiogroup', 'aria-label': 'Drawing tool' });
    for (const [tool, label] of [
      ['paint', 'Paint'],
      ['erase', 'Erase'],
    ] as const) {
      const b = el('button', { type: 'button', role: 'radio', 'aria-checked': String(tool === this.tool), text: label, 'data-tool': tool });
      b.addEventListener('click', () => {
        this.tool = tool;
        for (const o of toolGroup.querySelectorAll('button')) o.setAttribute('aria-checked', String(o.dataset.tool === tool));
      });
      toolGroup.append(b);
    }
    this.widthInput = el('input', { type: 'number', min: 1, max: this.maxSide, id: `${id}-w`, 'aria-label': 'Width in cells' });
    this.heightInput = el('input', { type: 'number', min: 1, max: this.maxSide, id: `${id}-h`, 'aria-label': 'Height in cells' });
    for (const input of [this.widthInput, this.heightInput]) {
      input.classList.add('size-input');
      input.addEventListener('change', () => this.resize(Number(this.widthInput.value), Number(this.heightInput.value)));
    }
    const button = (label: string, aria: string, f: () => void) => {
      // The spoken name holds the visible one (WCAG 2.5.3); a longer explanation is the title.
      const b = el('button', { type: 'button', text: label, ...(aria.toLowerCase().includes(label.toLowerCase()) ? { 'aria-label': aria } : { title: aria }) });
      b.addEventListener('click', f);
      return b;
    };
    this.undoButton = button('Undo', 'Undo the last drawing change', () => this.undo());
    this.redoButton = button('Redo', 'Redo the drawing change', () => this.redo());
    const toolbar = el(
      'div',
      { class: 'row-buttons grid-toolbar' },
      toolGroup,
      el('label', {}, 'W ', this.widthInput),
      el('label', {}, 'H ', this.heightInput),
      button('Trim', 'Trim empty rows and columns', () => this.trim()),
      button('Clear', 'Clear every cell', () => this.edit((s) => s.cells.fill(0))),
      this.undoButton,
      this.redoButton,
    );
    this.canvas = el('canvas', {
      class: 'grid-canvas',
      tabindex: 0,
      role: 'application',
      'aria-label': `${opts.label}: drag to paint cells; arrow keys move the cursor, Space toggles a cell, Delete clears it`,
    });
    this.text = el('textarea', { id: `${id}-text`, rows: 6, spellcheck: 'false' });
    const useText = button('Use text', 'Replace the drawing with the text', () => {
      const s = this.read(this.text.value);
      if (s) this.commit(s);
    });
    this.error = el('p', { class: 'error', role: 'status', 'aria-live': 'polite' });
    this.status = el('p', { class: 'hint' });
    const details = el(
      'details',
      {},
      el('summary', { text: 'As text (import / export)' }),
      el('label', { for: this.text.id, class: 'sr-only', text: `${opts.label} as text` }),
      this.text,
      el('div', { class: 'row-buttons' }, useText),
    );
    clear(root);
    root.append(toolbar, this.canvas, this.error, this.status, details);
    this.bind();
    this.resizeObserver = new ResizeObserver(() => this.draw());
    this.resizeObserver.observe(root);
    this.sync();
  }

  /** Shows a shape that changed elsewhere (undo, a preset), unless it is the same. */
  setText(text: string) {
    const s = this.read(text, false);
    if (s && formatShape(this.opts.lattice, s) !== formatShape(this.opts.lattice, this.shape)) {
      this.shape = s;
      this.history.clear();
      this.error.textContent = '';
      this.sync();
    }
  }

  destroy() {
    this.resizeObserver.disconnect();
    this.gestures?.destroy();
    clear(this.root);
  }

  private read(text: string, report = true): Shape | null {
    try {
      return parseShape(this.opts.lattice, text);
    } catch (e) {
      if (report) this.error.textContent = message(e);
      return null;
    }
  }

  private edit(change: (s: Shape) => void) {
    const next = { ...this.shape, cells: [...this.shape.cells] };
    change(next);
    this.commit(next);
  }

  /** Records the current shape for undo, shows `next` and applies it. */
  private commit(next: Shape) {
    this.history.push(this.shape);
    this.shape = next;
    this.sync();
    this.push();
  }

  private push() {
    if (!this.shape.cells.some(Boolean)) {
      this.error.textContent = 'The shape is empty: paint at least one cell.';
      return;
    }
    void this.opts.apply(formatShape(this.opts.lattice, this.shape)).then((problem) => {
      this.error.textContent = problem ? `${problem} (the drawing is kept; fix it and it is applied)` : '';
    });
  }

  private undo() {
    this.restore(this.history.undo(this.shape));
  }

  private redo() {
    this.restore(this.history.redo(this.shape));
  }

  private restore(shape: Shape | null) {
    if (!shape) return;
    this.shape = shape;
    this.sync();
    this.push();
  }

  private resize(w: number, h: number) {
    w = Math.max(1, Math.min(this.maxSide, Math.round(w) || 1));
    h = Math.max(1, Math.min(this.maxSide, Math.round(h) || 1));
    if (w === this.shape.w && h === this.shape.h) return this.sync();
    const cells = new Array<number>(w * h).fill(0);
    // Keep the bottom rows in place: shapes grow upwards from their base (the supply row).
    const dy = h - this.shape.h;
    for (let y = 0; y < this.shape.h; y++) {
      for (let x = 0; x < Math.min(w, this.shape.w); x++) {
        const ny = y + dy;
        if (ny >= 0 && ny < h) cells[ny * w + x] = this.shape.cells[y * this.shape.w + x];
      }
    }
    this.commit({ w, h, d: 1, cells });
  }

  private trim() {
    const { w, h, cells } = this.shape;
    let x0 = w;
    let x1 = -1;
    let y0 = h;
    let y1 = -1;
    for (let y = 0; y < h; y++) {
      for (let x = 0; x < w; x++) {
        if (cells[y * w + x]) {
          x0 = Math.min(x0, x);
          x1 = Math.max(x1, x);
          y0 = Math.min(y0, y);
          y1 = Math.max(y1, y);
        }
      }
    }
    if (x1 < 0) return;
    // On the hex lattice rows keep their parity, or the shape would shear.
    if (this.opts.lattice === 'hex') y0 -= y0 & 1;
    const nw = x1 - x0 + 1;
    const nh = y1 - y0 + 1;
    const out = new Array<number>(nw * nh).fill(0);
    for (let y = 0; y < nh; y++) for (let x = 0; x < nw; x++) out[y * nw + x] = cells[(y + y0) * w + x + x0];
    this.commit({ w: nw, h: nh, d: 1, cells: out });
  }

  private sync() {
    this.widthInput.value = String(this.shape.w);
    this.heightInput.value = String(this.shape.h);
    if (document.activeElement !== this.text) this.text.value = formatShape(this.opts.lattice, this.shape);
    const n = this.shape.cells.filter(Boolean).length;
    this.status.textContent = `${n} cell${n === 1 ? '' : 's'} · ${this.shape.w} × ${this.shape.h}`;
    this.undoButton.disabled = !this.history.canUndo;
    this.redoButton.disabled = !this.history.canRedo;
    this.cursor = Math.min(this.cursor, this.shape.w * this.shape.h - 1);
    this.draw();
  }

  private layout() {
    const world = this.geometry().bounds();
    const worldW = world.x1;
    const worldH = world.y1 + (this.opts.below ? 1.2 : 0);
    const avail = Math.max(160, this.root.clientWidth || 320);
    // At least 3 px a cell for painting, unless that would make the canvas larger than
    // MAX_CANVAS_PX on a side: a huge shape from a link is shown whole, cells smaller than a pixel.
    const floor = Math.min(3, MAX_CANVAS_PX / Math.max(worldW, worldH));
    this.scale = Math.max(floor, Math.min(36, avail / worldW, 420 / worldH));
    return { cssW: Math.ceil(worldW * this.scale), cssH: Math.ceil(worldH * this.scale) };
  }

  private draw() {
    // Nothing to see while the editor's tab is hidden; the resize observer calls again when it
    // is shown.
    if (!this.root.isConnected || this.root.getClientRects().length === 0) return;
    const { cssW, cssH } = this.layout();
    drawGrid(this.canvas, cssW, cssH, {
      lattice: this.opts.lattice,
      shape: this.shape,
      geometry: this.geometry(),
      scale: this.scale,
      below: this.opts.below,
      cursor: document.activeElement === this.canvas ? this.cursor : null,
    });
  }

  private cellAt(at: Point): number {
    return this.geometry().cellAt(at.x / this.scale, at.y / this.scale);
  }

  /** The geometry of the shape's lattice as it is now sized (kept until the size changes). */
  private geometry(): Geometry {
    const { w, h } = this.shape;
    const g = this.geo;
    if (g && g.lattice === this.opts.lattice && g.dims[0] === w && g.dims[1] === h) return g;
    g?.free();
    this.geo = new Geometry(this.opts.lattice, [w, h, 1]);
    return this.geo;
  }

  private paintCell(i: number, erase: boolean) {
    if (i < 0 || !this.stroke) return;
    const v = erase ? 0 : 1;
    if (this.shape.cells[i] !== v) {
      if (!this.stroke.changed) {
        this.history.push({ ...this.shape, cells: [...this.shape.cells] });
        this.stroke.changed = true;
      }
      this.shape.cells[i] = v;
    }
  }

  /** Ends a paint stroke: one undo step for all of it, applied once. */
  private endStroke() {
    if (!this.stroke) return;
    const changed = this.stroke.changed;
    this.stroke = null;
    this.sync();
    if (changed) this.push();
  }

  private bind() {
    const c = this.canvas;
    this.gestures = bindGestures(c, {
      press: (at, button, mods, pointers) => {
        c.focus();
        // A second finger is a pinch, not painting: the stroke so far is kept and ends here.
        if (pointers > 1) return this.endStroke();
        const i = this.cellAt(at);
        this.stroke = { erase: this.tool === 'erase' || button === 2 || mods.shiftKey, last: i, changed: false };
        if (i >= 0) this.cursor = i;
        this.paintCell(i, this.stroke.erase);
        this.draw();
      },
      drag: (_dx, _dy, _kind, at) => {
        if (!this.stroke) return;
        const i = this.cellAt(at);
        if (i === this.stroke.last) return;
        this.stroke.last = i;
        this.paintCell(i, this.stroke.erase);
        this.draw();
      },
      release: () => this.endStroke(),
    });
    c.addEventListener('focus', () => this.draw());
    c.addEventListener('blur', () => this.draw());
    c.addEventListener('keydown', (e) => {
      const { w, h } = this.shape;
      let x = this.cursor % w;
      let y = Math.floor(this.cursor / w);
      if ((e.ctrlKey || e.metaKey) && e.key.toLowerCase() === 'z') {
        e.preventDefault();
        e.stopPropagation();
        if (e.shiftKey) this.redo();
        else this.undo();
        return;
      }
      switch (e.key) {
        case 'ArrowLeft':
          x = Math.max(0, x - 1);
          break;
        case 'ArrowRight':
          x = Math.min(w - 1, x + 1);
          break;
        case 'ArrowUp':
          y = Math.max(0, y - 1);
          break;
        case 'ArrowDown':
          y = Math.min(h - 1, y + 1);
          break;
        case ' ':
        case 'Enter':
          this.edit((s) => (s.cells[this.cursor] = s.cells[this.cursor] ? 0 : 1));
          break;
        case 'Delete':
        case 'Backspace':
          if (this.shape.cells[this.cursor]) this.edit((s) => (s.cells[this.cursor] = 0));
          break;
        default:
          return;
      }
      e.preventDefault();
      e.stopPropagation();
      this.cursor = y * w + x;
      this.draw();
    });
  }
}
