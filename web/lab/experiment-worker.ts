// An experiment worker: parses the experiment once, then runs the jobs it is handed. It runs the
// page's compiled lab module, handed over with the experiment: nothing is downloaded or compiled.
import init, { ExperimentRunner, panic_message } from '../pkg/kumiki_lab.js';

export type ToExperimentWorker = { type: 'setup'; experiment: string; module: WebAssembly.Module } | { type: 'run'; index: number };
export type FromExperimentWorker = { type: 'ready' } | { type: 'row'; index: number; row: string } | { type: 'error'; index: number; message: string };

const scope = self as unknown as DedicatedWorkerGlobalScope;
const post = (m: FromExperimentWorker) => scope.postMessage(m);
let runner: ExperimentRunner | null = null;

scope.onmessage = async (e: MessageEvent<ToExperimentWorker>) => {
  const msg = e.data;
  try {
    if (msg.type === 'setup') {
      await init({ module_or_path: msg.module });
      runner = new ExperimentRunner(msg.experiment);
      post({ type: 'ready' });
    } else if (runner) {
      post({ type: 'row', index: msg.index, row: runner.run(msg.index) });
    }
  } catch (err) {
    const panic = panic_message();
    post({ type: 'error', index: msg.type === 'run' ? msg.index : -1, message: panic ?? (err instanceof Error ? err.message : String(err)) });
  }
};
