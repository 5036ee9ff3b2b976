// The page's own records. Every record the core hands the page, the run's frame included, is
// generated from its Rust type (contract.gen.ts and scenario.gen.ts by `kumiki schema`,
// view.gen.ts by the view's test) and imported from there; these are what the simulation worker
// measures itself.

import type { RenderStats } from './view.gen';

/**
 * What the worker adds to each frame of the run (web/sim/pace.ts): how fast the run goes, what the
 * view drew, and where the worker's time went.
 */
export interface Drawn {
  /** Steps a second over the last two seconds while playing; 0 when paused. */
  stepsPerSecond: number;
  /** The overlay's finite [min, max], for its legend; null without an overlay. */
  overlayRange: [number, number] | null;
  /** What a 3-D view drew; null for a planar one or before the view is attached. */
  scene: RenderStats | null;
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
