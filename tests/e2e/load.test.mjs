// The first load as a visitor meets it: the page's wasm module is held back (a slow network), and
// a Play pressed while it arrives, by a click or by Space, starts the run once the page can run
// it, without a second press; a page used while it loaded gets no welcome over it, and on a first
// visit left alone the welcome is open before the page is ready, never after.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { audit, session, waitForSteps } from './harness.mjs';

const s = session();
/** How long the page's wasm module is held back. */
const HOLD_MS = 2500;

/**
 * A first visit (no link, nothing stored) whose wasm module is held back HOLD_MS: resolves once
 * the page's script runs (its module scripts ran before DOMContentLoaded), the module still held.
 * The page records whether the welcome was open when it marked itself ready.
 */
async function slowFirstVisit() {
  const context = await s.browser.newContext({ viewport: { width: 1280, height: 800 }, serviceWorkers: 'block' });
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  let held = 0;
  await page.route(/kumiki_wasm_bg-[\w-]+\.wasm$/, async (route) => {
    held++;
    await new Promise((r) => setTimeout(r, HOLD_MS));
    await route.continue();
  });
  await page.addInitScript(() => {
    new MutationObserver((_, observer) => {
      if (document.body?.dataset.ready !== 'true') return;
      observer.disconnect();
      window.welcomeAtReady = document.querySelector('#welcome')?.open ?? false;
    }).observe(document, { attributes: true, subtree: true, attributeFilter: ['data-ready'] });
  });
  await page.goto(s.server.url, { waitUntil: 'domcontentloaded' });
  assert.ok(held > 0, 'the wasm module was asked for and is held');
  assert.equal(await page.evaluate(() => document.body.dataset.ready), undefined, 'the page is still loading');
  return { context, page, problems };
}

describe('the first load', () => {
  test('a Play clicked while the page loads starts the run once it can, and no welcome opens over it', async () => {
    const { context, page, problems } = await slowFirstVisit();
    await page.click('#play');
    assert.equal(await page.getAttribute('#play', 'aria-pressed'), 'true', 'the press shows');
    assert.equal(await page.getAttribute('#play', 'aria-label'), 'Pause (Space)');
    await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
    assert.ok((await waitForSteps(page, 10)) >= 10, 'the run plays without another press');
    assert.equal(await page.getAttribute('#play', 'aria-pressed'), 'true');
    assert.equal(await page.evaluate(() => window.welcomeAtReady), false);
    assert.equal(await page.isVisible('#welcome'), false, 'the welcome does not open over a page in use');
    assert.deepEqual(await audit(page, 'playing after an early press'), []);
    await page.click('#play');
    await page.waitForSelector('#play[aria-pressed="false"]');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('Space pressed while the page loads plays too; pressed twice, it does not', async () => {
    for (const presses of [1, 2]) {
      const { context, page, problems } = await slowFirstVisit();
      for (let i = 0; i < presses; i++) await page.keyboard.press('Space');
      await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
      if (presses === 1) assert.ok((await waitForSteps(page, 5)) >= 5);
      else {
        await page.waitForTimeout(1000);
        assert.equal(await page.textContent('#step-count'), '0', 'two presses: play, then pause');
        assert.equal(await page.getAttribute('#play', 'aria-pressed'), 'false');
      }
      assert.deepEqual(problems, []);
      await context.close();
    }
  });

  test('a first visit left alone: the welcome is open before the page is ready', async () => {
    const { context, page, problems } = await slowFirstVisit();
    await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
    assert.equal(await page.evaluate(() => window.welcomeAtReady), true);
    assert.equal(await page.isVisible('#welcome'), true);
    await page.click('#welcome-skip');
    await page.click('#play');
    assert.ok((await waitForSteps(page, 5)) >= 5);
    assert.deepEqual(problems, []);
    await context.close();
  });
});
