// A large scenario opens in the simulation worker first: the page says so with a notice and a
// busy bar, stays responsive while the worker builds it and while it draws it (no task on the main
// thread of a second or more, a click answered at once), and the scenario then runs. One the
// worker refuses leaves the scenario in view as it was.
//
// The main thread's tasks are measured with the Long Tasks API rather than by gaps between
// animation frames: on a shared machine headless Chromium's compositor can skip frames for a
// second while the page's own thread is idle, and that is not the page hanging.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { describe, test } from 'node:test';
import { deflateRawSync } from 'node:zlib';
import { loadWasm, openPage, session, waitForSteps } from './harness.mjs';

const wasm = loadWasm();
const s = session();

/** A share link for any scenario text, valid or not, made the way the page makes them. */
const linkOf = (text) => `k1.${deflateRawSync(Buffer.from(text)).toString('base64url')}`;

/** The page's largest AMAS: 4096 cells wide and, with its 8 supply rows, 4096 high. */
function largestAmas(keys = {}) {
  const bench = JSON.parse(readFileSync(new URL('../bench/amas-square1024.json', import.meta.url), 'utf8')).scenario;
  return JSON.stringify({ ...bench, name: 'amas-4096', target: { rect: [4096, 4088] }, initial: { rect: [4096, 4000] }, ...keys });
}

/**
 * Starts recording, in the page, the main thread's tasks longer than 50 ms and how long each click
 * waited before its handlers ran; `done` returns them (ms).
 */
async function watchMainThread(page) {
  await page.evaluate(() => {
    const record = { tasks: [], clicks: [] };
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) record.tasks.push(e.duration);
    }).observe({ type: 'longtask' });
    document.addEventListener('click', (e) => record.clicks.push(performance.now() - e.timeStamp), { capture: true });
    document.addEventListener('kumiki-test-done', () => (document.body.dataset.mainThread = JSON.stringify(record)));
  });
  return {
    done: async () => {
      await page.evaluate(() => document.dispatchEvent(new Event('kumiki-test-done')));
      return JSON.parse(await page.evaluate(() => document.body.dataset.mainThread));
    },
  };
}

describe('large scenarios', () => {
  test('the largest AMAS opens in the worker with a notice; the page answers meanwhile and it runs', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    const watch = await watchMainThread(page);
    const link = wasm.encode_link(largestAmas());
    await page.evaluate((l) => {
      location.hash = l;
    }, link);
    // It needs far more memory than the page asks about: it opens once agreed to.
    await page.waitForSelector('#large-ask[open]', { timeout: 5000 });
    await page.click('#large-ask-open');
    await page.waitForSelector('#opening:not([hidden])', { timeout: 5000 });
    assert.match(await page.textContent('#opening-text'), /^This scenario is large \(16,744,448 cells\); opening it…/);
    assert.equal(await page.getAttribute('#opening .progress', 'role'), 'progressbar');
    // A click is handled while the worker builds the run: another tab opens at once.
    await page.click('#tab-about');
    await page.waitForSelector('#tab-about[aria-selected="true"]');
    assert.ok(await page.isVisible('#opening'), 'the click was answered while the scenario was still opening');
    await page.waitForSelector('#opening', { state: 'hidden', timeout: 120000 });
    // Its introduction comes once it has opened.
    await page.waitForSelector('#intro[open]');
    assert.equal(await page.textContent('#intro-title'), 'amas-4096');
    await page.click('#intro button.primary');
    await page.click('#tab-run');
    await page.waitForFunction(() => document.querySelector('#scenario-name').textContent === 'amas-4096', null, { timeout: 30000 });
    await page.click('#step');
    await waitForSteps(page, 1, 60000);
    // Playing, each step takes tens of milliseconds, yet the page is shown the run as it goes: the
    // worker makes way for its draws (and the frames the page follows go out with them).
    await page.click('#play');
    await waitForSteps(page, 4, 60000);
    await page.click('#play');
    const { tasks, clicks } = await watch.done();
    const longest = Math.max(0, ...tasks);
    assert.ok(longest < 1000, `the longest task on the main thread took ${longest.toFixed(0)} ms`);
    assert.ok(clicks.length >= 3 && Math.max(...clicks) < 1000, `clicks waited ${clicks.map((c) => c.toFixed(0)).join(', ')} ms`);
    assert.ok(await page.isHidden('#banner'), 'no message');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('a large scenario the worker refuses leaves the scenario in view and says why', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    const before = await page.textContent('#state-hash');
    const name = await page.textContent('#scenario-name');
    await page.evaluate(
      (l) => {
        location.hash = l;
      },
      linkOf(largestAmas({ supply_rows: 1, robots: 4097 })),
    );
    await page.click('#large-ask-open');
    await page.waitForSelector('#banner:not([hidden])', { timeout: 60000 });
    assert.match(await page.textContent('#banner-text'), /^This scenario cannot run: robots: 4097 robots do not fit/);
    assert.ok(await page.isHidden('#opening'), 'the notice is gone');
    assert.equal(await page.textContent('#state-hash'), before, 'the scenario in view is kept');
    assert.equal(await page.textContent('#scenario-name'), name);
    assert.ok(await page.isHidden('#intro'), 'a scenario that did not open is not introduced');
    await page.click('#step');
    await waitForSteps(page, 1);
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('one estimated to need much memory says how much and opens only when agreed to', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    const name = await page.textContent('#scenario-name');
    const before = await page.textContent('#state-hash');
    const amas = (side) =>
      JSON.stringify({ ...JSON.parse(wasm.preset_json('amas-L')), name: `amas-${side}`, target: { rect: [side, side] }, disturbances: [] });
    const go = (json) =>
      page.evaluate((l) => {
        location.hash = l;
      }, wasm.encode_link(json));
    // 2000 × 2000 (within the page's limits): 4,000,000 cells at 34 bytes a cell.
    await go(amas(2000));
    await page.waitForSelector('#large-ask[open]', { timeout: 5000 });
    const text = await page.textContent('#large-ask-text');
    assert.match(text, /4,000,000 cells/);
    assert.match(text, /about 130 MB of memory/);
    // Declined: nothing opens, the scenario in view and its run stay, the link is let go.
    await page.click('#large-ask-keep');
    await page.waitForSelector('#large-ask', { state: 'hidden' });
    // The dialog's close event, which lets the link go, comes a task after the dialog hides.
    await page.waitForFunction(() => location.hash === '', null, { timeout: 5000 });
    assert.ok(await page.isHidden('#opening'));
    assert.equal(await page.textContent('#scenario-name'), name);
    assert.equal(await page.textContent('#state-hash'), before);
    await page.click('#step');
    await waitForSteps(page, 1);
    // Agreed: it opens, and its edits (a new seed) are not asked again.
    await go(amas(2000));
    await page.click('#large-ask-open');
    await page.waitForSelector('#intro[open]', { timeout: 60000 });
    await page.click('#intro button.primary');
    assert.equal(await page.textContent('#scenario-name'), 'amas-2000');
    await page.click('#new-seed');
    await page.waitForSelector('#opening:not([hidden])', { timeout: 5000 });
    assert.ok(await page.isHidden('#large-ask'));
    await page.waitForSelector('#opening', { state: 'hidden', timeout: 60000 });
    // Under the estimate it opens without a question: 1024 × 1024 is about 40 MB.
    await go(amas(1024));
    await page.waitForSelector('#intro[open]', { timeout: 60000 });
    assert.ok(await page.isHidden('#large-ask'));
    assert.deepEqual(problems, []);
    await context.close();
  });
});
