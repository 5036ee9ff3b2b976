// The Experiments panel: choose or edit an experiment, keep it across reloads, share it as a
// link (`#x1.…`) or a file, run it on a pool of workers with a progress bar, draw its figures
// (the core's SVG, saved as SVG or PNG), and export the rows with their provenance, the same
// bytes `kumiki sweep` writes. Its content comes from the lab module (web/lab/), loaded when the
// tab is first shown, an experiment link is opened or the report opens an experiment.
import type { ExperimentInfo } from '../../contract.gen';
import { experimentExport, experimentInfo, experimentJson, experiments, loadLab, packExperiment, unpackExperiment } from '../../lab';
import type { PageContext } from '../../page/context';
import { byId, download, el, formatNumber } from '../../widgets/dom';
import * as core from '../../wasm';
import panelHtml from './panel.html?raw';
import { renderPlots } from './plots';
import { ExperimentPool } from '../../lab/pool';

/** The time a sweep started, as its provenance records it (RFC 3339, to the second). */
const timestamp = () => new Date().toISOString().replace(/\.\d+Z$/, 'Z');

export function setupExperiments(page: PageContext) {
  const { prefs, events } = page;
  page.tabs.section('experiments', panelHtml, 10);
  const savePrefs = page.persistPrefs;
  const report = (text: string) => page.banner.report(text);
  const showTab = () => page.tabs.select('experiments');
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
  const traces = byId<HTMLButtonElement>('export-traces');
  const linkButton = byId<HTMLButtonElement>('experiment-link');
  const saveButton = byId<HTMLButtonElement>('experiment-save');
  const openInput = byId<HTMLInputElement>('experiment-open');

  let builtIn: ExperimentInfo[] = [];
  const cores = Math.max(1, Math.min(8, navigator.hardwareConcurrency || 2));
  workersInput.value = String(prefs.workers > 0 ? prefs.workers : cores);

  let pool: ExperimentPool | null = null;
  let texts: string[] = [];
  let ran: { info: ExperimentInfo; text: string; time: string } | null = null;

  const describe = (text: string) => {
    try {
      const info = experimentInfo(text);
      description.textContent = `${info.description} (${info.jobs.toLocaleString('en-US')} runs)`;
    } catch (e) {
      description.textContent = `This experiment cannot run: ${core.message(e)}`;
    }
  };
  const show = (name: string) => {
    const e = builtIn.find((x) => x.name === name) ?? builtIn[0];
    if (!e) return;
    select.value = e.name;
    editor.value = experimentJson(e.name);
    description.textContent = `${e.description} (${e.jobs.toLocaleString('en-US')} runs)`;
  };
  /** Shows an experiment's text as an edited one, kept across reloads. */
  const showEdited = (text: string) => {
    editor.value = text;
    select.value = '';
    prefs.experimentText = text;
    savePrefs();
    describe(text);
  };
  const fromLink = (hash: string): boolean => {
    if (!hash.startsWith('#x1.')) return false;
    try {
      showEdited(unpackExperiment(hash));
      return true;
    } catch (e) {
      report(`This experiment link could not be opened.\n${core.message(e)}`);
      return false;
    }
  };

  // Until the lab module is loaded, nothing can run, be shared, be chosen or be typed: the load
  // fills the editor, and would overwrite what was typed meanwhile.
  const startLink = location.hash.startsWith('#x1.') ? location.hash : null;
  if (startLink) prefs.tab = 'experiments';
  runButton.disabled = select.disabled = linkButton.disabled = true;
  editor.readOnly = true;
  let loaded: Promise<boolean> | null = null;
  /** Loads the lab module once, then fills the panel: the built-in experiments and the one in view. */
  const load = (): Promise<boolean> => {
    loaded ??= loadLab().then(
      () => {
        builtIn = experiments();
        for (const e of builtIn) select.append(el('option', { value: e.name, text: e.title ? `${e.name}: ${e.title}` : e.name }));
        select.append(el('option', { value: '', text: 'Edited experiment' }));
        status.textContent = '';
        const opened = startLink !== null && fromLink(startLink);
        if (!opened && prefs.experimentText) showEdited(prefs.experimentText);
        else if (!opened) show(prefs.experiment);
        runButton.disabled = select.disabled = linkButton.disabled = false;
        editor.readOnly = false;
        return true;
      },
      (e: unknown) => {
        loaded = null;
        status.textContent = `The experiments could not be loaded: ${core.message(e)}`;
        return false;
      },
    );
    return loaded;
  };
  if (startLink) void load();
  events.on('tab', (tab) => {
    if (tab !== 'experiments') return;
    if (!loaded) status.textContent = 'Loading the experiments…';
    void load();
  });
  window.addEventListener('hashchange', () => {
    if (!location.hash.startsWith('#x1.')) return;
    void load().then((ok) => {
      if (ok && fromLink(location.hash)) showTab();
    });
  });
  /** Once the experiment changes, the address no longer holds it: a reload keeps the edit. */
  const leaveLink = () => {
    if (location.hash.startsWith('#x1.')) history.replaceState(null, '', `${location.pathname}${location.search}`);
  };

  // The reproduction report opens the experiment behind its figures.
  events.on('open-experiment', (name) => {
    showTab();
    void load().then((ok) => {
      if (!ok || !builtIn.some((x) => x.name === name)) return;
      leaveLink();
      prefs.experiment = name;
      prefs.experimentText = '';
      savePrefs();
      show(name);
    });
  });
  select.addEventListener('change', () => {
    if (!select.value) return;
    leaveLink();
    prefs.experiment = select.value;
    prefs.experimentText = '';
    savePrefs();
    show(select.value);
  });
  let typing: ReturnType<typeof setTimeout> | undefined;
  editor.addEventListener('input', () => {
    select.value = '';
    leaveLink();
    clearTimeout(typing);
    typing = setTimeout(() => {
      prefs.experimentText = editor.value;
      savePrefs();
    }, 300);
  });
  workersInput.addEventListener('change', () => {
    prefs.workers = Math.max(1, Math.min(16, Math.round(Number(workersInput.value)) || cores));
    workersInput.value = String(prefs.workers);
    savePrefs();
  });

  linkButton.addEventListener('click', async () => {
    let payload: string;
    try {
      payload = packExperiment(editor.value);
    } catch (e) {
      status.textContent = `This experiment cannot be shared: ${core.message(e)}`;
      return;
    }
    const url = `${location.origin}${location.pathname}${location.search}#${payload}`;
    history.replaceState(null, '', `#${payload}`);
    linkButton.dataset.link = url;
    try {
      await navigator.clipboard.writeText(url);
      linkButton.textContent = 'Link copied';
    } catch {
      linkButton.textContent = 'Link in address bar';
    }
    setTimeout(() => (linkButton.textContent = 'Copy experiment link'), 2000);
  });
  saveButton.addEventListener('click', () => {
    let name = 'experiment';
    try {
      name = experimentInfo(editor.value).name;
    } catch {
      // A draft that does not read yet is saved as it is, under a neutral name.
    }
    download(`${name}.json`, editor.value, 'application/json');
  });
  openInput.addEventListener('change', async () => {
    const file = openInput.files?.[0];
    openInput.value = '';
    if (!file) return;
    const text = await file.text();
    leaveLink();
    showEdited(text);
    status.textContent = `Opened ${file.name}.`;
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
  const finished = () => texts.filter(Boolean);
  const draw = () => {
    if (!ran) return;
    try {
      renderPlots(plots, ran.text, ran.info.name, finished());
    } catch (e) {
      status.textContent = `The plots could not be drawn: ${core.message(e)}`;
    }
  };
  const exportable = (on: boolean) => {
    csv.disabled = json.disabled = traces.disabled = !on;
    traces.hidden = !ran?.info.traced;
  };

  runButton.addEventListener('click', () => {
    const text = editor.value;
    let info: ExperimentInfo;
    try {
      info = experimentInfo(text);
    } catch (e) {
      status.textContent = `This experiment cannot run: ${core.message(e)}`;
      return;
    }
    ran = { info, text, time: timestamp() };
    texts = new Array<string>(info.jobs);
    let done = 0;
    const started = performance.now();
    let lastPlot = started;
    exportable(false);
    plots.replaceChildren();
    setProgress(0, info.jobs);
    running(true);
    status.textContent = `Running ${info.jobs.toLocaleString('en-US')} runs…`;
    pool = new ExperimentPool(text, info.jobs, {
      row(index, row) {
        texts[index] = row;
        done++;
        setProgress(done, info.jobs);
        const elapsed = (performance.now() - started) / 1000;
        const left = (elapsed / done) * (info.jobs - done);
        status.textContent = `${done.toLocaleString('en-US')} / ${info.jobs.toLocaleString('en-US')} runs · ${formatNumber(elapsed)} s${done < info.jobs ? ` · about ${formatNumber(left)} s left` : ''}`;
        if (performance.now() - lastPlot > 2500 && done < info.jobs) {
          lastPlot = performance.now();
          draw();
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
        status.textContent = `Done: ${info.jobs.toLocaleString('en-US')} runs in ${formatNumber(elapsed)} s.`;
        draw();
        exportable(true);
      },
    });
    pool.start(Number(workersInput.value) || cores);
  });

  cancel.addEventListener('click', () => {
    pool?.stop();
    pool = null;
    running(false);
    const partial = finished();
    status.textContent = `Cancelled after ${partial.length} runs.`;
    if (ran && partial.length) {
      draw();
      exportable(true);
    }
  });

  const save = (format: 'csv' | 'json' | 'traces') => {
    if (!ran) return;
    const ext = format === 'json' ? 'jsonl' : 'csv';
    const name = format === 'traces' ? `${ran.info.name}-traces` : ran.info.name;
    const text = experimentExport(ran.text, `[${finished().join(',')}]`, format, ran.time);
    download(`${name}.${ext}`, text, format === 'json' ? 'application/x-ndjson' : 'text/csv');
  };
  csv.addEventListener('click', () => save('csv'));
  json.addEventListener('click', () => save('json'));
  traces.addEventListener('click', () => save('traces'));
}
