// The first hour: a page opened cold says what Kumiki is and offers four ways in; a lesson and the
// gallery are reached from it by mouse and by keyboard alone; the tour can be taken, skipped and
// reopened; an exercise's verdict stays in view at 1366 × 768.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { loadWasm, openPage, session } from './harness.mjs';

const wasm = loadWasm();
const s = session();

/** Presses Tab until the element `id` has the focus (at most `limit` presses); the presses made. */
async function tabTo(page, id, limit = 60) {
  for (let i = 1; i <= limit; i++) {
    await page.keyboard.press('Tab');
    if ((await page.evaluate(() => document.activeElement?.id)) === id) return i;
  }
  throw new Error(`#${id} was not reached in ${limit} Tab presses`);
}

describe('the first screen', () => {
  test('opened cold it says what Kumiki is and leads, by mouse, to a lesson, the papers and the gallery', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url, { keepWelcome: true });
    await page.waitForSelector('#welcome[open]');
    assert.match(await page.textContent('#welcome-what'), /^Kumiki is a playground/);
    assert.deepEqual(await page.$$eval('#welcome .way strong', (ws) => ws.map((w) => w.textContent)), [
      "Watch a paper's scenarios",
      'Take a lesson',
      'Build your own',
      'Compare two runs',
    ]);
    assert.equal(await page.textContent('h1'), 'Kumiki');

    await page.click('#way-lesson');
    await page.waitForSelector('#gallery[open]');
    assert.equal(await page.textContent('#gallery-title'), 'Lessons');
    assert.equal(await page.locator('#gallery-list [data-lesson]').count(), wasm.lessons().length);
    assert.equal(await page.locator('#gallery-list [data-preset]').count(), 0);
    const lesson = wasm.lessons()[0];
    await page.click(`#gallery-list [data-lesson="${lesson.name}"]`);
    await page.waitForSelector('#exercise:not([hidden])');
    assert.equal(await page.textContent('#exercise-title'), JSON.parse(wasm.lesson_json(lesson.name)).exercise.title);

    // Seen once, the first screen stays away, and "Start here" brings it back.
    await page.reload();
    await page.waitForSelector('body[data-ready="true"]');
    assert.equal(await page.isVisible('#welcome'), false);
    await page.click('#open-welcome');
    await page.click('#way-watch');
    await page.waitForSelector('#gallery[open]');
    assert.equal(await page.locator('#gallery-list [data-lesson]').count(), 0);
    assert.equal(await page.locator('#gallery-list [data-preset]').count(), wasm.presets().length);
    // Each card shows a picture of its scenario, drawn by the page's renderer as it comes into view.
    await page.locator('#gallery-list [data-preset="fracta-repair"]').scrollIntoViewIfNeeded();
    await page.waitForSelector('#gallery-list [data-preset="fracta-repair"] canvas.card-picture[data-drawn="true"]', { timeout: 20000 });
    const lit = await page.$eval('#gallery-list [data-preset="fracta-repair"] canvas.card-picture', (c) => {
      const { data } = c.getContext('2d').getImageData(0, 0, c.width, c.height);
      const colours = new Set();
      for (let i = 0; i < data.length; i += 4 * 97) colours.add(`${data[i]},${data[i + 1]},${data[i + 2]}`);
      return colours.size;
    });
    assert.ok(lit > 2, `the picture has ${lit} colours: the lattice and its units are drawn`);
    await page.click('#gallery-list [data-preset="fracta-repair"]');
    // The gallery's card and the header give its title in words, with its code name beside it.
    await page.waitForFunction(() => document.querySelector('#scenario-code').textContent === 'fracta-repair');
    assert.equal(await page.textContent('#scenario-name'), 'A triangle repairs itself');

    // The Lessons and Gallery buttons stay at the top.
    await page.click('#open-scenarios');
    await page.waitForSelector('#gallery[open]');
    assert.equal(await page.locator('#gallery-list [data-lesson]').count(), wasm.lessons().length);
    await page.keyboard.press('Escape');
    await page.click('#open-lessons');
    await page.waitForSelector('#gallery[open]');
    assert.equal(await page.locator('#gallery-list [data-preset]').count(), 0);
    await page.keyboard.press('Escape');

    await page.click('#open-welcome');
    await page.click('#way-build');
    await page.waitForSelector('#panel-scenario:not([hidden])');
    assert.equal(await page.evaluate(() => document.activeElement?.id), 'tab-scenario');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('by keyboard alone: a lesson, the gallery and the whole tour', async () => {
    const { page, context } = await openPage(s.browser, s.server.url, { keepWelcome: true });
    await page.waitForSelector('#welcome[open]');
    await tabTo(page, 'way-lesson');
    await page.keyboard.press('Enter');
    await page.waitForSelector('#gallery[open]');
    // The filter has the focus; the first lesson is the next stop.
    assert.equal(await page.evaluate(() => document.activeElement?.id), 'gallery-filter');
    await page.keyboard.press('Tab');
    const chosen = await page.evaluate(() => document.activeElement?.dataset.lesson);
    assert.equal(chosen, wasm.lessons()[0].name);
    await page.keyboard.press('Enter');
    await page.waitForSelector('#exercise:not([hidden])');

    await page.evaluate(() => document.activeElement?.blur());
    await tabTo(page, 'open-scenarios');
    await page.keyboard.press('Enter');
    await page.waitForSelector('#gallery[open]');
    await page.keyboard.press('Escape');
    await page.waitForSelector('#gallery', { state: 'hidden' });

    await page.evaluate(() => document.activeElement?.blur());
    await tabTo(page, 'open-welcome');
    await page.keyboard.press('Enter');
    await page.waitForSelector('#welcome[open]');
    await tabTo(page, 'welcome-tour');
    await page.keyboard.press('Enter');
    await page.waitForSelector('#tour:not([hidden])');
    const stops = [];
    for (let i = 0; i < 10 && (await page.isVisible('#tour')); i++) {
      stops.push(await page.textContent('#tour-title'));
      // The stop marks its part of the page, the box stands beside it (never over it), and Next
      // has the focus.
      assert.equal(await page.locator('.tour-target').count(), 1);
      const [box, target] = await page.evaluate(() =>
        [document.querySelector('#tour'), document.querySelector('.tour-target')].map((e) => e.getBoundingClientRect().toJSON()),
      );
      const apart = box.right <= target.left || target.right <= box.left || box.bottom <= target.top || target.bottom <= box.top;
      assert.ok(apart, `stop ${i + 1}: the box ${JSON.stringify(box)} covers ${JSON.stringify(target)}`);
      assert.equal(await page.evaluate(() => document.activeElement?.id), 'tour-next');
      await page.keyboard.press('Enter');
    }
    assert.equal(stops.length, 5);
    assert.equal(await page.isVisible('#tour'), false);
    assert.equal(await page.locator('.tour-target').count(), 0);
    // Esc leaves the tour part-way.
    await page.click('#open-welcome');
    await page.click('#welcome-tour');
    // The dialog's close event (which starts the tour) comes as a task after the click.
    await page.waitForSelector('#tour:not([hidden])');
    await page.keyboard.press('Enter');
    assert.equal(await page.textContent('#tour-count'), 'Stop 2 of 5');
    await page.keyboard.press('Escape');
    await page.waitForSelector('#tour', { state: 'hidden' });
    await context.close();
  });

  test('on a laptop and on a tablet the header is read in the order the keyboard goes, with the scenario named in full', async () => {
    for (const [width, height] of [
      [1366, 768],
      [768, 1024],
    ]) {
      const { page, context } = await openPage(s.browser, s.server.url, { width, height });
      await page.evaluate(() => document.activeElement?.blur());
      const stops = [];
      for (let i = 0; i < 7; i++) {
        await page.keyboard.press('Tab');
        stops.push(
          await page.evaluate(() => {
            const e = document.activeElement;
            const r = e.getBoundingClientRect();
            return { id: e.id || e.tagName, x: r.x, y: r.y, h: r.height };
          }),
        );
      }
      const ids = stops.map((s) => s.id);
      assert.deepEqual(ids, ['A', 'open-gallery', 'open-lessons', 'open-scenarios', 'open-welcome', 'open-record', 'copy-link'], `${width} px`);
      // Each stop is right of the one before on its row, or on a row below it.
      for (let i = 1; i < stops.length; i++) {
        const [a, b] = [stops[i - 1], stops[i]];
        const sameRow = Math.abs(a.y + a.h / 2 - (b.y + b.h / 2)) < 4;
        assert.ok(sameRow ? b.x > a.x : b.y >= a.y + a.h - 4, `${width} px: ${b.id} comes after ${a.id} on the screen`);
      }
      const [shown, whole] = await page.$eval('#scenario-name', (e) => [e.clientWidth, e.scrollWidth]);
      assert.ok(whole <= shown, `${width} px: the scenario's name is not cut (${whole} > ${shown})`);
      await context.close();
    }
  });

  test('the first screen shows the robots, the key metrics, the chart and the colour legend at 1366 × 768 and 768 × 1024', async () => {
    for (const [width, height] of [
      [1366, 768],
      [768, 1024],
    ]) {
      const { page, context } = await openPage(s.browser, s.server.url, { width, height });
      await page.waitForSelector('#metrics-key .metric');
      const boxes = await page.evaluate(() =>
        ['#view', '#metrics-key', '#metric-chart', '#legend'].map((id) => {
          const r = document.querySelector(id).getBoundingClientRect();
          return { id, top: r.top, bottom: r.bottom, left: r.left, right: r.right, height: r.height };
        }),
      );
      for (const b of boxes) {
        assert.ok(
          b.height > 0 && b.top >= 0 && b.bottom <= height && b.left >= 0 && b.right <= width,
          `${width} px: ${b.id} is on the first screen: ${JSON.stringify(b)}`,
        );
      }
      // The model's key metrics come first; the rest, a click away.
      const key = await page.$$eval('#metrics-key .metric > span:first-child', (s) => s.map((x) => x.textContent));
      const table = wasm.metric_table('amas');
      assert.deepEqual(
        key,
        table.filter((m) => m.shown === 'key').map((m) => m.name.replace(/_/g, ' ')),
      );
      assert.equal(await page.isVisible('#metrics-more'), false);
      assert.equal(await page.textContent('#more-metrics-summary'), `More metrics (${table.filter((m) => m.shown === 'more').length})`);
      await context.close();
    }
  });

  test('at 1366 × 768 the lesson with the longest instructions keeps Check and its verdict in view', async () => {
    const longest = wasm
      .lessons()
      .map((l) => JSON.parse(wasm.lesson_json(l.name)))
      .sort((a, b) => b.exercise.instructions.length - a.exercise.instructions.length)[0];
    const { page, context } = await openPage(s.browser, `${s.server.url}#${wasm.encode_link(JSON.stringify(longest))}`, { width: 1366, height: 768 });
    await page.waitForSelector('#exercise:not([hidden])');
    await page.click('#exercise-check');
    await page.waitForFunction(() => document.querySelector('#exercise-result').textContent !== '');
    for (const id of ['exercise-check', 'exercise-result']) {
      const box = await page.locator(`#${id}`).boundingBox();
      assert.ok(box && box.y >= 0 && box.y + box.height <= 768, `#${id} is within the window: ${JSON.stringify(box)}`);
    }
    await context.close();
  });
});

describe('metric explanations', () => {
  test("every metric card explains itself from the core's table, on hover and on keyboard focus", async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    const model = await page.textContent('#scenario-model');
    const table = new Map(wasm.metric_table(model).map((m) => [m.name.replace(/_/g, ' '), m]));
    const cards = page.locator('#metrics .metric');
    const count = await cards.count();
    assert.ok(count > 3);
    for (let i = 0; i < count; i++) {
      const card = cards.nth(i);
      const name = await card.locator('span').first().textContent();
      const info = table.get(name);
      assert.ok(info, `${name} is in the ${model} metric table`);
      const tip = card.locator('.metric-about');
      assert.equal(await tip.textContent(), `${info.about} Unit: ${info.unit}.`);
      assert.equal(await card.getAttribute('aria-describedby'), await tip.getAttribute('id'));
    }
    const first = cards.first();
    assert.equal(await first.locator('.metric-about').isVisible(), false);
    await first.hover();
    assert.equal(await first.locator('.metric-about').isVisible(), true);
    await page.mouse.move(0, 0);
    assert.equal(await first.locator('.metric-about').isVisible(), false);
    // Every card's explanation opens inside the window, those at its right edge included.
    const { width, height } = page.viewportSize();
    for (const card of await page.locator('#metrics-key .metric').all()) {
      await card.hover();
      await page.waitForFunction(() => document.querySelector('.metric:hover .metric-about')?.style.top !== '');
      const tip = await card.locator('.metric-about').boundingBox();
      assert.ok(tip.x >= 0 && tip.y >= 0 && tip.x + tip.width <= width && tip.y + tip.height <= height, `the tip is on the screen: ${JSON.stringify(tip)}`);
    }
    await page.mouse.move(0, 0);
    // From the keyboard: the cards are in the Tab order and show their explanation when focused.
    await page.locator('#play').focus();
    let reached = false;
    for (let i = 0; i < 40 && !reached; i++) {
      await page.keyboard.press('Tab');
      reached = await page.evaluate(() => document.activeElement?.classList.contains('metric') ?? false);
    }
    assert.ok(reached, 'a metric card takes the focus');
    assert.equal(await page.locator('.metric:focus .metric-about').isVisible(), true);
    await context.close();
  });
});
