// What a 3-D view of the cubic lattice draws, worked out once per frame for both renderers: the
// units with their colours (legend or overlay), the bonds between adjacent units, the ghost cells
// not already occupied, the plane under the structure with the units' shadows on it, the lamp of a
// light source, and the marks (hover, selection, reachable cells, an editing cursor).
import type { Layout } from '../types';
import { coordOf } from './geometry';
import { heatTable, legendTable } from './palette';
import type { Scene } from './renderer';

export type V3 = [number, number, number];

export interface CubicModel {
  dims: V3;
  /** Units: lower corner (x, y, z) and RGBA per unit, and its cell. */
  unitPos: Float32Array;
  unitColor: Uint8Array;
  unitCell: Uint32Array;
  units: number;
  /** The units that can be seen: not covered on all six faces (indices into the unit arrays). */
  visible: Uint32Array;
  /** Bonds between face-adjacent units: midpoint and axis (0 x, 1 y, 2 z). */
  bondMid: Float32Array;
  bondAxis: Uint8Array;
  bonds: number;
  /** Ghost cells that hold no unit. */
  ghost: number[];
  /** Reachable (highlighted) cells that hold no unit. */
  highlight: number[];
  /** The box around the units (world units), or null with none. */
  box: { min: V3; max: V3 } | null;
  /** The plane drawn under the structure: the model's ground, or a reference just under the units. */
  plane: { z: number; solid: boolean } | null;
  /** Shadow squares on the plane: (x, y, strength 0..1) per column of units. */
  shadows: Float32Array;
  /** The lamp: position, direction of the light (toward the source) and a box-relative size. */
  lamp: { at: V3; dir: V3; size: number } | null;
}

export interface RenderStats {
  units: number;
  bonds: number;
  ghost: number;
  highlight: number;
  light: boolean;
  ground: boolean;
}

/** Colour of a unit under the pointer: lightened toward white. */
const HOVER_LIFT = 0.35;
/** A unit marked for removal: tinted red. */
const REMOVE_TINT: V3 = [235, 80, 70];

/** Caches the legend and heat tables per layout and the model per frame, marks and options. */
export class CubicBuilder {
  private layout: Layout | null = null;
  private palette = new Uint8Array(256 * 4);
  private readonly heat = heatTable();
  private key: unknown[] = [];
  private model: CubicModel | null = null;

  build(scene: Scene): CubicModel {
    if (scene.layout !== this.layout) {
      this.layout = scene.layout;
      this.palette = legendTable(scene.layout.cells);
      this.model = null;
    }
    const m = scene.marks;
    const key = [scene.frame, scene.overlay, scene.world, m?.hover, m?.cursor?.cell, m?.cursor?.kind, m?.bonds, m?.ghost, m?.highlight];
    if (this.model && key.every((k, i) => k === this.key[i])) return this.model;
    this.key = key;
    this.model = buildModel(scene, this.palette, this.heat);
    return this.model;
  }
}

function buildModel(scene: Scene, palette: Uint8Array, heat: Uint8Array): CubicModel {
  const dims = scene.layout.dims as V3;
  const [w, h] = dims;
  const cells = scene.frame.cells;
  const world = scene.world ?? null;
  const marks = scene.marks;
  const o = scene.overlay;
  const hover = marks?.hover ?? -1;
  const removing = marks?.cursor?.kind === 'remove' ? marks.cursor.cell : -1;

  let n = 0;
  for (let i = 0; i < cells.length; i++) if (cells[i] !== 0) n++;
  const unitPos = new Float32Array(n * 3);
  const unitColor = new Uint8Array(n * 4);
  const unitCell = new Uint32Array(n);
  const min: V3 = [Infinity, Infinity, Infinity];
  const max: V3 = [-Infinity, -Infinity, -Infinity];
  const span = o ? Math.max(o.max - o.min, 1e-9) : 1;
  const [, , d] = dims;
  const layer = w * h;
  // A unit covered on all six faces cannot be seen: a solid block draws only its shell.
  const covered = (i: number, x: number, y: number, z: number) =>
    x > 0 && x + 1 < w && y > 0 && y + 1 < h && z > 0 && z + 1 < d &&
    cells[i - 1] !== 0 && cells[i + 1] !== 0 && cells[i - w] !== 0 && cells[i + w] !== 0 && cells[i - layer] !== 0 && cells[i + layer] !== 0;
  const visible: number[] = [];
  let k = 0;
  for (let i = 0; i < cells.length; i++) {
    const code = cells[i];
    if (code === 0) continue;
    const x = i % w;
    const y = Math.floor(i / w) % h;
    const z = Math.floor(i / (w * h));
    unitPos[3 * k] = x;
    unitPos[3 * k + 1] = y;
    unitPos[3 * k + 2] = z;
    unitCell[k] = i;
    if (!covered(i, x, y, z)) visible.push(k);
    if (x < min[0]) min[0] = x;
    if (y < min[1]) min[1] = y;
    if (z < min[2]) min[2] = z;
    if (x + 1 > max[0]) max[0] = x + 1;
    if (y + 1 > max[1]) max[1] = y + 1;
    if (z + 1 > max[2]) max[2] = z + 1;
    const v = o ? o.data[i] : NaN;
    let src = palette;
    let at = code * 4;
    if (o && Number.isFinite(v)) {
      src = heat;
      at = Math.round(Math.min(1, Math.max(0, (v - o.min) / span)) * 255) * 4;
    }
    for (let c = 0; c < 4; c++) unitColor[4 * k + c] = src[at + c];
    if (i === removing) {
      for (let c = 0; c < 3; c++) unitColor[4 * k + c] = Math.round(unitColor[4 * k + c] * 0.35 + REMOVE_TINT[c] * 0.65);
    } else if (i === hover) {
      for (let c = 0; c < 3; c++) unitColor[4 * k + c] = Math.round(unitColor[4 * k + c] + (255 - unitColor[4 * k + c]) * HOVER_LIFT);
    }
    k++;
  }
  const box = n > 0 ? { min, max } : null;

  // Bonds, from the model's bond masks: each unit with its +x, +y and +z neighbours (bits 0, 2
  // and 4 of the mask, the lattice's direction order).
  const masks = scene.frame.bonds;
  const drawBonds = !!masks && marks?.bonds !== false;
  const mids: number[] = [];
  const axes: number[] = [];
  if (drawBonds) {
    const stride = [1, w, w * h];
    for (let u = 0; u < n; u++) {
      const i = unitCell[u];
      const c = [unitPos[3 * u], unitPos[3 * u + 1], unitPos[3 * u + 2]];
      const inner = covered(i, c[0], c[1], c[2]);
      for (let a = 0; a < 3; a++) {
        if (c[a] + 1 >= dims[a] || !(masks![i] & (1 << (2 * a)))) continue;
        // A bond between two covered units is buried in the structure.
        if (inner && covered(i + stride[a], c[0] + (a === 0 ? 1 : 0), c[1] + (a === 1 ? 1 : 0), c[2] + (a === 2 ? 1 : 0))) continue;
        mids.push(c[0] + 0.5 + (a === 0 ? 0.5 : 0), c[1] + 0.5 + (a === 1 ? 0.5 : 0), c[2] + 0.5 + (a === 2 ? 0.5 : 0));
        axes.push(a);
      }
    }
  }

  const ghost = marks?.ghost === false ? [] : (world?.ghost ?? []).filter((i) => i < cells.length && cells[i] === 0);
  const highlight = (marks?.highlight ?? []).filter((i) => i >= 0 && i < cells.length && cells[i] === 0);

  // The plane: the model's ground, else a reference grid under the lowest unit.
  let plane: CubicModel['plane'] = null;
  if (world?.ground !== undefined) plane = { z: world.ground, solid: true };
  else if (box) plane = { z: box.min[2], solid: false };

  // Shadows: one square per column of units, fainter the higher its lowest unit floats.
  const shadows: number[] = [];
  if (plane && n > 0) {
    const lowest = new Map<number, number>();
    for (let u = 0; u < n; u++) {
      const col = unitPos[3 * u + 1] * w + unitPos[3 * u];
      const z = unitPos[3 * u + 2];
      const had = lowest.get(col);
      if (had === undefined || z < had) lowest.set(col, z);
    }
    for (const [col, z] of lowest) {
      const lift = Math.max(0, z - plane.z);
      shadows.push(col % w, Math.floor(col / w), 1 / (1 + 0.35 * lift));
    }
  }

  // The lamp stands clear of the units and of the ghost.
  let around = box ? { min: [...box.min] as V3, max: [...box.max] as V3 } : null;
  for (const i of ghost) {
    const c = coordOf(dims, i);
    around ??= { min: [...c] as V3, max: [c[0] + 1, c[1] + 1, c[2] + 1] };
    for (let a = 0; a < 3; a++) {
      around.min[a] = Math.min(around.min[a], c[a]);
      around.max[a] = Math.max(around.max[a], c[a] + 1);
    }
  }
  const lamp = world?.light ? lampPlacement(around ?? { min: [0, 0, 0], max: dims }, world.light, dims) : null;

  return {
    dims,
    unitPos,
    unitColor,
    unitCell,
    units: n,
    visible: Uint32Array.from(visible),
    bondMid: new Float32Array(mids),
    bondAxis: Uint8Array.from(axes),
    bonds: axes.length,
    ghost,
    highlight,
    box,
    plane,
    shadows: new Float32Array(shadows),
    lamp,
  };
}

/**
 * The lamp of a light source in direction `dir`: beyond the box, an arrow's length away. Its size
 * follows the space, not the structure, so it does not jump when the structure changes.
 */
export function lampPlacement(b: { min: V3; max: V3 }, dir: V3, dims: V3 | [number, number, number]): CubicModel['lamp'] {
  const len = Math.hypot(dir[0], dir[1], dir[2]);
  if (!(len > 0)) return null;
  const d: V3 = [dir[0] / len, dir[1] / len, dir[2] / len];
  const centre: V3 = [(b.min[0] + b.max[0]) / 2, (b.min[1] + b.max[1]) / 2, (b.min[2] + b.max[2]) / 2];
  const size = Math.max(1, Math.min(4, Math.max(dims[0], dims[1], dims[2]) / 24));
  // Half the box's extent along the light, then a gap, the arrow and the lamp itself.
  const half = (Math.abs(d[0]) * (b.max[0] - b.min[0]) + Math.abs(d[1]) * (b.max[1] - b.min[1]) + Math.abs(d[2]) * (b.max[2] - b.min[2])) / 2;
  const reach = half + 0.9 + 2.4 * size;
  return { at: [centre[0] + d[0] * reach, centre[1] + d[1] * reach, centre[2] + d[2] * reach], dir: d, size };
}

export function statsOf(m: CubicModel): RenderStats {
  return { units: m.units, bonds: m.bonds, ghost: m.ghost.length, highlight: m.highlight.length, light: m.lamp !== null, ground: m.plane?.solid === true };
}
