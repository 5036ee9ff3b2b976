// The tabs and the page's keys: Space plays, the arrows step, R resets, + - 0 zoom, Ctrl+Z undoes.
import { byId, typingIn } from '../ui/dom';
import type { Page } from './page';
import type { RunPanel } from './run';
import type { ScenarioPanel } from './scenario';

export const TABS = ['run', 'scenario', 'experiments', 'about'];

export interface Keys {
  selectTab(name: string, focus?: boolean): void;
}

export function setupKeys(page: Page, run: RunPanel, scenario: ScenarioPanel): Keys {
  const { view, prefs } = page;

  function selectTab(name: string, focus = false) {
    for (const t of TABS) {
      const tab = byId(`tab-${t}`);
      const on = t === name;
      tab.setAttribute('aria-selected', String(on));
      tab.tabIndex = on ? 0 : -1;
      byId(`panel-${t}`).hidden = !on;
      if (on && focus) tab.focus();
    }
    prefs.tab = name;
    document.body.dataset.tab = name;
    page.persistPrefs();
    run.renderChart();
  }
  for (const t of TABS) {
    const tab = byId(`tab-${t}`);
    tab.addEventListener('click', () => selectTab(t));
    tab.addEventListener('keydown', (e) => {
      // The tabs shown (an embed shows only some of them).
      const shown = TABS.filter((n) => byId(`tab-${n}`).getClientRects().length > 0);
      const i = shown.indexOf(t);
      if (e.key === 'ArrowRight' || e.key === 'ArrowLeft') {
        e.preventDefault();
        e.stopPropagation();
        selectTab(shown[(i + (e.key === 'ArrowRight' ? 1 : shown.length - 1)) % shown.length], true);
      }
    });
  }

  /** When the Left arrow held down was first pressed. */
  let heldSince = 0;
  /**
   * Steps one Left-arrow event goes back: a press goes back one; held, the key's repeats scrub,
   * one step each for the first half second, then twice as many every further half second (to
   * 64), so a long run can be crossed by holding the key.
   */
  function backStride(e: KeyboardEvent): number {
    if (!e.repeat) {
      heldSince = e.timeStamp;
      return 1;
    }
    return 2 ** Math.min(6, Math.floor(Math.max(0, e.timeStamp - heldSince) / 500));
  }

  document.addEventListener('keydown', (e) => {
    if (e.defaultPrevented || typingIn(e.target) || (document.querySelector('dialog[open]') && e.key !== 'Escape')) return;
    if ((e.ctrlKey || e.metaKey) && e.key.toLowerCase() === 'z') {
      e.preventDefault();
      if (e.shiftKey) scenario.redo();
      else scenario.undo();
      return;
    }
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    // The page's keys act only when no control has the focus: Space on a checkbox ticks it, and
    // the arrows move sliders and tool groups. Left steps back only from the view.
    const onView = e.target === byId('view');
    if (
      !onView &&
      e.target instanceof HTMLElement &&
      e.target !== document.body &&
      e.target.closest('input, select, textarea, button, a, summary, [role="radiogroup"], [role="tablist"], [tabindex]')
    )
      return;
    switch (e.key) {
      case ' ':
        e.preventDefault();
        run.togglePlay();
        return;
      case 'ArrowRight':
        e.preventDefault();
        run.stepOnce();
        return;
      case 'ArrowLeft':
        if (!onView) return;
        e.preventDefault();
        run.stepBack(backStride(e));
        return;
      case 'r':
      case 'R':
        e.preventDefault();
        run.reset();
        return;
      case '+':
      case '=':
        view.zoom(1.25);
        return;
      case '-':
        view.zoom(0.8);
        return;
      case '0':
        view.fit();
        return;
    }
  });
  byId('zoom-in').addEventListener('click', () => view.zoom(1.25));
  byId('zoom-out').addEventListener('click', () => view.zoom(0.8));
  byId('zoom-fit').addEventListener('click', () => view.fit());

  return { selectTab };
}
