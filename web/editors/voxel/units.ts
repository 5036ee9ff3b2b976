// The voxel editor's units: a set of cells keyed "x,y,z", settled on the ground and written as the
// core's cubic text, and the editor's own two-colour lattice.
import type { Layout } from '../../contract.gen';
import { formatShape, parseShape } from '../../wasm';

export type Cell = [number, number, number];

/** The editor's lattice around the units: its origin in the units' coordinates and its size. */
export interface Box {
  ox: number;
  oy: number;
  w: number;
  h: number;
  d: number;
}

/** Free cells shown around the shape on each side, and above it. */
export const PAD = 2;

const UNIT_COLOR = '#5b8fd0';
const LAYER_COLOR = '#2fb7a4';

export const key = (x: number, y: number, z: number) => `${x},${y},${z}`;
export const unkey = (k: string): Cell => k.split(',').map(Number) as Cell;

/** Lowers a shape so that its lowest layer is the ground (layers are written from the ground up). */
export function settle(units: Set<string>): Set<string> {
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
export function formatUnits(units: Set<string>): string {
  if (!units.size) return '';
  const cs = [...units].map(unkey);
  const lo = [0, 1, 2].map((a) => Math.min(...cs.map((c) => c[a])));
  const hi = [0, 1, 2].map((a) => Math.max(...cs.map((c) => c[a])));
  const [w, h, d] = [0, 1, 2].map((a) => hi[a] - lo[a] + 1);
  const cells = new Array<number>(w * h * d).fill(0);
  for (const [x, y, z] of cs) cells[((z - lo[2]) * h + (y - lo[1])) * w + (x - lo[0])] = 1;
  return formatShape('cubic', { w, h, d, cells });
}

export function editorLayout(dims: [number, number, number]): Layout {
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

export function cap(s: string): string {
  return s.charAt(0).toUpperCase() + s.slice(1);
}

/** The units of a shape's cubic text (the core reads it); throws with the place of a bad character. */
export function readUnits(text: string): Set<string> {
  const out = new Set<string>();
  if (!text.trim()) return out;
  const s = parseShape('cubic', text);
  for (let z = 0; z < s.d; z++) for (let y = 0; y < s.h; y++) for (let x = 0; x < s.w; x++) if (s.cells[(z * s.h + y) * s.w + x]) out.add(key(x, y, z));
  return out;
}

/** The least and one past the greatest coordinate of the units on each axis; null for none. */
export function unitBounds(units: Set<string>): { lo: number[]; hi: number[] } | null {
  if (!units.size) return null;
  const cs = [...units].map(unkey);
  return { lo: [0, 1, 2].map((a) => Math.min(...cs.map((c) => c[a]))), hi: [0, 1, 2].map((a) => Math.max(...cs.map((c) => c[a])) + 1) };
}

/** The units' size on each axis ([0, 0, 0] for none). */
export function extent(units: Set<string>): Cell {
  const b = unitBounds(units);
  return b ? [b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]] : [0, 0, 0];
}

/** The box drawn around the units: PAD free cells on each side and above (a 4 × 4 floor for none). */
export function boxAround(units: Set<string>): Box {
  const b = unitBounds(units) ?? { lo: [0, 0, 0], hi: [4, 4, 0] };
  const [x0, y0] = b.lo;
  const [x1, y1, z1] = b.hi;
  return { ox: x0 - PAD, oy: y0 - PAD, w: x1 - x0 + 2 * PAD, h: y1 - y0 + 2 * PAD, d: z1 + PAD };
}

/** A cell's index in the box's lattice. */
export const indexIn = (b: Box, [x, y, z]: Cell): number => (z * b.h + (y - b.oy)) * b.w + (x - b.ox);

/** The cell at an index of the box's lattice. */
export const cellIn = (b: Box, i: number): Cell => [(i % b.w) + b.ox, (Math.floor(i / b.w) % b.h) + b.oy, Math.floor(i / (b.w * b.h))];

/** The nearest cell inside the box. */
export const clampIn = (b: Box, [x, y, z]: Cell): Cell => [
  Math.max(b.ox, Math.min(b.ox + b.w - 1, x)),
  Math.max(b.oy, Math.min(b.oy + b.h - 1, y)),
  Math.max(0, Math.min(b.d - 1, z)),
];

/** Where the keyboard cursor starts: just above the middle of the shape. */
export function aboveMiddle(units: Set<string>): Cell {
  const cs = [...units].map(unkey);
  if (!cs.length) return [0, 0, 0];
  const mid = cs[Math.floor(cs.length / 2)];
  const top = Math.max(...cs.filter((c) => c[0] === mid[0] && c[1] === mid[1]).map((c) => c[2]));
  return [mid[0], mid[1], top + 1];
}

/**
 * The step along the lattice axis nearest to a screen direction (`right` and `up`, each -1, 0 or
 * 1) for a camera turned `yaw` radians about the vertical.
 */
export function screenStep(yaw: number, right: number, up: number): Cell {
  // Screen right is (-sin yaw, cos yaw) in the ground plane; screen up (away) is -(cos, sin).
  const dx = -right * Math.sin(yaw) - up * Math.cos(yaw);
  const dy = right * Math.cos(yaw) - up * Math.sin(yaw);
  return Math.abs(dx) >= Math.abs(dy) ? [Math.sign(dx), 0, 0] : [0, Math.sign(dy), 0];
}
