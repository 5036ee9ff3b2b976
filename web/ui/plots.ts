// Draws experiment rows as the experiment's `plot` section asks (see docs/experiments.md):
// lines with spreads, traces over steps with bands, histograms, bars and summary tables.
import uPlot from 'uplot';
import type { Row } from '../types';
import { clear, el, formatNumber } from './dom';

type Spec = Record<string, unknown>;
const COLORS = ['#2b6cb0', '#d9822b', '#0f9960', '#c23030', '#7157d9', '#29a634', '#a67908', '#d13913', '#00998c', '#634dbf'];

/** A value of a row by path: `steps`, `params.robots`, `metrics.total_steps`. */
export function valueAt(row: Row, path: string): unknown {
  if (path.startsWith('params.')) return row.params[path.slice(7)];
  if (path.startsWith('metrics.')) return row.metrics[path.slice(8)];
  return (row as unknown as Record<string, unknown>)[path];
}

const num = (v: unknown): number => (typeof v === 'number' ? v : typeof v === 'boolean' ? Number(v) : NaN);
const key = (v: unknown): string => (typeof v === 'string' ? v : JSON.stringify(v));
const str = (s: Spec, k: string, d = ''): string => (typeof s[k] === 'string' ? (s[k] as string) : d);
const short = (path: string) => path.replace(/^(params|metrics)\./, '');

function groupBy<T>(items: T[], f: (t: T) => string): Map<string, T[]> {
  const m = new Map<string, T[]>();
  for (const it of items) {
    const k = f(it);
    const list = m.get(k);
    if (list) list.push(it);
    else m.set(k, [it]);
  }
  return m;
}

/** Count, mean, sample sd, extremes and quartiles of the finite values. */
export function stats(values: number[]) {
  const v = values.filter((x) => Number.isFinite(x)).sort((a, b) => a - b);
  const n = v.length;
  if (!n) return { n, mean: NaN, min: NaN, max: NaN, sd: NaN, q1: NaN, median: NaN, q3: NaN };
  const mean = v.reduce((a, b) => a + b, 0) / n;
  const sd = Math.sqrt(v.reduce((a, b) => a + (b - mean) ** 2, 0) / Math.max(1, n - 1));
  // Linear interpolation between order statistics, as the reproduction report computes them.
  const q = (p: number) => {
    const pos = p * (n - 1);
    const lo = Math.floor(pos);
    const hi = Math.ceil(pos);
    return v[lo] + (v[hi] - v[lo]) * (pos - lo);
  };
  return { n, mean, min: v[0], max: v[n - 1], sd, q1: q(0.25), median: q(0.5), q3: q(0.75) };
}

/** The band a plot draws around a mean: `minmax`, `sd`, `quartiles`, or none. */
export function spreadOf(s: ReturnType<typeof stats>, spread: string): [number, number] | null {
  if (spread === 'minmax') return [s.min, s.max];
  if (spread === 'sd') return [s.mean - s.sd, s.mean + s.sd];
  if (spread === 'quartiles') return [s.q1, s.q3];
  return null;
}

export function renderPlots(root: HTMLElement, plot: unknown, rows: Row[]) {
  clear(root);
  const specs = (Array.isArray(plot) ? plot : plot ? [plot] : []) as Spec[];
  if (!specs.length) specs.push({ kind: 'summary', group: ['scenario'], values: ['steps'] });
  for (const spec of specs) {
    const box = el('figure', { class: 'plot' });
    root.append(box);
    const title = str(spec, 'title');
    if (title) box.append(el('h3', { text: title }));
    switch (spec.kind) {
      case 'lines':
        facets(box, spec, rows, (panel, part) => lines(panel, spec, part));
        break;
      case 'trace':
        facets(box, spec, rows, (panel, part) => trace(panel, spec, part));
        break;
      case 'histogram':
        histogram(box, spec, rows);
        break;
      case 'bars':
        facets(box, spec, rows, (panel, part) => bars(panel, spec, part));
        break;
      default:
        summary(box, spec, rows);
    }
  }
}

function facets(box: HTMLElement, spec: Spec, rows: Row[], draw: (panel: HTMLElement, rows: Row[]) => void) {
  const facet = str(spec, 'facet');
  if (!facet) return draw(box, rows);
  for (const [k, part] of groupBy(rows, (r) => key(valueAt(r, facet)))) {
    box.append(el('p', { class: 'facet-title', text: `${short(facet)} = ${k}` }));
    const panel = el('div');
    box.append(panel);
    draw(panel, part);
  }
}

interface Line {
  label: string;
  ys: number[];
  band: [number[], number[]] | null;
}

function chart(panel: HTMLElement, xs: number[], lines: Line[], spec: Spec, xLabel: string, yLabel: string, opts: Partial<uPlot.Options> = {}) {
  const series: uPlot.Series[] = [{ label: xLabel }];
  const data: (number | null)[][] = [xs];
  const bands: uPlot.Band[] = [];
  lines.forEach((line, i) => {
    const color = COLORS[i % COLORS.length];
    const idx = data.length;
    series.push({ label: line.label, stroke: color, width: 2, points: { show: xs.length < 40 } });
    data.push(line.ys.map((y) => (Number.isFinite(y) ? y : null)));
    if (line.band) {
      series.push({ label: `${line.label} (low)`, stroke: `${color}55`, width: 1, points: { show: false } });
      series.push({ label: `${line.label} (high)`, stroke: `${color}55`, width: 1, points: { show: false } });
      data.push(line.band[0].map((y) => (Number.isFinite(y) ? y : null)));
      data.push(line.band[1].map((y) => (Number.isFinite(y) ? y : null)));
      bands.push({ series: [idx + 2, idx + 1], fill: `${color}22` });
    }
  });
  const width = Math.max(260, panel.clientWidth || panel.parentElement?.clientWidth || 340);
  new uPlot(
    {
      width,
      height: 260,
      legend: { show: false },
      scales: { x: { time: false }, y: spec.log_y ? { distr: 3 } : {} },
      axes: [{ label: str(spec, 'x_label', xLabel) }, { label: str(spec, 'y_label', yLabel), size: 64 }],
      series,
      bands,
      ...opts,
    },
    data as uPlot.AlignedData,
    panel,
  );
  if (lines.length > 1 || lines[0]?.band) legendOf(panel, lines.map((l, i) => [l.label, COLORS[i % COLORS.length]]), lines.some((l) => l.band) ? spreadName(str(spec, 'spread', 'sd')) : '');
}

function spreadName(spread: string): string {
  return spread === 'minmax' ? 'bands: min to max' : spread === 'quartiles' ? 'bands: quartiles' : spread === 'sd' ? 'bands: ± one standard deviation' : '';
}

/** A compact legend: one swatch per line, and what the bands show. */
function legendOf(panel: HTMLElement, entries: [string, string][], note = '') {
  const legend = el('div', { class: 'legend' });
  for (const [label, color] of entries) {
    const swatch = el('i');
    swatch.style.background = color;
    legend.append(el('span', {}, swatch, label));
  }
  if (note) legend.append(el('span', { class: 'hint', text: note }));
  panel.append(legend);
}

function lines(panel: HTMLElement, spec: Spec, rows: Row[]) {
  const x = str(spec, 'x', 'seed');
  const ys = (Array.isArray(spec.y) ? spec.y : [spec.y ?? 'steps']) as string[];
  const seriesPath = str(spec, 'series');
  const spread = str(spec, 'spread', 'minmax');
  const xs = [...new Set(rows.map((r) => num(valueAt(r, x))).filter(Number.isFinite))].sort((a, b) => a - b);
  const out: Line[] = [];
  const groups = seriesPath ? groupBy(rows, (r) => key(valueAt(r, seriesPath))) : new Map([['', rows]]);
  for (const y of ys) {
    const first = out.length;
    for (const [s, part] of groups) {
      const byX = groupBy(part, (r) => String(num(valueAt(r, x))));
      const st = xs.map((xv) => stats((byX.get(String(xv)) ?? []).map((r) => num(valueAt(r, y)))));
      const spreads = st.map((s2) => spreadOf(s2, spread));
      out.push({
        label: [ys.length > 1 ? short(y) : '', s].filter(Boolean).join(' · ') || short(y),
        ys: st.map((s2) => s2.mean),
        band: spread !== 'none' && spreads.every(Boolean) ? [spreads.map((b) => b![0]), spreads.map((b) => b![1])] : null,
      });
    }
    // A quantity that does not depend on the series (a bound, say) is one line, not several
    // drawn on top of each other.
    const mine = out.slice(first);
    if (mine.length > 1 && mine.every((l) => sameValues(l, mine[0]))) out.splice(first, mine.length, { ...mine[0], label: short(y), band: null });
  }
  chart(panel, xs, out, spec, short(x), ys.length === 1 ? short(ys[0]) : 'value');
}

function sameValues(a: Line, b: Line): boolean {
  const same = (p: number[], q: number[]) => p.length === q.length && p.every((v, i) => v === q[i] || (Number.isNaN(v) && Number.isNaN(q[i])));
  return same(a.ys, b.ys) && (!a.band || !b.band || (same(a.band[0], b.band[0]) && same(a.band[1], b.band[1])));
}

function trace(panel: HTMLElement, spec: Spec, rows: Row[]) {
  const y = str(spec, 'y');
  const seriesPath = str(spec, 'series');
  const spread = str(spec, 'spread', 'sd');
  const carry = str(spec, 'carry', 'last') === 'last';
  const traced = rows.filter((r) => r.trace?.values[y]);
  if (!traced.length) {
    panel.append(el('p', { class: 'hint', text: `No runs traced '${y}'.` }));
    return;
  }
  let steps = [...new Set(traced.flatMap((r) => r.trace!.step))].sort((a, b) => a - b);
  if (steps.length > 1500) {
    const every = Math.ceil(steps.length / 1500);
    steps = steps.filter((_, i) => i % every === 0 || i === steps.length - 1);
  }
  const groups = seriesPath ? groupBy(traced, (r) => key(valueAt(r, seriesPath))) : new Map([['', traced]]);
  const out: Line[] = [];
  for (const [s, part] of groups) {
    // Each run's value at every plotted step: its last sample at or before the step.
    const cols = part.map((r) => {
      const st = r.trace!.step;
      const vs = r.trace!.values[y];
      const res = new Array<number>(steps.length);
      let j = 0;
      for (let k = 0; k < steps.length; k++) {
        while (j + 1 < st.length && st[j + 1] <= steps[k]) j++;
        const beyond = steps[k] > st[st.length - 1];
        res[k] = st[j] <= steps[k] && (carry || !beyond) ? num(vs[j]) : NaN;
      }
      return res;
    });
    const st = steps.map((_, k) => stats(cols.map((c) => c[k])));
    const spreads = st.map((s2) => spreadOf(s2, spread));
    out.push({
      label: s || y,
      ys: st.map((s2) => s2.mean),
      band: spread !== 'none' ? [spreads.map((b) => b?.[0] ?? NaN), spreads.map((b) => b?.[1] ?? NaN)] : null,
    });
  }
  chart(panel, steps, out, spec, 'step', y);
}

function histogram(box: HTMLElement, spec: Spec, rows: Row[]) {
  const path = str(spec, 'value', 'steps');
  const seriesPath = str(spec, 'series');
  const bins = Math.max(2, Math.min(200, Number(spec.bins ?? 20)));
  const use = spec.where === 'completed' ? rows.filter((r) => r.completed) : rows;
  const groups = seriesPath ? groupBy(use, (r) => key(valueAt(r, seriesPath))) : new Map([['', use]]);
  for (const [s, part] of groups) {
    const values = part.map((r) => num(valueAt(r, path))).filter(Number.isFinite);
    if (s) box.append(el('p', { class: 'facet-title', text: `${short(seriesPath)} = ${s}` }));
    const panel = el('div');
    box.append(panel);
    if (!values.length) {
      panel.append(el('p', { class: 'hint', text: 'No values to count.' }));
      continue;
    }
    const lo = Math.min(...values);
    const hi = Math.max(...values);
    const width = hi > lo ? (hi - lo) / bins : 1;
    const counts = new Array<number>(bins).fill(0);
    for (const v of values) counts[Math.min(bins - 1, Math.floor((v - lo) / width))]++;
    const xs = counts.map((_, i) => lo + (i + 0.5) * width);
    const st = stats(values);
    panel.append(el('p', { class: 'hint', text: `n = ${st.n}, mean ${formatNumber(st.mean)}, median ${formatNumber(st.median)}, min ${formatNumber(st.min)}, max ${formatNumber(st.max)}` }));
    chart(panel, xs, [{ label: 'runs', ys: counts, band: null }], spec, short(path), 'runs', {
      series: [{ label: short(path) }, { label: 'runs', fill: `${COLORS[0]}99`, stroke: COLORS[0], paths: uPlot.paths.bars!({ size: [0.95, 100] }), points: { show: false } }],
    });
  }
}

function bars(panel: HTMLElement, spec: Spec, rows: Row[]) {
  const x = str(spec, 'x', 'scenario');
  const y = str(spec, 'y', 'steps');
  const seriesPath = str(spec, 'series');
  const spread = str(spec, 'spread', 'minmax');
  const cats = [...new Set(rows.map((r) => key(valueAt(r, x))))];
  const groups = [...(seriesPath ? groupBy(rows, (r) => key(valueAt(r, seriesPath))) : new Map([['', rows]]))];
  const table = groups.map(([, part]) => {
    const byCat = groupBy(part, (r) => key(valueAt(r, x)));
    return cats.map((c) => stats((byCat.get(c) ?? []).map((r) => num(valueAt(r, y)))));
  });
  const top = Math.max(1e-9, ...table.flat().map((s2) => (spread === 'none' ? s2.mean : spreadOf(s2, spread)?.[1] ?? s2.mean)).filter(Number.isFinite));
  const width = Math.max(260, panel.clientWidth || panel.parentElement?.clientWidth || 340);
  const height = 240;
  const dpr = Math.min(2, window.devicePixelRatio || 1);
  const canvas = el('canvas', { width: width * dpr, height: height * dpr, role: 'img', 'aria-label': `${short(y)} by ${short(x)}` });
  canvas.style.width = `${width}px`;
  canvas.style.height = `${height}px`;
  panel.append(canvas);
  const ctx = canvas.getContext('2d')!;
  ctx.scale(dpr, dpr);
  const left = 56;
  const bottom = 36;
  const plotW = width - left - 8;
  const plotH = height - bottom - 10;
  ctx.font = '11px system-ui, sans-serif';
  ctx.fillStyle = '#52606d';
  ctx.strokeStyle = '#d9e2ec';
  for (let t = 0; t <= 4; t++) {
    const v = (top * t) / 4;
    const yy = 10 + plotH - (plotH * t) / 4;
    ctx.beginPath();
    ctx.moveTo(left, yy);
    ctx.lineTo(left + plotW, yy);
    ctx.stroke();
    ctx.textAlign = 'right';
    ctx.fillText(formatNumber(v), left - 4, yy + 4);
  }
  const slot = plotW / Math.max(1, cats.length);
  const barW = (slot * 0.8) / Math.max(1, groups.length);
  cats.forEach((c, ci) => {
    ctx.fillStyle = '#52606d';
    ctx.textAlign = 'center';
    ctx.fillText(c.length > 14 ? `${c.slice(0, 13)}…` : c, left + slot * (ci + 0.5), height - bottom + 14);
    groups.forEach((_, gi) => {
      const s2 = table[gi][ci];
      if (!Number.isFinite(s2.mean)) return;
      const x0 = left + slot * ci + slot * 0.1 + barW * gi;
      const h = (plotH * s2.mean) / top;
      ctx.fillStyle = COLORS[gi % COLORS.length];
      ctx.fillRect(x0, 10 + plotH - h, barW * 0.92, h);
      const b = spread === 'none' ? null : spreadOf(s2, spread);
      if (b) {
        ctx.strokeStyle = '#1f2933';
        const mid = x0 + barW * 0.46;
        ctx.beginPath();
        ctx.moveTo(mid, 10 + plotH - (plotH * b[0]) / top);
        ctx.lineTo(mid, 10 + plotH - (plotH * b[1]) / top);
        ctx.stroke();
      }
    });
  });
  ctx.fillStyle = '#52606d';
  ctx.textAlign = 'center';
  ctx.fillText(str(spec, 'x_label', short(x)), left + plotW / 2, height - 4);
  if (groups.length > 1 || groups[0][0]) legendOf(panel, groups.map(([name], gi) => [name || short(y), COLORS[gi % COLORS.length]]), spread === 'none' ? '' : spreadName(spread).replace('bands', 'whiskers'));
}

function summary(box: HTMLElement, spec: Spec, rows: Row[]) {
  const group = (Array.isArray(spec.group) ? spec.group : ['scenario']) as string[];
  const values = (Array.isArray(spec.values) ? spec.values : ['steps']) as string[];
  const table = el('table');
  const head = el('tr');
  for (const g of group) head.append(el('th', { text: short(g) }));
  head.append(el('th', { text: 'runs' }), el('th', { text: 'completed' }));
  for (const v of values) head.append(el('th', { text: `${short(v)} mean (min–max)` }));
  table.append(el('thead', {}, head));
  const body = el('tbody');
  for (const part of groupBy(rows, (r) => group.map((g) => key(valueAt(r, g))).join('\u0000')).values()) {
    const tr = el('tr');
    for (const g of group) tr.append(el('td', { text: key(valueAt(part[0], g)) }));
    const done = part.filter((r) => r.completed).length;
    tr.append(el('td', { text: String(part.length) }), el('td', { text: `${done} (${((100 * done) / part.length).toFixed(1)}%)` }));
    for (const v of values) {
      const s = stats(part.map((r) => num(valueAt(r, v))));
      tr.append(el('td', { text: s.n ? `${formatNumber(s.mean)} (${formatNumber(s.min)}–${formatNumber(s.max)})` : '–' }));
    }
    body.append(tr);
  }
  table.append(body);
  box.append(el('div', { class: 'table-scroll', tabindex: 0, role: 'region', 'aria-label': 'Summary table' }, table));
}
