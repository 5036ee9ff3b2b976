// Drawing a grid editor's shape on its canvas: a path per cell (hexagons on the hex lattice), or
// for a large shape one pixel a cell scaled up; the strip below it and the keyboard cursor.
import type { Cells as Shape } from '../../contract.gen';
import { Geometry } from '../../wasm';

/** Shapes with more cells than this are drawn as a bitmap rather than a path per cell. */
const PATH_CELLS = 20_000;
/** Canvas colours as little-endian RGBA words for ImageData. */
const rgba = (r: number, g: number, b: number) => ((255 << 24) | (b << 16) | (g << 8) | r) >>> 0;
const BACKGROUND = rgba(0x1b, 0x23, 0x2c);
const FILLED = rgba(0x2b, 0x95, 0xd6);
const EMPTY = rgba(0x2a, 0x36, 0x42);

/** What is drawn: the shape on its lattice at `scale` CSS pixels a cell. */
export interface GridPicture {
  lattice: 'square' | 'hex';
  shape: Shape;
  geometry: Geometry;
  scale: number;
  /** A fixed strip drawn below the shape (AMAS's supply row). */
  below?: { label: string; color: string };
  /** The keyboard cursor's cell, when the canvas has the focus. */
  cursor: number | null;
}

/** Draws `p` on `canvas`, sized `cssW` × `cssH` CSS pixels. */
export function drawGrid(canvas: HTMLCanvasElement, cssW: number, cssH: number, p: GridPicture) {
  const dpr = cssW * cssH > 1 << 20 ? 1 : Math.min(2, window.devicePixelRatio || 1);
  canvas.width = cssW * dpr;
  canvas.height = cssH * dpr;
  canvas.style.width = `${cssW}px`;
  canvas.style.height = `${cssH}px`;
  const ctx = canvas.getContext('2d')!;
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.fillStyle = '#1b232c';
  ctx.fillRect(0, 0, cssW, cssH);
  const { w, h, cells } = p.shape;
  const s = p.scale;
  if (w * h > PATH_CELLS || s < 4) {
    drawBitmap(ctx, p);
  } else {
    for (let y = 0; y < h; y++) {
      for (let x = 0; x < w; x++) {
        const i = y * w + x;
        ctx.fillStyle = cells[i] ? '#2b95d6' : '#2a3642';
        cellPath(ctx, p, x, y);
        ctx.fill();
        if (s >= 6) {
          ctx.strokeStyle = '#1b232c';
          ctx.lineWidth = 1;
          ctx.stroke();
        }
      }
    }
  }
  if (p.below) {
    const top = p.geometry.bounds().y1 * s + 0.2 * s;
    ctx.fillStyle = p.below.color;
    ctx.fillRect(0, top, cssW, s);
    ctx.fillStyle = '#1b232c';
    ctx.font = `${Math.min(13, s * 0.7)}px system-ui, sans-serif`;
    ctx.textBaseline = 'middle';
    ctx.fillText(p.below.label, 6, top + s / 2);
  }
  if (p.cursor !== null) {
    ctx.strokeStyle = '#f0b429';
    ctx.lineWidth = 2;
    cellPath(ctx, p, p.cursor % w, Math.floor(p.cursor / w));
    ctx.stroke();
  }
}

/**
 * Every cell at once, one pixel each (two on the hex lattice, whose rows are offset by half a
 * cell), scaled up without smoothing: large shapes draw in milliseconds instead of one path
 * per cell.
 */
function drawBitmap(ctx: CanvasRenderingContext2D, p: GridPicture) {
  const { w, h, cells } = p.shape;
  const hex = p.lattice === 'hex';
  const bw = hex ? 2 * w + 1 : w;
  const image = new ImageData(bw, h);
  const px = new Uint32Array(image.data.buffer);
  px.fill(BACKGROUND);
  for (let y = 0; y < h; y++) {
    const row = y * bw + (hex ? y & 1 : 0);
    for (let x = 0; x < w; x++) {
      const colour = cells[y * w + x] ? FILLED : EMPTY;
      if (hex) px[row + 2 * x] = px[row + 2 * x + 1] = colour;
      else px[row + x] = colour;
    }
  }
  const bitmap = document.createElement('canvas');
  bitmap.width = bw;
  bitmap.height = h;
  bitmap.getContext('2d')!.putImageData(image, 0, 0);
  const s = p.scale;
  ctx.imageSmoothingEnabled = false;
  if (hex) ctx.drawImage(bitmap, 0, (Geometry.hexRadius - Geometry.hexRow / 2) * s, (w + 0.5) * s, h * Geometry.hexRow * s);
  else ctx.drawImage(bitmap, 0, 0, w * s, h * s);
}

function cellPath(ctx: CanvasRenderingContext2D, p: GridPicture, x: number, y: number) {
  const s = p.scale;
  ctx.beginPath();
  if (p.lattice === 'hex') {
    const [cx, cy] = p.geometry.centre(y * p.shape.w + x);
    const c = Geometry.hexCorners(cx * s, cy * s, Geometry.hexRadius * s);
    ctx.moveTo(c[0][0], c[0][1]);
    for (let k = 1; k < 6; k++) ctx.lineTo(c[k][0], c[k][1]);
    ctx.closePath();
  } else {
    ctx.rect(x * s, y * s, s, s);
  }
}
