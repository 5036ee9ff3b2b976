// Lessons, the every-step chart, the live region and the keyboard cursor, in the page: a lesson
// opened from the gallery fails as given and is met after the intended edit; at full speed a
// fracta fault and its repair show in the chart's record and are said in the live region; the
// view's cell cursor clicks a cell with a tool from the keyboard.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { loadWasm, openPage, session, stepCount } from './harness.mjs';

const wasm = loadWasm();
const s = session();

async function fullSpeed(page) {
  await page.$eval('#speed', (el) => {
    el.value = el.max;
    el.dispatchEvent(new Event('input'));
  });
}

/** Keeps every text the live region holds, in window.liveTexts. */
async function listen(page) {
  await page.evaluate(() => {
    window.liveTexts = [];
    const region = document.querySelector('#run-live');
    new MutationObserver(() => window.liveTexts.push(region.textContent)).observe(region, { childList: true, characterData: true, subtree: true });
  });
}
const heard = (page) => page.evaluate(() => window.liveTexts.join('\n'));

/** Presses C and waits for the cursor: it starts on the structure, which the worker finds. */
async function showCursor(page) {
  await page.keyboard.press('c');
  await page.waitForFunction(() => Number(document.querySelector('#view').dataset.cursor ?? -1) >= 0);
  return Number(await page.getAttribute('#view', 'data-cursor'));
}

describe('lessons', () => {
  test('the gallery lists every lesson with its section; one opens with its exercise, fails, then meets its goal', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    await page.click('#open-gallery');
    // The gallery lists the catalogue once it has arrived (the page fetches it when first needed).
    await page.waitForSelector('#gallery-list [data-lesson]');
    const lessons = wasm.lessons();
    assert.ok(lessons.length >= 8);
    const cards = await page.$$eval('#gallery-list [data-lesson]', (cs) => cs.map((c) => [c.dataset.lesson, c.textContent]));
    assert.deepEqual(
      cards.map(([name]) => name),
      lessons.map((l) => l.name),
    );
    for (const [name, text] of cards) {
      const lesson = lessons.find((l) => l.name === name);
      assert.ok(text.includes(lesson.title) && text.includes(lesson.section) && text.includes(lesson.model), text);
    }
    assert.equal(new Set(lessons.map((l) => l.model)).size, 4, 'every model has lessons');

    await page.click('#gallery-list [data-lesson="lesson-chobie-forms"]');
    await page.waitForSelector('#exercise:not([hidden])');
    assert.equal(await page.textContent('#exercise-title'), 'When no leader is elected');
    assert.match(await page.textContent('#exercise-instructions'), /section IV and figure 15/);
    await listen(page);
    await fullSpeed(page);
    await page.click('#play');
    await page.waitForFunction(() => document.querySelector('#exercise-result').textContent.startsWith('Not met yet'), null, { timeout: 30000 });
    assert.match(await heard(page), /Goal not met yet: metrics\.transformations is 0/);

    await page.click('#tab-scenario');
    await page.selectOption('#param-method', '"cautious"');
    await page.waitForFunction(() => document.querySelector('#scenario-json').value.includes('"cautious"'));
    await page.click('#tab-run');
    await page.click('#play');
    await page.waitForFunction(() => document.querySelector('#exercise-result').textContent.startsWith('Goal met'), null, { timeout: 30000 });
    assert.match(await heard(page), /Goal met: metrics\.transformations is \d+/);
    assert.deepEqual(problems, []);
    await context.close();
  });
});

describe('the run recorded and told', () => {
  test('at full speed a fracta fault and its repair show in the chart and are said in the live region', async () => {
    const link = wasm.encode_link(wasm.preset_json('fracta-repair'));
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${link}`);
    await page.selectOption('#chart-metric', 'mean_difference');
    await listen(page);
    await fullSpeed(page);
    await page.click('#play');
    // (The start is already complete, so the status says "completed" before the fault; the run's
    // end is when it stops playing.)
    await page.waitForFunction(() => window.liveTexts.some((t) => t.includes('Completed in')), null, { timeout: 30000 });
    const steps = await stepCount(page);
    await page.waitForFunction((n) => document.querySelector('#metric-chart').dataset.points === String(n + 1), steps);
    const chart = await page.$eval('#metric-chart', (c) => ({ ...c.dataset }));
    assert.equal(chart.metric, 'mean_difference');
    assert.equal(chart.span, '1', 'every step at full resolution');
    assert.ok(Number(chart.max) > 0, `the fault's rise in the difference is recorded: ${JSON.stringify(chart)}`);
    assert.equal(Number(chart.min), 0, 'and the repaired, complete shape');
    const text = await heard(page);
    assert.match(text, /Step 10: fault, unit 1\./);
    assert.match(text, new RegExp(`Completed in ${steps} steps\\.`));
    assert.match(await page.textContent('#run-live'), /Completed in/);
    assert.deepEqual(problems, []);
    await context.close();
  });
});

describe('keyboard cell clicking', () => {
  test('C shows a cursor the arrows move; Enter applies the tool there; Escape gives the arrows back to stepping', async () => {
    const link = wasm.encode_link(wasm.preset_json('fracta-hexagon7'));
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${link}`);
    await page.click('#tools button[data-tool="fault"]');
    await page.locator('#view').focus();
    const start = await showCursor(page);
    assert.ok(start >= 0);
    // Messages less than 0.8 s apart are joined: on a slow machine the load's may come first.
    // The cell's state comes from the worker, so the message follows the cursor by a moment.
    await page.waitForFunction(() => /Cursor at/.test(document.querySelector('#run-live').textContent));
    assert.match(await page.textContent('#run-live'), /(^|\. )Cursor at cell \(\d+, \d+\), [^.]+\. Enter: Fault \(cut power\)\.$/);

    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowLeft');
    await page.keyboard.press('ArrowLeft');
    assert.equal(Number(await page.getAttribute('#view', 'data-cursor')), start - 1, 'the arrows move the cursor');
    assert.equal(await stepCount(page), 0, 'and do not step');
    await page.keyboard.press('ArrowRight');

    await listen(page);
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => document.querySelector('#scenario-json').value.includes('"fault"'));
    const doc = JSON.parse(await page.$eval('#scenario-json', (t) => t.value));
    assert.deepEqual(doc.disturbances, [{ at: 0, kind: 'fault', cells: [start] }]);
    assert.match(await heard(page), /Step 0: fault, at cell \(\d+, \d+\)\./);

    await page.keyboard.press('Escape');
    assert.equal(await page.getAttribute('#view', 'data-cursor'), '-1');
    await page.keyboard.press('ArrowRight');
    await page.waitForFunction(() => document.querySelector('#step-count').textContent === '1');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('the cursor moves by rows on the square lattice and by layers on the cubic one', async () => {
    for (const [preset, key, cells] of [
      ['amas-L', 'ArrowDown', (w) => w],
      ['cubes-cube8-zigzag', 'PageUp', (w, h) => w * h],
    ]) {
      const sim = new wasm.Sim(wasm.preset_json(preset));
      const [w, h] = sim.layout().dims;
      sim.free();
      const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${wasm.encode_link(wasm.preset_json(preset))}`);
      await page.locator('#view').focus();
      const start = await showCursor(page);
      await page.keyboard.press(key);
      const moved = Number(await page.getAttribute('#view', 'data-cursor'));
      assert.equal(moved, start + cells(w, h), `${preset}: one row or one layer`);
      await page.keyboard.press(key === 'PageUp' ? 'PageDown' : 'ArrowUp');
      await page.keyboard.press(key === 'PageUp' ? 'PageDown' : 'ArrowUp');
      assert.equal(Number(await page.getAttribute('#view', 'data-cursor')), start - cells(w, h), `${preset}: back past the start`);
      assert.deepEqual(problems, []);
      await context.close();
    }
  });
});
