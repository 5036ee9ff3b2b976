// A grading worker: grades the rows of a class's file it is handed, each as `kumiki check` does
// (the core's grading::grade through the lab's grade_row): replayed within the exercise's budget
// and judged by the class's exercise. It runs the page's compiled lab module, handed over at
// setup: nothing is downloaded, and no hand-in leaves the machine.
import init, { grade_row, panic_message } from '../../pkg/kumiki_lab.js';
import type { GradeRow } from './handins';

export type ToGradeWorker =
  /** The lab module, and the class's exercise (its `ClassExercise.teacher`). */
  | { type: 'setup'; module: WebAssembly.Module; teacher: string }
  /** A row of the class's file (a `Handin2` record as JSON), the `index`-th of the table. */
  | { type: 'grade'; index: number; handin: string };
export type FromGradeWorker = { type: 'ready' } | { type: 'graded'; index: number; row: GradeRow } | { type: 'failed'; message: string };

const scope = self as unknown as DedicatedWorkerGlobalScope;
const post = (m: FromGradeWorker) => scope.postMessage(m);
let teacher = '';

scope.onmessage = async (e: MessageEvent<ToGradeWorker>) => {
  const msg = e.data;
  if (msg.type === 'setup') {
    try {
      await init({ module_or_path: msg.module });
      teacher = msg.teacher;
      post({ type: 'ready' });
    } catch (err) {
      post({ type: 'failed', message: err instanceof Error ? err.message : String(err) });
    }
    return;
  }
  try {
    post({ type: 'graded', index: msg.index, row: grade_row(msg.handin, teacher) as GradeRow });
  } catch (err) {
    // A panic stops this instance: the row is named, and the worker is not reused.
    const panic = panic_message();
    const why = err instanceof Error ? err.message : String(err);
    if (panic) post({ type: 'failed', message: `row ${msg.index + 1}: ${panic}` });
    else post({ type: 'graded', index: msg.index, row: { handin: msg.index + 1, error: why } });
  }
};
