// Canvas 2D renderer: planar lattices as an image (square) or hexagon paths (hex), the cubic
// lattice as shaded cube faces in painter's order (cubic-canvas.ts). The fallback when WebGL2 is
// unavailable.
import type { Layout } from '../types';
import type { Camera2D, Camera3D } from './camera';
import { CubicCanvas } from './cubic-canvas';
import { HEX_RADIUS, cellCentre, hexCorners } from './geometry';
import { css, heat, legendTable, type RGBA } from './palette';
import type { Renderer, Scene } from './renderer';

export class Canvas2DRenderer implements Renderer {
  readonly kind = 'canvas2d' as const;
  private image: ImageData | null = null;
  private imageCanvas: OffscreenCanvas | HTMLCanvasElement | null = null;
  private cellTable = new Uint32Array(256);
  private cellCss: string[] = [];
  private dpr = 1;
  private agentCss: string[] = [];
  private cubic: CubicCanvas | null = null;

  private constructor(private readonly canvas: HTMLCanvasElement, private readonly ctx: CanvasRenderingContext2D) {}

  static create(canvas: HTMLCanvasElement): Canvas2DRenderer | null {
    const ctx = canvas.getContext('2d', { alpha: false });
    return ctx ? new Canvas2DRenderer(canvas, ctx) : null;
  }

  setLayout(layout: Layout) {
    const table = legendTable(layout.cells);
    this.cellTable = new Uint32Array(256);
    this.cellCss = [];
    for (let c = 0; c < 256; c++) {
      const [r, g, b, a] = [table[c * 4], table[c * 4 + 1], table[c * 4 + 2], table[c * 4 + 3]];
      this.cellTable[c] = ((a << 24) | (b << 16) | (g << 8) | r) >>> 0;
      this.cellCss[c] = a ? css([r, g, b, a]) : '';
    }
    this.agentCss = [];
    for (const a of layout.agents) this.agentCss[a.code] = a.color;
    this.image = null;
    if (layout.lattice === 'square') {
      const [w, h] = layout.dims;
      this.image = new ImageData(w, h);
      this.imageCanvas = typeof OffscreenCanvas !== 'undefined' ? new OffscreenCanvas(w, h) : Object.assign(document.createElement('canvas'), { width: w, height: h });
    }
  }

  resize(cssWidth: number, cssHeight: number, dpr: number) {
    this.dpr = dpr;
    this.canvas.width = Math.max(1, Math.round(cssWidth * dpr));
    this.canvas.height = Math.max(1, Math.round(cssHeight * dpr));
  }

  draw(scene: Scene) {
    const { ctx, canvas } = this;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = '#1b232c';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    // Everything below is drawn in CSS pixels, the camera's units.
    ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
    if (scene.camera.kind === '3d') this.drawCubic(scene, scene.camera);
    else if (scene.layout.lattice === 'square') this.drawSquare(scene, scene.camera);
    else this.drawHex(scene, scene.camera);
  }

  private overlayColor(scene: Scene, i: number): RGBA | null {
    const o = scene.overlay;
    if (!o) return null;
    const v = o.data[i];
    if (!Number.isFinite(v)) return null;
    return heat(o.max > o.min ? (v - o.min) / (o.max - o.min) : 0.5);
  }

  private drawSquare(scene: Scene, cam: Camera2D) {
    const { image, imageCanvas, ctx } = this;
    if (!image || !imageCanvas) return;
    const px = new Uint32Array(image.data.buffer);
    const cells = scene.frame.cells;
    const table = this.cellTable;
    const o = scene.overlay;
    if (o) {
      const span = o.max > o.min ? o.max - o.min : 1;
      for (let i = 0; i < cells.length; i++) {
        const v = o.data[i];
        if (!Number.isNaN(v) && cells[i] !== 0) {
          const [r, g, b] = heat((v - o.min) / span);
          px[i] = ((255 << 24) | (b << 16) | (g << 8) | r) >>> 0;
        } else {
          px[i] = table[cells[i]];
        }
      }
    } else {
      for (let i = 0; i < cells.length; i++) px[i] = table[cells[i]];
    }
    (imageCanvas.getContext('2d') as CanvasRenderingContext2D | OffscreenCanvasRenderingContext2D).putImageData(image, 0, 0);
    ctx.imageSmoothingEnabled = false;
    const [x0, y0] = cam.toScreen(0, 0);
    ctx.drawImage(imageCanvas as CanvasImageSource, x0, y0, image.width * cam.scale, image.height * cam.scale);
    this.drawAgents(scene, cam);
  }

  private drawHex(scene: Scene, cam: Camera2D) {
    const { ctx } = this;
    const [w, h] = scene.layout.dims;
    const cells = scene.frame.cells;
    const vis = cam.visible();
    const yFrom = Math.max(0, Math.floor(vis.y0 / (Math.sqrt(3) / 2)) - 1);
    const yTo = Math.min(h - 1, Math.ceil(vis.y1 / (Math.sqrt(3) / 2)) + 1);
    const xFrom = Math.max(0, Math.floor(vis.x0) - 1);
    const xTo = Math.min(w - 1, Math.ceil(vis.x1) + 1);
    const r = HEX_RADIUS * cam.scale * (cam.scale > 8 ? 0.96 : 1.02);
    for (let y = yFrom; y <= yTo; y++) {
      for (let x = xFrom; x <= xTo; x++) {
        const i = y * w + x;
        const code = cells[i];
        if (code === 0) continue;
        const over = this.overlayColor(scene, i);
        const fill = over ? css(over) : this.cellCss[code];
        if (!fill) continue;
        const [wx, wy] = cellCentre('hex', x, y);
        const [sx, sy] = cam.toScreen(wx, wy);
        ctx.beginPath();
        const corners = hexCorners(sx, sy, r);
        ctx.moveTo(corners[0][0], corners[0][1]);
        for (let k = 1; k < 6; k++) ctx.lineTo(corners[k][0], corners[k][1]);
        ctx.closePath();
        ctx.fillStyle = fill;
        ctx.fill();
      }
    }
    this.drawAgents(scene, cam);
  }

  private drawAgents(scene: Scene, cam: Camera2D) {
    const { ctx } = this;
    const a = scene.frame.agents;
    const w = scene.layout.dims[0];
    const radius = Math.max(1.2, cam.scale * 0.34);
    for (let k = 0; k + 1 < a.length; k += 2) {
      const cell = a[k];
      const [wx, wy] = cellCentre(scene.layout.lattice, cell % w, Math.floor(cell / w));
      const [sx, sy] = cam.toScreen(wx, wy);
      ctx.fillStyle = this.agentCss[a[k + 1]] ?? '#ffffff';
      if (radius < 2) {
        ctx.fillRect(sx - 1, sy - 1, 2, 2);
      } else {
        ctx.beginPath();
        ctx.arc(sx, sy, radius, 0, Math.PI * 2);
        ctx.fill();
        ctx.lineWidth = Math.max(1, radius * 0.15);
        ctx.strokeStyle = 'rgba(0,0,0,0.55)';
        ctx.stroke();
      }
    }
  }

  private drawCubic(scene: Scene, cam: Camera3D) {
    this.cubic ??= new CubicCanvas();
    const stats = this.cubic.draw(this.ctx, scene, cam);
    this.canvas.dataset.scene = JSON.stringify(stats);
  }

  destroy() {
    this.image = null;
    this.imageCanvas = null;
  }
}
