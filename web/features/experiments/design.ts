// The sweep's design as a form beside the JSON editor: each grid key as a list of values or a range
// (start, step, end), the sampling (the grid alone, random, or Latin hypercube, with a count, a
// seed and each sampled key's min and max) and a stop condition in the goal language. The form
// reads the experiment's JSON and writes the same keys back (`grid`, `sample`, `stop`), leaving the
// rest as it was; the core checks the result, and its message is shown beside the field it names.
import { byId, el } from '../../widgets/dom';

type Json = Record<string, unknown>;
type GridRow = { key: string; range: boolean; values: string; start: string; step: string; end: string };
type RangeRow = { key: string; min: string; max: string; integer: boolean };

const isObject = (v: unknown): v is Json => !!v && typeof v === 'object' && !Array.isArray(v);
const numberText = (v: unknown) => (typeof v === 'number' ? String(v) : '');

/** A list's values as typed: "1, 3, continuous". */
export const valuesText = (values: unknown[]) => values.map((v) => (typeof v === 'string' ? v : JSON.stringify(v))).join(', ');

/** The values typed in a list: each read as JSON where it reads (numbers, true, "text"), else as text. */
export function readValues(text: string): unknown[] {
  return text
    .split(',')
    .map((t) => t.trim())
    .filter((t) => t !== '')
    .map((t) => {
      try {
        return JSON.parse(t);
      } catch {
        return t;
      }
    });
}

const numberOf = (text: string): number | string => (text.trim() !== '' && Number.isFinite(Number(text)) ? Number(text) : text);

/** The form's state from an experiment's JSON value. */
export function designOf(experiment: Json): { grid: GridRow[]; method: string; count: string; seed: string; ranges: RangeRow[]; stop: string } {
  const grid = Object.entries(isObject(experiment.grid) ? experiment.grid : {}).map(([key, v]): GridRow => {
    const r = isObject(v) ? v : null;
    return {
      key,
      range: r !== null,
      values: Array.isArray(v) ? valuesText(v) : '',
      start: numberText(r?.start),
      step: numberText(r?.step),
      end: numberText(r?.end),
    };
  });
  const sample = isObject(experiment.sample) ? experiment.sample : null;
  const ranges = Object.entries(sample && isObject(sample.ranges) ? sample.ranges : {}).map(([key, v]): RangeRow => {
    const b = isObject(v) ? v : {};
    return { key, min: numberText(b.min), max: numberText(b.max), integer: b.integer === true };
  });
  return {
    grid,
    method: sample ? (sample.method === 'random' ? 'random' : 'latin') : 'grid',
    count: numberText(sample?.count),
    seed: numberText(sample?.seed),
    ranges,
    stop: typeof experiment.stop === 'string' ? experiment.stop : '',
  };
}

/** The experiment with the form's design written in: `grid`, `sample` and `stop` replaced, the rest kept in its order. */
export function withDesign(experiment: Json, d: ReturnType<typeof designOf>): Json {
  const grid: Json = {};
  for (const g of d.grid) {
    if (!g.key.trim()) continue;
    grid[g.key.trim()] = g.range ? { start: numberOf(g.start), step: numberOf(g.step), end: numberOf(g.end) } : readValues(g.values);
  }
  const ranges: Json = {};
  for (const r of d.ranges) {
    if (!r.key.trim()) continue;
    ranges[r.key.trim()] = { min: numberOf(r.min), max: numberOf(r.max), ...(r.integer ? { integer: true } : {}) };
  }
  const sample = d.method === 'grid' ? undefined : { method: d.method, count: numberOf(d.count), ...(d.seed.trim() ? { seed: numberOf(d.seed) } : {}), ranges };
  const out: Json = {};
  const keys = [...Object.keys(experiment)];
  // New keys go where the format lists them: grid and sample after the scenarios, stop after the seeds.
  for (const [key, after] of [
    ['grid', 'scenarios'],
    ['sample', 'grid'],
    ['stop', 'seeds'],
  ] as const) {
    if (!keys.includes(key)) keys.splice(keys.includes(after) ? keys.indexOf(after) + 1 : keys.length, 0, key);
  }
  for (const k of keys) {
    const v =
      k === 'grid' ? (Object.keys(grid).length ? grid : undefined) : k === 'sample' ? sample : k === 'stop' ? d.stop.trim() || undefined : experiment[k];
    if (v !== undefined) out[k] = v;
  }
  return out;
}

/** The experiment's JSON value, or null when the text does not read as an object. */
function parsed(text: string): Json | null {
  try {
    const value: unknown = JSON.parse(text);
    return isObject(value) ? value : null;
  } catch {
    return null;
  }
}

/**
 * The form; `current` gives the experiment's JSON text as it stands, and `write` its new text after
 * each change made in the form (the design written into the current text, so nothing typed in the
 * JSON meanwhile is lost).
 */
export class DesignForm {
  private readonly root = byId('experiment-design-form');
  private readonly gridRows = byId('design-grid-rows');
  private readonly rangeRows = byId('design-range-rows');
  private readonly method = byId<HTMLSelectElement>('design-method');
  private readonly count = byId<HTMLInputElement>('design-count');
  private readonly seed = byId<HTMLInputElement>('design-seed');
  private readonly stop = byId<HTMLInputElement>('design-stop');
  private readonly sampling = byId('design-sampling');
  private readonly notice = byId('design-notice');
  private readonly problems = { grid: byId('design-grid-problem'), sample: byId('design-sample-problem'), stop: byId('design-stop-problem') };
  private rows = 0;

  constructor(
    private readonly current: () => string,
    private readonly write: (text: string) => void,
  ) {
    byId('design-add-grid').addEventListener('click', () => {
      this.gridRow({ key: '', range: false, values: '', start: '', step: '', end: '' }).querySelector('input')?.focus();
    });
    byId('design-add-range').addEventListener('click', () => {
      this.rangeRow({ key: '', min: '', max: '', integer: false }).querySelector('input')?.focus();
    });
    this.method.addEventListener('change', () => {
      this.showSampling();
      this.changed();
    });
    this.root.addEventListener('submit', (e) => e.preventDefault());
    this.root.addEventListener('change', (e) => {
      if (e.target !== this.method) this.changed();
    });
  }

  /** Reads the experiment's JSON text into the form; a text that does not read leaves the form disabled. */
  sync(text: string) {
    const experiment = parsed(text);
    const fields = this.root.querySelector('fieldset.design-fields') as HTMLFieldSetElement;
    fields.disabled = experiment === null;
    this.notice.textContent = experiment ? '' : 'The JSON does not read as an experiment yet: the form follows once it does.';
    if (!experiment) return;
    const d = designOf(experiment);
    this.gridRows.replaceChildren();
    this.rangeRows.replaceChildren();
    for (const g of d.grid) this.gridRow(g);
    for (const r of d.ranges) this.rangeRow(r);
    this.method.value = d.method;
    this.count.value = d.count;
    this.seed.value = d.seed;
    this.stop.value = d.stop;
    this.showSampling();
  }

  /**
   * Shows the core's message beside the field it names (`grid.KEY…`, `sample…`, `stop…`), or clears
   * every field's message (`null`, or a message about another part of the experiment).
   */
  showProblem(message: string | null) {
    for (const p of Object.values(this.problems)) p.textContent = '';
    for (const input of this.root.querySelectorAll('[aria-invalid]')) input.removeAttribute('aria-invalid');
    const part = message?.match(/^(grid|sample|stop)\b/)?.[1] as keyof DesignForm['problems'] | undefined;
    if (!message || !part) return;
    this.problems[part].textContent = message;
    const field = part === 'stop' ? this.stop : part === 'sample' ? this.count : null;
    field?.setAttribute('aria-invalid', 'true');
    const key = part === 'grid' ? message.match(/^grid\.([^:]+?)(\.(start|step|end))?:/)?.[1] : undefined;
    for (const input of this.gridRows.querySelectorAll<HTMLInputElement>('input.design-key'))
      if (input.value === key) input.setAttribute('aria-invalid', 'true');
  }

  private changed() {
    const experiment = parsed(this.current());
    if (experiment) this.write(JSON.stringify(withDesign(experiment, this.read()), null, 2));
  }

  private read(): ReturnType<typeof designOf> {
    const grid = [...this.gridRows.children].map((row): GridRow => {
      const v = (name: string) => (row.querySelector(`[data-field="${name}"]`) as HTMLInputElement).value;
      return { key: v('key'), range: v('kind') === 'range', values: v('values'), start: v('start'), step: v('step'), end: v('end') };
    });
    const ranges = [...this.rangeRows.children].map((row): RangeRow => {
      const v = (name: string) => row.querySelector(`[data-field="${name}"]`) as HTMLInputElement;
      return { key: v('key').value, min: v('min').value, max: v('max').value, integer: v('integer').checked };
    });
    return { grid, method: this.method.value, count: this.count.value, seed: this.seed.value, ranges, stop: this.stop.value };
  }

  private showSampling() {
    this.sampling.hidden = this.method.value === 'grid';
  }

  /** A labelled input of a row; `n` numbers the row so each label is its own. */
  private input(field: string, label: string, value: string, attrs: Record<string, string> = {}) {
    const input = el('input', { type: 'text', 'data-field': field, value, 'aria-label': label, ...attrs });
    input.value = value;
    return input;
  }

  private gridRow(g: GridRow): HTMLElement {
    const n = ++this.rows;
    const key = this.input('key', `Grid key ${n}: scenario path`, g.key, { class: 'design-key', placeholder: 'robots' });
    const kind = el('select', { 'data-field': 'kind', 'aria-label': `Grid key ${n}: values as` });
    kind.append(el('option', { value: 'list', text: 'a list' }), el('option', { value: 'range', text: 'a range' }));
    kind.value = g.range ? 'range' : 'list';
    const list = this.input('values', `Grid key ${n}: values, separated by commas`, g.values, { placeholder: '1, 2, 3' });
    const start = this.input('start', `Grid key ${n}: start`, g.start, { inputmode: 'decimal', class: 'design-number' });
    const step = this.input('step', `Grid key ${n}: step`, g.step, { inputmode: 'decimal', class: 'design-number' });
    const end = this.input('end', `Grid key ${n}: end (included)`, g.end, { inputmode: 'decimal', class: 'design-number' });
    const range = el('span', { class: 'design-range' }, start, step, end);
    const show = () => {
      list.hidden = kind.value === 'range';
      range.hidden = kind.value !== 'range';
    };
    kind.addEventListener('change', show);
    show();
    const remove = el('button', { type: 'button', text: 'Remove', 'aria-label': `Remove grid key ${n}` });
    const row = el('li', { class: 'design-row' }, key, kind, list, range, remove);
    remove.addEventListener('click', () => {
      row.remove();
      this.changed();
    });
    this.gridRows.append(row);
    return row;
  }

  private rangeRow(r: RangeRow): HTMLElement {
    const n = ++this.rows;
    const key = this.input('key', `Sampled key ${n}: scenario path`, r.key, { placeholder: 'tip_load' });
    const min = this.input('min', `Sampled key ${n}: min`, r.min, { inputmode: 'decimal', class: 'design-number' });
    const max = this.input('max', `Sampled key ${n}: max`, r.max, { inputmode: 'decimal', class: 'design-number' });
    const integer = el('input', { type: 'checkbox', 'data-field': 'integer' });
    integer.checked = r.integer;
    const whole = el('label', { class: 'design-check' }, integer, ' whole numbers');
    const remove = el('button', { type: 'button', text: 'Remove', 'aria-label': `Remove sampled key ${n}` });
    const row = el('li', { class: 'design-row' }, key, min, max, whole, remove);
    remove.addEventListener('click', () => {
      row.remove();
      this.changed();
    });
    this.rangeRows.append(row);
    return row;
  }
}
