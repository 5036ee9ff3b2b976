// An experiment worker: parses the experiment once, then runs the jobs it is handed.
import init, { ExperimentRunner, panic_message } from '../pkg/kumiki_wasm.js';
import wasmUrl from '../pkg/kumiki_wasm_bg.wasm?url';

export type ToExperimentWorker = { type: 'setup'; experiment: string } | { type: 'run'; index: number };
export type FromExperimentWorker =
  | { type: 'ready' }
  | { type: 'row'; index: number; row: unknown }
  | { type: 'error'; index: number; message: string };

const scope = self as unknown as DedicatedWorkerGlobalScope;
const post = (m: FromExperimentWorker) => scope.postMessage(m);
let runner: ExperimentRunner | null = null;
const ready = init({ module_or_path: wasmUrl });

scope.onmessage = async (e: MessageEvent<ToExperimentWorker>) => {
  await ready;
  const msg = e.data;
  try {
    if (msg.type === 'setup') {
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
