// A live line chart of one metric against step, drawn with uPlot.
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';

const MAX_POINTS = 4000;

export class MetricChart {
  private plot: uPlot | null = null;
  private xs: number[] = [];
  private ys: number[] = [];
  private label = '';
  private dirty = false;

  constructor(private readonly root: HTMLElement) {
    new ResizeObserver(() => this.resize()).observe(root);
  }

  reset(label: string) {
    this.label = label;
    this.xs = [];
    this.ys = [];
    this.plot?.destroy();
    this.plot = null;
    this.dirty = true;
  }

  push(step: number, value: number) {
    const last = this.xs.length - 1;
    if (last >= 0 && step <= this.xs[last]) {
      if (step === this.xs[last]) this.ys[last] = value;
      return;
    }
    this.xs.push(step);
    this.ys.push(value);
    if (this.xs.length > MAX_POINTS) {
      // Halve the resolution of the older half, keep the newest points.
      this.xs = this.xs.filter((_, i) => i % 2 === 0 || i > MAX_POINTS / 2);
      this.ys = this.ys.filter((_, i) => i % 2 === 0 || i > MAX_POINTS / 2);
    }
    this.dirty = true;
  }

  /** Forgets the points after `step`: the run forked there. */
  truncate(step: number) {
    const keep = this.xs.findIndex((x) => x > step);
    if (keep < 0) return;
    this.xs = this.xs.slice(0, keep);
    this.ys = this.ys.slice(0, keep);
    this.dirty = true;
  }

  render() {
    if (!this.dirty || !this.root.isConnected || this.root.offsetParent === null) return;
    this.dirty = false;
    const data: uPlot.AlignedData = [this.xs, this.ys];
    if (!this.plot) {
      this.plot = new uPlot(
        {
          width: Math.max(200, this.root.clientWidth),
          height: 150,
          legend: { show: false },
          cursor: { drag: { x: false, y: false } },
          scales: { x: { time: false } },
          axes: [{ label: 'step', size: 36 }, { size: 56 }],
          series: [{}, { label: this.label, stroke: '#2b6cb0', width: 2 }],
        },
        data,
        this.root,
      );
    } else {
      this.plot.setData(data);
    }
  }

  private resize() {
    if (this.plot) this.plot.setSize({ width: Math.max(200, this.root.clientWidth), height: 150 });
  }
}
