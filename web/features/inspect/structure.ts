// The last step in detail, for models whose inspector facts describe the whole structure as well
// as the cell asked about: `slots`, the step's signals slot by slot ([{meaning, count, signals:
// [cell, faces, ...]}], faces a mask of lattice directions), and `displacement`, each unit's
// displacement in cells ([cell, dx, dy, ...], y down). The panel stays hidden for models without
// them; while one of its views is on, the facts are asked again after every step.
import type { View } from '../../render/view';
import { byId } from '../../widgets/dom';

/** The facts about the whole structure, shown by this panel rather than by the cell inspector. */
export const STRUCTURE_FACTS = ['slots', 'displacement'];

interface Slot {
  meaning: string;
  count: number;
  signals: number[];
}

export class StructureViews {
  private slots: Slot[] = [];
  private displacement: number[] = [];
  private index = 0;
  private shownStep = -1;
  private latestStep = -1;
  private asking = false;
  private readonly slotView = byId<HTMLInputElement>('slot-view');
  private readonly range = byId<HTMLInputElement>('slot-range');
  private readonly deflection = byId<HTMLInputElement>('deflection-view');
  private readonly scale = byId<HTMLInputElement>('deflection-scale');

  constructor(
    private readonly view: View,
    private readonly inspect: (cell: number) => Promise<Record<string, unknown>>,
  ) {
    const refresh = () => {
      this.shownStep = -1;
      this.ask();
      this.draw();
    };
    this.slotView.addEventListener('change', refresh);
    this.deflection.addEventListener('change', refresh);
    this.scale.addEventListener('input', () => this.draw());
    this.range.addEventListener('input', () => this.go(Number(this.range.value)));
    byId('slot-prev').addEventListener('click', () => this.go(this.index - 1));
    byId('slot-next').addEventListener('click', () => this.go(this.index + 1));
  }

  /** A run loaded: shows the panel if the model describes its steps this way. */
  loaded() {
    this.slots = [];
    this.displacement = [];
    this.index = 0;
    this.shownStep = -1;
    byId('structure-views').hidden = true;
    this.draw();
    void this.inspect(0).then((facts) => {
      byId('structure-views').hidden = !Array.isArray(facts.slots) && !Array.isArray(facts.displacement);
      this.ask();
    });
  }

  /** A frame arrived after `steps` steps. */
  frame(steps: number) {
    this.latestStep = steps;
    this.ask();
  }

  private wanted(): boolean {
    return !byId('structure-views').hidden && (this.slotView.checked || this.deflection.checked);
  }

  private ask() {
    if (!this.wanted() || this.asking || this.latestStep === this.shownStep) return;
    const step = this.latestStep;
    this.asking = true;
    void this.inspect(0).then((facts) => {
      this.asking = false;
      this.shownStep = step;
      this.slots = Array.isArray(facts.slots) ? (facts.slots as Slot[]) : [];
      this.displacement = Array.isArray(facts.displacement) ? (facts.displacement as number[]) : [];
      this.go(this.index);
      // Steps taken while this answer was on its way.
      this.ask();
    });
  }

  private go(index: number) {
    this.index = Math.max(0, Math.min(index, this.slots.length - 1));
    this.draw();
  }

  private draw() {
    const stepper = byId('slot-stepper');
    const label = byId('slot-label');
    const marks = this.view.marks;
    if (this.slotView.checked && this.slots.length) {
      const slot = this.slots[this.index];
      const first = this.slots.slice(0, this.index).reduce((n, s) => n + s.count, 1);
      const total = this.slots.reduce((n, s) => n + s.count, 0);
      const senders = slot.signals.length / 2;
      const span = slot.count > 1 ? `Slots ${first}–${first + slot.count - 1}` : `Slot ${first}`;
      label.textContent = `${span} of ${total}: ${slot.meaning} (${senders === 0 ? 'nobody sends' : `${senders} robot${senders === 1 ? '' : 's'} send`}).`;
      this.range.max = String(this.slots.length - 1);
      this.range.value = String(this.index);
      stepper.hidden = false;
      marks.signals = slot.signals;
    } else {
      label.textContent = this.slotView.checked ? 'No signals in the last step.' : '';
      stepper.hidden = true;
      marks.signals = undefined;
    }
    const factor = Number(this.scale.value);
    if (this.deflection.checked && this.displacement.length && Number.isFinite(factor) && factor > 0) {
      const d = this.displacement;
      const out: number[] = [];
      for (let k = 0; k + 2 < d.length; k += 3) out.push(d[k], d[k + 1] * factor, d[k + 2] * factor);
      marks.displaced = out;
    } else {
      marks.displaced = undefined;
    }
    this.view.request();
  }
}
