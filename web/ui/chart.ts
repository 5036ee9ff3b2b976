// A live chart of one metric against step, drawn with uPlot. The worker records every step's
// metrics (kumiki_core::series) and sends the charted one merged into about one point per pixel:
// per point, the least and greatest value over its steps, drawn as a band, so a one-step dip
// still shows however fast the run went.
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import type { ChartBand } from '../types';

const COLOR = '#2b6cb0';

export class MetricChart {
  private plot: uPlot | null = null;
  private band: ChartBand | null = null;
  private label = '';
  private dirty = false;

  constructor(private readonly root: HTMLElement) {
    new ResizeObserver(() => this.resize()).observe(root);
  }

  /** Points worth asking the worker for: about one per pixel of the plot. */
  get points(): number {
    return Math.max(100, Math.round(this.root.clientWidth || 400));
  }

  reset(label: string) {
    this.label = label;
    this.band = null;
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
  }

  render() {
    if (!this.dirty || !this.root.isConnected || this.root.offsetParent === null) return;
    this.dirty = false;
    const b = this.band;
    const data: uPlot.AlignedData = b ? [Array.from(b.steps), Array.from(b.max), Array.from(b.min)] : [[], [], []];
    if (!this.plot) {
      const options: uPlot.Options = {
        width: Math.max(200, this.root.clientWidth),
        height: 150,
        legend: { show: false },
        cursor: { drag: { x: false, y: false } },
        scales: { x: { time: false } },
        axes: [{ label: 'step', size: 36 }, { size: 56 }],
        series: [{}, { label: `${this.label} (greatest)`, stroke: COLOR, width: 2 }, { label: `${this.label} (least)`, stroke: COLOR, width: 2 }],
        bands: [{ series: [1, 2], fill: 'rgba(43, 108, 176, 0.3)' }],
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
