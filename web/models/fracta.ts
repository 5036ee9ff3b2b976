// fracta: the starting configuration as a hex shape, and the goal statements, typed with live
// checking or derived from goal shapes drawn one per priority.
import { clear, el } from '../widgets/dom';
import { message, modelQuery } from '../wasm';
import type { ModelEditor } from '../editors/editor';
import { GridEditor } from '../editors/grid/editor';

export const editor: ModelEditor = {
  title: 'Start and goal',
  owns: ['start', 'goal'],
  mount(root, ctx) {
    const doc = ctx.scenario();
    const startBox = el('div');
    root.append(el('h4', { text: 'Starting configuration' }), startBox);
    const start = new GridEditor(startBox, {
      lattice: 'hex',
      label: 'Starting configuration',
      text: String(doc.start ?? ''),
      apply: (text) => ctx.change({ start: text }),
    });

    // Goal statements, checked by the core as they are typed.
    const goalText = el('textarea', { id: 'fracta-goal', rows: 4, spellcheck: 'false', 'aria-describedby': 'fracta-goal-error' });
    goalText.value = String(doc.goal ?? '');
    const goalError = el('p', { id: 'fracta-goal-error', class: 'error', role: 'status', 'aria-live': 'polite' });
    const applyGoal = el('button', { type: 'button', text: 'Apply statements', title: 'Apply the goal statements' });
    let timer = 0;
    const check = (): string | null => {
      try {
        modelQuery('fracta', 'check', { goal: goalText.value });
        goalError.textContent = '';
        return null;
      } catch (e) {
        goalError.textContent = message(e);
        return goalError.textContent;
      }
    };
    goalText.addEventListener('input', () => {
      clearTimeout(timer);
      timer = window.setTimeout(check, 250);
    });
    applyGoal.addEventListener('click', () => {
      if (check()) return;
      void ctx.change({ goal: goalText.value }).then((problem) => (goalError.textContent = problem ?? ''));
    });

    // Goal shapes, one per priority, from which the statements are derived.
    const shapes: string[] = [String(doc.start ?? '')];
    let current = 0;
    const priority = el('select', { id: 'fracta-priority', 'aria-label': 'Priority of the goal shape being drawn' });
    const shapeBox = el('div');
    const goalShape = new GridEditor(shapeBox, {
      lattice: 'hex',
      label: 'Goal shape',
      text: shapes[0],
      apply: async (text) => {
        shapes[current] = text;
        return null;
      },
    });
    const renderPriorities = () => {
      clear(priority);
      for (let i = 0; i < shapes.length; i++)
        priority.append(el('option', { value: String(i), text: i === 0 ? 'priority 1 (the goal)' : `priority ${i + 1} (with spares)` }));
      priority.value = String(current);
    };
    priority.addEventListener('change', () => {
      current = Number(priority.value);
      goalShape.setText(shapes[current]);
    });
    const addPriority = el('button', { type: 'button', text: 'Add priority', title: 'Add a goal shape of the next priority' });
    addPriority.addEventListener('click', () => {
      shapes.push(shapes[shapes.length - 1]);
      current = shapes.length - 1;
      renderPriorities();
      goalShape.setText(shapes[current]);
    });
    const removePriority = el('button', { type: 'button', text: 'Remove', 'aria-label': 'Remove the goal shape of this priority' });
    removePriority.addEventListener('click', () => {
      if (shapes.length < 2) return;
      shapes.splice(current, 1);
      current = Math.min(current, shapes.length - 1);
      renderPriorities();
      goalShape.setText(shapes[current]);
    });
    const derive = el('button', { type: 'button', class: 'primary', text: 'Derive statements', title: 'Derive the goal statements from the goal shapes' });
    derive.addEventListener('click', () => {
      try {
        const answer = modelQuery<{ goal: string }>('fracta', 'derive', { shape: shapes.join('---\n') });
        goalText.value = answer.goal;
        goalError.textContent = '';
        void ctx.change({ goal: answer.goal }).then((problem) => (goalError.textContent = problem ?? ''));
      } catch (e) {
        goalError.textContent = message(e);
      }
    });
    renderPriorities();

    root.append(
      el('h4', { text: 'Goal statements' }),
      el('label', { for: goalText.id, class: 'sr-only', text: 'Goal statements' }),
      goalText,
      goalError,
      el('div', { class: 'row-buttons' }, applyGoal),
      el(
        'details',
        {},
        el('summary', { text: 'Derive statements from goal shapes' }),
        el('div', { class: 'row-buttons' }, priority, addPriority, removePriority),
        shapeBox,
        el('div', { class: 'row-buttons' }, derive),
      ),
    );

    return {
      update(scenario) {
        start.setText(String(scenario.start ?? ''));
        if (document.activeElement !== goalText && String(scenario.goal ?? '') !== goalText.value) {
          goalText.value = String(scenario.goal ?? '');
          goalError.textContent = '';
        }
      },
      destroy() {
        start.destroy();
        goalShape.destroy();
        clear(root);
      },
    };
  },
};

/** Its built-in scenarios' titles in words, by code name (the gallery and the page's header show both). */
export const titles: Record<string, string> = {
  'fracta-deadlock': 'Two triangles in deadlock (figure 4)',
  'fracta-deadlock-corner': 'Two triangles in deadlock, the spare beside a corner',
  'fracta-hexagon7': 'A line curls into a hexagon',
  'fracta-large': '990 units form a large triangle',
  'fracta-repair': 'A triangle repairs itself',
  'fracta-repair-corner': 'A triangle repairs itself, the spare beside a corner',
  'fracta-triangle10': 'Two lines form a triangle',
  'fracta-triangle10-3spares': 'A triangle with three spares',
  'fracta-triangle10-3spares-corner': 'A triangle with three spares beside its corners',
  'fracta-triangle10-corner': 'Two lines form a triangle, the spare beside a corner',
};
