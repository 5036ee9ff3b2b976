// The page's keys: Space plays, the arrows step, R resets, + - 0 zoom (the run feature's), Ctrl+Z
// undoes (the scenario feature's). A key is the page's when it is not typed into a field and no
// dialog is open (Escape aside); a plain key only when no control has the focus, so that Space
// ticks a checkbox and the arrows move sliders and tool groups. The view counts as the page.
import { typingIn } from '../widgets/dom';

/** Where a key of the page was pressed: on the view, or elsewhere on the page. */
export interface KeyPlace {
  onView: boolean;
}

/** True when a keydown is the page's at all. */
function pages(e: KeyboardEvent): boolean {
  return !(e.defaultPrevented || typingIn(e.target) || (document.querySelector('dialog[open]') && e.key !== 'Escape'));
}

/** The control that has the focus takes plain keys itself. */
function controlFocused(e: KeyboardEvent, onView: boolean): boolean {
  return (
    !onView &&
    e.target instanceof HTMLElement &&
    e.target !== document.body &&
    !!e.target.closest('input, select, textarea, button, a, summary, [role="radiogroup"], [role="tablist"], [tabindex]')
  );
}

/** Calls `listener` for the page's keys pressed with Ctrl or ⌘ (shortcuts). */
export function onShortcut(listener: (e: KeyboardEvent) => void) {
  document.addEventListener('keydown', (e) => {
    if (pages(e) && (e.ctrlKey || e.metaKey)) listener(e);
  });
}

/** Calls `listener` for the page's plain keys (no Ctrl, ⌘ or Alt), unless a control has the focus. */
export function onPlainKey(listener: (e: KeyboardEvent, place: KeyPlace) => void) {
  document.addEventListener('keydown', (e) => {
    if (!pages(e) || e.ctrlKey || e.metaKey || e.altKey) return;
    const onView = e.target === document.getElementById('view');
    if (!controlFocused(e, onView)) listener(e, { onView });
  });
}
