// The page's own records: what the simulation worker makes of the wasm's answers and posts to the
// page. Every record the core itself hands the page is generated from its Rust type
// (contract.gen.ts and scenario.gen.ts by `kumiki schema`, view.gen.ts by the view's test) and
// imported from there.

import type { Metrics, Scene } from './contract.gen';
import type { RenderStats } from './view.gen';

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
  scene: Scene | null;
  /** The charted metric's record, when the page asked for one. */
  chart: ChartBand | null;
  /** The overlay's finite [min, max], for its legend; null without an overlay. */
  overlayRange: [number, number] | null;
  /** What a 3-D view drew; null for a planar one or before the view is attached. */
  drawn: RenderStats | null;
  /** Where the worker's time went since the view began (the page benchmark's breakdown). */
  work: WorkerTiming;
}

/**
 * Milliseconds the worker spent stepping, uploading buffers and issuing draws, and frames drawn;
 * and the size of the worker's wasm memory, which grows to the most it ever held and never
 * shrinks (the page benchmark's bytes per cell).
 */
export interface WorkerTiming {
  stepMs: number;
  frames: number;
  uploadMs: number;
  drawMs: number;
  wasmBytes: number;
}
