// The parameter form: one input per scenario key, its kind read from the model's JSON Schema (a
// select for every choice, bounds and help text from the schema), falling back to the value's own
// type for a key the schema does not describe. A change is validated by the core; an invalid value
// stays in its field with the core's message under it.
import { ENVELOPE } from '../contract.gen';
import type { ModelSchema, SchemaNode } from '../wasm';
import { clear, el } from './dom';

/** The envelope's format keys and sections, which have editors of their own (or none). */
const HIDDEN = new Set(ENVELOPE.filter((k) => k.role === 'format' || k.role === 'section').map((k) => k.key));
/** The envelope's texts and settings come first, in the core's order; the model's keys follow. */
const ORDER = ENVELOPE.filter((k) => !HIDDEN.has(k.key)).map((k) => k.key);

/** Applies a field's value (JSON, or else text); resolves to the core's complaint, or null when it runs. */
export type Apply = (key: string, valueJson: string) => Promise<string | null>;

/** The node `$ref` points to, or the node itself. */
export function resolve(node: SchemaNode | undefined, schema: ModelSchema | undefined): SchemaNode | undefined {
  const ref = node?.$ref?.replace('#/$defs/', '');
  return ref ? { ...schema?.defs[ref], ...node, $ref: undefined } : node;
}

/** The constants a key may take, when the schema lists them (an enum). */
export function choices(node: SchemaNode | undefined): unknown[] | undefined {
  if (node?.enum) return node.enum;
  const consts = node?.oneOf?.map((n) => n.const);
  return consts?.length && consts.every((c) => c !== undefined) ? consts : undefined;
}

/**
 * A number other than `own` within `bounds`, to start the second run's value from: one more (or
 * less) for a whole number, twice (or half) for another. The same value would compare nothing.
 */
export function otherNumber(own: number, bounds: { min: number; max: number; integer: boolean }): number {
  const candidates = bounds.integer ? [own + 1, own - 1] : own === 0 ? [1, -1, 0.5, -0.5] : [own * 2, own / 2, own + 1, own - 1];
  return candidates.find((v) => v !== own && v >= bounds.min && v <= bounds.max) ?? own;
}

/** Help text: the key's description and each choice's. */
function help(node: SchemaNode | undefined): string {
  const lines = [node?.description ?? ''];
  for (const option of node?.oneOf ?? []) {
    if (option.const !== undefined && option.description) lines.push(`${String(option.const)}: ${option.description}`);
  }
  return lines.filter(Boolean).join('\n');
}

/** `locked` fields (an exercise's) are shown read-only, with a note. */
export function renderParams(
  form: HTMLFormElement,
  scenario: Record<string, unknown>,
  apply: Apply,
  skip: string[] = [],
  locked: Set<string> = new Set(),
  schema?: ModelSchema,
) {
  const focused = document.activeElement instanceof HTMLElement && form.contains(document.activeElement) ? document.activeElement.id : '';
  clear(form);
  const keys = Object.keys(scenario).filter((k) => !HIDDEN.has(k) && k !== 'seed' && !skip.includes(k));
  keys.sort((a, b) => {
    const ia = ORDER.indexOf(a);
    const ib = ORDER.indexOf(b);
    if (ia >= 0 || ib >= 0) return (ia < 0 ? 99 : ia) - (ib < 0 ? 99 : ib);
    return a.localeCompare(b);
  });
  for (const key of keys) {
    const value = scenario[key];
    const id = `param-${key}`;
    const error = el('p', { class: 'error', id: `${id}-error`, role: 'status', 'aria-live': 'polite' });
    const wrap = el('div', { class: 'param' });
    const label = el('label', { for: id, text: key.replace(/_/g, ' ') });
    const node = resolve(schema?.properties[key], schema);
    const options = choices(node);
    const about = help(node);
    const note = about ? el('p', { class: 'help', id: `${id}-help`, text: about }) : undefined;
    const describedBy = note ? `${note.id} ${error.id}` : error.id;
    let input: HTMLInputElement | HTMLTextAreaElement | HTMLSelectElement;
    let read: () => string;
    if (options) {
      const select = el('select', { id, 'aria-describedby': describedBy });
      for (const option of options) {
        const text = JSON.stringify(option);
        const item = el('option', { value: text, text: String(option) });
        item.selected = text === JSON.stringify(value);
        select.append(item);
      }
      input = select;
      read = () => select.value;
    } else if (typeof value === 'boolean') {
      const box = el('input', { id, type: 'checkbox', 'aria-describedby': describedBy });
      box.checked = value;
      input = box;
      read = () => JSON.stringify(box.checked);
    } else if (typeof value === 'number') {
      const integer = node?.type === 'integer' || (Array.isArray(node?.type) && node.type.includes('integer'));
      const box = el('input', { id, type: 'number', step: integer ? '1' : 'any', value: String(value), 'aria-describedby': describedBy });
      if (node?.minimum !== undefined) box.min = String(node.minimum);
      if (node?.maximum !== undefined) box.max = String(node.maximum);
      input = box;
      read = () => (box.value.trim() === '' ? '""' : box.value.trim());
    } else if (typeof value === 'string' && !value.includes('\n') && key !== 'description') {
      const box = el('input', { id, type: 'text', value, 'aria-describedby': describedBy });
      input = box;
      read = () => JSON.stringify(box.value);
    } else if (typeof value === 'string') {
      const area = el('textarea', { id, rows: Math.min(16, Math.max(3, value.split('\n').length + 1)), spellcheck: 'false', 'aria-describedby': describedBy });
      area.value = value;
      input = area;
      read = () => JSON.stringify(area.value);
    } else {
      const area = el('textarea', { id, rows: 4, spellcheck: 'false', 'aria-describedby': describedBy });
      area.value = JSON.stringify(value, null, 1);
      input = area;
      read = () => area.value;
    }
    input.addEventListener('change', () => {
      void apply(key, read()).then((problem) => {
        error.textContent = problem ?? '';
        wrap.classList.toggle('invalid', !!problem);
        input.setAttribute('aria-invalid', problem ? 'true' : 'false');
      });
    });
    wrap.append(label, input);
    if (note) wrap.append(note);
    wrap.append(error);
    if (locked.has(key)) {
      input.disabled = true;
      wrap.classList.add('locked');
      wrap.append(el('p', { class: 'locked-note', text: 'Locked by the exercise.' }));
    }
    form.append(wrap);
  }
  if (focused) document.getElementById(focused)?.focus();
}
