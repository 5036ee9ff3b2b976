// A grading worker: replays the hand-ins it is handed and judges each as `kumiki check` does
// (the core's grading::grade, through grade_handin). It runs the page's compiled lab module,
// handed over at setup: nothing is downloaded, and no hand-in leaves the machine.
import type { Graded } from '../../contract.gen';
import init, { grade_handin, panic_message } from '../../pkg/kumiki_lab.js';

export type ToGradeWorker = { type: 'setup'; module: WebAssembly.Module; exercise: string | null } | { type: 'grade'; index: number; link: string };
export type FromGradeWorker = { type: 'ready' } | { type: 'graded'; index: number; row: Graded } | { type: 'failed'; message: string };

const scope = self as unknown as DedicatedWorkerGlobalScope;
const post = (m: FromGradeWorker) => scope.postMessage(m);
let exercise: string | null = null;

scope.onmessage = async (e: MessageEvent<ToGradeWorker>) => {
  const msg = e.data;
  if (msg.type === 'setup') {
    try {
      await init({ module_or_path: msg.module });
      exercise = msg.exercise;
      post({ type: 'ready' });
    } catch (err) {
      post({ type: 'failed', message: err instanceof Error ? err.message : String(err) });
    }
    return;
  }
  try {
    post({ type: 'graded', index: msg.index, row: grade_handin(msg.link, exercise ?? undefined) as Graded });
  } catch (err) {
    // A panic stops this instance: the hand-in is reported, and the worker is not reused.
    const panic = panic_message();
    if (panic) post({ type: 'failed', message: panic });
    else post({ type: 'graded', index: msg.index, row: { error: err instanceof Error ? err.message : String(err) } });
  }
};
