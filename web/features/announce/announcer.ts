// The run described for screen readers, in a polite live region. While the run plays, its progress
// is said at most once every CALM_MS; its end, the disturbances it meets (scheduled or clicked),
// the exercise's verdict and the keyboard cursor are said at once. Messages that come together
// are said together, so a completion is not cut off by the verdict that follows it.
import type { Frame } from '../../contract.gen';
import { formatNumber } from '../../widgets/dom';

/** The least time between two progress messages while the run plays. */
export const CALM_MS = 5000;
/** Immediate messages this close together are joined into one. */
const JOIN_MS = 800;

export interface Disturbance {
  at: number;
  kind: string;
  [key: string]: unknown;
}

export class Announcer {
  private lastProgress = 0;
  private lastImmediate = -Infinity;
  private finished = false;
  private lastStep = 0;
  /** The scenario's name when it was last loaded. */
  private name: string | null = null;
  private disturbances: Disturbance[] = [];
  /** The disturbances already said, so passing one again after going back stays quiet. */
  private said = new Set<string>();

  constructor(private readonly region: HTMLElement) {}

  /**
   * A run (re)started from `disturbances`: nothing has been said about it yet. Only what changed
   * is said: a scenario of another name is named; the same one, reset or edited, is said only when
   * it moved the run back to step 0 (an edit at step 0 changes nothing a listener hears).
   */
  loaded(name: string, disturbances: Disturbance[]) {
    const before = this.lastStep;
    const renamed = name !== this.name;
    this.name = name;
    this.disturbances = disturbances;
    this.said.clear();
    this.finished = false;
    this.lastStep = 0;
    this.lastProgress = performance.now();
    if (renamed) this.say(`${name} opened.`);
    else if (before > 0) this.say('Back to step 0.');
  }

  /** The scenario's disturbances changed (a click recorded one): say the new one. */
  disturbed(disturbances: Disturbance[], cellText: (cell: number) => string) {
    const added = disturbances.filter((d) => !this.disturbances.some((o) => JSON.stringify(o) === JSON.stringify(d)));
    this.disturbances = disturbances;
    for (const d of added) this.sayDisturbance(d, cellText);
  }

  private sayDisturbance(d: Disturbance, cellText: (cell: number) => string) {
    const key = JSON.stringify(d);
    if (this.said.has(key)) return;
    this.said.add(key);
    this.say(`Step ${formatNumber(d.at)}: ${describe(d, cellText)}.`);
  }

  /** A frame arrived: say what it passed (disturbances, the end) at once, its progress calmly. */
  frame(frame: Frame, playing: boolean, metric: string, cellText: (cell: number) => string) {
    const from = this.lastStep;
    this.lastStep = frame.steps;
    if (frame.steps > from) {
      for (const d of this.disturbances) if (d.at >= from && d.at < frame.steps) this.sayDisturbance(d, cellText);
    }
    if (frame.finished && !this.finished) {
      this.finished = true;
      const steps = formatNumber(frame.steps);
      this.say(frame.completed ? `Completed in ${steps} steps.` : `Stopped at the step limit, ${steps} steps, not completed.`);
      return;
    }
    if (!frame.finished) this.finished = false;
    const now = performance.now();
    if (!playing || now - this.lastProgress < CALM_MS || now - this.lastImmediate < CALM_MS) return;
    this.lastProgress = now;
    const value = frame.metrics[metric];
    const tail = metric && value !== undefined ? `, ${metric.replace(/_/g, ' ')} ${formatNumber(value)}` : '';
    this.replace(`Running: step ${formatNumber(frame.steps)}${tail}.`);
  }

  /** Says something now (joined to what was said just before). */
  say(text: string) {
    const now = performance.now();
    const current = this.region.textContent ?? '';
    this.region.textContent = now - this.lastImmediate < JOIN_MS && current ? `${current} ${text}` : text;
    this.lastImmediate = now;
  }

  private replace(text: string) {
    this.region.textContent = text;
  }
}

/** A disturbance in words: its kind, its other settings, and the cells it was clicked on. */
function describe(d: Disturbance, cellText: (cell: number) => string): string {
  const parts: string[] = [];
  for (const [k, v] of Object.entries(d)) {
    if (k === 'at' || k === 'kind') continue;
    if (k === 'cells' && Array.isArray(v)) parts.push(`at ${v.map((c) => cellText(Number(c))).join(', ')}`);
    else parts.push(`${k.replace(/_/g, ' ')} ${typeof v === 'object' ? JSON.stringify(v) : String(v)}`);
  }
  return [d.kind.replace(/_/g, ' '), ...parts].join(', ');
}
