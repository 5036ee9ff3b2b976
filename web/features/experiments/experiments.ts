// The Experiments panel: choose or edit an experiment, keep it across reloads, share it as a
// link (`#x1.…`) or a file, run it on a pool of workers with a progress bar, draw its figures
// (the core's SVG, saved as SVG or PNG), and export the rows with their provenance, the same
// bytes `kumiki sweep` writes. Each sweep that ends (or is cancelled) is kept in IndexedDB and
// listed under "Saved sweeps" (./saved.ts), to reopen, compare or delete. Its content comes from the
// lab module (web/lab/), loaded when the tab is first shown, a link is opened or the report opens one.
import type { ExperimentInfo } from '../../contract.gen';
import { experimentExport, experimentInfo, experimentJson, experiments, loadLab, unpackExperiment } from '../../lab';
import type { PageContext } from '../../page/context';
import { byId, el, formatNumber } from '../../widgets/dom';
import * as core from '../../wasm';
import panelHtml from './panel.html?raw';
import { renderPlots } from './plots';
import { ExperimentPool } from '../../lab/pool';
import { renderComparison } from './compare';
import { DesignForm } from './design';
import { shareFiles } from './files';
import { dateText, runsText, SavedSweeps } from './saved';
import { partial, type SavedSweep, SweepStore } from './store';
import { explain } from './suggest';

/** The time a sweep started, as its provenance records it (RFC 3339, to the second). */
const timestamp = () => new Date().toISOString().replace(/\.\d+Z$/, 'Z');

export function setupExperiments(page: PageContext, address = location.hash) {
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
  const exportButtons = ['export-csv', 'export-json', 'export-traces'].map((id) => byId<HTMLButtonElement>(id));
  const linkButton = byId<HTMLButtonElement>('experiment-link');
  const problemBox = byId('experiment-problem');
  const shown = byId('experiment-shown');
  const compareBox = byId('sweep-compare');
  const compareFigures = byId('sweep-compare-figures');

  let builtIn: ExperimentInfo[] = [];
  const cores = Math.max(1, Math.min(8, navigator.hardwareConcurrency || 2));
  workersInput.value = String(prefs.workers > 0 ? prefs.workers : cores);

  let pool: ExperimentPool | null = null;
  let texts: string[] = [];
  /** The sweep in view: what ran, its exports once it has ended, and its saved record once kept. */
  let ran: { info: ExperimentInfo; text: string; time: string; exports?: SavedSweep['exports']; saved?: SavedSweep } | null = null;
  const saved = new SavedSweeps(new SweepStore(), {
    open: (s) => reopen(s),
    compare: (s) => compare(s),
    canCompare: () => !pool && ran?.exports !== undefined,
  });

  /**
   * Says what is wrong with the experiment, styled as an error; where the core suggests a name for
   * a near miss, a button puts it in the experiment. `null` clears it.
   */
  const problem = (text: string | null) => {
    problemBox.replaceChildren();
    if (text) say(problemBox, text);
  };
  /** Writes a core message into `box` in the page's words, with a button that applies its "did you mean". */
  const say = (box: HTMLElement, text: string) =>
    explain(box, text, editor.value, (fixed) => {
      leaveLink();
      showEdited(fixed);
      problem(null);
    });
  /** The description of an experiment that reads, with its runs. */
  const describeInfo = (info: ExperimentInfo) => {
    description.className = 'hint';
    description.textContent = `${info.description} (${info.jobs.toLocaleString('en-US')} runs)`;
  };
  /** Describes the experiment's text, or says why it cannot run as an error (and beside the form's field it names). */
  const describe = (text: string) => {
    try {
      describeInfo(experimentInfo(text));
      design.showProblem(null);
    } catch (e) {
      description.className = 'error';
      say(description, `This experiment cannot run: ${core.message(e)}`);
      design.showProblem(core.message(e));
    }
  };
  /** The form writes the design into the experiment in view: it becomes an edited one, described again. */
  const design = new DesignForm(
    () => editor.value,
    (text) => {
      // The form's text replaces the JSON typed before: that edit's pending save and description are of the old text.
      clearTimeout(typing);
      leaveLink();
      showEdited(text, false);
    },
  );
  const show = (name: string) => {
    const e = builtIn.find((x) => x.name === name) ?? builtIn[0];
    if (!e) return;
    select.value = e.name;
    editor.value = experimentJson(e.name);
    describeInfo(e);
    design.sync(editor.value);
    design.showProblem(null);
    problem(null);
  };
  /** Shows an experiment's text as an edited one, kept across reloads; the form shows it too, unless it wrote it (`toForm` false). */
  const showEdited = (text: string, toForm = true) => {
    editor.value = text;
    select.value = '';
    prefs.experimentText = text;
    savePrefs();
    if (toForm) design.sync(text);
    describe(text);
    problem(null);
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
  const startLink = address.startsWith('#x1.') ? address : null;
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
        void saved.refresh();
        return true;
      },
      (e: unknown) => {
        loaded = null;
        status.textContent = '';
        problem(`The experiments could not be loaded: ${core.message(e)}`);
        return false;
      },
    );
    return loaded;
  };
  const onTab = (tab: string) => {
    if (tab !== 'experiments') return;
    if (!loaded) status.textContent = 'Loading the experiments…';
    void load();
  };
  events.on('tab', onTab);
  // Mounted after the first frame (./index.ts): a link shows the tab, which may be shown already.
  if (startLink && !page.embedded) showTab();
  else onTab(startLink ? 'experiments' : (document.body.dataset.tab ?? ''));
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
    // The form follows each keystroke (a few rows, no core call), so a change made in it at once
    // after typing starts from what was typed; the description, which asks the core, waits.
    design.sync(editor.value);
    clearTimeout(typing);
    typing = setTimeout(() => {
      prefs.experimentText = editor.value;
      savePrefs();
      describe(editor.value);
    }, 300);
  });
  workersInput.addEventListener('change', () => {
    prefs.workers = Math.max(1, Math.min(16, Math.round(Number(workersInput.value)) || cores));
    workersInput.value = String(prefs.workers);
    savePrefs();
  });

  shareFiles({
    editor,
    status,
    problem,
    showEdited: (text) => {
      leaveLink();
      showEdited(text);
    },
    exports: () => (ran?.exports ? { name: ran.info.name, ...ran.exports } : null),
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
    saved.draw();
  };
  const finished = () => texts.filter(Boolean);
  const draw = () => {
    if (!ran) return;
    try {
      renderPlots(plots, ran.text, ran.info.name, finished());
    } catch (e) {
      problem(`The plots could not be drawn: ${core.message(e)}`);
    }
  };
  const exportable = (on: boolean) => {
    for (const b of exportButtons) b.disabled = !on;
    exportButtons[2].hidden = !ran?.info.traced;
  };

  runButton.addEventListener('click', () => {
    const text = editor.value;
    let info: ExperimentInfo;
    try {
      info = experimentInfo(text);
    } catch (e) {
      status.textContent = '';
      problem(`This experiment cannot run: ${core.message(e)}`);
      return;
    }
    problem(null);
    shown.textContent = '';
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
        status.textContent = '';
        problem(`The experiment stopped: ${message}`);
        report(`The experiment stopped: ${message}`);
      },
      done() {
        running(false);
        pool = null;
        const elapsed = (performance.now() - started) / 1000;
        status.textContent = `Done: ${info.jobs.toLocaleString('en-US')} runs in ${formatNumber(elapsed)} s.`;
        draw();
        void keep();
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
      void keep();
    }
  });

  /**
   * The sweep in view has ended: its exports are made now, once (the bytes `kumiki sweep` writes
   * for it), and it is kept with them, so that reopened it saves the same bytes whatever version
   * of the page reopens it.
   */
  const keep = async () => {
    if (!ran) return;
    const r = ran;
    const rows = finished();
    const made = (format: 'csv' | 'json' | 'traces') => experimentExport(r.text, `[${rows.join(',')}]`, format, r.time);
    let exports: SavedSweep['exports'];
    try {
      exports = { csv: made('csv'), json: made('json'), ...(r.info.traced ? { traces: made('traces') } : {}) };
    } catch (e) {
      problem(`The rows could not be exported: ${core.message(e)}`);
      return;
    }
    r.exports = exports;
    exportable(true);
    const build = exports.csv.match(/^# (.+)$/m)?.[1] ?? '';
    const sweep: SavedSweep = { name: r.info.name, title: r.info.title ?? '', text: r.text, rows, jobs: r.info.jobs, time: r.time, build, exports };
    const id = await saved.keep(sweep);
    if (id !== null) r.saved = { ...sweep, id };
    saved.draw();
  };

  /** A saved sweep's words: its name, when it ran, by which build, and its runs. */
  const sweepLabel = (s: SavedSweep) => `“${s.name}” of ${dateText(s.time)}, ${runsText(s)}${partial(s) ? ' (partial)' : ''}`;

  /** Reopens a saved sweep: its experiment in the editor, its figures drawn again from its rows, and its exports as saved. */
  const reopen = (s: SavedSweep) => {
    if (pool) return;
    let info: ExperimentInfo;
    try {
      info = experimentInfo(s.text);
    } catch (e) {
      problem(`The saved sweep “${s.name}” cannot be read by this version of the page: ${core.message(e)}`);
      return;
    }
    leaveLink();
    showEdited(s.text);
    ran = { info, text: s.text, time: s.time, exports: s.exports, saved: s };
    texts = [...s.rows];
    setProgress(s.rows.length, s.jobs);
    status.textContent = '';
    shown.textContent = `Showing the saved sweep ${sweepLabel(s)}, made by ${s.build}.`;
    draw();
    exportable(true);
    saved.draw();
    shown.scrollIntoView?.({ block: 'nearest' });
  };

  /** The sweep in view beside a saved one, figure by figure. */
  const compare = (s: SavedSweep) => {
    if (!ran?.exports) return;
    const inView = ran.saved ? `In view: ${sweepLabel(ran.saved)}` : `In view: “${ran.info.name}” of ${dateText(ran.time)}`;
    try {
      renderComparison(
        compareFigures,
        { label: inView, text: ran.text, name: ran.info.name, rows: finished() },
        { label: `Saved: ${sweepLabel(s)}`, text: s.text, name: s.name, rows: s.rows },
      );
    } catch (e) {
      problem(`The two sweeps could not be drawn side by side: ${core.message(e)}`);
      return;
    }
    compareBox.hidden = false;
    compareBox.scrollIntoView?.({ block: 'start' });
  };
  byId('sweep-compare-close').addEventListener('click', () => {
    compareBox.hidden = true;
    compareFigures.replaceChildren();
  });
}
