// AMAS: the target shape, painted on the square lattice above the supply row.
import type { ModelEditor } from './editor';
import { GridEditor } from './grid-editor';

export const amasEditor: ModelEditor = {
  title: 'Target shape',
  owns: ['target'],
  mount(root, ctx) {
    const editor = new GridEditor(root, {
      lattice: 'square',
      label: 'Target shape',
      text: String(ctx.scenario().target ?? ''),
      apply: (text) => ctx.change({ target: text }),
      below: { label: 'supply row', color: '#c9a66b' },
    });
    return {
      update: (scenario) => editor.setText(String(scenario.target ?? '')),
      destroy: () => editor.destroy(),
    };
  },
};
