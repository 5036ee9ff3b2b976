// The targets of a cubes3d scenario: per target its type-lists (typed or pasted, one or more, as
// `C31[C41, C31, C31]`), checked by the core as you type with errors that name the line, column and
// problem; "derive from shape", which writes the unique description of the shape in the 3-D editor;
// and the target's name, switching threshold and hold-lit flag. Text that does not check stays as
// typed, with the error under it, and the scenario keeps its last valid targets.
import { clear, el } from '../widgets/dom';
import { message, modelQuery } from '../wasm';

export type TargetSpec = Record<string, unknown>;

export interface TargetsOptions {
  /** The scenario's targets as they now stand. */
  targets(): TargetSpec[];
  /** Applies new targets; returns the core's complaint, or null when accepted. */
  apply(targets: TargetSpec[]): Promise<string | null>;
  /** The shape now in the 3-D editor (cubic text, '' for none) and what it is. */
  editorShape(): { text: string; label: string };
}

interface Described {
  type_lists: string;
  count: number;
  units?: number;
}

const CHECK_DELAY_MS = 200;

/** Checks type-list text with the core: the canonical text, or the problem (line, column, what). */
export function checkTypeLists(text: string): { ok: Described } | { problem: string } {
  try {
    return { ok: modelQuery<Described>('cubes3d', 'check', { type_lists: text }) };
  } catch (e) {
    return { problem: message(e).replace(/^type_lists: /, '') };
  }
}

class Card {
  readonly node: HTMLFieldSetElement;
  readonly text: HTMLTextAreaElement;
  private readonly name: HTMLInputElement;
  private readonly threshold: HTMLInputElement;
  private readonly holdLit: HTMLInputElement;
  private readonly error: HTMLElement;
  private readonly hint: HTMLElement;
  private readonly removeButton: HTMLButtonElement;
  /** The text differs from the scenario's (being typed, or refused). */
  dirty = false;
  private timer = 0;

  constructor(
    private readonly owner: TargetsEditor,
    readonly index: number,
    idBase: string,
  ) {
    const id = `${idBase}-${index}`;
    this.name = el('input', { id: `${id}-name`, type: 'text', class: 'target-name' });
    this.text = el('textarea', { id: `${id}-lists`, rows: 3, spellcheck: 'false', class: 'type-lists', 'aria-describedby': `${id}-error ${id}-hint` });
    this.error = el('p', { class: 'error', id: `${id}-error`, role: 'status', 'aria-live': 'polite' });
    this.hint = el('p', { class: 'hint', id: `${id}-hint` });
    this.threshold = el('input', { id: `${id}-threshold`, type: 'number', min: 0, step: 'any', class: 'size-input' });
    this.holdLit = el('input', { id: `${id}-hold`, type: 'checkbox' });
    const apply = el('button', {
      type: 'button',
      text: 'Apply',
      'aria-label': `Apply the type-lists of target ${index + 1}`,
      'aria-keyshortcuts': 'Control+Enter',
    });
    const derive = el('button', {
      type: 'button',
      text: 'Derive from shape',
      'aria-label': `Derive from shape, for target ${index + 1}`,
      title: `Derive the type-lists of target ${index + 1} from the shape in the 3-D editor`,
    });
    this.removeButton = el('button', { type: 'button', text: 'Remove target', 'aria-label': `Remove target ${index + 1}` });
    apply.addEventListener('click', () => this.applyText());
    derive.addEventListener('click', () => this.derive());
    this.removeButton.addEventListener('click', () => owner.remove(index));
    this.text.addEventListener('input', () => {
      this.dirty = true;
      window.clearTimeout(this.timer);
      this.timer = window.setTimeout(() => this.check(), CHECK_DELAY_MS);
    });
    this.text.addEventListener('change', () => this.applyText());
    this.text.addEventListener('keydown', (e) => {
      if (e.key === 'Enter' && (e.ctrlKey || e.metaKey)) {
        e.preventDefault();
        e.stopPropagation();
        this.applyText();
      }
    });
    this.name.addEventListener('change', () => this.owner.change(index, { name: this.name.value }, this.error));
    this.threshold.addEventListener('change', () => {
      const v = Number(this.threshold.value);
      this.owner.change(index, { threshold: this.threshold.value.trim() === '' || !Number.isFinite(v) ? this.threshold.value : v }, this.error);
    });
    this.holdLit.addEventListener('change', () => this.owner.change(index, { hold_lit: this.holdLit.checked }, this.error));
    this.node = el(
      'fieldset',
      { class: 'group target-card' },
      el('legend', { text: `Target ${index + 1}` }),
      el('label', { class: 'row', for: this.name.id }, 'Name', this.name),
      el('label', { class: 'row', for: this.text.id }, 'Type-lists (one or more; a unit type, then its neighbours’ types)'),
      this.text,
      this.error,
      this.hint,
      el('div', { class: 'row-buttons' }, apply, derive),
      el(
        'div',
        { class: 'row-buttons target-extra' },
        el('label', { for: this.threshold.id }, 'Switch below ', this.threshold),
        el('label', { class: 'check', for: this.holdLit.id }, this.holdLit, 'Hold lit units'),
        this.removeButton,
      ),
    );
  }

  /** Shows the scenario's target, keeping text that is being typed or was refused. */
  show(t: TargetSpec, count: number) {
    const focused = document.activeElement;
    if (focused !== this.name) this.name.value = String(t.name ?? '');
    if (focused !== this.threshold) this.threshold.value = String(t.threshold ?? 0);
    this.holdLit.checked = t.hold_lit === true;
    this.removeButton.disabled = count < 2;
    const lists = typeof t.type_lists === 'string' ? t.type_lists : '';
    this.text.placeholder = typeof t.shape === 'string' ? 'empty: derived from the target’s shape' : 'e.g. C31[C31, C31, C31]';
    if (!this.dirty) {
      this.text.value = lists;
      this.error.textContent = '';
      this.text.removeAttribute('aria-invalid');
    }
    this.describe(t);
  }

  private describe(t: TargetSpec) {
    if (this.dirty) return;
    if (typeof t.type_lists === 'string' && t.type_lists.trim()) {
      const r = checkTypeLists(t.type_lists);
      this.hint.textContent = 'ok' in r ? `${r.ok.count} type-list${r.ok.count === 1 ? '' : 's'}.` : '';
    } else if (typeof t.shape === 'string') {
      try {
        const d = modelQuery<Described>('cubes3d', 'derive', { shape: t.shape });
        this.hint.textContent = `Empty: derived from the target’s shape: ${d.type_lists.trim().split('\n').join('; ')}`;
      } catch (e) {
        this.hint.textContent = message(e);
      }
    } else {
      this.hint.textContent = '';
    }
  }

  /** Checks the text as typed; returns whether it is valid. */
  check(): boolean {
    window.clearTimeout(this.timer);
    const text = this.text.value;
    if (!text.trim()) {
      this.error.textContent = '';
      this.text.removeAttribute('aria-invalid');
      this.hint.textContent = 'Empty: the type-lists are derived from the target’s shape (it needs one).';
      return true;
    }
    const r = checkTypeLists(text);
    if ('problem' in r) {
      this.error.textContent = r.problem;
      this.text.setAttribute('aria-invalid', 'true');
      return false;
    }
    this.error.textContent = '';
    this.text.removeAttribute('aria-invalid');
    this.hint.textContent = `${r.ok.count} type-list${r.ok.count === 1 ? '' : 's'}.`;
    return true;
  }

  async applyText() {
    if (!this.check()) {
      this.showErrorPlace();
      return;
    }
    const text = this.text.value;
    const problem = await this.owner.change(this.index, { type_lists: text.trim() ? text : undefined }, this.error);
    if (!problem) this.dirty = false;
  }

  private derive() {
    const shape = this.owner.opts.editorShape();
    if (!shape.text.trim()) {
      this.error.textContent = `There is no shape in the 3-D editor to derive from: build ${shape.label} first.`;
      return;
    }
    try {
      const d = modelQuery<Described>('cubes3d', 'derive', { shape: shape.text });
      this.text.value = d.type_lists;
      this.dirty = true;
      void this.applyText().then(() => {
        if (!this.dirty) this.hint.textContent = `Derived from ${shape.label} (${d.units ?? '?'} units): ${d.count} type-list${d.count === 1 ? '' : 's'}.`;
      });
    } catch (e) {
      this.error.textContent = `${shape.label}: ${message(e)}`;
    }
  }

  /** Puts the caret where the core found the problem ("line L, column C"). */
  private showErrorPlace() {
    const m = /line (\d+), column (\d+)/.exec(this.error.textContent ?? '');
    if (!m) return;
    const lines = this.text.value.split('\n');
    const line = Math.min(lines.length, Number(m[1])) - 1;
    let at = 0;
    for (let i = 0; i < line; i++) at += lines[i].length + 1;
    at += Math.min(lines[line].length, Number(m[2]) - 1);
    this.text.focus();
    this.text.setSelectionRange(at, at);
  }
}

export class TargetsEditor {
  private cards: Card[] = [];
  private readonly list: HTMLElement;
  private readonly addButton: HTMLButtonElement;
  private readonly error: HTMLElement;

  constructor(
    private readonly root: HTMLElement,
    readonly opts: TargetsOptions,
    private readonly idBase: string,
  ) {
    this.list = el('div', { class: 'target-list' });
    this.addButton = el('button', { type: 'button', text: 'Add target', title: 'Add a target (its type-lists derived from the shape in the 3-D editor)' });
    this.addButton.addEventListener('click', () => this.add());
    this.error = el('p', { class: 'error', role: 'status', 'aria-live': 'polite' });
    clear(root);
    root.append(
      el('p', {
        class: 'hint',
        text: 'With two or more targets each unit switches to the next when its own difference D_0 stays below the threshold of its target for stable steps.',
      }),
      this.list,
      el('div', { class: 'row-buttons' }, this.addButton),
      this.error,
    );
    this.update();
  }

  /** The scenario changed: show its targets. */
  update() {
    const targets = this.opts.targets();
    if (targets.length !== this.cards.length) {
      clear(this.list);
      this.cards = targets.map((_, i) => new Card(this, i, this.idBase));
      for (const c of this.cards) this.list.append(c.node);
    }
    for (const [i, t] of targets.entries()) this.cards[i].show(t, targets.length);
  }

  /** Changes target i's fields (undefined deletes one); the problem goes to `errorNode`. */
  async change(i: number, fields: Record<string, unknown>, errorNode: HTMLElement): Promise<string | null> {
    const targets = this.opts.targets().map((t) => ({ ...t }));
    for (const [k, v] of Object.entries(fields)) {
      if (v === undefined) delete targets[i][k];
      else targets[i][k] = v;
    }
    const problem = await this.opts.apply(targets);
    errorNode.textContent = problem ? `${problem} (your text is kept)` : '';
    return problem;
  }

  remove(i: number) {
    const targets = this.opts.targets().filter((_, k) => k !== i);
    void this.opts.apply(targets).then((problem) => (this.error.textContent = problem ?? ''));
  }

  private add() {
    const targets = this.opts.targets().map((t) => ({ ...t }));
    const shape = this.opts.editorShape();
    let lists = 'C31[C31, C31, C31]\n';
    if (shape.text.trim()) {
      try {
        lists = modelQuery<Described>('cubes3d', 'derive', { shape: shape.text }).type_lists;
      } catch {
        // Keep the default: the shape in the editor is not valid yet.
      }
    }
    targets.push({ name: `target ${targets.length + 1}`, type_lists: lists });
    void this.opts.apply(targets).then((problem) => (this.error.textContent = problem ?? ''));
  }

  destroy() {
    clear(this.root);
  }
}
