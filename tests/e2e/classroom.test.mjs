// Rewind and keys: the timeline goes back to any step reached with the identical state, the view's
// Left arrow steps back, and the page's keys leave focused controls alone.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { openPage, session, stepCount } from './harness.mjs';

const s = session();

const hash = (page) => page.textContent('#state-hash');
async function atStep(page, n) {
  await page.waitForFunction((k) => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) === k, n);
  await page.waitForFunction(() => document.querySelector('#state-hash').textContent.length === 16);
  return hash(page);
}
async function stepBy(page, n) {
  const from = await stepCount(page);
  await page.locator('#view').focus();
  for (let i = 0; i < n; i++) await page.keyboard.press('ArrowRight');
  return atStep(page, from + n);
}

describe('rewind', () => {
  test('the timeline and the Left arrow go back to identical states, and forward again', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    const at10 = await stepBy(page, 10);
    const at40 = await stepBy(page, 30);
    assert.equal(await page.getAttribute('#timeline', 'max'), '40');

    await page.locator('#timeline').fill('10');
    assert.equal(await atStep(page, 10), at10, 'the timeline returns the state first passed through');
    assert.equal(await page.textContent('#timeline-out'), '10 / 40');

    await page.locator('#view').focus();
    await page.keyboard.press('ArrowLeft');
    await atStep(page, 9);
    assert.equal(await stepBy(page, 31), at40, 'forward again gives the same hash');

    await page.locator('#timeline').fill('0');
    await atStep(page, 0);
    await page.click('#play');
    await page.waitForFunction(() => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) > 40);
    await page.click('#play');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test("a click in the past forks the run: the timeline ends there", async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    await stepBy(page, 150);
    await page.locator('#timeline').fill('120');
    await atStep(page, 120);
    const tools = await page.$$eval('#tools button', (bs) => bs.map((b) => b.dataset.tool));
    await page.click(`#tools button[data-tool="${tools[1]}"]`);
    // Click cells until one holds a module the tool applies to (the page's own picking decides).
    const box = await page.locator('#view').boundingBox();
    const clicked = () => document.querySelector('#scenario-json').value.includes('"disturbances"');
    for (let k = 0; k < 40 && !(await page.evaluate(clicked)); k++) {
      await page.mouse.click(box.x + box.width * (0.2 + (0.6 * ((k * 7) % 40)) / 40), box.y + box.height * (0.5 + (0.45 * ((k * 13) % 40)) / 40));
      // The click was refused (a cell with nothing to act on), recorded, or missed the lattice.
      await page
        .waitForFunction(() => !document.querySelector('#banner').hidden || document.querySelector('#scenario-json').value.includes('"disturbances"'), null, { timeout: 1000 })
        .catch(() => {});
      if (await page.isVisible('#banner')) await page.click('#banner-close');
    }
    await page.waitForFunction(() => document.querySelector('#timeline').max === '120');
    assert.equal(await stepCount(page), 120);
    assert.match(await page.$eval('#scenario-json', (t) => t.value), /"at": 120/);
    await page.locator('#view').focus();
    await page.keyboard.press('Control+z');
    await page.waitForFunction(() => !document.querySelector('#scenario-json').value.includes('"at": 120'));
    await context.close();
  });
});

describe('keys', () => {
  test('arrows and Space act on the focused control, not on the run', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    await page.locator('#speed').focus();
    const speed = await page.inputValue('#speed');
    await page.keyboard.press('ArrowRight');
    assert.notEqual(await page.inputValue('#speed'), speed, 'the slider moved');
    await page.locator('#timeline').focus();
    await page.keyboard.press('Space');
    assert.equal(await page.getAttribute('#play', 'aria-pressed'), 'false');
    assert.equal(await stepCount(page), 0, 'no step was taken');
    await page.locator('#view').focus();
    await page.keyboard.press('ArrowRight');
    await atStep(page, 1);
    await context.close();
  });
});
