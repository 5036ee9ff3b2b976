// Draws an experiment's plots: the core computes each figure from the rows and draws it as SVG
// (crate/core/src/plot), the same figure `kumiki sweep --plot svg` writes; the page shows it,
// writes a summary as a table with its tests, and saves each figure as SVG, PNG (twice the size)
// or PDF (the core's own layout, `kumiki sweep --plot pdf`).
import type { Figure } from '../../contract.gen';
import { experimentFigurePdf, experimentFigures } from '../../lab';
import { clear, download, el, figureFileName, formatNumber } from '../../widgets/dom';

/** The SVG as a PNG of twice its size, drawn on a white background. */
export async function svgToPng(svg: string): Promise<Blob> {
  const url = URL.createObjectURL(new Blob([svg], { type: 'image/svg+xml' }));
  try {
    const img = new Image();
    img.src = url;
    await img.decode();
    const canvas = document.createElement('canvas');
    canvas.width = img.naturalWidth * 2;
    canvas.height = img.naturalHeight * 2;
    const ctx = canvas.getContext('2d')!;
    ctx.fillStyle = '#ffffff';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    ctx.scale(2, 2);
    ctx.drawImage(img, 0, 0);
    return await new Promise<Blob>((resolve, reject) => canvas.toBlob((b) => (b ? resolve(b) : reject(new Error('no PNG'))), 'image/png'));
  } finally {
    URL.revokeObjectURL(url);
  }
}

/** A value's path in words: "metrics.total_steps" as "total steps". */
export const words = (path: string) => path.replace(/^(params|metrics)\./, '').replace(/[_.]/g, ' ');

/**
 * The names of a summary's condition columns: the figure's axis label names its `group` paths,
 * one a column ("scenario, tip load, adaptation"); one "condition" column if they do not match.
 */
export function conditionNames(f: Figure): string[] {
  const width = f.table[0]?.condition.length ?? 1;
  const names = f.x_label.split(', ');
  return names.length === width ? names : ['condition'];
}

function summaryTable(f: Figure): HTMLElement {
  const table = el('table', { class: 'summary' });
  const head = el('tr');
  const names = conditionNames(f);
  const text = [...names, 'value'];
  for (const h of [...text, 'n', 'mean', 'sd', 'median', 'IQR', '95% CI of the mean'])
    head.append(el('th', { scope: 'col', class: text.includes(h) ? '' : 'num', text: h }));
  table.append(el('caption', { text: f.described }), el('thead', {}, head));
  const body = el('tbody');
  for (const r of f.table) {
    const s = r.stats;
    const conditions = names.length === r.condition.length ? r.condition : [r.condition.join(', ')];
    const cells = [
      ...conditions,
      r.unit ? `${words(r.value)} [${r.unit}]` : words(r.value),
      s ? String(s.n) : '0',
      s ? formatNumber(s.mean) : '–',
      s ? formatNumber(s.sd) : '–',
      s ? formatNumber(s.median) : '–',
      s ? `${formatNumber(s.q1)}–${formatNumber(s.q3)}` : '–',
      s ? `${formatNumber(s.ci95[0])}–${formatNumber(s.ci95[1])}` : '–',
    ];
    body.append(el('tr', {}, ...cells.map((c, i) => el('td', { class: i > conditions.length ? 'num' : '', text: c }))));
  }
  table.append(body);
  const box = el('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-label': `${f.title || 'Summary'}: statistics per condition` }, table);
  if (f.omnibus.length) {
    const list = el('ul', { class: 'comparisons' });
    for (const o of f.omnibus) {
      const t = o.test;
      list.append(
        el('li', {
          text: `${words(o.value)}, ${o.conditions.length} conditions: Kruskal-Wallis H = ${formatNumber(t.h)}, df = ${t.df}, n = ${t.n}, p = ${formatNumber(t.p)}`,
        }),
      );
    }
    box.append(el('p', { class: 'hint', text: 'All conditions at once:' }), list);
  }
  if (f.comparisons.length) {
    const list = el('ul', { class: 'comparisons' });
    const corrected = f.comparisons.some((c) => c.p_holm !== undefined && c.p_holm !== null);
    for (const c of f.comparisons) {
      const k = c.comparison;
      const holm = c.p_holm === undefined || c.p_holm === null ? '' : `, Holm-corrected p = ${formatNumber(c.p_holm)}`;
      list.append(
        el('li', {
          text: `${words(c.value)}, ${c.conditions[0]} against ${c.conditions[1]}: difference of means ${formatNumber(k.difference)}, Cohen's d ${formatNumber(k.cohens_d)}, rank-biserial correlation ${formatNumber(k.rank_biserial)}, Mann-Whitney U = ${formatNumber(k.u)}, p = ${formatNumber(k.p)} (${k.method})${holm}`,
        }),
      );
    }
    const lead = corrected ? 'Each pair of conditions compared (p corrected for the number of pairs by Holm’s method).' : 'Two conditions compared.';
    box.append(el('p', { class: 'hint', text: `${lead} ${f.direction}` }), list);
  }
  return box;
}

/** Draws every figure of `experiment` (its JSON text or built-in name) from the rows' JSON texts; returns the figures drawn. */
export function renderPlots(root: HTMLElement, experiment: string, name: string, rowTexts: string[]): Figure[] {
  clear(root);
  const rowsJson = `[${rowTexts.join(',')}]`;
  const drawn = experimentFigures(experiment, rowsJson);
  drawn.forEach(({ figure, svg }, i) => {
    const box = el('figure', { class: 'plot', 'data-kind': figure.kind });
    const heading = figure.title || `Figure ${i + 1}`;
    box.append(el('h3', { text: heading }));
    if (figure.kind === 'summary') {
      box.append(summaryTable(figure));
    } else {
      const doc = new DOMParser().parseFromString(svg, 'image/svg+xml').documentElement;
      doc.setAttribute('aria-label', `${heading}: ${figure.described}`);
      doc.setAttribute('class', 'plot-svg');
      box.append(document.importNode(doc, true));
      box.append(el('figcaption', { class: 'hint', text: figure.described }));
    }
    const save = el('div', { class: 'row-buttons' });
    const asSvg = el('button', { type: 'button', text: 'Save SVG', 'aria-label': `Save SVG of “${heading}”` });
    const asPng = el('button', { type: 'button', text: 'Save PNG (2×)', 'aria-label': `Save PNG (2×) of “${heading}”, twice its size` });
    asSvg.addEventListener('click', () => download(figureFileName(name, i + 1, 'svg'), svg, 'image/svg+xml'));
    asPng.addEventListener('click', async () => download(figureFileName(name, i + 1, 'png'), await svgToPng(svg), 'image/png'));
    const asPdf = el('button', { type: 'button', text: 'Save PDF', 'aria-label': `Save PDF of “${heading}”` });
    asPdf.addEventListener('click', () => download(figureFileName(name, i + 1, 'pdf'), experimentFigurePdf(experiment, rowsJson, i), 'application/pdf'));
    save.append(asSvg, asPng, asPdf);
    box.append(save);
    root.append(box);
  });
  return drawn.map((d) => d.figure);
}
