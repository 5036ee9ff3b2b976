// The lattice view: owns the canvases, the renderer and the camera; turns gestures (pointer,
// wheel, pinch: see gestures.ts) and keyboard input into camera moves and cell clicks; draws at
// most once per animation frame.
import type { Frame, Layout, SceneInfo } from '../types';
import { annotate, type Marks } from './annotate';
import { Camera2D, Camera3D, type Camera, type Hit, cameraGestures, fitCamera, occupiedBox } from './camera';
import { lampPlacement } from './cubic-scene';
import { type Bounds, HEX_RADIUS, cellCentre, is3d, sameLattice } from './geometry';
import { bindGestures } from './gestures';
import { range } from './palette';
import { createRenderer, type Overlay, type Renderer, type RendererKind } from './renderer';

export interface ViewEvents {
  /** A click (or tap) on a cell; `hit` carries the 3-D face information. */
  click(cell: number, hit: Hit | null): void;
  hover(cell: number): void;
  /** A frame from the worker was drawn; the worker may send the next. */
  drawn(): void;
}

export class View {
  private renderer: Renderer | null = null;
  private camera: Camera = new Camera2D();
  private layout: Layout | null = null;
  private frame: Frame | null = null;
  private world: SceneInfo | null = null;
  /** Fit frames what is on the lattice, so after a new lattice it waits for the first frame. */
  private fitPending = false;
  private overlay: Overlay | null = null;
  private pendingFrame = false;
  private scheduled = false;
  private cssWidth = 1;
  private cssHeight = 1;
  private dpr = 1;
  /** Drawing-buffer multiple used while recording at 2×; 1 otherwise. */
  private captureScale = 1;
  private gestures: { destroy(): void } | null = null;
  readonly marks: Marks = { arrows: true, labels: true, hover: -1, highlight: [], selected: -1, ghost: true, bonds: true };
  private readonly annotations: CanvasRenderingContext2D;

  constructor(
    private canvas: HTMLCanvasElement,
    annotationCanvas: HTMLCanvasElement,
    private readonly wrap: HTMLElement,
    private readonly on: ViewEvents,
  ) {
    this.annotations = annotationCanvas.getContext('2d')!;
    new ResizeObserver(() => this.resize()).observe(wrap);
    this.bind(canvas);
  }

  /** The lattice in view has depth (see geometry's is3d); false before the first layout. */
  get is3d(): boolean {
    return !!this.layout && is3d(this.layout);
  }

  get rendererKind(): RendererKind | null {
    return this.renderer?.kind ?? null;
  }

  /** Creates the renderer, replacing the canvas when switching (a canvas keeps its first context). */
  async useRenderer(prefer: RendererKind | 'auto') {
    if (this.renderer) {
      this.renderer.destroy();
      const fresh = this.canvas.cloneNode(false) as HTMLCanvasElement;
      this.canvas.replaceWith(fresh);
      this.canvas = fresh;
      this.bind(fresh);
    }
    this.renderer = await createRenderer(this.canvas, prefer);
    this.resize();
    if (this.layout) this.renderer.setLayout(this.layout);
    this.request();
  }

  setLayout(layout: Layout) {
    const sameShape = sameLattice(this.layout, layout);
    this.layout = layout;
    this.frame = null;
    this.world = null;
    if (!sameShape) {
      this.camera = is3d(layout) ? new Camera3D() : new Camera2D();
      this.sizeCamera();
      fitCamera(this.camera, layout);
      this.fitPending = true;
    }
    this.renderer?.setLayout(layout);
    this.request();
  }

  setFrame(frame: Frame) {
    this.frame = frame;
    if (frame.scene) this.world = frame.scene;
    if (this.fitPending) this.fit();
    if (frame.field) {
      const [min, max] = range(frame.field.data);
      this.overlay = { name: frame.field.name, data: frame.field.data, min, max };
    } else {
      this.overlay = null;
    }
    this.pendingFrame = true;
    this.request();
  }

  get overlayRange(): [number, number] | null {
    return this.overlay ? [this.overlay.min, this.overlay.max] : null;
  }

  /**
   * Frames what is on the lattice with a margin: the units (and in 3-D the ghost and the lamp),
   * or the whole lattice when it is empty. Before the first frame of a run it waits for it.
   */
  fit() {
    if (!this.layout) return;
    const c = this.camera;
    if (!this.frame) {
      this.fitPending = true;
      return;
    }
    this.fitPending = false;
    if (c.kind === '3d') {
      const box = occupiedBox(this.layout.dims, this.frame.cells, this.marks.ghost === false ? [] : this.world?.ghost ?? []);
      if (box) {
        // The lamp of a light source is part of the picture.
        const lamp = this.world?.light ? lampPlacement(box, this.world.light, this.layout.dims) : null;
        if (lamp) {
          const r = lamp.size * 0.9;
          for (let a = 0; a < 3; a++) {
            box.min[a] = Math.min(box.min[a], lamp.at[a] - r);
            box.max[a] = Math.max(box.max[a], lamp.at[a] + r);
          }
        }
        c.fitBox(box.min, box.max);
      } else {
        fitCamera(c, this.layout);
      }
    } else {
      const content = contentBounds(this.layout, this.frame.cells);
      if (content) c.fit(content);
      else fitCamera(c, this.layout);
    }
    this.request();
  }

  zoom(factor: number) {
    this.camera.zoom(factor);
    this.request();
  }

  request() {
    if (this.scheduled) return;
    this.scheduled = true;
    requestAnimationFrame(() => {
      this.scheduled = false;
      this.draw();
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

  /**
   * The view as a picture: the lattice and its annotations drawn now, at the drawing buffer's
   * resolution, composited into one bitmap. Drawing just before copying makes the copy independent
   * of when the browser last presented the canvas.
   */
  captureFrame(): Promise<ImageBitmap> {
    if (!this.drawScene()) return Promise.reject(new Error('nothing is drawn yet'));
    const out = new OffscreenCanvas(this.canvas.width, this.canvas.height);
    const ctx = out.getContext('2d')!;
    ctx.drawImage(this.canvas, 0, 0);
    ctx.drawImage(this.annotations.canvas, 0, 0, out.width, out.height);
    return Promise.resolve(out.transferToImageBitmap());
  }

  /** Draws the lattice and its annotations as they stand; false when there is nothing to draw. */
  private drawScene(): boolean {
    if (!(this.renderer && this.layout && this.frame)) return false;
    const scene = { layout: this.layout, frame: this.frame, overlay: this.overlay, camera: this.camera, world: this.world, marks: this.marks };
    this.renderer.draw(scene);
    annotate(this.annotations, this.dpr, scene, this.marks);
    return true;
  }

  private draw() {
    this.drawScene();
    if (this.pendingFrame) {
      this.pendingFrame = false;
      this.on.drawn();
    }
  }

  private sizeCamera() {
    this.camera.width = this.cssWidth;
    this.camera.height = this.cssHeight;
  }

  private resize() {
    const rect = this.wrap.getBoundingClientRect();
    this.cssWidth = Math.max(1, rect.width);
    this.cssHeight = Math.max(1, rect.height);
    this.dpr = Math.min(2, window.devicePixelRatio || 1) * this.captureScale;
    const c = this.camera;
    const hadSize = c.width > 1;
    const [wx, wy] = c.kind === '2d' && hadSize ? c.toWorld(c.width / 2, c.height / 2) : [0, 0];
    this.sizeCamera();
    if (c.kind === '2d' && hadSize) {
      c.cx = wx;
      c.cy = wy;
    } else if (this.layout && !(c.kind === '3d' && hadSize)) {
      this.fit();
    }
    this.renderer?.resize(this.cssWidth, this.cssHeight, this.dpr);
    const a = this.annotations.canvas;
    a.width = Math.round(this.cssWidth * this.dpr);
    a.height = Math.round(this.cssHeight * this.dpr);
    this.request();
  }

  private pick(x: number, y: number): { cell: number; hit: Hit | null } {
    if (!this.layout || !this.frame) return { cell: -1, hit: null };
    if (this.camera.kind === '2d') return { cell: this.camera.pick(this.layout, x, y), hit: null };
    const cells = this.frame.cells;
    const hit = this.camera.pick(this.layout.dims, (i) => cells[i] !== 0, x, y);
    return { cell: hit?.cell ?? -1, hit };
  }

  private bind(canvas: HTMLCanvasElement) {
    this.gestures?.destroy();
    this.gestures = bindGestures(canvas, {
      ...cameraGestures(() => this.camera, () => this.request()),
      tap: (at) => {
        const { cell, hit } = this.pick(at.x, at.y);
        this.on.click(cell, hit);
      },
      hover: (at) => {
        const { cell } = this.pick(at.x, at.y);
        if (cell !== this.marks.hover) {
          this.marks.hover = cell;
          this.on.hover(cell);
          this.request();
        }
      },
      leave: () => {
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
      if (e.shiftKey && this.camera.kind === '3d') this.camera.orbit(dir[0] * 24, dir[1] * 24);
      else this.camera.pan(-dir[0] * 40, -dir[1] * 40);
      this.request();
    });
  }
}

/** World bounds of the non-empty cells of a planar lattice, two cells wider all round. */
function contentBounds(layout: Layout, cells: Uint8Array): Bounds | null {
  const w = layout.dims[0];
  let x0 = Infinity;
  let y0 = Infinity;
  let x1 = -Infinity;
  let y1 = -Infinity;
  for (let i = 0; i < cells.length; i++) {
    if (!cells[i]) continue;
    const [cx, cy] = cellCentre(layout.lattice, i % w, Math.floor(i / w));
    if (cx < x0) x0 = cx;
    if (cx > x1) x1 = cx;
    if (cy < y0) y0 = cy;
    if (cy > y1) y1 = cy;
  }
  if (x1 < x0) return null;
  const pad = 2 + (layout.lattice === 'hex' ? HEX_RADIUS : 0.5);
  return { x0: x0 - pad, y0: y0 - pad, x1: x1 + pad, y1: y1 + pad };
}
