// The Experiments panel: choose or edit an experiment, run it on a pool of workers with a
// progress bar, plot it as its file says, export the rows as CSV or JSON.
import { ExperimentPool } from '../experiments/pool';
import type { Prefs } from '../store';
import type { ExperimentInfo, Row } from '../types';
import * as core from '../wasm';
import { byId, download, el, formatNumber } from './dom';
import { renderPlots } from './plots';

export function setupExperiments(prefs: Prefs, savePrefs: () => void, report: (msg: string) => void) {
  const select = byId<HTMLSelectElement>('experiment-select');
  const description = byId('experiment-description');
  const editor = byId<HTMLTextAreaElement>('experiment-json');
  const runButton = byId<HTMLButtonElement>('experiment-run');
  const cancel = byId<HTMLButtonElement>('experiment-cancel');
  const workersInput = byId<HTMLInputElement>('experiment-workers');
  const progress = byId('experiment-progress');
  const status = byId('experiment-status');
  const plots = byId('experiment-plots');
  const csv = byId<HTMLButtonElement>('export-csv');
  const json = byId<HTMLButtonElement>('export-json');

  const builtIn = core.experiments();
  for (const e of builtIn) select.append(el('option', { value: e.name, text: e.title ? `${e.name}: ${e.title}` : e.name }));
  const cores = Math.max(1, Math.min(8, navigator.hardwareConcurrency || 2));
  workersInput.value = String(prefs.workers > 0 ? prefs.workers : cores);

  let pool: ExperimentPool | null = null;
  let rows: Row[] = [];
  let info: ExperimentInfo | null = null;

  const show = (name: string) => {
    const e = builtIn.find((x) => x.name === name) ?? builtIn[0];
    if (!e) return;
    select.value = e.name;
    editor.value = core.experimentJson(e.name);
    description.textContent = `${e.description} (${e.jobs.toLocaleString('en-US')} runs)`;
  };
  show(prefs.experiment);
  select.addEventListener('change', () => {
    prefs.experiment = select.value;
    savePrefs();
    show(select.value);
  });
  workersInput.addEventListener('change', () => {
    prefs.workers = Math.max(1, Math.min(16, Math.round(Number(workersInput.value)) || cores));
    workersInput.value = String(prefs.workers);
    savePrefs();
  });

  const setProgress = (done: number, total: number) => {
    const pct = total ? (100 * done) / total : 0;
    (progress.firstElementChild as HTMLElement).style.width = `${pct}%`;
    progress.setAttribute('aria-valuenow', pct.toFixed(0));
  };

  const running = (on: boolean) => {
    runButton.disabled = on;
    cancel.disabled = !on;
    select.disabled = on;
  };

  runButton.addEventListener('click', () => {
    const text = editor.value;
    try {
      info = core.experimentInfo(text);
    } catch (e) {
      status.textContent = `This experiment cannot run: ${core.message(e)}`;
      return;
    }
    const current = info;
    rows = new Array<Row>(current.jobs);
    let done = 0;
    const started = performance.now();
    let lastPlot = started;
    csv.disabled = json.disabled = true;
    plots.replaceChildren();
    setProgress(0, current.jobs);
    running(true);
    status.textContent = `Running ${current.jobs.toLocaleString('en-US')} runs…`;
    const complete = () => rows.filter(Boolean);
    pool = new ExperimentPool(text, current.jobs, {
      row(index, row) {
        rows[index] = row;
        done++;
        setProgress(done, current.jobs);
        const elapsed = (performance.now() - started) / 1000;
        const left = (elapsed / done) * (current.jobs - done);
        status.textContent = `${done.toLocaleString('en-US')} / ${current.jobs.toLocaleString('en-US')} runs · ${formatNumber(elapsed)} s${done < current.jobs ? ` · about ${formatNumber(left)} s left` : ''}`;
        if (performance.now() - lastPlot > 2500 && done < current.jobs) {
          lastPlot = performance.now();
          renderPlots(plots, current.plot, complete());
        }
      },
      error(message) {
        running(false);
        pool = null;
        status.textContent = `Stopped: ${message}`;
        report(`The experiment stopped: ${message}`);
      },
      done() {
        running(false);
        pool = null;
        const elapsed = (performance.now() - started) / 1000;
        status.textContent = `Done: ${current.jobs.toLocaleString('en-US')} runs in ${formatNumber(elapsed)} s.`;
        renderPlots(plots, current.plot, rows);
        csv.disabled = json.disabled = false;
      },
    });
    pool.start(Number(workersInput.value) || cores);
  });

  cancel.addEventListener('click', () => {
    pool?.stop();
    pool = null;
    running(false);
    const partial = rows.filter(Boolean);
    status.textContent = `Cancelled after ${partial.length} runs.`;
    if (info && partial.length) {
      renderPlots(plots, info.plot, partial);
      csv.disabled = json.disabled = false;
    }
  });

  const name = () => info?.name ?? 'experiment';
  csv.addEventListener('click', () => download(`${name()}.csv`, core.rowsToCsv(JSON.stringify(rows.filter(Boolean))), 'text/csv'));
  json.addEventListener('click', () => download(`${name()}.json`, JSON.stringify(rows.filter(Boolean), null, 1), 'application/json'));
}
