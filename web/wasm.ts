// The main thread's own wasm instance, for what the page asks beside the scenario in view:
// links unpacked, metric tables, the models' helper calls and the lattices'
// geometry for the editors. The scenario in view and its runs live in the simulation worker
// (web/sim/); experiments, the report's claims and grading are the lab module's (web/lab/),
// loaded when a panel needs them. The built-in scenarios and lessons are not in the page's module:
// they come as JSON (web/pkg/catalog.json, scripts/catalog.mjs), imported when first asked for,
// and the scenario a first visit opens with the page's script.
import init, * as core from './pkg/kumiki_wasm.js';
import wasmUrl from './pkg/kumiki_wasm_bg.wasm?url';
import type { Cells, LatticeKind, LessonInfo, MetricInfo, PresetInfo, Unpacked } from './contract.gen';
import defaultScenarioText from './pkg/default-scenario.json?raw';
import scenarioSchema from './scenario.schema.gen.json';
import { LARGE_CELLS } from './sim/protocol';

let compiled: Promise<WebAssembly.Module> | null = null;

/**
 * The compiled wasm module, compiled once (while it downloads) and handed to the simulation
 * workers, which would otherwise each download and compile their own copy.
 */
export function wasmModule(): Promise<WebAssembly.Module> {
  compiled ??= WebAssembly.compileStreaming(fetch(wasmUrl)).catch(async () =>
    // A host that serves the file without the application/wasm type cannot stream it.
    WebAssembly.compile(await (await fetch(wasmUrl)).arrayBuffer()),
  );
  return compiled;
}

/** The page's own wasm memory (the worker has another). */
let memory: WebAssembly.Memory | null = null;

export async function loadCore(): Promise<void> {
  memory = (await init({ module_or_path: await wasmModule() })).memory;
}

/** Bytes of the page's own wasm memory: the most it ever held, since wasm memory never shrinks. */
export function wasmBytes(): number {
  return memory?.buffer.byteLength ?? 0;
}

/** A core error as plain text (wasm-bindgen's JsError arrives as an Error). */
export function message(e: unknown): string {
  return e instanceof Error ? e.message : String(e);
}

/** A number as every figure, table and export shows it: the core's one rule (crate/core/src/plot/number.rs). */
export const formatNumber = (v: number): string => core.format_number(v);

/** The built-in scenarios and lessons: the gallery's lists, and each one's text by name. */
export interface Catalogue {
  presets: PresetInfo[];
  lessons: LessonInfo[];
  presetText: Record<string, string>;
  lessonText: Record<string, string>;
}
let catalogue: Promise<Catalogue> | null = null;
/** The built-in scenarios and lessons, fetched once, when first asked for: no part of the first load. */
export function loadCatalogue(): Promise<Catalogue> {
  catalogue ??= import('./pkg/catalog.json').then(
    (m) => m.default as Catalogue,
    (e: unknown) => {
      catalogue = null;
      throw e;
    },
  );
  return catalogue;
}
/** The text of the scenario a first visit opens (web/page/start.ts), which comes with the page's script. */
export const defaultScenario = (): string => defaultScenarioText;
/** The text of the lesson `name`. */
export async function lessonJson(name: string): Promise<string> {
  const text = (await loadCatalogue()).lessonText[name];
  if (text === undefined) throw new Error(`no lesson is named '${name}'`);
  return text;
}
/** The most cells a shape may span in the page; a scenario over it is refused. */
export const pageShapeCells = (): number => core.page_shape_cells();
/** A link's scenario JSON, not yet validated, and the model versions that made and read it. */
export const unpackLink = (link: string): Unpacked => core.unpack_link(link) as Unpacked;
/** A fresh seed from crypto.getRandomValues (through getrandom), 0 to 2^53 − 1. */
export const freshSeed = (): number => core.fresh_seed();
/** A goal in words, for students; undefined when it does not parse. */
export const goalWords = (text: string): string | undefined => core.goal_words(text);
/**
 * How a scenario (its JSON, named `name`) differs from the preset it is named after, each change
 * in words (`robots: 10 → 3`), with that preset's text; null when no preset has its name, or when
 * it is too large to read on the page's thread (its worker reads it).
 */
export async function presetChanges(json: string, name: string): Promise<{ changes: string[]; preset: string } | null> {
  const preset = (await loadCatalogue()).presetText[name];
  if (preset === undefined) return null;
  const changes = (core.scenario_changes(preset, json, LARGE_CELLS) as string[] | undefined) ?? null;
  return changes && { changes, preset };
}

/** A model's metrics: name, unit and a one-sentence explanation (docs/metrics.md). */
export const metricTable = (model: string): MetricInfo[] => core.metric_table(model) as MetricInfo[];
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

/** A text shape read by the core's rules; throws with the row and column of a bad character. */
export const parseShape = (lattice: LatticeKind, text: string): Cells => core.shape_parse(lattice, text) as Cells;
export const formatShape = (lattice: LatticeKind, s: Cells): string => core.shape_format(lattice, s.w, s.h, s.d, Uint8Array.from(s.cells));

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
    readonly lattice: LatticeKind,
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
