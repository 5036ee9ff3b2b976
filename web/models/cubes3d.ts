// cubes3d: the initial configuration and the targets' shapes, built in 3-D (voxel-editor.ts), and
// the targets' type-lists, typed, checked and derived from a shape (typelist-editor.ts). Both edit
// the scenario keys `shape` and `targets`, so they travel in the share link.
import { el } from '../widgets/dom';
import type { ModelEditor } from '../editors/editor';
import { TargetsEditor, type TargetSpec } from '../editors/typelist-editor';
import { VoxelEditor, type VoxelSubject } from '../editors/voxel/editor';

export const editor: ModelEditor = {
  title: 'Shapes and targets',
  owns: ['shape', 'targets'],
  mount(root, ctx) {
    const targets = (): TargetSpec[] => {
      const t = ctx.scenario().targets;
      return Array.isArray(t) ? (t as TargetSpec[]) : [];
    };
    /** -1: the initial shape; i: target i's shape. */
    let subject = -1;
    const subjectOf = (i: number): VoxelSubject => {
      if (i < 0) {
        return { label: 'the initial shape', text: String(ctx.scenario().shape ?? ''), apply: (text) => ctx.change({ shape: text }) };
      }
      const t = targets()[i] ?? {};
      return {
        label: `the shape of target ${i + 1}`,
        text: typeof t.shape === 'string' ? t.shape : '',
        apply: (text) => ctx.change({ targets: targets().map((x, k) => (k === i ? { ...x, shape: text } : x)) }),
      };
    };

    const picker = el('select', { id: 'cubes-subject', 'aria-label': 'Shape to edit' });
    const fillPicker = () => {
      const list = targets();
      const want = [['-1', 'initial shape (where the units start)']];
      for (const [i, t] of list.entries())
        want.push([String(i), `target ${i + 1}${t.name ? ` “${String(t.name)}”` : ''}${typeof t.shape === 'string' ? '' : ' (no shape yet)'}`]);
      if ([...picker.options].map((o) => `${o.value}:${o.text}`).join() !== want.map((w) => w.join(':')).join()) {
        picker.replaceChildren(...want.map(([value, text]) => el('option', { value, text })));
      }
      if (subject >= list.length) subject = -1;
      picker.value = String(subject);
    };
    const shapeBox = el('div', { class: 'voxel-editor' });
    const targetBox = el('div', { class: 'targets-editor' });
    root.append(
      el('h4', { text: 'Shape in 3-D' }),
      el('label', { class: 'row', for: picker.id }, 'Edit', picker),
      shapeBox,
      el('h4', { text: 'Targets: type-lists' }),
      targetBox,
    );
    const voxels = new VoxelEditor(shapeBox, 'cubes-voxel');
    fillPicker();
    voxels.load(subjectOf(subject));
    picker.addEventListener('change', () => {
      subject = Number(picker.value);
      voxels.load(subjectOf(subject));
    });
    const lists = new TargetsEditor(
      targetBox,
      {
        targets,
        apply: (next) => ctx.change({ targets: next }),
        editorShape: () => ({ text: voxels.shapeText(), label: subjectOf(subject).label }),
      },
      'cubes-target',
    );
    return {
      update: () => {
        fillPicker();
        voxels.setText(subjectOf(subject).text);
        lists.update();
      },
      destroy: () => {
        voxels.destroy();
        lists.destroy();
      },
    };
  },
};

/** Its built-in scenarios' titles in words, by code name (the gallery and the page's header show both). */
export const titles: Record<string, string> = {
  'cubes-box12-ladder': 'A ladder of 12 units folds into a box',
  'cubes-box16-ladder': 'A ladder of 16 units folds into a box',
  'cubes-box16-movers': 'Sixteen units, four moving at once',
  'cubes-box20-ladder': 'A ladder of 20 units folds into a box',
  'cubes-box27-plank': '27 units try to fold into a cube',
  'cubes-cube8-ladder': 'A cube lays itself out flat',
  'cubes-cube8-zigzag': 'A zigzag gathers into a cube',
  'cubes-light': 'A cube walks toward a light',
};
