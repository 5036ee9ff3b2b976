// The About panel's reproduction rows: the paper's claims about results beside Kumiki's figures,
// read from the same generated report as docs/reproduction.md (`kumiki reproduce`).
import report from '../../docs/reproduction.json';
import { clear, el } from './dom';

export interface Finding {
  section: string;
  claim: string;
  kumiki: string;
  runs: number;
  verdict: 'holds' | 'differs' | 'not_stated';
  note: string;
}

export interface Section {
  model: string;
  citation: string;
  experiments: string[];
  findings: Finding[];
}

const sections = (report as { models: Record<string, Section> }).models;

/** The event a reproduction section sends to open one of its experiments (detail: its name). */
export const OPEN_EXPERIMENT = 'kumiki:open-experiment';

const VERDICT_TEXT: Record<Finding['verdict'], string> = {
  holds: 'holds',
  differs: 'differs',
  not_stated: 'not stated',
};

/** Fills `root` with the paper and findings of `model`, or says there are none. */
export function renderReproduction(root: HTMLElement, model: string) {
  clear(root);
  const section = sections[model];
  root.append(el('h3', { text: 'What the paper found, and what Kumiki finds' }));
  if (!section) {
    root.append(el('p', { text: `No paper claims are recorded for the model “${model}” yet.` }));
    return;
  }
  const count = (v: Finding['verdict']) => section.findings.filter((f) => f.verdict === v).length;
  root.append(
    el('p', { class: 'citation', text: section.citation }),
    el('p', {
      text: `${section.findings.length} claims: ${count('holds')} hold, ${count('differs')} differ, ${count('not_stated')} with no comparison stated. Each figure comes from the built-in experiments (${section.experiments.join(', ')}), seeded, so the command line's “kumiki reproduce” gives the same.`,
    }),
  );
  // Each experiment behind the figures opens in the Experiments tab, ready to run again.
  const open = el('p', { class: 'row-buttons' });
  for (const name of section.experiments) {
    const button = el('button', { type: 'button', text: name, 'aria-label': `Open the experiment ${name} in the Experiments tab` });
    button.addEventListener('click', () => window.dispatchEvent(new CustomEvent(OPEN_EXPERIMENT, { detail: name })));
    open.append(button);
  }
  root.append(el('p', { class: 'hint', text: 'Open an experiment to run it again:' }), open);
  const table = el('table', { class: 'findings' });
  table.append(
    el('caption', { text: `Reproduction of ${section.model}'s paper` }),
    el('thead', {}, el('tr', {}, ...['§', 'The paper', 'Kumiki', 'Runs', 'Verdict'].map((h) => el('th', { scope: 'col', text: h })))),
  );
  const body = el('tbody');
  for (const f of section.findings) {
    const kumiki = el('td', {}, f.kumiki);
    if (f.note) kumiki.append(el('span', { class: 'note', text: f.note }));
    body.append(
      el(
        'tr',
        {},
        el('td', { text: f.section }),
        el('td', { text: f.claim }),
        kumiki,
        el('td', { class: 'num', text: f.runs }),
        el('td', {}, el('span', { class: `verdict verdict-${f.verdict}`, text: VERDICT_TEXT[f.verdict] })),
      ),
    );
  }
  table.append(body);
  root.append(el('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-label': 'Reproduction table' }, table));
}
