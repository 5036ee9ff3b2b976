// Where lattice cells are in world space, and which cell a world point falls in. One place for
// the layout of each lattice, matching kumiki_core::lattice (row-major, odd-r hex rows).
import type { Layout } from '../types';

export const HEX_ROW = Math.sqrt(3) / 2;
export const HEX_RADIUS = 1 / Math.sqrt(3);

export interface Bounds {
  x0: number;
  y0: number;
  x1: number;
  y1: number;
}

/** Centre of a planar cell in world units. Square cells are unit squares at integer corners. */
export function cellCentre(lattice: Layout['lattice'], x: number, y: number): [number, number] {
  if (lattice === 'hex') return [x + 0.5 + (y & 1 ? 0.5 : 0), y * HEX_ROW + HEX_RADIUS];
  return [x + 0.5, y + 0.5];
}

/** The lattice has depth: a 3-D view, where a selected unit stays selected and shows its reach. */
export const is3d = (layout: Layout): boolean => layout.lattice === 'cubic';

/** Both layouts are the same lattice of the same size (the camera and the cursor can stay). */
export const sameLattice = (a: Layout | null, b: Layout): boolean => !!a && a.lattice === b.lattice && a.dims.join() === b.dims.join();

/** A cell index's (x, y, z) in a lattice of `dims` (z is 0 in 2-D). */
export function coordOf(dims: readonly number[], i: number): [number, number, number] {
  const [w, h] = dims;
  return [i % w, Math.floor(i / w) % h, Math.floor(i / (w * h))];
}

/** A cell's coordinates as the page writes them: (x, y), and (x, y, z) in 3-D. */
export function cellCoords(layout: Layout, cell: number): string {
  const [x, y, z] = coordOf(layout.dims, cell);
  return is3d(layout) ? `(${x}, ${y}, ${z})` : `(${x}, ${y})`;
}

export function worldBounds(layout: Layout): Bounds {
  const [w, h] = layout.dims;
  if (layout.lattice === 'hex') return { x0: 0, y0: 0, x1: w + 0.5, y1: (h - 1) * HEX_ROW + 2 * HEX_RADIUS };
  return { x0: 0, y0: 0, x1: w, y1: h };
}

/** The planar cell index under a world point, or -1. */
export function cellAt(layout: Layout, wx: number, wy: number): number {
  const [w, h] = layout.dims;
  let x: number;
  let y: number;
  if (layout.lattice === 'hex') {
    // Pointy-top axial coordinates of the point, rounded to the nearest hex.
    const px = wx - 0.5;
    const py = wy - HEX_RADIUS;
    const r = py / HEX_ROW;
    const q = px - r / 2;
    let rq = Math.round(q);
    let rr = Math.round(r);
    const rs = Math.round(-q - r);
    const dq = Math.abs(rq - q);
    const dr = Math.abs(rr - r);
    const ds = Math.abs(rs - (-q - r));
    if (dq > dr && dq > ds) rq = -rr - rs;
    else if (dr > ds) rr = -rq - rs;
    y = rr;
    x = rq + (rr - (rr & 1)) / 2;
  } else {
    x = Math.floor(wx);
    y = Math.floor(wy);
  }
  if (x < 0 || y < 0 || x >= w || y >= h) return -1;
  return y * w + x;
}

/** Corners of a pointy-top hexagon around a centre, radius r. */
export function hexCorners(cx: number, cy: number, r: number): [number, number][] {
  const out: [number, number][] = [];
  for (let k = 0; k < 6; k++) {
    const a = (Math.PI / 180) * (60 * k - 30);
    out.push([cx + r * Math.cos(a), cy + r * Math.sin(a)]);
  }
  return out;
}

/**
 * Neighbours of a planar cell in the core's direction order. With `byDirection`, the list has
 * one entry per direction and -1 where the neighbour would be outside the lattice.
 */
export function neighbours(layout: Layout, i: number, byDirection = false): number[] {
  const [w, h] = layout.dims;
  const x = i % w;
  const y = Math.floor(i / w);
  const out: number[] = [];
  const push = (nx: number, ny: number) => {
    if (nx >= 0 && ny >= 0 && nx < w && ny < h) out.push(ny * w + nx);
    else if (byDirection) out.push(-1);
  };
  if (layout.lattice === 'hex') {
    const odd = y & 1;
    push(x + 1, y);
    push(x + odd, y - 1);
    push(x - 1 + odd, y - 1);
    push(x - 1, y);
    push(x - 1 + odd, y + 1);
    push(x + odd, y + 1);
  } else {
    push(x + 1, y);
    push(x, y - 1);
    push(x - 1, y);
    push(x, y + 1);
  }
  return out;
}
