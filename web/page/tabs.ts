// The side's tabs: one per feature that has one, in the order of the features' list, each with its
// panel. A feature adds its markup to any tab's panel as a section placed by its order, so one
// panel can gather several features (the Run tab: the exercise, the metrics and the chart, the
// comparison's controls, the click tools).
import { byId, el, markup } from '../widgets/dom';
import type { Events } from './events';
import type { PageEvents } from './context';
import type { Prefs } from './store';

export class Tabs {
  private readonly names: string[] = [];
  private readonly list = byId('side-tabs');

  constructor(
    private readonly prefs: Prefs,
    private readonly persist: () => void,
    private readonly events: Events<PageEvents>,
  ) {}

  /** Adds a tab and its empty panel, after those added before it. */
  add(name: string, label: string) {
    const first = this.names.length === 0;
    this.names.push(name);
    const tab = el('button', {
      role: 'tab',
      id: `tab-${name}`,
      'aria-controls': `panel-${name}`,
      'aria-selected': String(first),
      type: 'button',
      tabindex: first ? undefined : -1,
      text: label,
    });
    // Named for a screen reader's list of headings, unless a section brings a heading of its own.
    const panel = el(
      'section',
      { role: 'tabpanel', id: `panel-${name}`, 'aria-labelledby': `tab-${name}`, class: 'panel', hidden: !first },
      el('h2', { class: 'sr-only', text: label }),
    );
    this.list.append(tab);
    (this.list.parentElement ?? document.body).append(panel);
    tab.addEventListener('click', () => this.select(name));
    tab.addEventListener('keydown', (e) => {
      // The tabs shown (an embed shows only some of them).
      const shown = this.names.filter((n) => byId(`tab-${n}`).getClientRects().length > 0);
      const i = shown.indexOf(name);
      if (e.key === 'ArrowRight' || e.key === 'ArrowLeft') {
        e.preventDefault();
        e.stopPropagation();
        this.select(shown[(i + (e.key === 'ArrowRight' ? 1 : shown.length - 1)) % shown.length], true);
      }
    });
  }

  /** Every tab's name, in order. */
  get all(): readonly string[] {
    return this.names;
  }

  /**
   * Adds `html` to a tab's panel, before the sections of a higher `order`; returns the section.
   * A section's markup is the feature's own file.
   */
  section(tab: string, html: string, order: number): HTMLElement {
    const panel = byId(`panel-${tab}`);
    const section = el('div', { class: 'panel-section', 'data-order': order });
    section.append(markup(html));
    if (section.firstElementChild?.tagName === 'H2') panel.querySelector(':scope > h2.sr-only')?.remove();
    const after = [...panel.querySelectorAll<HTMLElement>(':scope > .panel-section')].find((s) => Number(s.dataset.order) > order);
    panel.insertBefore(section, after ?? null);
    return section;
  }

  /** Shows a tab's panel (and focuses its tab when `focus`). */
  select(name: string, focus = false) {
    for (const t of this.names) {
      const tab = byId(`tab-${t}`);
      const on = t === name;
      tab.setAttribute('aria-selected', String(on));
      tab.tabIndex = on ? 0 : -1;
      byId(`panel-${t}`).hidden = !on;
      if (on && focus) tab.focus();
    }
    this.prefs.tab = name;
    document.body.dataset.tab = name;
    this.persist();
    this.events.emit('tab', name);
  }
}
