// fracta in the page: hexagons with bonds and type labels, the start-shape and statement editors.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { loadWasm, openPage, session, waitForSteps } from './harness.mjs';

const wasm = loadWasm();

const s = session('/');

const open = (preset) => openPage(s.browser, `${s.server.url}#${wasm.encode_link(wasm.preset_json(preset))}`);
const scenario = async (page) => JSON.parse(await page.$eval('#scenario-json', (t) => t.value));

test('fracta draws hexagons with bonds and type labels, and runs', async () => {
  const { page, context, problems } = await open('fracta-triangle10');
  assert.equal(await page.textContent('#scenario-model'), 'fracta');
  const legend = await page.$$eval('#legend span', (s) => s.map((x) => x.textContent));
  assert.ok(legend.includes('K') && legend.includes('o') && legend.includes('s'), legend.join(','));
  // Labels are drawn on the annotation layer only when the structure is large on screen.
  const inked = () =>
    page.$eval('#annotations', (c) => {
      const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 3; i < data.length; i += 4) if (data[i] > 0) n++;
      return n;
    });
  await page.waitForFunction(() => {
    const c = document.querySelector('#annotations');
    const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    for (let i = 3; i < data.length; i += 4) if (data[i] > 0) return true;
    return false;
  });
  const n = await inked();
  assert.ok(n > 500, `the annotation layer drew ${n} pixels of bonds and labels`);
  await page.click('#play');
  await waitForSteps(page, 10);
  await page.click('#play');
  assert.deepEqual(problems, []);
  await context.close();
});

test('the fault tool cuts a unit, and the click is recorded for the link', async () => {
  const { page, context } = await open('fracta-triangle10');
  await page.click('#tools button[data-tool]:not([data-tool="inspect"])');
  const box = await page.locator('#view').boundingBox();
  await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
  await page.waitForFunction(() => document.querySelector('#scenario-json').value.includes('"disturbances"'));
  const link = wasm.encode_link(await page.$eval('#scenario-json', (t) => t.value));
  assert.ok(wasm.decode_link(link).includes('"disturbances"'), 'the recorded fault survives a link');
  await context.close();
});

test('the statement editor names the bad line and keeps the text; derive writes the statements', async () => {
  const { page, context, problems } = await open('fracta-triangle10');
  await page.click('#tab-scenario');
  await page.waitForSelector('#fracta-goal');
  const before = (await scenario(page)).goal;
  await page.fill('#fracta-goal', 'o{K, K}\nK{o, K, Q, s}');
  await page.waitForFunction(() => document.querySelector('#fracta-goal-error').textContent.includes('line 2'));
  await page.click('button[aria-label="Apply the goal statements"]');
  assert.equal(await page.inputValue('#fracta-goal'), 'o{K, K}\nK{o, K, Q, s}', 'the typed text is kept');
  assert.equal((await scenario(page)).goal, before, 'a bad goal does not reach the scenario');

  // Draw the 10-unit triangle as the goal shape and derive its statements.
  await page.click('summary:has-text("Derive statements from goal shapes")');
  const text = page.locator('details:has(#fracta-priority) textarea');
  await page.click('details:has(#fracta-priority) summary:has-text("As text")');
  await text.fill('. . # .\n . # # .\n. # # #\n # # # #\n');
  await page.click('details:has(#fracta-priority) button[aria-label="Replace the drawing with the text"]');
  await page.click('button[aria-label="Derive the goal statements from the goal shapes"]');
  await page.waitForFunction(() => JSON.parse(document.querySelector('#scenario-json').value).goal.startsWith('o{K, K}  K{o, K, K, s}'));
  assert.equal(await page.inputValue('#fracta-goal'), 'o{K, K}  K{o, K, K, s}  s{K, K, K, K, K, K}\n');
  assert.deepEqual(problems, []);
  await context.close();
});

test('editing the start shape changes the scenario; undo in the editor restores it', async () => {
  const { page, context } = await open('fracta-triangle10');
  await page.click('#tab-scenario');
  const canvas = page.locator('#model-editor .grid-canvas').first();
  await canvas.waitFor();
  const start = (await scenario(page)).start;
  const units = (text) => wasm.shape_parse('hex', text).cells.reduce((a, b) => a + b, 0);
  await canvas.focus();
  // The cursor starts on the top-left cell, a unit of the top line: Delete removes it.
  await page.keyboard.press('Delete');
  await page.waitForFunction((s) => JSON.parse(document.querySelector('#scenario-json').value).start !== s, start);
  assert.equal(units((await scenario(page)).start), units(start) - 1);
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => !document.querySelector('#model-editor button[aria-label="Redo the drawing change"]').disabled);
  await page.waitForTimeout(300);
  const restored = wasm.shape_parse('hex', (await scenario(page)).start);
  const original = wasm.shape_parse('hex', start);
  assert.equal(units((await scenario(page)).start), units(start));
  assert.deepEqual(restored.cells.slice(0, 6), original.cells.slice(0, 6));
  await context.close();
});
