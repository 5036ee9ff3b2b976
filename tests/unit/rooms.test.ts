// @vitest-environment happy-dom
// The page's rooms one by one, without a browser (tests/unit/page.ts): the gallery's cards, the
// click tools and their note, the comparison's choices, the exercise's hints and locks, the About
// tab's debug control, and the first screen's metrics from the model's table.
import { describe, expect, it } from 'vitest';
import { FEATURES } from '../../web/features/index';
import * as wasm from '../../web/pkg/kumiki_wasm.js';
import { catalog, preset, startCore, testPage } from './page';

const $ = <T extends HTMLElement = HTMLElement>(selector: string) => {
  const e = document.querySelector<T>(selector);
  if (!e) throw new Error(`no ${selector}`);
  return e;
};
const all = (selector: string) => [...document.querySelectorAll<HTMLElement>(selector)];

/** Every feature mounted, the scenario `text` opened, its first frame shown. */
async function page(text = preset('amas-L')) {
  history.replaceState(null, '', window.location.pathname);
  await new Promise((r) => setTimeout(r, 0));
  const t = testPage([...FEATURES]);
  expect(await t.page.session.open(text, { record: false, opens: true })).toBe(true);
  await t.until(() => t.page.session.frame !== null, 'the first frame');
  return t;
}

describe('the gallery', () => {
  it('lists every lesson and built-in scenario, each titled in words with its code name beside it, and filters them', async () => {
    const { until } = await page();
    $('#open-scenarios').click();
    // It opens once the catalogue (web/pkg/catalog.json) has arrived.
    await until(() => $<HTMLDialogElement>('#gallery').open, 'the gallery');
    expect(all('#gallery-list [data-preset]').length).toBe(catalog.presets.length);
    expect(all('#gallery-list [data-lesson]').length).toBe(catalog.lessons.length);
    const card = $('#gallery-list [data-preset="fracta-repair"]');
    expect([card.querySelector('strong')?.textContent, card.querySelector('.card-code')?.textContent]).toEqual(['A triangle repairs itself', 'fracta-repair']);
    // Each card has a place for its picture, for the picture worker to fill as it comes into view.
    expect(card.querySelector('canvas.card-picture')?.getAttribute('aria-hidden')).toBe('true');
    const filter = $<HTMLInputElement>('#gallery-filter');
    filter.value = 'repairs itself';
    filter.dispatchEvent(new Event('input'));
    expect(all('#gallery-list [data-preset]').map((c) => c.dataset.preset)).toEqual(['fracta-repair', 'fracta-repair-corner']);
  });

  it('opens a chosen scenario, and its name in words heads the page', async () => {
    const { until } = await page();
    $('#open-scenarios').click();
    await until(() => $<HTMLDialogElement>('#gallery').open, 'the gallery');
    $('#gallery-list [data-preset="cubes-light"]').click();
    await until(() => $('#scenario-code').textContent === 'cubes-light', 'the scenario');
    expect([$('#scenario-name').textContent, $('#scenario-model').textContent, document.title]).toEqual([
      'A cube walks toward a light',
      'cubes3d',
      'A cube walks toward a light · Kumiki',
    ]);
  });
});

describe('the first screen', () => {
  it("shows the model's key metrics first and its internal counters only in the debug view", async () => {
    await page(preset('cubes-light'));
    startCore();
    const table = wasm.metric_table('cubes3d') as { name: string; shown: string }[];
    const names = (selector: string) => all(`${selector} .metric > span:first-child`).map((s) => s.textContent);
    expect(names('#metrics-key')).toEqual(table.filter((m) => m.shown === 'key').map((m) => m.name.replace(/_/g, ' ')));
    expect(names('#metrics-more')).not.toContain('connectivity checks');
    expect(table.some((m) => m.name === 'connectivity_checks' && m.shown === 'debug')).toBe(true);
    // The chart offers what is shown, and charts the model's own choice first.
    expect([...$<HTMLSelectElement>('#chart-metric').options].map((o) => o.value)).not.toContain('connectivity_checks');
  });
});

describe('the click tools', () => {
  it("offer the model's disturbances, and note those the scenario carries with a way to clear them", async () => {
    const doc = { ...JSON.parse(preset('amas-L')), disturbances: [{ at: 5, kind: 'remove', count: 2 }] };
    const { page: p, until } = await page(JSON.stringify(doc));
    expect(all('#tools button').map((b) => b.dataset.tool)).toEqual(['inspect', ...(p.session.layout?.tools.map((t) => t.name) ?? [])]);
    expect($('#tools').getAttribute('role')).toBe('radiogroup');
    const note = $('.recorded');
    expect(note.textContent).toMatch(/^1 scheduled or recorded disturbance\. /);
    note.querySelector('button')?.click();
    await until(() => document.querySelector('.recorded') === null, 'the note to go');
    expect(p.session.doc().disturbances ?? []).toEqual([]);
  });

  it('are offered locked, each with the reason, when the exercise allows no disturbance', async () => {
    const doc = { ...JSON.parse(preset('amas-L')), disturbances: [{ at: 5, kind: 'remove', count: 2 }] };
    doc.exercise = { title: 'Locked', instructions: 'Watch.', locked: { disturbances: doc.disturbances }, goal: 'completed', hints: [] };
    const { page: p, until } = await page(JSON.stringify(doc));
    const tools = p.session.layout?.tools ?? [];
    expect(all('#tools button').map((b) => b.dataset.tool)).toEqual(['inspect', ...tools.map((t) => t.name)]);
    await until(() => all('#tools button[aria-disabled="true"]').length === tools.length, 'the locks');
    for (const t of tools) {
      const b = $(`#tools button[data-tool="${t.name}"]`);
      const why = document.getElementById(b.getAttribute('aria-describedby') ?? '')?.textContent;
      expect(why).toBe(`${t.label} is locked by the exercise: it allows no '${t.action.kind}' disturbance`);
    }
    // Nor is a way to clear those it carries.
    expect(document.querySelector('.recorded')).toBeNull();
  });
});

describe('two runs compared', () => {
  it("offer every choice and switch of the model's settings with its other values, and numbers within their bounds", async () => {
    await page();
    const settings = [...$<HTMLSelectElement>('#compare-setting').options].map((o) => o.value);
    expect(settings).toContain('collision');
    expect(settings).not.toContain('name');
    expect(settings).not.toContain('max_steps');
    const setting = $<HTMLSelectElement>('#compare-setting');
    setting.value = 'collision';
    setting.dispatchEvent(new Event('change'));
    // The scenario's own value is not among the second run's.
    expect([...$<HTMLSelectElement>('#compare-value').options].map((o) => o.textContent)).toEqual(['relay', 'blackboard']);
    setting.value = 'supply_rows';
    setting.dispatchEvent(new Event('change'));
    const number = $<HTMLInputElement>('#compare-number');
    expect([number.hidden, number.max, number.step]).toEqual([false, '64', '1']);
  });
});

describe('an exercise', () => {
  it('reveals its hints one at a time, and its locked seed cannot be changed', async () => {
    const doc = JSON.parse(preset('amas-L'));
    doc.exercise = { title: 'Hints', instructions: 'Try.', locked: { seed: 1 }, goal: 'completed', hints: ['First.', 'Second.'] };
    await page(JSON.stringify(doc));
    expect($('#exercise').hidden).toBe(false);
    expect($('#exercise-hint').textContent).toBe('Show a hint (2 left)');
    $('#exercise-hint').click();
    $('#exercise-hint').click();
    expect(all('#exercise-hints li').map((l) => l.textContent)).toEqual(['First.', 'Second.']);
    expect([$('#exercise-hint').textContent, $<HTMLButtonElement>('#exercise-hint').disabled]).toEqual(['No more hints', true]);
    expect([$<HTMLInputElement>('#seed').readOnly, $<HTMLButtonElement>('#new-seed').disabled]).toEqual([true, true]);
    expect($('#seed').getAttribute('aria-label')).toBe('Random seed, locked by the exercise');
  });
});

describe('the About tab', () => {
  it('shows the version, and the crash button only in the debug view', async () => {
    await page();
    startCore();
    expect($('#diag-version').textContent).toBe(wasm.version());
    expect($('#simulate-crash').hidden).toBe(true);
  });
});

describe('every built-in scenario', () => {
  it('every chobie preset opens with its robots, terrain and no error', async () => {
    startCore();
    const chobie = catalog.presets.filter((p) => p.model === 'chobie').map((p) => p.name);
    expect(chobie.length).toBeGreaterThanOrEqual(11);
    const { page: p, until } = await page();
    for (const name of chobie) {
      expect(await p.session.open(preset(name), { opens: true }), name).toBe(true);
      await until(() => $('#scenario-code').textContent === name && p.session.frame?.metrics.robots !== undefined, name);
      expect($('#scenario-model').textContent).toBe('chobie');
      const legend = all('#legend span').map((x) => x.textContent);
      for (const entry of ['terrain', 'R: resting robot', 'D: driving robot']) expect(legend, `${name}: ${legend.join(', ')}`).toContain(entry);
      const robots = all('#metrics .metric')
        .find((m) => m.firstChild?.textContent === 'robots')
        ?.querySelector('strong')?.textContent;
      expect(Number(robots), name).toBeGreaterThanOrEqual(3);
      expect($('#banner').hidden, name).toBe(true);
    }
  });

  it('each opens in the page with its legend, its key metrics and its chart, and no message', async () => {
    startCore();
    const { page: p, until } = await page();
    for (const { name, model } of catalog.presets) {
      expect(await p.session.open(preset(name), { opens: true }), name).toBe(true);
      await until(() => $('#scenario-code').textContent === name, name);
      expect($('#scenario-model').textContent, name).toBe(model);
      expect(all('#legend span').length, name).toBeGreaterThan(0);
      expect(all('#metrics-key .metric').length, name).toBeGreaterThan(0);
      expect($<HTMLSelectElement>('#chart-metric').value, name).not.toBe('');
      expect($('#banner').hidden, name).toBe(true);
    }
  });
});

describe('the type-list editor (moved from the browser tests)', () => {
  it('a malformed type-list shows an error naming the line, and keeps the text', async () => {
    const { page: p, until } = await page(preset('cubes-cube8-zigzag'));
    const before = (p.session.doc().targets as unknown[]).map((t) => JSON.stringify(t));
    const area = $<HTMLTextAreaElement>('#cubes-target-0-lists');
    const type = (text: string) => {
      area.value = text;
      area.dispatchEvent(new Event('input', { bubbles: true }));
    };
    const typed = 'C31[C31, C31, C31]\nC99[C1]';
    type(typed);
    await until(() => /line 2/.test($('#cubes-target-0-error').textContent ?? ''), 'the error');
    expect($('#cubes-target-0-error').textContent).toMatch(/line 2, column 1: unknown connection type 'C99'/);
    $('button[aria-label="Apply the type-lists of target 1"]').click();
    await new Promise((r) => setTimeout(r, 10));
    expect([area.value, area.getAttribute('aria-invalid')]).toEqual([typed, 'true']);
    expect(
      (p.session.doc().targets as unknown[]).map((t) => JSON.stringify(t)),
      'the scenario keeps its valid targets',
    ).toEqual(before);
    type('C31[C31, C31]');
    await until(() => /valence 3/.test($('#cubes-target-0-error').textContent ?? ''), 'the valence');
    expect($('#cubes-target-0-error').textContent).toMatch(/line 1/);
  });
});

describe('the reproduction report', () => {
  it("shows the model in view's claims beside Kumiki's figures, from the lab module, each opening its experiment", async () => {
    const { readFileSync } = await import('node:fs');
    const { resolve } = await import('node:path');
    const bytes = readFileSync(resolve(__dirname, '../../web/pkg/kumiki_lab_bg.wasm'));
    // The lab module is fetched as the page fetches it.
    const fetched: string[] = [];
    const realFetch = globalThis.fetch;
    globalThis.fetch = (async (url: string) => {
      fetched.push(String(url));
      return new Response(bytes, { headers: { 'content-type': 'application/wasm' } });
    }) as typeof fetch;
    try {
      const { page: p, until } = await page();
      const opened: string[] = [];
      p.events.on('open-experiment', (name) => opened.push(name));
      $('#tab-about').click();
      await until(() => document.querySelector('#paper-report table.findings') !== null, 'the report');
      const report = JSON.parse(readFileSync(resolve(__dirname, '../../docs/reproduction.json'), 'utf8')).models.amas;
      expect(all('#paper-report table.findings tbody tr').length).toBe(report.findings.length);
      expect(all('#paper-report .claim-text')[0].textContent).toBe(report.findings[0].claim);
      expect($('#paper-report .citation').textContent).toBe(report.citation);
      expect(fetched.some((u) => u.includes('kumiki_lab_bg'))).toBe(true);
      // Each experiment behind the figures opens in the Experiments tab (through the page's events).
      all('#paper-report p.row-buttons button')[0].click();
      expect(opened).toEqual([report.experiments[0]]);
    } finally {
      globalThis.fetch = realFetch;
    }
  });
});
