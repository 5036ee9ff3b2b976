// The parameter form: one input per scenario key, generated from the scenario itself. A change is
// validated by the core; an invalid value stays in its field with the core's message under it.
import { clear, el } from './dom';

const HIDDEN = new Set(['version', 'model', 'disturbances', 'exercise']);
const ORDER = ['name', 'description', 'max_steps'];

export type Apply = (key: string, valueJson: string) => string | null;

/** `locked` fields (an exercise's) are shown read-only, with a note. */
export function renderParams(form: HTMLFormElement, scenario: Record<string, unknown>, apply: Apply, skip: string[] = [], locked: Set<string> = new Set()) {
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
    let input: HTMLInputElement | HTMLTextAreaElement;
    let read: () => string;
    if (typeof value === 'boolean') {
      const box = el('input', { id, type: 'checkbox', 'aria-describedby': error.id });
      box.checked = value;
      input = box;
      read = () => JSON.stringify(box.checked);
    } else if (typeof value === 'number') {
      const box = el('input', { id, type: 'number', step: 'any', value: String(value), 'aria-describedby': error.id });
      input = box;
      read = () => (box.value.trim() === '' ? '""' : box.value.trim());
    } else if (typeof value === 'string' && !value.includes('\n') && key !== 'description') {
      const box = el('input', { id, type: 'text', value, 'aria-describedby': error.id });
      input = box;
      read = () => JSON.stringify(box.value);
    } else if (typeof value === 'string') {
      const area = el('textarea', { id, rows: Math.min(16, Math.max(3, value.split('\n').length + 1)), spellcheck: 'false', 'aria-describedby': error.id });
      area.value = value;
      input = area;
      read = () => JSON.stringify(area.value);
    } else {
      const area = el('textarea', { id, rows: 4, spellcheck: 'false', 'aria-describedby': error.id });
      area.value = JSON.stringify(value, null, 1);
      input = area;
      read = () => area.value;
    }
    input.addEventListener('change', () => {
      const problem = apply(key, read());
      error.textContent = problem ?? '';
      wrap.classList.toggle('invalid', !!problem);
      input.setAttribute('aria-invalid', problem ? 'true' : 'false');
    });
    wrap.append(label, input, error);
    if (locked.has(key)) {
      input.disabled = true;
      wrap.classList.add('locked');
      wrap.append(el('p', { class: 'locked-note', text: 'Locked by the exercise.' }));
    }
    form.append(wrap);
  }
  if (focused) document.getElementById(focused)?.focus();
}
