// The click tools: what a click on the lattice does (inspect, or inject one of the model's
// disturbances), the numbers typed beside a tool, and the note of the disturbances the scenario
// carries, with a way to clear them.
import type { PageContext } from '../../page/context';
import { byId, clear, el } from '../../widgets/dom';
import toolsHtml from './tools.html?raw';

/** Where the tools go in the Run tab, among other features' sections. */
const ORDER = 60;

export interface Tools {
  /** The tool a click on the lattice applies ('inspect' or one of the layout's tools). */
  readonly tool: string;
  /** The label of that tool. */
  label(): string;
  /** The numbers typed next to a tool, by action key. */
  values(name: string): Record<string, number>;
}

export function setupTools(page: PageContext): Tools {
  const { session, tabs } = page;
  tabs.section('run', toolsHtml, ORDER);
  let tool = 'inspect';

  /** The scenario's locked fields, when it is an exercise. */
  const lockedFields = () => Object.keys((session.doc().exercise as { locked?: Record<string, unknown> } | undefined)?.locked ?? {});

  function render() {
    const layout = session.layout;
    if (!layout) return;
    const tools = byId('tools');
    clear(tools);
    // Clicked disturbances are recorded in the scenario: not when the exercise locks them.
    const clickable = lockedFields().includes('disturbances') ? [] : layout.tools;
    const all = [{ name: 'inspect', label: 'Inspect' }, ...clickable];
    if (!all.some((t) => t.name === tool)) tool = 'inspect';
    for (const t of all) {
      const b = el('button', { type: 'button', role: 'radio', 'aria-checked': String(t.name === tool), 'data-tool': t.name, text: t.label });
      b.addEventListener('click', () => {
        tool = t.name;
        for (const other of tools.querySelectorAll('button')) other.setAttribute('aria-checked', String(other.dataset.tool === tool));
      });
      tools.append(b);
    }
    // A number in a tool's action (a load's force, say) can be set before clicking; the value
    // typed is what the recorded action carries.
    const values = byId('tool-values');
    clear(values);
    for (const t of clickable) {
      for (const [key, value] of Object.entries(t.action)) {
        if (typeof value !== 'number') continue;
        const input = el('input', {
          type: 'number',
          step: 'any',
          value: String(value),
          id: `tool-${t.name}-${key}`,
          'data-tool': t.name,
          'data-key': key,
          'aria-label': `${t.label}: ${key}`,
        });
        values.append(el('label', { class: 'row' }, `${t.label}: ${key} `, input));
      }
    }
    renderDisturbanceNote();
  }

  /** Shows how many disturbances the scenario carries, with a way to clear them. */
  function renderDisturbanceNote() {
    const tools = byId('tools');
    tools.parentElement?.querySelector('.recorded')?.remove();
    const count = (session.doc().disturbances as unknown[] | undefined)?.length ?? 0;
    if (!count || lockedFields().includes('disturbances')) return;
    const clearButton = el('button', { type: 'button', text: 'Clear them' });
    clearButton.addEventListener('click', () => void session.set('disturbances', '[]', { onProblem: (problem) => page.banner.report(problem) }));
    tools.after(el('p', { class: 'hint recorded' }, `${count} scheduled or recorded disturbance${count > 1 ? 's' : ''}. `, clearButton));
  }

  session.on('loaded', render);
  session.on('recorded', renderDisturbanceNote);

  return {
    get tool() {
      return tool;
    },
    label: () => session.layout?.tools.find((t) => t.name === tool)?.label ?? 'Inspect',
    values(name) {
      const out: Record<string, number> = {};
      for (const input of byId('tool-values').querySelectorAll<HTMLInputElement>('input')) {
        if (input.dataset.tool === name && input.dataset.key && input.value !== '') out[input.dataset.key] = Number(input.value);
      }
      return out;
    },
  };
}
