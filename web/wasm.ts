// The main thread's own wasm instance, for work on documents: presets, validation, links,
// experiments and CSV. Runs happen in workers.
import init, * as core from './pkg/kumiki_wasm.js';
import wasmUrl from './pkg/kumiki_wasm_bg.wasm?url';
import type { ExperimentInfo, PresetInfo } from './types';

export async function loadCore(): Promise<void> {
  await init({ module_or_path: wasmUrl });
}

/** A core error as plain text (wasm-bindgen's JsError arrives as an Error). */
export function message(e: unknown): string {
  return e instanceof Error ? e.message : String(e);
}

export const presets = (): PresetInfo[] => core.presets() as PresetInfo[];
export const presetJson = (name: string): string => core.preset_json(name);
export const normalize = (json: string): string => core.normalize_scenario(json);
export const encodeLink = (json: string): string => core.encode_link(json);
export const decodeLink = (link: string): string => core.decode_link(link);
/** The behaviour version of its model that made a link, and this page's. */
export const linkVersions = (link: string): { made_with: number; current: number } => core.link_model_versions(link) as { made_with: number; current: number };
export const goalProblem = (text: string): string | undefined => core.goal_problem(text);
export const override = (json: string, path: string, valueJson: string): string => core.override_scenario(json, path, valueJson);
export const experiments = (): ExperimentInfo[] => core.experiments() as ExperimentInfo[];
export const experimentJson = (name: string): string => core.experiment_json(name);
/** A model's helper call (see `kumiki queries`): JSON arguments, a JSON answer. */
export const query = <T = Record<string, unknown>>(model: string, name: string, args: unknown): T =>
  JSON.parse(core.model_query(model, name, JSON.stringify(args))) as T;
export const rowsToCsv = (rowsJson: string): string => core.rows_to_csv(rowsJson);
export const version = (): string => core.version();

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
