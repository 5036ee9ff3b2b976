// Gestures on the planar view and the grid editor in headless Chromium: the wheel zooms about the
// pointer, a drag pans, two fingers zoom about themselves, and a drag paints a stroke. The 3-D
// view and the voxel editor's gestures are in cubes3d.test.mjs.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { openPage, session, settle, stepCount } from './harness.mjs';

const s = session('/');

/** The cell the inspector names under the mouse at (x, y), or '' for none. */
async function cellAt(page, x, y) {
  await page.mouse.move(x + 1, y);
  await page.mouse.move(x, y);
  await settle(page);
  return page.evaluate(() => {
    const inspector = document.querySelector('#inspector');
    return inspector.hidden ? '' : (inspector.querySelector('dd')?.textContent ?? '');
  });
}

describe('gestures on the planar view', () => {
  test('the wheel zooms about the pointer, a drag pans, two fingers zoom about themselves', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    await settle(page);
    const box = await page.locator('#view').boundingBox();
    const p = { x: box.x + box.width * 0.4, y: box.y + box.height * 0.55 };
    const q = { x: box.x + box.width * 0.65, y: box.y + box.height * 0.35 };
    const underP = await cellAt(page, p.x, p.y);
    const underQ = await cellAt(page, q.x, q.y);
    assert.ok(underP && underQ && underP !== underQ, `two cells under two points (${underP}, ${underQ})`);

    await page.mouse.move(p.x, p.y);
    await page.mouse.wheel(0, -600);
    assert.equal(await cellAt(page, p.x, p.y), underP, 'the cell under the wheel stays there');
    assert.notEqual(await cellAt(page, q.x, q.y), underQ, 'the rest of the picture grows');

    await page.mouse.move(p.x, p.y);
    await page.mouse.down();
    await page.mouse.move(p.x + 90, p.y + 30, { steps: 6 });
    await page.mouse.up();
    assert.equal(await cellAt(page, p.x + 90, p.y + 30), underP, 'the dragged cell follows the pointer');

    const cdp = await context.newCDPSession(page);
    const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) });
    const m = { x: p.x + 90, y: p.y + 30 };
    await touch('touchStart', [
      [m.x - 20, m.y],
      [m.x + 20, m.y],
    ]);
    for (let k = 1; k <= 6; k++)
      await touch('touchMove', [
        [m.x - 20 - 10 * k, m.y],
        [m.x + 20 + 10 * k, m.y],
      ]);
    await touch('touchEnd', []);
    assert.equal(await cellAt(page, m.x, m.y), underP, 'the cell between the fingers stays between them');
    assert.notEqual(await cellAt(page, q.x, q.y), underQ);

    assert.equal(await stepCount(page), 0, 'gestures do not step');
    assert.doesNotMatch(await page.$eval('#scenario-json', (t) => t.value), /"disturbances"/, 'no gesture was taken for a click');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('a drag in the grid editor paints a stroke, one undo step', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    await page.click('#tab-scenario');
    await page.waitForSelector('.grid-canvas');
    const count = async () => Number((await page.textContent('#model-editor .grid-canvas ~ .hint')).match(/^(\d+) cell/)[1]);
    const rows = JSON.parse(await page.$eval('#scenario-json', (t) => t.value))
      .target.trim()
      .split('\n');
    const w = rows[0].length;
    const box = await page.locator('.grid-canvas').boundingBox();
    const cell = box.width / w;
    // Along the bottom row from the right: its last three cells are empty in amas-L (the L
    // stands on its stem).
    assert.equal(rows[rows.length - 1].slice(-3), '...');
    const before = await count();
    const y = box.y + (rows.length - 0.5) * cell;
    await page.mouse.move(box.x + (w - 0.5) * cell, y);
    await page.mouse.down();
    await page.mouse.move(box.x + (w - 2.5) * cell, y, { steps: 8 });
    await page.mouse.up();
    await page.waitForFunction(
      (n) => /^(\d+) cell/.exec(document.querySelector('#model-editor .grid-canvas ~ .hint').textContent)?.[1] === String(n),
      before + 3,
    );
    await page.click('#model-editor button[aria-label="Undo the last drawing change"]');
    assert.equal(await count(), before, 'one undo takes the whole stroke back');
    assert.deepEqual(problems, []);
    await context.close();
  });
});
