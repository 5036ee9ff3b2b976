// The lab module (crate/lab, kumiki_lab): experiments, their figures and exports, the report's
// claims recomputed and hand-ins graded. The page opens without it: it is downloaded and compiled
// the first time a panel needs it (the Experiments tab, a claim's re-run, the Grade view), then
// handed, compiled, to the experiment and grading workers. Call `loadLab` before the rest.
import labUrl from '../pkg/kumiki_lab_bg.wasm?url';
import type * as Lab from '../pkg/kumiki_lab.js';
import type { ClassExercise, ExperimentInfo, Figure, Finding, Handin2, Section } from '../contract.gen';

let compiled: Promise<WebAssembly.Module> | null = null;
let loading: Promise<void> | null = null;
let lab: typeof Lab | null = null;

/** The compiled lab module, compiled once (while it downloads), for this thread and the workers. */
export function labModule(): Promise<WebAssembly.Module> {
  compiled ??= WebAssembly.compileStreaming(fetch(labUrl)).catch(async () =>
    // A host that serves the file without the application/wasm type cannot stream it.
    WebAssembly.compile(await (await fetch(labUrl)).arrayBuffer()),
  );
  return compiled;
}

/** Loads the lab module on this thread, once; a failed load is tried again at the next call. */
export function loadLab(): Promise<void> {
  loading ??= (async () => {
    const bindings = await import('../pkg/kumiki_lab.js');
    await bindings.default({ module_or_path: await labModule() });
    lab = bindings;
  })().catch((e: unknown) => {
    loading = null;
    compiled = null;
    throw e;
  });
  return loading;
}

const loaded = (): typeof Lab => {
  if (!lab) throw new Error('the lab module is not loaded yet');
  return lab;
};

export const experiments = (): ExperimentInfo[] => loaded().experiments() as ExperimentInfo[];
export const experimentJson = (name: string): string => loaded().experiment_json(name);
export const experimentInfo = (json: string): ExperimentInfo => {
  const runner = new (loaded().ExperimentRunner)(json);
  try {
    return runner.info() as ExperimentInfo;
  } finally {
    runner.free();
  }
};
/** Each figure of an experiment's plots from its rows (a JSON array), and its SVG. */
export const experimentFigures = (experiment: string, rowsJson: string): { figure: Figure; svg: string }[] =>
  loaded().experiment_figures(experiment, rowsJson) as { figure: Figure; svg: string }[];
/** Figure `index` of an experiment's plots from its rows, as a one-page PDF (the bytes `kumiki sweep --plot pdf` writes). */
export const experimentFigurePdf = (experiment: string, rowsJson: string, index: number): Uint8Array<ArrayBuffer> =>
  loaded().experiment_figure_pdf(experiment, rowsJson, index) as Uint8Array<ArrayBuffer>;
/** The rows exported with their provenance, the bytes `kumiki sweep` writes (`csv`, `json` lines, `traces`). */
export const experimentExport = (experiment: string, rowsJson: string, format: 'csv' | 'json' | 'traces', time: string): string =>
  loaded().experiment_export(experiment, rowsJson, format, time);
/** An experiment's link payload (`x1.…`), and the experiment inside one. */
export const packExperiment = (json: string): string => loaded().pack_experiment(json);
export const unpackExperiment = (link: string): string => loaded().unpack_experiment(link);
/** A claim of the reproduction report recomputed from its experiments' rows (name → row texts), as `kumiki reproduce` computes it. */
export const reproduceClaim = (model: string, id: string, rows: Record<string, string[]>): Finding =>
  loaded().reproduce_claim(
    model,
    id,
    `{${Object.entries(rows)
      .map(([name, texts]) => `${JSON.stringify(name)}:[${texts.join(',')}]`)
      .join(',')}}`,
  ) as Finding;
/** The title of the teacher's exercise (a link or a lesson's name) the Grade view grades by; throws why it cannot. */
export const exerciseTitle = (text: string): string => loaded().exercise_title(text);
/** The hand-ins in a class's file (links, a form's CSV or text export, or a workbook), numbered as the grade table numbers them; throws one message for any other file. */
export const readHandins = (bytes: Uint8Array): Handin2[] => loaded().read_handins(bytes) as Handin2[];
/** The class's exercise: the teacher's (a link or a lesson's name) or, when none is given, the one most of the `links` carry; throws why it cannot grade. */
export const classExercise = (exercise: string | null, links: string[]): ClassExercise =>
  loaded().class_exercise(exercise ?? undefined, links) as ClassExercise;
/** The grade table's CSV (`rowsJson`: its rows as JSON), as `kumiki check --format csv` writes it. */
export const gradeTableCsv = (rowsJson: string, teacher: string): string => loaded().grades_csv(rowsJson, teacher);
/** The reproduction report's section of each model (docs/reproduction.json, as `kumiki reproduce` wrote it). */
export const reproductionReport = (): Record<string, Section> => loaded().reproduction_report() as Record<string, Section>;
