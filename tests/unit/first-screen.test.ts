// @vitest-environment happy-dom
// The first screen's logic, without a browser: which metrics show first, where the tour's box and
// the metric tooltips go, and how the tabs gather the features' sections.
import { beforeAll, describe, expect, it } from 'vitest';

import type { MetricInfo } from '../../web/contract.gen';
import { arrangeMetrics, metricCard, metricText } from '../../web/features/run/cards';
import { MIN_WIDTH, placeBeside, type Rect } from '../../web/features/welcome/place';
import { Events } from '../../web/page/events';
import type { PageEvents } from '../../web/page/context';
import { Tabs } from '../../web/page/tabs';
import { tipPlace } from '../../web/widgets/tooltip';
import { startCore } from './page';

// Numbers are written by the core's one rule (web/wasm.ts's formatNumber).
beforeAll(startCore);

const info = (name: string, shown: MetricInfo['shown']): MetricInfo => ({ name, unit: 'count', about: `About ${name}.`, shown });

describe('the metrics of the first screen', () => {
  const table = new Map(
    [info('steps', 'more'), info('built', 'key'), info('collisions', 'key'), info('checks', 'debug'), info('placed', 'more')].map((m) => [m.name, m]),
  );

  it("shows the model's key metrics first, in its table's order, and the rest a click away", () => {
    const { key, more } = arrangeMetrics(['placed', 'collisions', 'steps', 'built', 'checks', 'unknown'], table, false);
    expect(key.map((m) => m.name)).toEqual(['built', 'collisions']);
    expect(more.map((m) => m.name)).toEqual(['steps', 'placed', 'unknown']);
  });

  it('shows a fraction as a percentage, anything else as a number', () => {
    const fraction = { ...info('built', 'key'), unit: 'fraction' };
    expect([metricText(0.48864, fraction), metricText(1, fraction), metricText(12345, info('steps', 'more')), metricText(null, fraction)]).toEqual([
      '48.9 %',
      '100 %',
      '12,345',
      '–',
    ]);
  });

  it('keeps the internal counters for the debug view', () => {
    const { more } = arrangeMetrics(['steps', 'checks'], table, true);
    expect(more.map((m) => m.name)).toEqual(['steps', 'checks']);
    expect(metricCard('checks', table.get('checks'), null).node.classList.contains('internal')).toBe(true);
  });

  it('a card names its metric in words, explains it and holds both runs while comparing', () => {
    const card = metricCard('built', table.get('built'), ['module relay', 'tokens only']);
    expect(card.node.firstElementChild?.textContent).toBe('built');
    expect(card.node.getAttribute('aria-describedby')).toBe('metric-about-built');
    expect(card.node.querySelector('[role="tooltip"]')?.textContent).toBe('About built. Unit: count.');
    expect(card.second).not.toBeNull();
    expect(card.node.textContent).toContain('module relay: ');
    expect(metricCard('mystery', undefined, null).node.hasAttribute('tabindex')).toBe(false);
  });
});

describe("the tour's box", () => {
  const view = { width: 1366, height: 768 };
  /** A box whose text needs 180 px of height at 520 px wide, more when narrower. */
  const heightAt = (w: number) => Math.ceil((180 * 520) / w);
  const overlap = (a: Rect, b: Rect) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
  const boxOf = (p: { left: number; top: number; width: number }): Rect => ({
    left: p.left,
    top: p.top,
    right: p.left + p.width,
    bottom: p.top + heightAt(p.width),
  });

  it('never covers the part of the page it points at, and stays on the screen', () => {
    const targets: Rect[] = [
      { left: 14, top: 70, right: 950, bottom: 606 }, // the view
      { left: 14, top: 615, right: 950, bottom: 655 }, // the run controls
      { left: 14, top: 700, right: 950, bottom: 732 }, // the timeline
      { left: 962, top: 70, right: 1352, bottom: 110 }, // the tabs
      { left: 665, top: 8, right: 972, bottom: 48 }, // the ways in
    ];
    for (const target of targets) {
      const p = placeBeside(target, 520, heightAt, view);
      const box = boxOf(p);
      expect(p.overlaps, JSON.stringify(target)).toBe(false);
      expect(overlap(box, target), JSON.stringify({ target, box })).toBe(false);
      expect(box.left >= 0 && box.top >= 0 && box.right <= view.width && box.bottom <= view.height).toBe(true);
      expect(p.width).toBeGreaterThanOrEqual(MIN_WIDTH);
    }
  });

  it('goes below when there is room, above otherwise, centred on what it points at', () => {
    const below = placeBeside({ left: 600, top: 100, right: 700, bottom: 140 }, 400, () => 150, view);
    expect([below.top, below.left]).toEqual([152, 450]);
    const above = placeBeside({ left: 600, top: 600, right: 700, bottom: 740 }, 400, () => 150, view);
    expect(above.top + 150).toBeLessThanOrEqual(588);
  });

  it('when no side has room it overlaps, but stays on the screen', () => {
    const p = placeBeside({ left: 0, top: 0, right: 1366, bottom: 768 }, 520, heightAt, view);
    expect(p.overlaps).toBe(true);
    expect(p.left + p.width).toBeLessThanOrEqual(view.width);
  });
});

describe('metric tooltips', () => {
  const viewport = { width: 1366, height: 768 };
  it('open below and to the right, inside the screen', () => {
    expect(tipPlace({ left: 980, top: 120, right: 1150, bottom: 170 }, 240, 60, viewport)).toEqual({ x: 0, y: 54 });
  });
  it("flip to the left at the screen's right edge and above at its bottom", () => {
    const at = tipPlace({ left: 1180, top: 700, right: 1350, bottom: 750 }, 240, 60, viewport);
    expect(1180 + at.x + 240).toBeLessThanOrEqual(1366);
    expect(at.y).toBe(-64);
  });
});

describe('the tabs', () => {
  it("are the features' own, in the list's order, and gather several features' sections by order", () => {
    document.body.innerHTML = '<aside><div id="side-tabs" role="tablist"></div></aside>';
    const prefs = { tab: 'run' } as never;
    const shown: string[] = [];
    const events = new Events<PageEvents>();
    events.on('tab', (t) => shown.push(t));
    const tabs = new Tabs(prefs, () => {}, events);
    tabs.add('run', 'Run');
    tabs.add('about', 'About');
    tabs.section('run', '<p id="later">later</p>', 30);
    tabs.section('run', '<p id="first">first</p>', 10);
    tabs.section('about', '<h2>About Kumiki</h2>', 10);
    expect([...document.querySelectorAll('[role="tab"]')].map((t) => t.textContent)).toEqual(['Run', 'About']);
    expect([...document.querySelectorAll('#panel-run p')].map((p) => p.id)).toEqual(['first', 'later']);
    // A section that brings its own heading replaces the panel's hidden one.
    expect(document.querySelectorAll('#panel-about h2').length).toBe(1);
    expect(document.querySelector<HTMLElement>('#panel-about')?.hidden).toBe(true);
    tabs.select('about');
    expect([document.querySelector<HTMLElement>('#panel-run')?.hidden, document.querySelector<HTMLElement>('#panel-about')?.hidden]).toEqual([true, false]);
    expect(document.querySelector('#tab-about')?.getAttribute('aria-selected')).toBe('true');
    expect([shown, (prefs as { tab: string }).tab, document.body.dataset.tab]).toEqual([['about'], 'about', 'about']);
  });
});
