// Two sweeps side by side. First each summary of the two in one table, the same condition's n, mean
// and interval of the mean of A beside B's, which is what a researcher reads across two sweeps;
// then each figure of the sweep in view beside the same figure of the saved one, one pair a row.
// Each figure keeps its own axes, as each sweep's export draws it (overlaying the two on one axis
// would be a new figure, which the core does not draw); the headings say which side is which.
import type { Figure, SummaryRow } from '../../contract.gen';
import { el, formatNumber } from '../../widgets/dom';
import { conditionNames, renderPlots, words } from './plots';

/** One side of the comparison: its heading, experiment, name for saved files, and rows. */
export interface Side {
  label: string;
  text: string;
  name: string;
  rows: string[];
}

/** Draws `a` and `b` into `root`, figure by figure; throws what the core says of a figure it cannot draw. */
export function renderComparison(root: HTMLElement, a: Side, b: Side) {
  const left = el('div');
  const right = el('div');
  const figuresA = renderPlots(left, a.text, a.name, a.rows);
  const figuresB = renderPlots(right, b.text, b.name, b.rows);
  // Where the pair no longer fits side by side it stacks, A above B: each figure's heading says its side.
  const mark = (side: string, figures: Element) => {
    for (const figure of figures.querySelectorAll('figure')) {
      const h = figure.querySelector('h3');
      if (!h) continue;
      const heading = h.textContent ?? '';
      h.textContent = `${side} · ${heading}`;
      // Its buttons name the side too: "Save SVG of “B · Total steps”".
      for (const b of figure.querySelectorAll('button[aria-label]'))
        b.setAttribute('aria-label', (b.getAttribute('aria-label') ?? '').replace(`“${heading}”`, `“${side} · ${heading}”`));
    }
    return [...figures.children];
  };
  const lefts = mark('A', left);
  const rights = mark('B', right);
  const grid = el('div', { class: 'compare-grid' });
  grid.append(el('p', { class: 'compare-side', text: `A · ${a.label}` }), el('p', { class: 'compare-side', text: `B · ${b.label}` }));
  const missing = () => el('p', { class: 'hint', text: 'No such figure in this sweep.' });
  for (let i = 0; i < Math.max(lefts.length, rights.length); i++) grid.append(lefts[i] ?? missing(), rights[i] ?? missing());
  const joined = figuresA.flatMap((f, i) => (f.kind === 'summary' && figuresB[i]?.kind === 'summary' ? [joinedTable(f, figuresB[i], i + 1)] : []));
  root.replaceChildren(...joined, grid);
}

const key = (r: SummaryRow) => JSON.stringify([r.condition, r.value]);
const cells = (r: SummaryRow | undefined) => {
  const s = r?.stats;
  return s ? [String(s.n), formatNumber(s.mean), `${formatNumber(s.ci95[0])}–${formatNumber(s.ci95[1])}`] : [r ? '0' : '–', '–', '–'];
};

/**
 * Summary `index` of the two sweeps in one table: per condition and value, A's n, mean and 95%
 * interval of the mean beside B's, so the same condition's numbers stand next to each other.
 * Nothing is computed here: each number is the one its own summary shows.
 */
function joinedTable(fa: Figure, fb: Figure, index: number): HTMLElement {
  const byKey = new Map(fb.table.map((r) => [key(r), r]));
  const rows = [...fa.table, ...fb.table.filter((r) => !fa.table.some((x) => key(x) === key(r)))];
  const names = conditionNames(fa);
  const heading = fa.title || `Figure ${index}`;
  const table = el('table', { class: 'summary' });
  table.append(el('caption', { text: `${heading}, A beside B: n, mean and 95% confidence interval of the mean per condition` }));
  const head = el('tr');
  for (const h of [...names, 'value', 'A n', 'A mean', 'A 95% CI', 'B n', 'B mean', 'B 95% CI'])
    head.append(el('th', { scope: 'col', class: h.startsWith('A ') || h.startsWith('B ') ? 'num' : '', text: h }));
  const body = el('tbody');
  for (const r of rows) {
    const inA = fa.table.find((x) => key(x) === key(r));
    const inB = byKey.get(key(r));
    const conditions = names.length === r.condition.length ? r.condition : [r.condition.join(', ')];
    const text = [...conditions, r.unit ? `${words(r.value)} [${r.unit}]` : words(r.value), ...cells(inA), ...cells(inB)];
    body.append(el('tr', {}, ...text.map((c, i) => el('td', { class: i > conditions.length ? 'num' : '', text: c }))));
  }
  table.append(el('thead', {}, head), body);
  return el('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-label': `${heading}: the two sweeps' statistics side by side` }, table);
}
