// The lattice view in the page: the canvases, the gestures and the marks. The drawing itself
// happens in the simulation worker (crate/view, through the wasm Viewer), on OffscreenCanvases
// transferred from here, next to the model's buffers: this side sends sizes, camera moves and
// marks, asks what is under the pointer, and learns from each frame what was drawn.
import type { Picked, RendererChoice, ViewMarks } from '../sim/protocol';
import type { SimClient } from '../sim/client';
import type { Layout } from '../contract.gen';
import type { Drawn } from '../types';
import { is3d } from './geometry';
import { bindGestures } from './gestures';

export type RendererKind = 'webgl2' | 'canvas2d';

/** A 3-D pick: the unit hit and the empty cell in front of the face hit (-1 off the lattice). */
export type Hit = NonNullable<Picked['hit']>;

/** The page's marks; -1 is "none" for the cells. */
export interface Marks {
  arrows: boolean;
  labels: boolean;
  hover: number;
  highlight: number[];
  /** A value per highlighted cell (the difference at a reachable position), labelled in 3-D. */
  highlightValues?: number[];
  /** The cell picked with the inspector, outlined. */
  selected?: number;
  /** An editing cursor in 3-D (where a unit would be added or removed), or the keyboard cursor. */
  cursor?: { cell: number; kind: 'add' | 'remove' | 'cursor' } | null;
  /** One slot's signals: pairs (cell, lit faces as a mask of lattice directions). */
  signals?: number[];
  /** Units drawn displaced over the view: triples (cell, dx, dy) in cells, y down. */
  displaced?: number[];
  /** 3-D view options (default on). */
  ghost?: boolean;
  bonds?: boolean;
}

export interface ViewEvents {
  /** A click (or tap) on a cell; `hit` carries the 3-D face information. */
  click(cell: number, hit: Hit | null): void;
  hover(cell: number): void;
  /** A frame from the worker was shown; the worker may send the next. */
  drawn(): void;
}

/** The marks as the worker's view reads them. */
function forWorker(m: Marks): ViewMarks {
  const cell = (i: number | undefined) => (i !== undefined && i >= 0 ? i : null);
  return {
    arrows: m.arrows,
    labels: m.labels,
    hover: cell(m.hover),
    highlight: m.highlight,
    highlightValues: m.highlightValues ?? [],
    selected: cell(m.selected),
    cursor: m.cursor && m.cursor.cell >= 0 ? m.cursor : null,
    signals: m.signals ?? [],
    displaced: m.displaced ?? [],
    ghost: m.ghost !== false,
    bonds: m.bonds !== false,
  };
}

export class View {
  private layout: Layout | null = null;
  private kind: RendererKind | null = null;
  private range: [number, number] | null = null;
  private transferred = false;
  private prefer: RendererChoice = 'auto';
  private scheduled = false;
  private sentMarks = '';
  private cssWidth = 1;
  private cssHeight = 1;
  /** Drawing-buffer multiple used while recording at 2×; 1 otherwise. */
  private captureScale = 1;
  /** One hover pick in flight at a time; the latest point waits for it. */
  private hoverBusy = false;
  private hoverNext: { x: number; y: number } | null = null;
  private gestures: { destroy(): void } | null = null;
  private kindKnown: ((kind: RendererKind) => void) | null = null;
  readonly marks: Marks = { arrows: true, labels: true, hover: -1, highlight: [], selected: -1, ghost: true, bonds: true };

  constructor(
    private canvas: HTMLCanvasElement,
    private annotations: HTMLCanvasElement,
    private readonly wrap: HTMLElement,
    private readonly sim: () => SimClient,
    private readonly on: ViewEvents,
  ) {
    new ResizeObserver(() => this.resize()).observe(wrap);
    this.bind(canvas);
  }

  /** The lattice in view has depth (see geometry's is3d); false before the first layout. */
  get is3d(): boolean {
    return !!this.layout && is3d(this.layout);
  }

  get rendererKind(): RendererKind | null {
    return this.kind;
  }

  /** The worker's view started drawing with `kind`. */
  started(kind: RendererKind) {
    this.kind = kind;
    this.canvas.dataset.renderer = kind;
    this.kindKnown?.(kind);
    this.kindKnown = null;
  }

  /**
   * Gives the worker the canvases to draw on with the preferred renderer. A canvas transfers
   * once, so each new renderer (and each restarted worker) gets fresh canvases in place of the old.
   */
  useRenderer(prefer: RendererChoice): Promise<RendererKind> {
    this.prefer = prefer;
    const known = new Promise<RendererKind>((resolve) => {
      this.kindKnown = resolve;
    });
    this.sim().useView(() => this.canvases());
    this.resize();
    this.sentMarks = '';
    this.request();
    return known;
  }

  private canvases() {
    if (this.transferred) {
      const fresh = this.canvas.cloneNode(false) as HTMLCanvasElement;
      this.canvas.replaceWith(fresh);
      this.canvas = fresh;
      this.bind(fresh);
      const notes = this.annotations.cloneNode(false) as HTMLCanvasElement;
      this.annotations.replaceWith(notes);
      this.annotations = notes;
    }
    this.transferred = true;
    delete this.canvas.dataset.scene;
    return { canvas: this.canvas.transferControlToOffscreen(), annotations: this.annotations.transferControlToOffscreen(), prefer: this.prefer };
  }

  setLayout(layout: Layout) {
    this.layout = layout;
  }

  /** A frame was drawn in the worker: what it drew, for the page and its tests. */
  setFrame(drawn: Drawn | null) {
    this.range = drawn?.overlayRange ?? null;
    if (drawn?.scene) this.canvas.dataset.scene = JSON.stringify(drawn.scene);
    else delete this.canvas.dataset.scene;
    this.on.drawn();
  }

  get overlayRange(): [number, number] | null {
    return this.range;
  }

  /** A view that the zoom buttons and keys move with this one (the second run of a comparison). */
  companion: View | null = null;

  /** Frames what is on the lattice with a margin (in 3-D with the ghost and the lamp). */
  fit() {
    this.sim().camera({ op: 'fit' });
    this.companion?.fit();
  }

  zoom(factor: number) {
    this.sim().camera({ op: 'zoom', factor, x: this.cssWidth / 2, y: this.cssHeight / 2 });
    this.companion?.zoom(factor);
  }

  /** Sends the marks to the worker's view if they changed (at most once per animation frame). */
  request() {
    if (this.scheduled) return;
    this.scheduled = true;
    requestAnimationFrame(() => {
      this.scheduled = false;
      const marks = forWorker(this.marks);
      const text = JSON.stringify(marks);
      if (text !== this.sentMarks) {
        this.sentMarks = text;
        this.sim().setMarks(marks);
      }
    });
  }

  /**
   * Renders the drawing buffers at `scale` times their usual resolution (a recording at 2×), or
   * back at 1. The canvases keep their size on the page.
   */
  setCaptureScale(scale: number) {
    if (scale === this.captureScale) return;
    this.captureScale = scale;
    this.resize();
  }

  private resize() {
    const rect = this.wrap.getBoundingClientRect();
    this.cssWidth = Math.max(1, rect.width);
    this.cssHeight = Math.max(1, rect.height);
    const dpr = Math.min(2, window.devicePixelRatio || 1) * this.captureScale;
    this.sim().resize(this.cssWidth, this.cssHeight, dpr);
  }

  private async hoverAt(x: number, y: number) {
    if (this.hoverBusy) {
      this.hoverNext = { x, y };
      return;
    }
    this.hoverBusy = true;
    const picked = await this.sim().pick(x, y);
    this.hoverBusy = false;
    const cell = picked?.cell ?? -1;
    if (cell !== this.marks.hover) {
      this.marks.hover = cell;
      this.on.hover(cell);
      this.request();
    }
    const next = this.hoverNext;
    this.hoverNext = null;
    if (next) void this.hoverAt(next.x, next.y);
  }

  private bind(canvas: HTMLCanvasElement) {
    this.gestures?.destroy();
    this.gestures = bindGestures(canvas, {
      drag: (dx, dy, kind) => this.sim().camera({ op: 'drag', dx, dy, orbit: kind === 'orbit' }),
      zoom: (factor, at) => this.sim().camera({ op: 'zoom', factor, x: at.x, y: at.y }),
      tap: (at) => {
        void this.sim()
          .pick(at.x, at.y)
          .then((picked) => this.on.click(picked?.cell ?? -1, picked?.hit ?? null));
      },
      hover: (at) => void this.hoverAt(at.x, at.y),
      leave: () => {
        this.hoverNext = null;
        if (this.marks.hover !== -1) {
          this.marks.hover = -1;
          this.on.hover(-1);
          this.request();
        }
      },
    });
    // Keyboard: Shift+arrows orbit a 3-D view, Alt+arrows pan (plain arrows stay the page's).
    canvas.addEventListener('keydown', (e) => {
      const dir = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] }[e.key];
      if (!dir || !(e.shiftKey || e.altKey) || e.ctrlKey || e.metaKey) return;
      e.preventDefault();
      e.stopPropagation();
      const orbit = e.shiftKey && this.is3d;
      const step = orbit ? 24 : -40;
      this.sim().camera({ op: 'drag', dx: dir[0] * step, dy: dir[1] * step, orbit });
    });
  }
}
