// An exercise on a phone (390×844): scrolled to the exercise, its instructions, Check and the
// verdict share the screen with Play (the view and the run controls stay at the top), also once the
// run has ended; every control of the exercise, the run and the click tools is at least 44 px high;
// a locked control looks locked (the seed, New seed, a locked click tool); axe finds nothing.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { describe, test } from 'node:test';
import { loadWasm, openPage, session } from './harness.mjs';

const require = createRequire(import.meta.url);
const AXE = readFileSync(require.resolve('axe-core/axe.min.js'), 'utf8');
const wasm = loadWasm();
const s = session();
const PHONE = { width: 390, height: 844 };

/** Where an element is on the screen: its top and bottom, in CSS pixels. */
const onScreen = (page, selector) =>
  page.$eval(selector, (e) => {
    const r = e.getBoundingClientRect();
    return { top: r.top, bottom: r.bottom };
  });

async function allOnOneScreen(page, selectors, when) {
  for (const selector of selectors) {
    const { top, bottom } = await onScreen(page, selector);
    assert.ok(top >= 0 && bottom <= PHONE.height, `${when}: ${selector} is on the screen (${Math.round(top)} to ${Math.round(bottom)})`);
  }
}

describe('an exercise on a phone', () => {
  test('instructions, Play, Check and the verdict on one screen; targets of 44 px; locks that look locked', async () => {
    const link = wasm.encode_link(wasm.lesson_json('lesson-amas-robots'));
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${link}`, PHONE);
    await page.waitForSelector('#exercise:not([hidden])');
    // Scrolled down to the exercise, as a student does: it comes up under the view and the controls.
    await page.evaluate(() => {
      const stage = document.querySelector('.stage').getBoundingClientRect();
      const exercise = document.querySelector('#exercise').getBoundingClientRect();
      window.scrollTo(0, window.scrollY + exercise.top - stage.height);
    });
    await allOnOneScreen(page, ['#view', '#play', '#exercise-title', '#exercise-instructions', '#exercise-check'], 'scrolled to the exercise');

    const small = await page.$$eval(
      '#exercise button, #exercise input, #exercise textarea, #transport button, #transport input, #timeline, #tools button',
      (es) =>
        es
          .filter((e) => e.getClientRects().length > 0)
          .map((e) => ({ what: e.id || e.dataset.tool || e.tagName, height: e.getBoundingClientRect().height }))
          .filter((t) => t.height < 44),
    );
    assert.deepEqual(small, [], 'every target is at least 44 px high');

    // Locked controls look locked: the seed's box and a locked tool are dashed; New seed is faded.
    assert.equal(await page.$eval('#seed', (i) => i.readOnly && getComputedStyle(i).borderTopStyle), 'dashed');
    assert.ok(Number(await page.$eval('#new-seed', (b) => getComputedStyle(b).opacity)) < 1);
    assert.equal(
      await page.$eval('#tools button[data-tool="remove"]', (b) => b.getAttribute('aria-disabled') === 'true' && getComputedStyle(b).borderTopStyle),
      'dashed',
    );

    // Played to its end: the verdict comes up where the student is looking.
    await page.$eval('#speed', (el) => {
      el.value = '8';
      el.dispatchEvent(new Event('input'));
    });
    await page.click('#play');
    await page.waitForFunction(() => /^(Goal met|Not met)/.test(document.querySelector('#exercise-result').textContent), null, { timeout: 60000 });
    await allOnOneScreen(page, ['#play', '#exercise-instructions', '#exercise-check', '#exercise-result'], 'after Play');

    if (!(await page.evaluate(() => 'axe' in window))) await page.evaluate(AXE);
    const violations = await page.evaluate(async () => {
      const result = await window.axe.run(document, {
        runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'best-practice'] },
        resultTypes: ['violations'],
      });
      return result.violations
        .filter((v) => v.impact === 'serious' || v.impact === 'critical')
        .map((v) => `${v.id} at ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
    });
    assert.deepEqual(violations, []);
    assert.deepEqual(problems, []);
    await context.close();
  });
});
