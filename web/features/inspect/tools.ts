// The click tools: what a click on the lattice does (inspect, or inject one of the model's
// disturbances), the numbers typed beside a tool, and the note of the disturbances the scenario
// carries, with a way to clear them. In an exercise each tool asks the scenario in view (its
// Draft, in the simulation worker) whether a click of it may be made: a refused tool stays in the
// list, reachable by the keyboard, shown as locked with the exercise's reason, and a click of it on
// the lattice is refused with that reason; an allowance ("remove at most 3 modules") counts down.
import type { ToolInfo } from '../../contract.gen';
import type { PageContext } from '../../page/context';
import type { ClickState } from '../../sim/protocol';
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
  /**
   * Applies a click of the tool `name` (its `action`, with the cells clicked) unless the exercise
   * in view refuses it; resolves to the refusal's reason (also shown beside the tools), or null
   * once the click was sent.
   */
  click(name: string, action: Record<string, unknown>): Promise<string | null>;
}

/** A tool's text in the list: its label, and what the exercise says of it. */
export function toolText(label: string, state: ClickState | undefined): string {
  if (state?.problem) return `${label} (locked)`;
  if (state && state.left !== null) return `${label} (${state.left} left)`;
  return label;
}

/** The id of the hidden text that gives a locked tool's reason (its description). */
const whyId = (name: string) => `tool-why-${name}`;

export function setupTools(page: PageContext): Tools {
  const { session, sim, tabs } = page;
  tabs.section('run', toolsHtml, ORDER);
  let tool = 'inspect';
  /** What the exercise in view says of each tool, by name; empty when no exercise is in view. */
  let states = new Map<string, ClickState>();
  /** The latest question to the worker: answers to earlier ones are dropped. */
  let asked: Promise<void> = Promise.resolve();

  /** The scenario's locked fields, when it is an exercise. */
  const lockedFields = () => Object.keys((session.doc().exercise as { locked?: Record<string, unknown> } | undefined)?.locked ?? {});
  const status = () => byId('tool-problem');

  /** Asks the worker what the exercise in view says of each tool, then shows it. */
  function refresh() {
    const tools = session.layout?.tools ?? [];
    if (!session.doc().exercise || !tools.length) {
      states = new Map();
      asked = Promise.resolve();
      show();
      return;
    }
    const asking: Promise<void> = sim.clicks(tools.map((t) => ({ kind: String(t.action.kind ?? ''), label: t.label }))).then((answer) => {
      if (asked !== asking) return;
      states = new Map(tools.map((t, i) => [t.name, answer[i]]));
      show();
    });
    asked = asking;
  }

  /** Waits for the answer to the latest question, however many were asked meanwhile. */
  async function answered() {
    let waited: Promise<void>;
    do {
      waited = asked;
      await waited;
    } while (waited !== asked);
  }

  function select(name: string) {
    tool = name;
    for (const other of byId('tools').querySelectorAll('button')) other.setAttribute('aria-checked', String(other.dataset.tool === tool));
  }

  function button(t: Pick<ToolInfo, 'name' | 'label'>) {
    const b = el('button', { type: 'button', role: 'radio', 'aria-checked': String(t.name === tool), 'data-tool': t.name, text: t.label });
    b.addEventListener('click', () => {
      const why = states.get(t.name)?.problem;
      // A locked tool is not taken up (unless it is the one in hand): its reason is said instead.
      if (why && t.name !== tool) {
        status().textContent = why;
        return;
      }
      status().textContent = why ?? '';
      select(t.name);
    });
    return b;
  }

  function render() {
    const layout = session.layout;
    if (!layout) return;
    const tools = byId('tools');
    clear(tools);
    status().textContent = '';
    const all = [{ name: 'inspect', label: 'Inspect' }, ...layout.tools];
    if (!all.some((t) => t.name === tool)) tool = 'inspect';
    for (const t of all) tools.append(button(t));
    // A number in a tool's action (a load's force, say) can be set before clicking; the value
    // typed is what the recorded action carries.
    const values = byId('tool-values');
    clear(values);
    for (const t of layout.tools) {
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
    refresh();
    renderDisturbanceNote();
  }

  /** Shows each tool as the exercise in view has it: locked with its reason, or what is left of its allowance. */
  function show() {
    const layout = session.layout;
    const reasons = byId('tool-reasons');
    clear(reasons);
    for (const b of byId('tools').querySelectorAll<HTMLButtonElement>('button')) {
      const t = layout?.tools.find((x) => x.name === b.dataset.tool);
      if (!t) continue;
      const state = states.get(t.name);
      b.textContent = toolText(t.label, state);
      b.classList.toggle('locked', Boolean(state?.problem));
      if (state?.problem) {
        b.setAttribute('aria-disabled', 'true');
        b.setAttribute('aria-describedby', whyId(t.name));
        b.title = state.problem;
        reasons.append(el('span', { id: whyId(t.name), text: state.problem }));
      } else {
        b.removeAttribute('aria-disabled');
        b.removeAttribute('aria-describedby');
        b.removeAttribute('title');
      }
    }
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

  // A click counts from its step on: rewound past (or played past again), the exercise's answer
  // changes, so the tools are asked again whenever the run's step crosses one of the scenario's.
  // The count is of the clicks the scenario held at the last frame: a click recorded since
  // (a frame may arrive before it is) makes it stale, and the next frame counts afresh.
  let reached = -1;
  session.on('loaded', render);
  session.on('recorded', () => {
    reached = -1;
    refresh();
    renderDisturbanceNote();
  });
  session.on('frame', (frame) => {
    if (!session.doc().exercise) return;
    const list = (session.doc().disturbances as { at?: number }[] | undefined) ?? [];
    const n = list.filter((d) => (d.at ?? 0) <= frame.steps).length;
    if (n === reached) return;
    reached = n;
    refresh();
  });

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
    async click(name, action) {
      // Asked at the step the click is made (the run may have gone back since the last answer).
      refresh();
      await answered();
      const why = states.get(name)?.problem ?? null;
      if (why) {
        status().textContent = why;
        return why;
      }
      sim.apply(action);
      // Asked after the click, so answered once the worker has recorded it: the count is current.
      refresh();
      return null;
    },
  };
}
