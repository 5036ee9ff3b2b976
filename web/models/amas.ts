// AMAS: the target shape painted on the square lattice above the supply row; the intermediate
// stage targets of section 6 and the structure already built at the start, when the scenario has
// them. Shapes given as {"rect": [w, h]} are shown as such: they are too large to paint.
import { clear, el } from '../widgets/dom';
import type { ModelEditor } from '../editors/editor';
import { GridEditor } from '../editors/grid/editor';

type Part = { key: 'target' | 'initial'; label: string } | { key: 'stages'; index: number; label: string };

const MAX_PAINTED = 200;

export const editor: ModelEditor = {
  title: 'Target shape',
  owns: ['target', 'stages', 'initial'],
  mount(root, ctx) {
    let doc = ctx.scenario();
    let chosen = 0;
    const select = el('select', { id: 'amas-part', 'aria-label': 'Which shape to edit' });
    const addStage = el('button', { type: 'button', text: 'Add stage', title: 'Add an intermediate stage target before the final target' });
    const removeStage = el('button', { type: 'button', text: 'Remove stage', title: 'Remove this stage target' });
    const note = el('p', { class: 'hint' });
    const box = el('div');
    root.append(el('div', { class: 'row-buttons' }, select, addStage, removeStage), note, box);
    let editor: GridEditor | null = null;

    const parts = (): Part[] => {
      const stages = Array.isArray(doc.stages) ? doc.stages : [];
      const list: Part[] = stages.map((_, index) => ({ key: 'stages' as const, index, label: `stage ${index + 1}` }));
      list.push({ key: 'target', label: stages.length ? 'final target' : 'target' });
      if (doc.initial !== undefined) list.push({ key: 'initial', label: 'built at the start' });
      return list;
    };
    const partValue = (p: Part): unknown => (p.key === 'stages' ? (doc.stages as unknown[])[p.index] : doc[p.key]);
    const change = (p: Part, value: unknown): Promise<string | null> => {
      if (p.key !== 'stages') return ctx.change({ [p.key]: value });
      const stages = [...(doc.stages as unknown[])];
      stages[p.index] = value;
      return ctx.change({ stages });
    };

    const show = () => {
      const list = parts();
      chosen = Math.min(chosen, list.length - 1);
      clear(select);
      for (const [i, p] of list.entries()) select.append(el('option', { value: String(i), text: p.label }));
      select.value = String(chosen);
      const part = list[chosen];
      removeStage.disabled = part.key !== 'stages';
      const value = partValue(part);
      editor?.destroy();
      editor = null;
      clear(box);
      if (typeof value === 'string') {
        note.textContent =
          part.key === 'initial'
            ? 'Cells of the target already built when the run starts.'
            : 'Paint the cells the robots should fill; the supply row is below.';
        editor = new GridEditor(box, {
          lattice: 'square',
          label: `AMAS ${part.label}`,
          text: value,
          apply: (text) => change(part, text),
          below: { label: 'supply row', color: '#c9a66b' },
          maxSide: MAX_PAINTED,
        });
      } else {
        const rect = (value as { rect?: [number, number] } | undefined)?.rect;
        note.textContent = rect
          ? `This shape is a ${rect[0]} × ${rect[1]} rectangle, given as {"rect": [w, h]}; change it in the scenario JSON.`
          : 'This shape is not drawn as text; change it in the scenario JSON.';
      }
    };

    select.addEventListener('change', () => {
      chosen = Number(select.value);
      show();
    });
    addStage.addEventListener('click', () => {
      const stages = Array.isArray(doc.stages) ? [...doc.stages] : [];
      stages.push(doc.target);
      void ctx.change({ stages }).then((problem) => {
        if (problem) note.textContent = problem;
        else chosen = stages.length - 1;
      });
    });
    removeStage.addEventListener('click', () => {
      const part = parts()[chosen];
      if (part.key !== 'stages') return;
      const stages = [...(doc.stages as unknown[])];
      stages.splice(part.index, 1);
      void ctx.change({ stages }).then((problem) => {
        if (problem) note.textContent = problem;
      });
    });
    show();

    return {
      update(scenario) {
        const before = parts()
          .map((p) => p.label)
          .join();
        doc = scenario;
        const value = partValue(parts()[Math.min(chosen, parts().length - 1)]);
        if (
          parts()
            .map((p) => p.label)
            .join() !== before ||
          !editor ||
          typeof value !== 'string'
        )
          show();
        else editor.setText(value);
      },
      destroy() {
        editor?.destroy();
        clear(root);
      },
    };
  },
};

/** Its built-in scenarios' titles in words, by code name (the gallery and the page's header show both). */
export const titles: Record<string, string> = {
  'amas-L': 'The L-shaped benchmark',
  'amas-T': 'The T-shaped benchmark',
  'amas-bridge-single': 'A bridge built in one stage',
  'amas-bridge-staged': 'A bridge built in three stages',
  'amas-fig24': 'The L with module relay (figure 24)',
  'amas-fig25': 'A square repaired after removals (figure 25)',
  'amas-fig26': 'A square with broken communication (figure 26)',
  'amas-square28': 'A 28 × 28 square for robustness tests',
};
