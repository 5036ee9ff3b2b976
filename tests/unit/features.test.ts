// @vitest-environment happy-dom
// The features' logic without a browser: the page's rooms mounted on the real page context and
// the real core (tests/unit/page.ts), the simulation worker's calls made in this thread. The
// browser tests keep the flows a person performs end to end; what a feature computes and shows is
// checked here. Tests moved from the browser files keep their names.
import { deflateRawSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
import { FEATURES } from '../../web/features/index';
import * as wasm from '../../web/pkg/kumiki_wasm.js';
import { preset, testPage } from './page';

const $ = <T extends HTMLElement = HTMLElement>(selector: string) => {
  const e = document.querySelector<T>(selector);
  if (!e) throw new Error(`no ${selector}`);
  return e;
};
const text = (selector: string) => $(selector).textContent ?? '';

/** Changes a form field as a person would: its value, then its change event. */
function change(selector: string, value: string) {
  const input = $<HTMLInputElement | HTMLSelectElement>(selector);
  input.value = value;
  input.dispatchEvent(new Event('change', { bubbles: true }));
}

/** The page with every feature, opened on the default scenario (amas-L), or on `link` when given. */
async function opened(link?: string) {
  // As the page finds it when it starts (the DOM library tells of the change; the features are not
  // listening yet).
  history.replaceState(null, '', link ? `#${link}` : window.location.pathname);
  await new Promise((r) => setTimeout(r, 0));
  const t = testPage([...FEATURES]);
  if (link) {
    const claim: { opened: Promise<boolean> | null } = { opened: null };
    t.page.events.emit('open-address', claim);
    await claim.opened;
  } else await t.page.session.open(preset('amas-L'), { record: false, opens: true });
  await t.until(() => t.page.session.frame !== null, 'the first frame');
  return t;
}

const linkOf = (doc: unknown) => wasm.encode_link(JSON.stringify(doc));

describe('the page (moved from the browser tests)', () => {
  it('an invalid parameter is refused with a message naming the field, and nothing is lost', async () => {
    const { page, until, worker } = await opened();
    const before = page.session.scenario;
    change('#param-robots', '0');
    await until(() => text('#param-robots-error') !== '', 'the refusal');
    expect(text('#param-robots-error')).toMatch(/^robots:/);
    expect($<HTMLInputElement>('#param-robots').value).toBe('0');
    expect($<HTMLInputElement>('#param-robots').getAttribute('aria-invalid')).toBe('true');
    expect([page.session.scenario, $<HTMLTextAreaElement>('#scenario-json').value]).toEqual([before, before]);
    // One message to the worker, with the change alone.
    expect(worker.sent.at(-1)).toBe('edit {"robots":0}');
  });

  it('the form offers every choice of the schema as a select, with bounds and help text', async () => {
    const { until } = await opened();
    expect($('#param-collision').tagName).toBe('SELECT');
    expect([...document.querySelectorAll('#param-collision option')].map((o) => o.textContent)).toEqual(['token', 'relay', 'blackboard']);
    expect($('#param-field').tagName).toBe('SELECT');
    expect($('#param-supply_rows').getAttribute('max')).toBe('64');
    expect(text('#param-collision-help')).toMatch(/relay: /);
    change('#param-collision', '"relay"');
    await until(() => $<HTMLTextAreaElement>('#scenario-json').value.includes('"collision": "relay"'), 'the change');
    expect(text('#param-collision-error')).toBe('');
  });

  it('text from a link is shown as text, never as HTML', async () => {
    const evil = '<img src=x id=injected onerror="document.body.dataset.pwned=1">';
    const doc = { ...JSON.parse(preset('amas-L')), name: evil, description: evil };
    await opened(linkOf(doc));
    expect(text('#scenario-name')).toBe(evil);
    expect(text('#intro-title')).toBe(evil);
    expect(document.querySelector('#injected')).toBeNull();
    expect(document.body.dataset.pwned).toBeUndefined();
  });
});

describe('a shared link (moved from the browser tests)', () => {
  it('names are shown without bidirectional overrides or NUL, and the banner clears on reset', async () => {
    const spoof = 'report\u202Efdp.exe\u0000';
    const { page, until } = await opened(linkOf({ ...JSON.parse(preset('amas-L')), name: spoof }));
    expect(text('#scenario-name')).toBe('reportfdp.exe');
    expect(document.title).toBe('reportfdp.exe · Kumiki');
    window.location.hash = 'k1.***';
    window.dispatchEvent(new HashChangeEvent('hashchange'));
    await until(() => !$('#banner').hidden, 'the banner');
    expect(text('#banner-text')).toMatch(/damaged: it holds '\*'/);
    $('#reset').click();
    await until(() => $('#banner').hidden, 'the banner to clear');
    expect(page.session.doc().name).toBe(spoof);
  });

  it('introduces itself first: its name and description, in a panel that Escape closes', async () => {
    const description = 'Line one.\nLine two, with <b>markup</b> that stays text.';
    await opened(linkOf({ ...JSON.parse(preset('amas-L')), name: 'Class 3: \u202Eexercise', description }));
    expect($<HTMLDialogElement>('#intro').open).toBe(true);
    expect(text('#intro-title')).toBe('Class 3: exercise');
    expect(text('#intro-model')).toBe('amas');
    expect(text('#intro-description')).toBe('Line one.\nLine two, with <b>markup</b> that stays text.');
    expect(document.querySelector('#intro-description b')).toBeNull();
  });

  it('a link made with another model version opens, with the notice; loading another scenario clears it', async () => {
    const doc = JSON.parse(preset('amas-L'));
    const current = wasm.link_model_versions(linkOf(doc)).current as number;
    const { until } = await opened(linkWithVersion(doc, current + 1));
    expect([text('#scenario-name'), text('#scenario-code')]).toEqual(['The L-shaped benchmark', 'amas-L']);
    expect($('#link-notice').hidden).toBe(false);
    expect(text('#link-notice')).toBe('This link was made with a newer Kumiki; results may differ.');
    expect($('#link-notice').getAttribute('role')).toBe('status');
    $('#step').click();
    await until(() => text('#step-count') === '1', 'a step');
    // A scenario of one's own (here: a new seed) is no longer the link's run.
    $('#new-seed').click();
    await until(() => $('#link-notice').hidden, 'the notice to go');
    expect($('#banner').hidden).toBe(true);
  });
});

/** A link whose JSON says it was made with behaviour version `version` of its model. */
function linkWithVersion(doc: Record<string, unknown>, version: number): string {
  return `k1.${deflateRawSync(Buffer.from(JSON.stringify({ ...doc, model_version: version }))).toString('base64url')}`;
}

describe('error messages (moved from the browser tests)', () => {
  it('a link with a long problem says it briefly, and all of it on request', async () => {
    // A misspelt field: the whole message lists every field AMAS allows (over 200 characters).
    const bad = { ...JSON.parse(preset('amas-L')), robtos: 5 };
    history.replaceState(null, '', `#k1.${deflateRawSync(Buffer.from(JSON.stringify(bad))).toString('base64url')}`);
    await new Promise((r) => setTimeout(r, 0));
    const { page } = testPage([...FEATURES]);
    const claim: { opened: Promise<boolean> | null } = { opened: null };
    page.events.emit('open-address', claim);
    expect(await claim.opened).toBe(false);
    expect($('#banner').hidden).toBe(false);
    expect(text('#banner-text').split('\n')[1]).toBe("robtos: unknown field 'robtos'; did you mean 'robots'?");
    expect(text('#banner-action')).toBe('Show all of it');
    $('#banner-action').click();
    const full = text('#banner-text').split('\n')[1];
    expect(full.length).toBeGreaterThanOrEqual(200);
    expect(full.startsWith("robtos: unknown field 'robtos'; expected one of") && full.includes("'supply_rows'"), full).toBe(true);
  });
});

describe('the exercise (moved from the browser tests)', () => {
  it("the teacher's goal is checked against the model's names as it is typed", async () => {
    const { until } = await opened();
    $('#make-exercise').click();
    const type = async (goal: string) => {
      const input = $<HTMLInputElement>('#ex-goal');
      input.value = goal;
      input.dispatchEvent(new Event('input', { bubbles: true }));
      await until(() => input.getAttribute('aria-invalid') !== null && text('#ex-goal-problem') !== 'pending', goal);
      await new Promise((r) => setTimeout(r, 0));
      return text('#ex-goal-problem');
    };
    expect(await type('completed and metrics.colisions < 40')).toBe("this model has no metric 'colisions'; did you mean 'metrics.collisions'?");
    expect(await type('completed and scenario.robot <= 6')).toBe("the scenario has no field 'robot'; did you mean 'scenario.robots'?");
    expect(await type('completed and metrics.collisions < 40')).toBe('');
  });
});
