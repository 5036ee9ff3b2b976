// The accessibility audit: axe-core (WCAG 2.1 A and AA, and its best practices) on every tab and
// every dialog of the page, the first screen, the tour and the compare view included, must find
// no serious or critical violation. axe is evaluated in the page by the test driver (the page's
// CSP allows no injected script, and needs not to).
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { audit, loadWasm, openPage, session } from './harness.mjs';

const wasm = loadWasm();
const s = session();

describe('accessibility audit (axe-core)', () => {
  test('no serious or critical violation on the first screen, the tour, every tab and every dialog', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url, { keepWelcome: true });
    const found = [];
    await page.waitForSelector('#welcome[open]');
    found.push(...(await audit(page, 'first screen')));
    await page.click('#welcome-tour');
    await page.waitForSelector('#tour:not([hidden])');
    found.push(...(await audit(page, 'tour')));
    await page.click('#tour-close');

    for (const tab of ['run', 'scenario', 'experiments', 'about']) {
      await page.click(`#tab-${tab}`);
      await page.waitForSelector(`#panel-${tab}:not([hidden])`);
      if (tab === 'scenario') await page.click('.json-editor summary');
      found.push(...(await audit(page, `${tab} tab`)));
    }
    // An experiment run, with a figure of every kind and a two-condition summary drawn.
    await page.click('#tab-experiments');
    await page.$eval('details:has(#experiment-json)', (d) => (d.open = true));
    await page.fill(
      '#experiment-json',
      JSON.stringify({
        version: 1,
        name: 'a11y',
        scenarios: ['amas-L'],
        grid: { robots: [1, 3] },
        seeds: 2,
        trace: { every: 100, metrics: ['built'] },
        plot: [
          { kind: 'lines', x: 'params.robots', y: 'metrics.total_steps' },
          { kind: 'trace', y: 'built', series: 'params.robots' },
          { kind: 'histogram', value: 'steps', bins: 4 },
          { kind: 'bars', x: 'params.robots', y: 'steps' },
          { kind: 'summary', group: ['params.robots'] },
        ],
      }),
    );
    // The description follows the text a moment after it is typed, moving what is below it: a
    // click made meanwhile lands where Run was.
    await page.waitForFunction(() => document.querySelector('#experiment-description').textContent.endsWith('(4 runs)'));
    await page.click('#experiment-run');
    await page.waitForFunction(() => document.querySelector('#experiment-status').textContent.startsWith('Done'), null, { timeout: 60000 });
    assert.equal(await page.locator('#experiment-plots figure').count(), 5);
    assert.equal(await page.locator('#experiment-plots .comparisons li').count(), 1);
    found.push(...(await audit(page, 'experiments tab with its figures')));

    // A claim opened by its link and re-run, its result shown under its row.
    await page.evaluate(() => (location.hash = 'claim=chobie-with-five-robots-a-load-at'));
    await page.click('#claim-chobie-with-five-robots-a-load-at button.rerun');
    await page.waitForSelector('#paper-report .rerun-match', { timeout: 60000 });
    found.push(...(await audit(page, 'a claim re-run on the about tab')));

    await page.click('#tab-run');
    for (const [button, dialog] of [
      ['#open-gallery', '#gallery'],
      ['#open-lessons', '#gallery'],
      ['#open-record', '#record'],
    ]) {
      await page.click(button);
      await page.waitForSelector(`${dialog}[open]`);
      found.push(...(await audit(page, `${dialog} dialog (from ${button})`)));
      await page.keyboard.press('Escape');
      await page.waitForSelector(dialog, { state: 'hidden' });
    }
    // The teachers' Grade view opens from the gallery.
    await page.click('#open-gallery');
    await page.click('#open-grade');
    await page.waitForSelector('#grade[open]');
    found.push(...(await audit(page, 'grade dialog')));
    for (const dialog of ['#grade', '#gallery']) {
      if (await page.isVisible(dialog)) await page.keyboard.press('Escape');
      await page.waitForSelector(dialog, { state: 'hidden' });
    }
    await page.click('#tab-scenario');
    await page.click('#make-exercise');
    await page.waitForSelector('#exercise-editor[open]');
    found.push(...(await audit(page, 'exercise editor dialog')));
    await page.keyboard.press('Escape');
    await page.waitForSelector('#exercise-editor', { state: 'hidden' });
    assert.deepEqual(found, []);
    assert.deepEqual(problems, []);
    await context.close();
  });

  test("every model's run and scenario tabs pass (each has its own editors, tools and legend)", async () => {
    const found = [];
    const models = new Map();
    for (const p of wasm.presets()) if (!models.has(p.model)) models.set(p.model, p.name);
    assert.equal(models.size, 4);
    // One page; each model's scenario opens from a link, as a shared one would.
    const { page, context } = await openPage(s.browser, s.server.url);
    for (const [model, preset] of models) {
      await page.click('#tab-run');
      await page.evaluate(
        (l) => {
          location.hash = l;
        },
        wasm.encode_link(wasm.preset_json(preset)),
      );
      await page.waitForFunction((m) => document.querySelector('#scenario-model').textContent === m && document.body.dataset.ready === 'true', model);
      if (await page.isVisible('#intro')) {
        await page.click('#intro button.primary');
        await page.waitForSelector('#intro', { state: 'hidden' });
      }
      found.push(...(await audit(page, `${model} run tab`)));
      await page.click('#tab-scenario');
      await page.waitForSelector('#panel-scenario:not([hidden])');
      for (const summary of await page.$$('#panel-scenario details:not([open]) > summary')) await summary.click();
      found.push(...(await audit(page, `${model} scenario tab`)));
    }
    await context.close();
    assert.deepEqual(found, []);
  });

  test('the compare view passes: two views, both runs named, the chart with its legend and the compare controls', async () => {
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${wasm.encode_link(wasm.lesson_json('lesson-amas-compare'))}`);
    await page.waitForSelector('body.comparing #compare-wrap[data-steps]');
    await page.click('#step');
    await page.waitForFunction(() => document.querySelector('#compare-wrap').dataset.steps === '1');
    const found = await audit(page, 'compare view');
    // On a tablet the views stack.
    await page.setViewportSize({ width: 768, height: 1024 });
    found.push(...(await audit(page, 'compare view on a tablet')));
    assert.deepEqual(found, []);
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('a shared link, its introduction and a lesson with its exercise panel pass too', async () => {
    const lesson = wasm.lessons()[0].name;
    const link = wasm.encode_link(wasm.lesson_json(lesson));
    const { page, context } = await openPage(s.browser, `${s.server.url}#${link}`, { keepIntro: true });
    await page.waitForSelector('#intro[open]');
    const found = await audit(page, 'shared link introduction');
    await page.click('#intro button.primary');
    await page.waitForSelector('#exercise:not([hidden])');
    found.push(...(await audit(page, 'lesson')));
    assert.deepEqual(found, []);
    await context.close();
  });

  test('the question a large scenario asks before it opens passes too', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    const large = { ...JSON.parse(wasm.preset_json('amas-L')), name: 'amas-large', target: { rect: [2000, 1992] }, initial: { rect: [2000, 1900] } };
    await page.evaluate(
      (l) => {
        location.hash = l;
      },
      wasm.encode_link(JSON.stringify(large)),
    );
    await page.waitForSelector('#large-ask[open]');
    const found = await audit(page, 'large scenario dialog');
    await page.click('#large-ask-keep');
    await page.waitForSelector('#large-ask', { state: 'hidden' });
    assert.deepEqual(found, []);
    await context.close();
  });
});
