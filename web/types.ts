// Shapes of the records that cross from the core (through serde-wasm-bindgen) into the page. Those
// the core's own types describe are generated from them (contract.gen.ts, by `kumiki schema`) and
// re-exported here; the rest are the page's and the glue's own.

import type { Scene as SceneInfo } from './contract.gen';

export type { FieldInfo, LatticeKind, Layout, LegendEntry, LessonInfo, PresetInfo, ToolInfo } from './contract.gen';
export type { SceneInfo };

export type Metrics = Record<string, number | boolean | string | null>;

/** A metric's every-step record, merged for drawing (kumiki_core::series::Band). */
export interface ChartBand {
  metric: string;
  /** The first step of each point's range. */
  steps: Float64Array;
  /** The least and the greatest value over each point's steps. */
  min: Float64Array;
  max: Float64Array;
  /** Steps per recorded bucket: 1 until the record is full, then doubling. */
  span: number;
}

/** What a 3-D frame drew (kumiki_view::scene::RenderStats). */
export interface RenderStats {
  units: number;
  bonds: number;
  ghost: number;
  highlight: number;
  light: boolean;
  ground: boolean;
}

/**
 * One frame of a running simulation, as the worker reports it after drawing it. The lattice
 * itself never crosses: the worker draws it (crate/view) and sends what the page's panels show.
 */
export interface Frame {
  steps: number;
  /** The furthest step reached since the last fork: where the timeline ends. */
  furthest: number;
  maxSteps: number;
  finished: boolean;
  completed: boolean;
  hash: string | null;
  metrics: Metrics;
  stepsPerSecond: number;
  /** The model's scene when it changed since the last frame (always in the first after a load), else null. */
  scene: SceneInfo | null;
  /** The charted metric's record, when the page asked for one. */
  chart: ChartBand | null;
  /** The overlay's finite [min, max], for its legend; null without an overlay. */
  overlayRange: [number, number] | null;
  /** What a 3-D view drew; null for a planar one or before the view is attached. */
  drawn: RenderStats | null;
  /** Where the worker's time went since the view began (the page benchmark's breakdown). */
  work: WorkerTiming;
}

/** Milliseconds the worker spent stepping, uploading buffers and issuing draws, and frames drawn. */
export interface WorkerTiming {
  stepMs: number;
  frames: number;
  uploadMs: number;
  drawMs: number;
}

/** One row of a model's metric table (Rust `models::MetricInfo`). */
export interface MetricInfo {
  name: string;
  unit: string;
  about: string;
}

/** Per-condition statistics (Rust `plot::stats::Stats`). */
export interface Stats {
  n: number;
  mean: number;
  sd: number;
  min: number;
  q1: number;
  median: number;
  q3: number;
  max: number;
  ci95: [number, number];
}

/** What a plot draws (Rust `plot::figure::Figure`), the fields the page reads. */
export interface Figure {
  kind: 'lines' | 'trace' | 'histogram' | 'bars' | 'summary';
  title: string;
  described: string;
  /** The x axis's label; a summary's names its condition paths in words, joined by ', '. */
  x_label: string;
  table: { condition: string[]; runs: number; completed: number; value: string; unit: string; stats: Stats | null }[];
  comparisons: {
    value: string;
    conditions: [string, string];
    comparison: { difference: number; cohens_d: number; u: number; rank_biserial: number; p: number; method: string };
  }[];
}

export interface ExperimentInfo {
  name: string;
  title: string;
  description: string;
  jobs: number;
  traced: boolean;
}

export interface Row {
  scenario: string;
  seed: number;
  completed: boolean;
  steps: number;
  hash: string;
  metrics: Metrics;
  params: Record<string, unknown>;
  scenario_hash: string;
  version: string;
  trace?: { step: number[]; values: Record<string, (number | null)[]> };
}
