// Colours: legend colours to RGBA, and the heatmap colour map (viridis, sampled).
import type { LegendEntry } from '../types';

export type RGBA = [number, number, number, number];

/** Parses #rgb, #rrggbb or #rrggbbaa; anything else is mid grey. */
export function parseColor(css: string): RGBA {
  const hex = css.trim().replace(/^#/, '');
  const full = hex.length === 3 ? hex.split('').map((c) => c + c).join('') : hex;
  if (!/^[0-9a-fA-F]{6}([0-9a-fA-F]{2})?$/.test(full)) return [128, 128, 128, 255];
  const n = (i: number) => parseInt(full.slice(i, i + 2), 16);
  return [n(0), n(2), n(4), full.length === 8 ? n(6) : 255];
}

/** 256 RGBA entries indexed by code; codes without a legend entry are transparent. */
export function legendTable(legend: LegendEntry[]): Uint8Array<ArrayBuffer> {
  const table = new Uint8Array(256 * 4);
  for (const e of legend) {
    if (e.code < 0 || e.code > 255) continue;
    table.set(parseColor(e.color), e.code * 4);
  }
  return table;
}

const VIRIDIS: RGBA[] = [
  [68, 1, 84, 255], [72, 35, 116, 255], [64, 67, 135, 255], [52, 94, 141, 255],
  [41, 120, 142, 255], [32, 144, 140, 255], [34, 167, 132, 255], [68, 190, 112, 255],
  [121, 209, 81, 255], [189, 222, 38, 255], [253, 231, 37, 255],
];

/** Viridis at t in [0, 1]. */
export function heat(t: number): RGBA {
  const x = Math.min(1, Math.max(0, t)) * (VIRIDIS.length - 1);
  const i = Math.min(VIRIDIS.length - 2, Math.floor(x));
  const f = x - i;
  const a = VIRIDIS[i];
  const b = VIRIDIS[i + 1];
  return [a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f, 255];
}

/** 256 RGBA entries of the heat map, for lookup textures. */
export function heatTable(): Uint8Array<ArrayBuffer> {
  const table = new Uint8Array(256 * 4);
  for (let i = 0; i < 256; i++) table.set(heat(i / 255).map(Math.round), i * 4);
  return table;
}

/** Finite minimum and maximum of a field. */
export function range(data: Float32Array): [number, number] {
  let lo = Infinity;
  let hi = -Infinity;
  for (let i = 0; i < data.length; i++) {
    const v = data[i];
    if (Number.isFinite(v)) {
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
  }
  return lo <= hi ? [lo, hi] : [0, 1];
}

export function css([r, g, b, a]: RGBA): string {
  return `rgba(${r | 0},${g | 0},${b | 0},${(a / 255).toFixed(3)})`;
}
