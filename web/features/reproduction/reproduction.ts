// The About panel's reproduction rows: the paper's claims about results beside Kumiki's figures,
// read from the same generated report as docs/reproduction.md (`kumiki reproduce`). Each claim
// opens the experiments behind it in the Experiments tab, re-runs them here on a pool of workers
// and recomputes its figure and verdict with the core's own function (`reproduce_claim`, the
// one `kumiki reproduce` writes the report with), beside the report's row. `#claim=ID` opens a
// claim. The report's rows come with the lab module, which holds the report `kumiki reproduce`
// wrote, so the page loads them when the About tab or a claim is first shown.
import type { Claim, Finding, Section } from '../../contract.gen';
import { experimentInfo, experimentJson, loadLab, reproduceClaim, reproductionReport } from '../../lab';
import { ExperimentPool } from '../../lab/pool';
import type { PageContext } from '../../page/context';
import { clear, el, formatNumber } from '../../widgets/dom';
import { copyLink } from '../../widgets/copylink';
import * as core from '../../wasm';

/** Each model's section of the report, once the lab module has loaded. */
let sections: Record<string, Section> = {};
/** Opens an experiment in the Experiments tab (the experiments feature's, through the page). */
let openExperiment: (name: string) => void = () => {};

const VERDICT_TEXT: Record<Finding['verdict'], string> = {
  holds: 'holds',
  partial: 'partial',
  differs: 'differs',
  not_stated: 'not stated',
};

const CLAIM_PREFIX = '#claim=';

/** The claim id the address names (`#claim=ID`), if any. */
function idInAddress(): string | null {
  return location.hash.startsWith(CLAIM_PREFIX) ? decodeURIComponent(location.hash.slice(CLAIM_PREFIX.length)) : null;
}

/** The model whose report holds the claim `id`. */
function modelOf(id: string): string | null {
  return Object.values(sections).find((s) => s.findings.some((c) => c.id === id))?.model ?? null;
}

/** The address of a claim, to share. */
export const claimLink = (id: string) => `${location.origin}${location.pathname}${location.search}${CLAIM_PREFIX}${encodeURIComponent(id)}`;

/** The re-run under way, if any: one at a time, and none outlives the table it shows in. */
let active: { stop(): void } | null = null;

/** Fills `root` with the paper and findings of `model` (or of the claim the address names). */
function renderReproduction(root: HTMLElement, model: string) {
  active?.stop();
  active = null;
  const hadFocus = root.contains(document.activeElement);
  clear(root);
  const wanted = idInAddress();
  const shown = (wanted && modelOf(wanted)) || model;
  const section = sections[shown];
  root.append(el('h3', { text: 'What the paper found, and what Kumiki finds' }));
  if (wanted && !modelOf(wanted)) {
    root.append(
      el('p', {
        class: 'problem',
        role: 'alert',
        text: `The link names the claim “${wanted}”, which this report does not have (a claim's name comes from its first words).`,
      }),
    );
  }
  if (shown !== model && model) {
    // The address's claim is of another model than the one in view; one click goes back to it.
    const back = el('button', { type: 'button', text: `Show ${model}'s claims` });
    back.addEventListener('click', () => {
      history.replaceState(null, '', `${location.pathname}${location.search}`);
      renderReproduction(root, model);
    });
    root.append(
      el(
        'p',
        { class: 'row-buttons' },
        el('span', { class: 'hint', text: `The claim linked in the address is ${shown}'s; the model in view is ${model}.` }),
        back,
      ),
    );
  }
  if (!section) {
    root.append(el('p', { text: `No paper claims are recorded for the model “${shown}” yet.` }));
    return;
  }
  const count = (v: Finding['verdict']) => section.findings.filter((f) => f.verdict === v).length;
  root.append(
    el('p', { class: 'citation', text: section.citation }),
    el('p', {
      text: `${section.findings.length} claims: ${count('holds')} hold, ${count('partial')} in part, ${count('differs')} differ, ${count('not_stated')} with no comparison stated. Each figure comes from the built-in experiments (${section.experiments.join(', ')}), seeded, so the command line's “kumiki reproduce” gives the same. Each claim opens the experiments it reads, and “Re-run” runs them here and recomputes its figure and verdict.`,
    }),
  );
  // Each experiment behind the figures opens in the Experiments tab, ready to run again.
  const open = el('p', { class: 'row-buttons' });
  for (const name of section.experiments) open.append(openButton(name));
  root.append(el('p', { class: 'hint', text: 'Open an experiment to run it again:' }), open);
  const table = el('table', { class: 'findings' });
  table.append(
    el('caption', { text: `Reproduction of ${section.model}'s paper` }),
    el('thead', {}, el('tr', {}, ...['§', 'The paper', 'Kumiki', 'Runs', 'Verdict'].map((h) => el('th', { scope: 'col', text: h })))),
  );
  const body = el('tbody');
  for (const c of section.findings) body.append(claimRow(section.model, c));
  table.append(body);
  // The table fits its panel from a tablet up; the region scrolls only on a phone's width.
  root.append(el('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-label': 'Reproduction table' }, table));
  // The claim the address names stays marked, and focused when it was, as the table is redrawn.
  const target = wanted ? document.getElementById(`claim-${wanted}`) : null;
  target?.classList.add('claim-target');
  if (hadFocus) target?.focus();
}

function openButton(name: string) {
  const button = el('button', { type: 'button', text: name, 'aria-label': `Open the experiment ${name} in the Experiments tab` });
  button.addEventListener('click', () => openExperiment(name));
  return button;
}

function claimRow(model: string, c: Claim) {
  const row = el('tr', { id: `claim-${c.id}`, tabindex: -1, 'data-claim': c.id });
  const kumiki = el('td', {}, c.kumiki);
  if (c.note) kumiki.append(el('span', { class: 'note', text: c.note }));
  const actions = el('div', { class: 'claim-actions' });
  for (const name of c.experiments) actions.append(openButton(name));
  if (c.experiments.length) {
    const rerun = el('button', {
      type: 'button',
      class: 'rerun',
      text: 'Re-run',
      'aria-label': `Re-run ${c.experiments.join(' and ')} here and recompute this claim (${c.section})`,
    });
    rerun.addEventListener('click', () => void startRerun(model, c, row));
    actions.append(rerun);
  } else {
    actions.append(el('span', { class: 'hint', text: 'Read from no experiment: nothing to re-run.' }));
  }
  const copy = el('button', { type: 'button', text: 'Copy link', 'aria-label': `Copy link to the claim ${c.section}` });
  copy.addEventListener('click', async () => {
    const url = claimLink(c.id);
    history.replaceState(null, '', `${CLAIM_PREFIX}${encodeURIComponent(c.id)}`);
    await copyLink(copy, url, 'Copy link');
  });
  actions.append(copy);
  row.append(
    el('td', {}, el('a', { href: `${CLAIM_PREFIX}${encodeURIComponent(c.id)}`, title: `Link to this claim: ${c.id}`, text: c.section })),
    el('td', {}, el('span', { class: 'claim-text', text: c.claim }), actions),
    kumiki,
    el('td', { class: 'num', text: c.runs }),
    el('td', {}, el('span', { class: `verdict verdict-${c.verdict}`, text: VERDICT_TEXT[c.verdict] })),
  );
  return row;
}

/** The parts of a recomputed finding that differ from the report's row. */
function differences(again: Finding, c: Claim): string[] {
  const out: string[] = [];
  if (again.kumiki !== c.kumiki) out.push('figure');
  if (again.runs !== c.runs) out.push('runs');
  if (again.verdict !== c.verdict) out.push('verdict');
  if (again.note !== c.note) out.push('note');
  return out;
}

/**
 * Runs the claim's experiments on a pool of workers, then recomputes the claim from their rows
 * (with the lab module, loaded first).
 */
async function startRerun(model: string, c: Claim, row: HTMLTableRowElement) {
  active?.stop();
  row.parentElement?.querySelector('tr.rerun-row')?.remove();
  const bar = el('div');
  const progress = el(
    'div',
    {
      class: 'progress',
      role: 'progressbar',
      'aria-label': `Progress of the re-run of ${c.section}`,
      'aria-valuemin': 0,
      'aria-valuemax': 100,
      'aria-valuenow': 0,
    },
    bar,
  );
  const status = el('p', { class: 'hint', role: 'status', 'aria-live': 'polite' });
  const cancel = el('button', { type: 'button', text: 'Cancel', 'aria-label': `Cancel the re-run of ${c.section}` });
  const result = el('div', { class: 'rerun-result' });
  const box = el(
    'div',
    { class: 'rerun-box', role: 'group', 'aria-label': `Re-run of the claim ${c.section}` },
    el('div', { class: 'row-buttons' }, progress, cancel),
    status,
    result,
  );
  const holder = el('tr', { class: 'rerun-row' }, el('td', { colspan: 5 }, box));
  row.after(holder);
  status.textContent = 'Loading the experiments…';
  try {
    await loadLab();
  } catch (e) {
    status.textContent = `The experiments could not be loaded: ${core.message(e)}`;
    return;
  }
  // Another re-run took this one's place while the lab module loaded.
  if (!holder.isConnected) return;

  const infos = c.experiments.map((name) => {
    const text = experimentJson(name);
    return { name, text, jobs: experimentInfo(text).jobs };
  });
  const total = infos.reduce((n, e) => n + e.jobs, 0);
  const rows: Record<string, string[]> = {};
  let done = 0;
  let pool: ExperimentPool | null = null;
  let stopped = false;
  const started = performance.now();
  const workers = Math.max(1, Math.min(8, navigator.hardwareConcurrency || 2));
  const setProgress = () => {
    const pct = total ? (100 * done) / total : 0;
    bar.style.width = `${pct}%`;
    progress.setAttribute('aria-valuenow', pct.toFixed(0));
    const elapsed = (performance.now() - started) / 1000;
    const left = done ? (elapsed / done) * (total - done) : 0;
    status.textContent = `${done.toLocaleString('en-US')} / ${total.toLocaleString('en-US')} runs · ${formatNumber(elapsed)} s${done && done < total ? ` · about ${formatNumber(left)} s left` : ''}`;
  };
  const finish = () => {
    cancel.disabled = true;
    if (active === handle) active = null;
  };
  const handle = {
    stop() {
      stopped = true;
      pool?.stop();
      pool = null;
      finish();
    },
  };
  active = handle;
  cancel.addEventListener('click', () => {
    handle.stop();
    status.textContent = `Cancelled after ${done.toLocaleString('en-US')} of ${total.toLocaleString('en-US')} runs.`;
  });

  const runOne = (i: number) => {
    if (stopped) return;
    if (i === infos.length) {
      recompute();
      return;
    }
    const e = infos[i];
    const texts = new Array<string>(e.jobs);
    rows[e.name] = texts;
    pool = new ExperimentPool(e.text, e.jobs, {
      row(index, text) {
        texts[index] = text;
        done++;
        setProgress();
      },
      error(message) {
        handle.stop();
        status.textContent = `Stopped: ${message}`;
      },
      done() {
        pool = null;
        runOne(i + 1);
      },
    });
    void pool.start(workers);
  };
  const recompute = () => {
    finish();
    let again: Finding;
    try {
      again = reproduceClaim(model, c.id, rows);
    } catch (e) {
      status.textContent = `The claim could not be recomputed: ${core.message(e)}`;
      return;
    }
    const differ = differences(again, c);
    status.textContent = `Done: ${total.toLocaleString('en-US')} runs in ${formatNumber((performance.now() - started) / 1000)} s.`;
    result.replaceChildren(
      el(
        'dl',
        {},
        el('dt', { text: 'Figure, recomputed' }),
        el('dd', { class: 'rerun-figure', text: again.kumiki }),
        el('dt', { text: 'Runs' }),
        el('dd', { class: 'rerun-runs', text: again.runs }),
        el('dt', { text: 'Verdict' }),
        el('dd', {}, el('span', { class: `verdict verdict-${again.verdict} rerun-verdict`, text: VERDICT_TEXT[again.verdict] })),
      ),
      el('p', {
        class: differ.length ? 'rerun-match problem' : 'rerun-match',
        'data-same': differ.length ? 'false' : 'true',
        text: differ.length ? `Not the report's row: the ${differ.join(', ')} differ.` : 'The same figure, runs and verdict as the report.',
      }),
    );
  };
  setProgress();
  runOne(0);
}

/**
 * The About tab's paper section, drawn for the model in view when the tab is first shown (the lab
 * module loads then); and the claim the address names (`#claim=ID`), opened now and whenever the
 * address changes: its model's report in the About panel, the row in view and focused.
 */
export function setupReproduction(page: PageContext) {
  const { session, tabs, events } = page;
  openExperiment = (name) => events.emit('open-experiment', name);
  const root = tabs.section('about', '<section id="paper-report" aria-label="The paper\'s findings"></section>', 20).firstElementChild as HTMLElement;
  let model = '';
  let loaded: Promise<boolean> | null = null;
  /** Loads the report once; a failed load says why and is tried again next time. */
  const load = (): Promise<boolean> => {
    if (!loaded) root.replaceChildren(el('p', { class: 'hint', role: 'status', text: "Loading the paper's findings…" }));
    loaded ??= loadLab().then(
      () => {
        sections = reproductionReport();
        return true;
      },
      (e: unknown) => {
        loaded = null;
        root.replaceChildren(el('p', { class: 'problem', text: `The paper's findings could not be loaded: ${core.message(e)}` }));
        return false;
      },
    );
    return loaded;
  };
  const show = () =>
    void load().then((ok) => {
      if (ok) renderReproduction(root, model);
    });
  const follow = () => {
    const now = String(session.doc().model ?? '');
    if (now === model) return;
    model = now;
    if (loaded || document.body.dataset.tab === 'about') show();
  };
  session.on('loaded', follow);
  events.on('tab', (tab) => {
    if (tab === 'about') show();
  });
  // Mounted after the first frame (./index.ts): the scenario in view, and the tab shown, are already there.
  follow();
  const open = () => {
    const id = idInAddress();
    if (id === null) return;
    void load().then((ok) => {
      if (!ok) return;
      renderReproduction(root, model);
      tabs.select('about');
      const row = document.getElementById(`claim-${id}`);
      if (!row) return;
      row.scrollIntoView({ block: 'center' });
      row.focus({ preventScroll: true });
    });
  };
  // A course page's frame shows no About tab.
  if (page.embedded) return;
  open();
  window.addEventListener('hashchange', open);
}
