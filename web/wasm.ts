// The main thread's own wasm instance, for work on documents: presets, validation, links,
// experiments and CSV. Runs happen in workers.
import init, * as core from './pkg/kumiki_wasm.js';
import wasmUrl from './pkg/kumiki_wasm_bg.wasm?url';
import scenarioSchema from '../docs/schema/scenario.schema.json';
import type { Finding } from './contract.gen';
import type { ExperimentInfo, Figure, LessonInfo, MetricInfo, PresetInfo } from './types';

let compiled: Promise<WebAssembly.Module> | null = null;

/**
 * The compiled wasm module, compiled once (while it downloads) and handed to the simulation worker
 * and the experiment workers, which would otherwise each download and compile their own copy.
 */
export function wasmModule(): Promise<WebAssembly.Module> {
  compiled ??= WebAssembly.compileStreaming(fetch(wasmUrl)).catch(async () =>
    // A host that serves the file without the application/wasm type cannot stream it.
    WebAssembly.compile(await (await fetch(wasmUrl)).arrayBuffer()),
  );
  return compiled;
}

export async function loadCore(): Promise<void> {
  await init({ module_or_path: await wasmModule() });
}

/** A core error as plain text (wasm-bindgen's JsError arrives as an Error). */
export function message(e: unknown): string {
  return e instanceof Error ? e.message : String(e);
}

export const presets = (): PresetInfo[] => core.presets() as PresetInfo[];
export const presetJson = (name: string): string => core.preset_json(name);
export const lessons = (): LessonInfo[] => core.lessons() as LessonInfo[];
export const lessonJson = (name: string): string => core.lesson_json(name);
export const normalize = (json: string): string => core.normalize_scenario(json);
/** A scenario's comparison: the second run's scenario and the two runs' names, or null (crate/core/src/compare.rs). */
export function comparePair(json: string): { second: string; labels: [string, string] } | null {
  const pair = core.compare_pair(json);
  return pair ? { second: pair[0], labels: [pair[1], pair[2]] } : null;
}
/** The whole of what is wrong with scenario JSON ("" when nothing is): `normalize` throws it briefly. */
export const problemInFull = (json: string): string => core.scenario_problem_in_full(json);
/** The link of a scenario the core validated before (the page's own); nothing is rebuilt. */
export const encodeLink = (json: string): string => core.pack_link(json);
/** The cells of the largest shape in scenario JSON, read from its text without building it. */
export const estimateCells = (json: string): number => core.estimate_cells(json);
/** The most cells a shape may span in the page; a scenario over it is refused. */
export const pageShapeCells = (): number => core.page_shape_cells();
/** A link's scenario JSON, not yet validated, and the model versions that made and read it. */
export const unpackLink = (link: string): { scenario: string; made_with: number; current: number } =>
  core.unpack_link(link) as { scenario: string; made_with: number; current: number };
/** Sets one dotted path without validating: for a large scenario, which the worker validates. */
export const setPath = (json: string, path: string, valueJson: string): string => core.set_scenario_path(json, path, valueJson);
/** A fresh seed from crypto.getRandomValues (through getrandom), 0 to 2^53 − 1. */
export const freshSeed = (): number => core.fresh_seed();
/** What is wrong with a goal: its syntax, or a metric or scenario field the model does not have. */
export const goalProblem = (text: string, metrics: string[], scenario: string): string | undefined => core.goal_problem(text, metrics, scenario);
/** A goal in words, for students; undefined when it does not parse. */
export const goalWords = (text: string): string | undefined => core.goal_words(text);
/** The title of the teacher's exercise (a link or a lesson's name) the Grade view grades by; throws why it cannot. */
export const exerciseTitle = (text: string): string => core.exercise_title(text);
/** Why an edit may not replace the exercise in force (a locked field, the exercise itself); undefined when it may. */
export const exerciseGuard = (current: string, next: string): string | undefined => core.exercise_guard(current, next);
export const override = (json: string, path: string, valueJson: string): string => core.override_scenario(json, path, valueJson);
export const experiments = (): ExperimentInfo[] => core.experiments() as ExperimentInfo[];
export const experimentJson = (name: string): string => core.experiment_json(name);
/** A model's helper call (see `kumiki queries`): JSON arguments, a JSON answer. */
export const query = <T = Record<string, unknown>>(model: string, name: string, args: unknown): T =>
  JSON.parse(core.model_query(model, name, JSON.stringify(args))) as T;
/** A model's metrics: name, unit and a one-sentence explanation (docs/metrics.md). */
export const metricTable = (model: string): MetricInfo[] => core.metric_table(model) as MetricInfo[];
/** Each figure of an experiment's plots from its rows (a JSON array), and its SVG. */
export const experimentFigures = (experiment: string, rowsJson: string): { figure: Figure; svg: string }[] =>
  core.experiment_figures(experiment, rowsJson) as { figure: Figure; svg: string }[];
/** The rows exported with their provenance, the bytes `kumiki sweep` writes (`csv`, `json` lines, `traces`). */
export const experimentExport = (experiment: string, rowsJson: string, format: 'csv' | 'json' | 'traces', time: string): string =>
  core.experiment_export(experiment, rowsJson, format, time);
/** An experiment's link payload (`x1.…`), and the experiment inside one. */
export const packExperiment = (json: string): string => core.pack_experiment(json);
export const unpackExperiment = (link: string): string => core.unpack_experiment(link);
/** A claim of the reproduction report recomputed from its experiments' rows (name → row texts), as `kumiki reproduce` computes it. */
export const reproduceClaim = (model: string, id: string, rows: Record<string, string[]>): Finding =>
  core.reproduce_claim(
    model,
    id,
    `{${Object.entries(rows)
      .map(([name, texts]) => `${JSON.stringify(name)}:[${texts.join(',')}]`)
      .join(',')}}`,
  ) as Finding;
export const version = (): string => core.version();

/** A JSON Schema node, as far as the page reads one. */
export interface SchemaNode {
  $ref?: string;
  type?: string | string[];
  description?: string;
  const?: unknown;
  enum?: unknown[];
  oneOf?: SchemaNode[];
  minimum?: number;
  maximum?: number;
  default?: unknown;
  properties?: Record<string, SchemaNode>;
}
/** A model's scenario keys as the schema gives them, with the definitions they refer to. */
export interface ModelSchema {
  properties: Record<string, SchemaNode>;
  defs: Record<string, SchemaNode>;
}
/** The schema of model `model`'s scenarios, from the published `docs/schema/scenario.schema.json`. */
export function modelSchema(model: string): ModelSchema | undefined {
  const defs = (scenarioSchema as { $defs: Record<string, SchemaNode> }).$defs;
  const def = Object.values(defs).find((d) => d.properties?.model?.const === model);
  return def?.properties ? { properties: def.properties, defs } : undefined;
}

export interface Shape {
  w: number;
  h: number;
  d: number;
  cells: number[];
}
/** A text shape read by the core's rules; throws with the row and column of a bad character. */
export const parseShape = (lattice: 'square' | 'hex' | 'cubic', text: string): Shape => core.shape_parse(lattice, text) as Shape;
export const formatShape = (lattice: 'square' | 'hex' | 'cubic', s: Shape): string => core.shape_format(lattice, s.w, s.h, s.d, Uint8Array.from(s.cells));
export const experimentInfo = (json: string): ExperimentInfo => {
  const runner = new core.ExperimentRunner(json);
  try {
    return runner.info() as ExperimentInfo;
  } finally {
    runner.free();
  }
};

/**
 * A model's helper call (see `models::query` in the core), for instance deriving the type-lists of
 * a cubic shape. Throws with the core's message, which names the argument and the problem.
 */
export const modelQuery = <T = Record<string, unknown>>(model: string, name: string, args: Record<string, unknown>): T =>
  JSON.parse(core.model_query(model, name, JSON.stringify(args))) as T;

/** A lattice's geometry, from the same Rust code the view draws with (crate/view). */
export class Geometry {
  private readonly g: core.LatticeGeometry;
  /** Centre-to-corner radius of a hex cell (read once the module is loaded). */
  static get hexRadius(): number {
    return core.LatticeGeometry.hex_radius();
  }
  /** Distance between hex rows. */
  static get hexRow(): number {
    return core.LatticeGeometry.hex_row();
  }

  constructor(
    readonly lattice: 'square' | 'hex' | 'cubic',
    readonly dims: [number, number, number],
  ) {
    this.g = new core.LatticeGeometry(lattice, dims[0], dims[1], dims[2]);
  }

  /** Centre of a planar cell in world units. */
  centre(cell: number): [number, number] {
    const c = this.g.centre(cell);
    return [c[0], c[1]];
  }

  /** The planar cell under a world point, or -1. */
  cellAt(wx: number, wy: number): number {
    return this.g.cell_at(wx, wy);
  }

  /** The world rectangle of the whole lattice. */
  bounds(): { x0: number; y0: number; x1: number; y1: number } {
    const [x0, y0, x1, y1] = this.g.bounds();
    return { x0, y0, x1, y1 };
  }

  /** Corners of a hexagon of radius r around a point. */
  static hexCorners(cx: number, cy: number, r: number): [number, number][] {
    const flat = core.LatticeGeometry.hex_corners(cx, cy, r);
    return Array.from({ length: 6 }, (_, k) => [flat[2 * k], flat[2 * k + 1]] as [number, number]);
  }

  free() {
    this.g.free();
  }
}

/** A view drawing on an OffscreenCanvas from this thread (an editor's); see crate/view. */
export type Viewer = core.Viewer;
export const newViewer = (canvas: OffscreenCanvas, prefer: 'webgl2' | 'canvas2d' | 'auto'): Viewer => new core.Viewer(canvas, undefined, prefer);
