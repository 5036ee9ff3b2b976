// Runs an experiment's jobs on a pool of workers, handing out the next job to whichever worker
// finishes first. Rows come back in any order and are stored by job index.
import { labModule } from './index';
import type { FromExperimentWorker, ToExperimentWorker } from './experiment-worker';

export interface PoolEvents {
  /** A run's row as JSON text, exactly as `kumiki sweep` writes it. */
  row(index: number, row: string): void;
  error(message: string): void;
  done(): void;
}

export class ExperimentPool {
  private workers: Worker[] = [];
  private next = 0;
  private finished = 0;
  private stopped = false;

  constructor(
    private readonly experiment: string,
    private readonly jobs: number,
    private readonly on: PoolEvents,
  ) {}

  /** Starts `size` workers (no more than there are jobs), each with the page's compiled lab module. */
  async start(size: number) {
    let module: WebAssembly.Module;
    try {
      module = await labModule();
    } catch (e) {
      this.fail(`the experiment cannot start: ${e instanceof Error ? e.message : String(e)}`);
      return;
    }
    if (this.stopped) return;
    const n = Math.max(1, Math.min(size, this.jobs));
    for (let w = 0; w < n; w++) {
      const worker = new Worker(new URL('./experiment-worker.ts', import.meta.url), { type: 'module', name: `kumiki-experiment-${w}` });
      worker.onmessage = (e: MessageEvent<FromExperimentWorker>) => this.receive(worker, e.data);
      worker.onerror = (e) => this.fail(`an experiment worker failed: ${e.message}`);
      worker.postMessage({ type: 'setup', experiment: this.experiment, module } satisfies ToExperimentWorker);
      this.workers.push(worker);
    }
  }

  private handOut(worker: Worker) {
    if (this.stopped || this.next >= this.jobs) return;
    worker.postMessage({ type: 'run', index: this.next++ } satisfies ToExperimentWorker);
  }

  private receive(worker: Worker, msg: FromExperimentWorker) {
    if (this.stopped) return;
    switch (msg.type) {
      case 'ready':
        this.handOut(worker);
        return;
      case 'row':
        this.on.row(msg.index, msg.row);
        this.finished++;
        if (this.finished === this.jobs) {
          this.stop();
          this.on.done();
        } else {
          this.handOut(worker);
        }
        return;
      case 'error':
        this.fail(msg.index >= 0 ? `run ${msg.index + 1}: ${msg.message}` : msg.message);
        return;
    }
  }

  private fail(message: string) {
    if (this.stopped) return;
    this.stop();
    this.on.error(message);
  }

  stop() {
    this.stopped = true;
    for (const w of this.workers) w.terminate();
    this.workers = [];
  }
}
