// A live chart of one metric against step, drawn with uPlot. The worker records every step's
// metrics (kumiki_core::series) and sends the charted one merged into about one point per pixel:
// per point, the least and greatest value over its steps, drawn as a band, so a one-step dip
// still shows however fast the run went. Comparing two runs (web/features/compare/), it draws the
// second run's band beside the first's, each named in words in the legend under it. uPlot (code
// and style) is fetched in the first idle moment after the first chart is asked for (the first
// frame): not part of the page's first load, and not competing with it.
import type uPlot from 'uplot';
import type { ChartBand } from '../contract.gen';
import { whenIdle } from './idle';

type UPlot = typeof uPlot;
/** The longest uPlot waits, after the first chart is asked for, for an idle moment. */
const UPLOT_MS = 500;
/** uPlot once fetched; `loading` while it is being fetched. */
let UPlotClass: UPlot | null = null;
let loading: Promise<unknown> | null = null;

/** uPlot, or null while it is still arriving (then `loading` resolves when it has). */
function loadedUPlot(): UPlot | null {
  loading ??= new Promise<void>((idle) => whenIdle(idle, UPLOT_MS))
    .then(() => Promise.all([import('uplot'), import('uplot/dist/uPlot.min.css')]))
    .then(([m]) => {
      UPlotClass = m.default;
    });
  return UPlotClass;
}

const COLOR = '#2b6cb0';
/** The second run of a comparison; its name in the legend says which is which, not the colour alone. */
const SECOND_COLOR = '#c05621';

/** The two runs' names in words, the first run's first. */
export type RunLabels = [string, string];

export class MetricChart {
  private plot: uPlot | null = null;
  private band: ChartBand | null = null;
  private second: ChartBand | null = null;
  private runs: RunLabels | null = null;
  private label = '';
  private dirty = false;
  /** A render is asked for once uPlot has arrived. */
  private awaitingUPlot = false;

  /** `legend` names the two runs' series while comparing. */
  constructor(
    private readonly root: HTMLElement,
    private readonly legend: HTMLElement,
  ) {
    new ResizeObserver(() => this.resize()).observe(root);
  }

  /** Points worth asking the worker for: about one per pixel of the plot. */
  get points(): number {
    return Math.max(100, Math.round(this.root.clientWidth || 400));
  }

  reset(label: string) {
    this.label = label;
    this.band = null;
    this.second = null;
    this.plot?.destroy();
    this.plot = null;
    this.dirty = true;
    this.describe();
  }

  /** The recorded band of the charted metric, as the worker sent it. */
  set(band: ChartBand) {
    if (band.metric !== this.label) return;
    this.band = band;
    this.dirty = true;
    this.describe();
  }

  /**
   * Compares two runs (`runs` names them, the first run's first) or, with null, charts one again.
   * The second run's band comes with `setSecond`.
   */
  compare(runs: RunLabels | null) {
    if (JSON.stringify(runs) === JSON.stringify(this.runs)) return;
    this.runs = runs;
    this.second = null;
    this.plot?.destroy();
    this.plot = null;
    this.dirty = true;
    this.legend.hidden = !runs;
    this.legend.replaceChildren(
      ...(runs ?? []).map((name, i) => {
        const swatch = document.createElement('i');
        swatch.style.background = i === 0 ? COLOR : SECOND_COLOR;
        const item = document.createElement('span');
        item.append(swatch, name);
        return item;
      }),
    );
    this.describe();
  }

  /** The second run's band of the charted metric. */
  setSecond(band: ChartBand) {
    if (!this.runs || band.metric !== this.label) return;
    this.second = band;
    this.dirty = true;
    this.describe();
  }

  /** What the chart holds, on the element: tests and assistive tools read it without the canvas. */
  private describe() {
    const d = this.root.dataset;
    const b = this.band;
    d.metric = this.label;
    d.points = String(b?.steps.length ?? 0);
    d.span = String(b?.span ?? 1);
    // Every frame brings a band: one pass over it, no copies.
    let low = Number.POSITIVE_INFINITY;
    let high = Number.NEGATIVE_INFINITY;
    for (const v of b?.min ?? []) if (Number.isFinite(v) && v < low) low = v;
    for (const v of b?.max ?? []) if (Number.isFinite(v) && v > high) high = v;
    d.min = Number.isFinite(low) ? String(low) : '';
    d.max = Number.isFinite(high) ? String(high) : '';
    const runs = this.runs;
    d.series = runs ? JSON.stringify(runs) : '';
    d.secondPoints = String(this.second?.steps.length ?? 0);
    this.root.setAttribute(
      'aria-label',
      runs ? `Chart of ${this.label.replace(/_/g, ' ')} over time for two runs: ${runs[0]} (blue) and ${runs[1]} (orange)` : 'Chart of the metric over time',
    );
  }

  render() {
    if (!this.dirty || !this.root.isConnected || this.root.offsetParent === null) return;
    const uPlot = loadedUPlot();
    if (!uPlot) {
      // Drawn once uPlot has arrived, with the band as it stands then.
      if (!this.awaitingUPlot) void loading?.then(() => this.render());
      this.awaitingUPlot = true;
      return;
    }
    this.dirty = false;
    const aligned = (b: ChartBand | null): uPlot.AlignedData => (b ? [Array.from(b.steps), Array.from(b.max), Array.from(b.min)] : [[], [], []]);
    const runs = this.runs;
    // Two runs record their steps apart: uPlot.join puts both on one step axis, each with gaps
    // where the other has a point.
    const data: uPlot.AlignedData = runs ? uPlot.join([aligned(this.band), aligned(this.second)]) : aligned(this.band);
    if (!this.plot) {
      const run = (name: string, color: string): uPlot.Series[] => [
        { label: `${name} (greatest)`, stroke: color, width: 2, spanGaps: true },
        { label: `${name} (least)`, stroke: color, width: 2, spanGaps: true },
      ];
      const options: uPlot.Options = {
        width: Math.max(200, this.root.clientWidth),
        height: 150,
        legend: { show: false },
        cursor: { drag: { x: false, y: false } },
        scales: { x: { time: false } },
        axes: [{ label: 'step', size: 36 }, { size: 56 }],
        series: runs ? [{}, ...run(`${this.label}, ${runs[0]}`, COLOR), ...run(`${this.label}, ${runs[1]}`, SECOND_COLOR)] : [{}, ...run(this.label, COLOR)],
        bands: runs
          ? [
              { series: [1, 2], fill: 'rgba(43, 108, 176, 0.3)' },
              { series: [3, 4], fill: 'rgba(192, 86, 33, 0.3)' },
            ]
          : [{ series: [1, 2], fill: 'rgba(43, 108, 176, 0.3)' }],
      };
      this.plot = drawnByCpu(() => new uPlot(options, data, this.root));
    } else {
      this.plot.setData(data);
    }
  }

  private resize() {
    if (this.plot) this.plot.setSize({ width: Math.max(200, this.root.clientWidth), height: 150 });
  }
}

/**
 * Runs `build` with every 2D context it asks for drawn by the CPU (`willReadFrequently`).
 *
 * Chromium draws a 2D canvas on the GPU by default, and holds the main thread whenever that canvas
 * gets ahead of the GPU process. With software WebGL the GPU process is busy presenting the
 * lattice view, and a redraw of this chart, which happens every frame while a run plays, blocked
 * the page for up to 300 ms. A chart this size draws in well under a millisecond on the CPU.
 * uPlot asks for its context inside its constructor, so the option is added only for that call.
 */
function drawnByCpu<T>(build: () => T): T {
  const proto = HTMLCanvasElement.prototype;
  const getContext = proto.getContext;
  proto.getContext = function (this: HTMLCanvasElement, type: string, options?: object) {
    return getContext.call(this, type, type === '2d' ? { ...options, willReadFrequently: true } : options);
  } as typeof getContext;
  try {
    return build();
  } finally {
    proto.getContext = getContext;
  }
}
