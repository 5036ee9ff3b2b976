// The Run tab's own sections: the metrics and the chart of each frame, the overlays, and the
// legend of the model in view. While two runs are compared (the compare feature), the chart and
// each metric card show both.
import type { Frame, MetricInfo, Metrics } from '../../contract.gen';
import type { PageContext, RunLabels } from '../../page/context';
import { debugRequested } from '../../page/address';
import { MetricChart } from '../../widgets/chart';
import { byId, clear, el, formatNumber } from '../../widgets/dom';
import { keepTipsInside } from '../../widgets/tooltip';
import * as core from '../../wasm';
import legendHtml from './legend.html?raw';
import { arrangeMetrics, metricCard, metricText } from './cards';
import metricsHtml from './metrics.html?raw';
import overlayHtml from './overlay.html?raw';

/** Where the Run tab's sections go, among other features' (the exercise's is first). */
export const ORDER = { metrics: 20, legend: 25, overlay: 40 };

export function setupRunPanel(page: PageContext) {
  const { session, sim, view, prefs, tabs, events } = page;
  tabs.section('run', metricsHtml, ORDER.metrics);
  tabs.section('run', overlayHtml, ORDER.overlay);
  tabs.section('run', legendHtml, ORDER.legend);

  const chart = new MetricChart(byId('metric-chart'), byId('chart-legend'));
  /** The two runs' names while comparing. */
  let runs: RunLabels | null = null;
  const chartSelect = byId<HTMLSelectElement>('chart-metric');
  /** Charts `metric`: the worker sends its record of every step with each frame. */
  function chartMetric(metric: string) {
    chart.reset(metric);
    sim.setChart(metric || null, chart.points);
  }
  chartSelect.addEventListener('change', () => {
    prefs.chartMetric = chartSelect.value;
    page.persistPrefs();
    chartMetric(chartSelect.value);
  });

  function showFrame(frame: Frame) {
    renderMetrics(frame.metrics);
    if (frame.chart) chart.set(frame.chart);
    chart.render();
    const range = view.overlayRange;
    const colorbar = byId('colorbar');
    colorbar.hidden = !range;
    if (range) {
      byId('colorbar-min').textContent = formatNumber(range[0]);
      byId('colorbar-max').textContent = formatNumber(range[1]);
    }
  }

  /** The model's metric table (name, unit, meaning), from the core: the same one the CLI and the docs use. */
  function explanations(): Map<string, MetricInfo> {
    try {
      return new Map(core.metricTable(String(session.doc().model ?? '')).map((m) => [m.name, m]));
    } catch {
      return new Map();
    }
  }

  const keyBox = byId('metrics-key');
  keepTipsInside(byId('metrics'), '.metric', '.metric-about');
  const moreBox = byId('metrics-more');
  const metricNodes = new Map<string, HTMLElement>();
  /** While comparing, each card's second value: the second run's. */
  const secondNodes = new Map<string, HTMLElement>();
  /** What the model's table says of each metric shown. */
  const infos = new Map<string, MetricInfo | undefined>();
  /** The metrics shown and where: the model's key ones first, the rest a click away, its internal counters only with `?debug`. */
  function renderMetrics(metrics: Metrics) {
    const names = Object.keys(metrics);
    if (names.join() !== shownNames.join()) {
      shownNames = names;
      clear(keyBox);
      clear(moreBox);
      metricNodes.clear();
      secondNodes.clear();
      infos.clear();
      const { key, more } = arrangeMetrics(names, explanations(), debug);
      for (const [box, list] of [
        [keyBox, key],
        [moreBox, more],
      ] as const) {
        for (const { name, info } of list) {
          const card = metricCard(name, info, runs);
          box.append(card.node);
          metricNodes.set(name, card.value);
          infos.set(name, info);
          if (card.second) secondNodes.set(name, card.second);
        }
      }
      byId('more-metrics').hidden = more.length === 0;
      byId('more-metrics-summary').textContent = `More metrics (${more.length})`;
      const numeric = [...key, ...more].map((m) => m.name).filter((n) => typeof metrics[n] === 'number');
      clear(chartSelect);
      for (const n of numeric) chartSelect.append(el('option', { value: n, text: n.replace(/_/g, ' ') }));
      const layout = session.layout;
      const preferred = layout && numeric.includes(layout.chart) ? layout.chart : (numeric[0] ?? '');
      const want = numeric.includes(prefs.chartMetric) ? prefs.chartMetric : preferred;
      chartSelect.value = want;
      if (want !== prefs.chartMetric) {
        prefs.chartMetric = want;
        chartMetric(want);
      }
    }
    for (const [name, node] of metricNodes) node.textContent = metricText(metrics[name], infos.get(name));
  }
  /** The metrics the cards show, in order: built again when they change. */
  let shownNames: string[] = [];
  const debug = debugRequested();

  // ---- overlays and legend ----

  const overlay = byId<HTMLSelectElement>('overlay');
  const arrows = byId<HTMLInputElement>('arrows');
  const labels = byId<HTMLInputElement>('labels');
  overlay.addEventListener('change', () => {
    prefs.overlay = overlay.value;
    page.persistPrefs();
    sim.setOverlay(overlay.value || null);
  });
  arrows.checked = prefs.arrows;
  labels.checked = prefs.labels;
  view.marks.arrows = prefs.arrows;
  view.marks.labels = prefs.labels;
  arrows.addEventListener('change', () => {
    prefs.arrows = view.marks.arrows = arrows.checked;
    page.persistPrefs();
    view.request();
  });
  labels.addEventListener('change', () => {
    prefs.labels = view.marks.labels = labels.checked;
    page.persistPrefs();
    view.request();
  });

  const showGhost = byId<HTMLInputElement>('show-ghost');
  const showBonds = byId<HTMLInputElement>('show-bonds');
  showGhost.addEventListener('change', () => {
    view.marks.ghost = showGhost.checked;
    view.request();
  });
  showBonds.addEventListener('change', () => {
    view.marks.bonds = showBonds.checked;
    view.request();
  });

  function renderLayout() {
    const layout = session.layout;
    if (!layout) return;
    byId('view3d-options').hidden = !view.is3d;
    clear(overlay);
    overlay.append(el('option', { value: '', text: 'none' }));
    for (const f of layout.fields) overlay.append(el('option', { value: f.name, text: f.label }));
    overlay.value = layout.fields.some((f) => f.name === prefs.overlay) ? prefs.overlay : '';
    sim.setOverlay(overlay.value || null);

    const legend = byId('legend');
    clear(legend);
    const swatch = (color: string, round = false) => {
      const i = el('i', { class: round ? 'round' : '' });
      i.style.background = color;
      return i;
    };
    for (const c of layout.cells) {
      // A code the view marks in every view (a ring or a cross over its cells) shows the mark on its swatch.
      const i = swatch(c.color);
      if (c.mark) i.dataset.mark = c.mark;
      legend.append(el('span', {}, i, c.name));
    }
    for (const a of layout.agents) legend.append(el('span', {}, swatch(a.color, true), a.name));
    for (const e of layout.events) {
      const i = swatch('transparent', true);
      i.style.border = `2px solid ${e.color}`;
      legend.append(el('span', {}, i, e.name));
    }
  }

  session.on('loaded', () => {
    renderLayout();
    chartMetric(prefs.chartMetric);
  });
  session.on('frame', showFrame);
  // The chart's size may have changed with the tab.
  events.on('tab', () => chart.render());
  events.on('compare', (labels) => {
    if (JSON.stringify(labels) === JSON.stringify(runs)) return;
    runs = labels;
    chart.compare(labels);
    // The cards are built again, with or without the second value.
    shownNames = [];
    if (session.frame) renderMetrics(session.frame.metrics);
  });
  events.on('second-frame', (frame) => {
    for (const [name, node] of secondNodes) node.textContent = metricText(frame.metrics[name], infos.get(name));
    if (frame.chart) chart.setSecond(frame.chart);
    chart.render();
  });
}
