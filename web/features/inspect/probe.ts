// Asks the simulation worker about the cell under the pointer without flooding it: one question at
// a time, at most one every `gapMs`, and only the newest cell is asked about once the last answer is
// in. Pacing only; nothing here reaches the simulation.

import type { Facts } from '../../contract.gen';

export class Probe {
  private busy = false;
  private want: number | null = null;
  private last = -Infinity;

  constructor(
    private readonly ask: (cell: number) => Promise<Facts>,
    private readonly answer: (cell: number, facts: Facts | null) => void,
    private readonly gapMs = 60,
  ) {}

  /** Asks about `cell` soon (a negative cell answers null at once, in turn). */
  request(cell: number) {
    this.want = cell;
    this.pump();
  }

  private pump() {
    if (this.busy || this.want === null) return;
    const cell = this.want;
    this.want = null;
    if (cell < 0) {
      this.answer(cell, null);
      return;
    }
    this.busy = true;
    const wait = Math.max(0, this.last + this.gapMs - performance.now());
    setTimeout(() => {
      this.last = performance.now();
      // A worker restarted after a panic never answers: give up after a second.
      const timeout = new Promise<null>((resolve) => setTimeout(() => resolve(null), 1000));
      void Promise.race([this.ask(cell), timeout]).then((facts) => {
        this.busy = false;
        if (this.want === null || this.want === cell) this.answer(cell, facts);
        this.pump();
      });
    }, wait);
  }
}

/** Reachable cells and the difference at each, from a cubic model's inspector facts. */
export function reachOf(facts: Facts | null): { cells: number[]; values: number[] } | null {
  if (facts?.unit !== true || !Array.isArray(facts.reachable)) return null;
  const cells = facts.reachable.filter((x): x is number => typeof x === 'number');
  const raw = Array.isArray(facts.reachable_differences) ? facts.reachable_differences : [];
  const values = cells.map((_, k) => (typeof raw[k] === 'number' ? (raw[k] as number) : NaN));
  return { cells, values };
}
