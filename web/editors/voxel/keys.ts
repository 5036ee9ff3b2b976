// The voxel editor's keys, with its canvas focused: Ctrl+Z and Ctrl+Shift+Z (or Ctrl+Y) undo and
// redo, Shift+arrows turn the view, the arrows move the cursor, Page Up and Page Down change its
// layer, Space or Enter toggles a unit (Delete removes one), [ and ] change the layer shown, + -
// and 0 zoom and fit.

/** What the keys do to the editor. */
export interface VoxelKeyActions {
  undo(): void;
  redo(): void;
  /** Turns the view by a drag of (dx, dy) pixels. */
  turn(dx: number, dy: number): void;
  /** Moves the cursor one cell to the screen's right (1) or left (-1), or up (1) or down (-1). */
  move(right: number, up: number): void;
  /** Moves the cursor a layer up (1) or down (-1). */
  layer(by: number): void;
  toggle(removeOnly: boolean): void;
  /** Shows a layer more (1) or less (-1). */
  slice(by: number): void;
  zoom(factor: number): void;
  fit(): void;
}

/** Acts on a key pressed on the editor's canvas; true when it was the editor's (it is then used up). */
export function voxelKey(e: KeyboardEvent, act: VoxelKeyActions): boolean {
  const mod = e.ctrlKey || e.metaKey;
  const lower = e.key.toLowerCase();
  if (mod && (lower === 'z' || lower === 'y')) {
    if (e.shiftKey || lower === 'y') act.redo();
    else act.undo();
  } else if (mod || e.altKey) {
    return false;
  } else if (e.shiftKey && e.key.startsWith('Arrow')) {
    const d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] }[e.key] ?? [0, 0];
    act.turn(d[0] * 24, d[1] * 24);
  } else if (!plainKey(e.key, act)) {
    return false;
  }
  e.preventDefault();
  e.stopPropagation();
  return true;
}

function plainKey(key: string, act: VoxelKeyActions): boolean {
  switch (key) {
    case 'ArrowLeft':
      act.move(-1, 0);
      return true;
    case 'ArrowRight':
      act.move(1, 0);
      return true;
    case 'ArrowUp':
      act.move(0, 1);
      return true;
    case 'ArrowDown':
      act.move(0, -1);
      return true;
    case 'PageUp':
    case 'PageDown':
      act.layer(key === 'PageUp' ? 1 : -1);
      return true;
    case ' ':
    case 'Enter':
      act.toggle(false);
      return true;
    case 'Delete':
    case 'Backspace':
      act.toggle(true);
      return true;
    case '[':
    case ']':
      act.slice(key === ']' ? 1 : -1);
      return true;
    case '+':
    case '=':
      act.zoom(1.25);
      return true;
    case '-':
      act.zoom(0.8);
      return true;
    case '0':
      act.fit();
      return true;
    default:
      return false;
  }
}
