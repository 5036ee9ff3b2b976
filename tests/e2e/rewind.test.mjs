// Rewind from the keyboard: every press of the Left arrow counts, however fast they come (a rewind
// takes the worker a while, and presses made meanwhile used to be lost), and holding the key
// scrubs back, faster the longer it is held.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { openPage, session, settle, stepCount } from './harness.mjs';

const s = session();

/** The default scenario (amas-L) run to its end at full speed, paused there; its last step. */
async function runToEnd(page) {
  await page.$eval('#speed', (el) => {
    el.value = el.max;
    el.dispatchEvent(new Event('input'));
  });
  await page.click('#play');
  await page.waitForSelector('#run-status:not(:empty)', { timeout: 60000 });
  await page.waitForSelector('#play[aria-pressed="false"]');
  await settle(page);
  return stepCount(page);
}

describe('rewind keys', () => {
  test('twenty quick presses of the Left arrow go back twenty steps', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    const end = await runToEnd(page);
    assert.ok(end > 100, `the run reached ${end}`);
    await page.locator('#view').focus();
    // Every frame shown on the way: the steps go down, never past the last press's target.
    await page.evaluate(() => {
      window.shownSteps = [];
      new MutationObserver(() => window.shownSteps.push(Number(document.querySelector('#step-count').textContent.replace(/,/g, '')))).observe(
        document.querySelector('#step-count'),
        { childList: true, characterData: true, subtree: true },
      );
    });
    for (let i = 0; i < 20; i++) await page.keyboard.press('ArrowLeft');
    await page.waitForFunction((n) => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) === n, end - 20, { timeout: 20000 });
    await settle(page);
    assert.equal(await stepCount(page), end - 20);
    const shown = await page.evaluate(() => window.shownSteps);
    assert.ok(
      shown.every((v) => v >= end - 20 && v < end),
      `steps shown: ${shown}`,
    );
    // And Right steps forward again from there.
    await page.keyboard.press('ArrowRight');
    await page.waitForFunction((n) => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) === n, end - 19);
    await context.close();
  });

  test('holding the Left arrow scrubs back, faster the longer it is held', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    const end = await runToEnd(page);
    await page.locator('#view').focus();
    await page.evaluate(() => {
      window.leftKeys = [];
      document.addEventListener('keydown', (e) => e.key === 'ArrowLeft' && window.leftKeys.push({ repeat: e.repeat, t: e.timeStamp }), { capture: true });
    });
    // A held key: one keydown, then repeats (Playwright marks a second down of a held key as a
    // repeat) about every 50 ms for 1.6 s, as a keyboard's auto-repeat sends them.
    const events = 32;
    for (let i = 0; i < events; i++) {
      await page.keyboard.down('ArrowLeft');
      await page.waitForTimeout(50);
    }
    await page.keyboard.up('ArrowLeft');
    // Each event's stride: one step for the first half second held, then twice as many every
    // further half second (to 64), counted from the key's first press.
    const keys = await page.evaluate(() => window.leftKeys);
    assert.equal(keys.length, events);
    assert.equal(keys.filter((k) => k.repeat).length, events - 1);
    const strides = keys.map((k) => (k.repeat ? 2 ** Math.min(6, Math.floor((k.t - keys[0].t) / 500)) : 1));
    const want = Math.max(0, end - strides.reduce((a, b) => a + b, 0));
    await page.waitForFunction((n) => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) === n, want, { timeout: 20000 });
    await settle(page);
    assert.equal(await stepCount(page), want);
    assert.ok(end - want > events, `held for ${events} events it went back ${end - want} steps: it scrubs faster than one step an event`);
    await context.close();
  });
});
