// The voxel editor's controls: its tools, undo and redo, the layer slice, the 3-D canvas, its
// messages and the shape as text. What they do is the editor's (web/editors/voxel/editor.ts).
import { el } from '../../widgets/dom';

export type Tool = 'add' | 'remove';
export type SliceMode = 'all' | 'below' | 'one';

/** What the controls ask of the editor. */
export interface VoxelActions {
  setTool(tool: Tool): void;
  undo(): void;
  redo(): void;
  fit(): void;
  /** Shows all layers, those up to the chosen one, or it alone. */
  slice(mode: SliceMode): void;
  /** Chooses the layer shown (from the ground up). */
  level(level: number): void;
  /** Replaces the shape with the text. */
  useText(): void;
}

/** The controls, their elements named, and in `nodes` the editor's parts in order. */
export function voxelControls(id: string, initialTool: Tool, act: VoxelActions) {
  const toolButtons: HTMLButtonElement[] = [];
  const toolGroup = el('div', { class: 'tools', role: 'radiogroup', 'aria-label': 'Editing tool' });
  for (const [tool, label, aria] of [
    ['add', 'Add', 'Add: a click on a face adds a unit there'],
    ['remove', 'Remove', 'Remove: a click on a unit removes it'],
  ] as const) {
    const b = el('button', { type: 'button', role: 'radio', 'aria-checked': String(tool === initialTool), 'aria-label': aria, text: label, 'data-tool': tool });
    b.addEventListener('click', () => act.setTool(tool));
    toolGroup.append(b);
    toolButtons.push(b);
  }
  const button = (label: string, aria: string, f: () => void, extra: Record<string, string> = {}) => {
    // The spoken name holds the visible one (WCAG 2.5.3); a longer explanation is the title.
    const b = el('button', {
      type: 'button',
      text: label,
      ...(aria.toLowerCase().includes(label.toLowerCase()) ? { 'aria-label': aria } : { title: aria }),
      ...extra,
    });
    b.addEventListener('click', f);
    return b;
  };
  const undoButton = button('Undo', 'Undo the last shape edit', () => act.undo(), { 'aria-keyshortcuts': 'Control+Z' });
  const redoButton = button('Redo', 'Redo the shape edit', () => act.redo(), { 'aria-keyshortcuts': 'Control+Shift+Z' });
  const fit = button('Fit', 'Fit the shape in the editor view', () => act.fit(), { class: 'voxel-fit' });

  const sliceSelect = el('select', { id: `${id}-slice`, 'aria-label': 'Layers shown' });
  for (const [value, label] of [
    ['all', 'all layers'],
    ['below', 'layers up to'],
    ['one', 'one layer'],
  ]) {
    sliceSelect.append(el('option', { value, text: label }));
  }
  sliceSelect.addEventListener('change', () => act.slice(sliceSelect.value as SliceMode));
  const levelInput = el('input', { id: `${id}-level`, type: 'range', min: 0, max: 2, step: 1, value: 0, 'aria-label': 'Layer (from the ground up)' });
  const levelOut = el('output', { for: levelInput.id, class: 'level-out' });
  levelInput.addEventListener('input', () => act.level(Number(levelInput.value)));

  const canvas = el('canvas', {
    class: 'voxel-canvas',
    tabindex: 0,
    role: 'application',
    'aria-label':
      'Shape in 3-D. Click a face to add a unit, Alt-click or right-click or long-press to remove; drag to turn, Shift-drag to pan, wheel or pinch to zoom. Keys: arrows move the cursor, Page Up and Page Down change its layer, Space or Enter toggles a unit, Delete removes, Shift+arrows turn the view, brackets change the shown layer.',
  });
  const wrap = el('div', { class: 'voxel-wrap' }, canvas, fit);
  const hint = el('p', { class: 'voxel-hint', 'aria-hidden': 'true' });
  wrap.append(hint);
  const status = el('p', { class: 'hint', role: 'status', 'aria-live': 'polite' });
  const help = el('p', {
    class: 'hint',
    text: 'Click a face to add a unit, the floor to start a layer. Alt-click, right-click or long-press removes. Drag to turn, Shift-drag to pan, wheel or pinch to zoom. Keys: arrows, Page Up/Down, Space.',
  });
  const error = el('p', { class: 'error', role: 'status', 'aria-live': 'polite' });

  const text = el('textarea', { id: `${id}-text`, rows: 7, spellcheck: 'false' });
  const textError = el('p', { class: 'error', role: 'status', 'aria-live': 'polite' });
  const useText = button('Use text', 'Replace the shape with the text', () => act.useText());
  const details = el(
    'details',
    { class: 'voxel-text' },
    el('summary', { text: 'As text (import / export)' }),
    el('p', { class: 'hint', text: 'Square layers from the ground up, separated by a line ---; # is a unit, . is empty.' }),
    el('label', { for: text.id, class: 'sr-only', text: 'Shape as text' }),
    text,
    el('div', { class: 'row-buttons' }, useText),
    textError,
  );

  const nodes = [
    el('div', { class: 'row-buttons voxel-toolbar' }, toolGroup, undoButton, redoButton),
    el('div', { class: 'row-buttons voxel-slice' }, el('label', { for: sliceSelect.id, text: 'Show' }), sliceSelect, levelInput, levelOut),
    wrap,
    error,
    status,
    help,
    details,
  ];
  return { nodes, toolButtons, undoButton, redoButton, sliceSelect, levelInput, levelOut, canvas, wrap, hint, status, error, text, textError };
}

export type VoxelControls = ReturnType<typeof voxelControls>;
