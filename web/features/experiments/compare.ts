// Two sweeps side by side: each figure of the sweep in view beside the same figure of a saved one
// (a summary's table beside the other's, a plot beside the other's), one pair a row, so a
// researcher reads the same condition's n, mean and interval across the two at one glance. Each
// figure keeps its own axes, as each sweep's export draws it; the pair's headings say which is which.
import { el } from '../../widgets/dom';
import { renderPlots } from './plots';

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
  renderPlots(left, a.text, a.name, a.rows);
  renderPlots(right, b.text, b.name, b.rows);
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
  root.replaceChildren(grid);
}
