// The page in headless Chromium: loading, running, keyboard, links, errors, recovery, persistence.
// What the features compute and show without a flow through the browser (the form from the schema,
// a refused parameter, text from a link shown as text) is tests/unit/features.test.ts's.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { animationFrames, kumiki, loadWasm, openPage, session, settle, stepCount, waitForSteps } from './harness.mjs';

const wasm = loadWasm();

const s = session('/classroom/kumiki/');

const hashOf = (page) => page.textContent('#state-hash');
const scenarioJson = (page) => page.$eval('#scenario-json', (t) => t.value);
async function waitForHashAt(page, steps) {
  await page.waitForFunction((n) => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) === n, steps);
  await page.waitForFunction(() => document.querySelector('#state-hash').textContent.length === 16);
}

describe('the page', () => {
  test('loads from a sub-path with no console errors, and shows step 0 and the state hash', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    assert.equal(await stepCount(page), 0);
    assert.match(await hashOf(page), /^[0-9a-f]{16}$/);
    assert.match(await page.textContent('#scenario-name'), /\S/);
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('play advances the step counter and pause stops it', async () => {
    // A long run at 86 steps a second (the slider at 5): one that kept playing would add steps within a few frames.
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${wasm.encode_link(wasm.preset_json('amas-square28'))}`);
    await page.$eval('#speed', (input) => {
      input.value = '5';
      input.dispatchEvent(new Event('input'));
    });
    await page.click('#play');
    const reached = await waitForSteps(page, 5);
    assert.ok(reached >= 5);
    await page.click('#play');
    await page.waitForSelector('#play[aria-pressed="false"]');
    // The worker has confirmed the pause. The page draws and acknowledges a frame on every
    // animation frame, so within a few of them the last frame from before the pause has landed;
    // a run that kept playing would show new steps on every one of the next 24.
    await animationFrames(page, 24);
    const paused = await stepCount(page);
    await animationFrames(page, 24);
    assert.equal(await stepCount(page), paused);
    // Paused, a Step adds exactly one step.
    await page.click('#step');
    await waitForSteps(page, paused + 1);
    await settle(page);
    assert.equal(await stepCount(page), paused + 1);
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('keyboard: Right arrow steps, R resets to the identical state, Space plays', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    const initial = await hashOf(page);
    await page.locator('#view').focus();
    for (let i = 0; i < 3; i++) await page.keyboard.press('ArrowRight');
    await waitForHashAt(page, 3);
    assert.notEqual(await hashOf(page), initial);
    await page.keyboard.press('r');
    await waitForHashAt(page, 0);
    assert.equal(await hashOf(page), initial);
    await page.keyboard.press('Space');
    await waitForSteps(page, 2);
    await page.keyboard.press('Space');
    await page.waitForSelector('#play[aria-pressed="false"]');
    await context.close();
  });

  test('a copied link restores the scenario exactly, gives the same run, and the CLI agrees', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    await page.fill('#seed', '4242');
    await page.dispatchEvent('#seed', 'change');
    await page.waitForFunction(() => document.querySelector('#scenario-json').value.includes('"seed": 4242'));
    await page.click('#copy-link');
    await page.waitForFunction(() => location.hash.startsWith('#k1.'));
    const link = await page.evaluate(() => location.href);
    const json = await scenarioJson(page);

    const second = await openPage(s.browser, link);
    assert.equal(await scenarioJson(second.page), json);
    for (const p of [page, second.page]) {
      await p.selectOption('#speed', { index: 0 }).catch(() => {});
      await p.$eval('#speed', (s) => {
        s.value = '8';
        s.dispatchEvent(new Event('input'));
      });
      await p.click('#play');
      await p.waitForSelector('#run-status:not(:empty)', { timeout: 60000 });
      await p.waitForSelector('#play[aria-pressed="false"]');
    }
    const final = await hashOf(page);
    assert.match(final, /^[0-9a-f]{16}$/);
    assert.equal(await hashOf(second.page), final);
    assert.equal(await stepCount(second.page), await stepCount(page));

    const out = kumiki(['run', link]);
    const row = JSON.parse(out.trim().split('\n')[0]);
    assert.equal(row.seed, 4242);
    assert.equal(row.hash, final, 'the command line reproduces the page run from the same link');
    assert.equal(row.steps, await stepCount(page));
    await second.context.close();
    await context.close();
  });

  test('a malformed link shows a readable message and the page stays usable', async () => {
    const { page, context } = await openPage(s.browser, `${s.server.url}#k1.this-is-not-a-scenario`);
    await page.waitForSelector('#banner:not([hidden])');
    assert.match(await page.textContent('#banner-text'), /could not be opened/);
    assert.match(await page.textContent('#banner-text'), /link:/);
    await page.click('#step');
    await waitForSteps(page, 1);
    await context.close();
  });

  test('a panic in the simulation is shown and the page recovers with the last good scenario', async () => {
    // The crash button is a debug control: hidden unless the address asks for ?debug.
    const plain = await openPage(s.browser, s.server.url);
    assert.equal(await plain.page.isVisible('#simulate-crash'), false);
    await plain.context.close();
    const { page, context } = await openPage(s.browser, `${s.server.url}?debug`);
    const initial = await hashOf(page);
    await page.click('#tab-about');
    await page.click('#simulate-crash');
    await page.waitForSelector('#banner:not([hidden])');
    assert.match(await page.textContent('#banner-text'), /Kumiki hit an internal error in amas; your scenario is kept/);
    assert.match(await page.textContent('#banner-text'), /simulated panic/);
    assert.equal(await page.textContent('#banner-action'), 'Copy the report');
    await waitForHashAt(page, 0);
    assert.equal(await hashOf(page), initial);
    await page.click('#step');
    await waitForSteps(page, 1);
    await context.close();
  });

  test('edits survive a reload, and undo brings the previous scenario back', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    await page.fill('#seed', '777');
    await page.dispatchEvent('#seed', 'change');
    await page.waitForFunction(() => document.querySelector('#scenario-json').value.includes('"seed": 777'));
    await page.reload();
    await page.waitForSelector('body[data-ready="true"]');
    await page.waitForFunction(() => document.querySelector('#seed').value === '777');
    await page.fill('#seed', '778');
    await page.dispatchEvent('#seed', 'change');
    await page.waitForFunction(() => document.querySelector('#seed').value === '778' && !document.querySelector('#undo').disabled);
    await page.click('#tab-scenario');
    await page.click('#undo');
    await page.waitForFunction(() => document.querySelector('#seed').value === '777');
    await page.click('#redo');
    await page.waitForFunction(() => document.querySelector('#seed').value === '778');
    await page.locator('#view').focus();
    await page.keyboard.press('Control+z');
    await page.waitForFunction(() => document.querySelector('#seed').value === '777');
    await context.close();
  });

  test('clicked disturbances are recorded in the link', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    for (let i = 0; i < 60; i++) await page.keyboard.press('ArrowRight');
    await waitForHashAt(page, 60);
    const tools = await page.$$eval('#tools button', (bs) => bs.map((b) => b.dataset.tool));
    assert.ok(tools.length > 1, 'the model offers click tools');
    await page.click(`#tools button[data-tool="${tools[1]}"]`);
    // Click the centre of a built module: find one from the page's own picking.
    const box = await page.locator('#view').boundingBox();
    let recorded = false;
    // A grid over the view, bottom rows first: the L stands on its stem, built up from the conveyor.
    const points = [];
    for (let j = 19; j >= 0; j--) for (let i = 0; i < 20; i++) points.push([(i + 0.5) / 20, (j + 0.5) / 20]);
    for (const [fx, fy] of points) {
      if (recorded) break;
      const x = box.x + box.width * fx;
      const y = box.y + box.height * fy;
      // The inspector names the cell under the pointer as it moves; only a module takes the tool.
      await page.mouse.move(x, y);
      const state = await page.evaluate(() => {
        const inspector = document.querySelector('#inspector');
        return inspector.hidden ? '' : (inspector.querySelectorAll('dd')[1]?.textContent ?? '');
      });
      if (state !== 'module') continue;
      await page.mouse.click(x, y);
      await page.waitForFunction(() => document.querySelector('#scenario-json').value.includes('"disturbances"'));
      recorded = true;
    }
    assert.ok(recorded, 'a click on a module records a disturbance');
    await context.close();
  });

  test('the simulation runs in a worker: the page stays responsive while a large run plays', async () => {
    const rows = Array.from({ length: 300 }, () => '#'.repeat(400)).join('\n');
    const big = { ...JSON.parse(wasm.preset_json('amas-L')), name: 'big', target: rows, robots: 300, max_steps: 1000000 };
    const link = wasm.encode_link(JSON.stringify(big));
    const { page, context } = await openPage(s.browser, `${s.server.url}#${link}`);
    await page.$eval('#speed', (s) => {
      s.value = '8';
      s.dispatchEvent(new Event('input'));
    });
    // The longest gap between 10 ms timers over `ms`: how long the main thread was kept busy.
    const worstGap = (ms) =>
      page.evaluate(
        (span) =>
          new Promise((resolve) => {
            let worst = 0;
            let last = performance.now();
            const end = last + span;
            const tick = () => {
              const now = performance.now();
              worst = Math.max(worst, now - last);
              last = now;
              if (now < end) setTimeout(tick, 10);
              else resolve(worst);
            };
            setTimeout(tick, 10);
          }),
        ms,
      );
    // Paused, the gaps show what the machine itself adds (other processes on a shared machine).
    const idle = await worstGap(1000);
    await page.click('#play');
    await waitForSteps(page, 3, 30000);
    // While it plays, the main thread answers timers promptly.
    const worst = await worstGap(2000);
    const later = await stepCount(page);
    assert.ok(later > 3, 'the run kept going');
    assert.ok(worst < 250 + idle, `the main thread stalled for ${worst.toFixed(0)} ms (${idle.toFixed(0)} ms while paused)`);
    // The live chart redraws every frame. Drawn on the GPU, Chromium holds the main thread when the
    // GPU process falls behind presenting software WebGL (up to 300 ms here; docs/benchmarks.md):
    // it draws on the CPU instead.
    const chart = await page.$eval('#metric-chart canvas', (c) => c.getContext('2d').getContextAttributes().willReadFrequently);
    assert.equal(chart, true, 'the live chart is drawn by the CPU');
    await page.click('#play');
    await context.close();
  });

  test('every control has an accessible name', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    const unnamed = await page.evaluate(() => {
      const missing = [];
      for (const el of document.querySelectorAll('button, input, select, textarea, [role="tab"], [role="radio"]')) {
        const aria = el.getAttribute('aria-label') || el.getAttribute('aria-labelledby');
        const labelled = el.labels && el.labels.length > 0;
        const text = el.textContent.trim();
        if (!aria && !labelled && !(el.tagName === 'BUTTON' && text)) missing.push(el.outerHTML.slice(0, 80));
      }
      return missing;
    });
    assert.deepEqual(unnamed, []);
    await context.close();
  });

  test('both renderers draw the lattice', async () => {
    for (const kind of ['webgl2', 'canvas2d']) {
      const { page, context, problems } = await openPage(s.browser, s.server.url);
      await page.click('#tab-about');
      await page.selectOption('#renderer-choice', kind);
      await page.waitForFunction((k) => document.body.dataset.renderer === k, kind);
      await page.click('#step');
      await waitForSteps(page, 1);
      await settle(page);
      const colours = await page.$eval('#view', (canvas) => {
        const probe = document.createElement('canvas');
        probe.width = 200;
        probe.height = 150;
        const ctx = probe.getContext('2d');
        ctx.drawImage(canvas, 0, 0, 200, 150);
        const data = ctx.getImageData(0, 0, 200, 150).data;
        const seen = new Set();
        for (let i = 0; i < data.length; i += 4) seen.add(`${data[i] >> 4},${data[i + 1] >> 4},${data[i + 2] >> 4}`);
        return seen.size;
      });
      assert.ok(colours >= 4, `${kind} drew ${colours} colours`);
      assert.deepEqual(problems, []);
      await context.close();
    }
  });

  test('on a small phone nothing overlaps: the run controls can be pressed', async () => {
    const { page, context } = await openPage(s.browser, s.server.url, { width: 375, height: 667 });
    for (const id of ['#play', '#step', '#reset', '#copy-link', '#tab-scenario']) {
      const covered = await page.$eval(id, (el) => {
        el.scrollIntoView({ block: 'center' });
        const r = el.getBoundingClientRect();
        const top = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
        return top === el || el.contains(top) ? null : top?.outerHTML.slice(0, 60);
      });
      assert.equal(covered, null, `${id} is covered`);
    }
    await page.click('#step');
    await waitForSteps(page, 1);
    const { scroll, width } = await page.evaluate(() => ({ scroll: document.documentElement.scrollWidth, width: window.innerWidth }));
    assert.ok(scroll <= width, `page is ${scroll}px wide in a ${width}px window`);
    await context.close();
  });

  test('works on a classroom tablet: no sideways scrolling, the view stays large', async () => {
    const { page, context } = await openPage(s.browser, s.server.url, { width: 820, height: 1180 });
    const { scroll, width, canvasHeight } = await page.evaluate(() => ({
      scroll: document.documentElement.scrollWidth,
      width: window.innerWidth,
      canvasHeight: document.querySelector('#view').getBoundingClientRect().height,
    }));
    assert.ok(scroll <= width, `page is ${scroll}px wide in a ${width}px window`);
    assert.ok(canvasHeight >= 400, `the view is only ${canvasHeight}px tall`);
    await context.close();
  });
});

describe('the AMAS target editor', () => {
  test('painting next to the structure changes the target; a disconnected stroke is refused and kept; undo works', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    await page.click('#tab-scenario');
    await page.waitForSelector('.grid-canvas');
    const target = async () => JSON.parse(await scenarioJson(page)).target;
    const before = await target();
    const rows = before.trim().split('\n');
    const [w, h] = [rows[0].length, rows.length];
    const box = await page.locator('.grid-canvas').boundingBox();
    const cell = box.width / w;
    const at = (x, y) => [box.x + (x + 0.5) * cell, box.y + (y + 0.5) * cell];
    // The right-hand cell of the row above the bottom is empty in amas-L (the L stands on its
    // stem, its bar on top) and touches nothing, not even the supply row below the bottom row
    // (which would hold it, as it holds a bridge's piers): painting it alone is refused.
    assert.deepEqual([rows[h - 3][w - 1], rows[h - 2][w - 2], rows[h - 2][w - 1], rows[h - 1][w - 1]], ['.', '.', '.', '.']);
    await page.mouse.click(...at(w - 1, h - 2));
    await page.waitForFunction(() => document.querySelector('#model-editor .error').textContent.includes('not connected'));
    assert.equal(await target(), before, 'a refused shape does not change the scenario');
    // Undo the stray cell, then paint a cell on top of the bar, which is connected.
    await page.click('#model-editor button[aria-label="Undo the last drawing change"]');
    await page.waitForFunction(() => document.querySelector('#model-editor .error').textContent === '');
    const bar = rows.findIndex((r) => r[0] === '#');
    assert.equal(bar, 0);
    await page.locator('#model-editor input[aria-label="Height in cells"]').fill(String(h + 1));
    await page.dispatchEvent('#model-editor input[aria-label="Height in cells"]', 'change');
    await page.waitForFunction((n) => JSON.parse(document.querySelector('#scenario-json').value).target.trim().split('\n').length === n, h + 1);
    const box2 = await page.locator('.grid-canvas').boundingBox();
    const cell2 = box2.width / w;
    await page.mouse.click(box2.x + 0.5 * cell2, box2.y + 0.5 * cell2);
    await page.waitForFunction(() => JSON.parse(document.querySelector('#scenario-json').value).target.startsWith('#'));
    assert.equal((await target()).split('#').length - 1, before.split('#').length);
    assert.equal(await page.$('#param-target'), null, 'the generic form leaves the target to the editor');
    assert.deepEqual(problems, []);
    await context.close();
  });
});

describe('the AMAS stage editor', () => {
  test('staged targets are listed, each drawn in turn, and a stage can be added and removed', async () => {
    const link = wasm.encode_link(wasm.preset_json('amas-bridge-staged'));
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${link}`);
    await page.click('#tab-scenario');
    const options = await page.$$eval('#amas-part option', (o) => o.map((x) => x.textContent));
    const stages = JSON.parse(await scenarioJson(page)).stages.length;
    assert.equal(options.length, stages + 1);
    assert.equal(options[options.length - 1], 'final target');
    const cellsShown = () => page.$eval('#model-editor .hint:last-of-type', (p) => p.textContent);
    await page.selectOption('#amas-part', '0');
    const first = await page.$eval('#model-editor textarea', (t) => t.value);
    await page.selectOption('#amas-part', String(stages));
    const last = await page.$eval('#model-editor textarea', (t) => t.value);
    assert.notEqual(first, last, 'each stage shows its own shape');
    assert.match(await cellsShown(), /cells/);
    await page.click('button[title="Add an intermediate stage target before the final target"]');
    await page.waitForFunction((n) => JSON.parse(document.querySelector('#scenario-json').value).stages.length === n + 1, stages);
    await page.click('button[title="Remove this stage target"]');
    await page.waitForFunction((n) => JSON.parse(document.querySelector('#scenario-json').value).stages.length === n, stages);
    assert.deepEqual(problems, []);
    await context.close();
  });
});
