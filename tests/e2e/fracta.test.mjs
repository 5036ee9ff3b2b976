// fracta in the page: hexagons with bonds and type labels, the start-shape and statement editors.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { loadWasm, openPage, session, waitForSteps } from './harness.mjs';
import { readLabels } from './labels.mjs';

const wasm = loadWasm();

const s = session('/');

const open = (preset) => openPage(s.browser, `${s.server.url}#${wasm.encode_link(wasm.preset_json(preset))}`);
const scenario = async (page) => JSON.parse(await page.$eval('#scenario-json', (t) => t.value));

test('fracta draws hexagons with bonds and type labels that name each unit, and runs', async () => {
  const json = wasm.preset_json('fracta-triangle10');
  const { page, context, problems } = await open('fracta-triangle10');
  assert.equal(await page.textContent('#scenario-model'), 'fracta');
  const legend = await page.$$eval('#legend span', (spans) => spans.map((x) => x.textContent));
  assert.ok(legend.includes('K') && legend.includes('o') && legend.includes('s'), legend.join(','));
  // Labels are drawn on the annotation layer only when the structure is large on screen.
  await page.waitForFunction(async () => {
    const c = document.querySelector('#annotations');
    const data = await (async () => {
      const bmp = await createImageBitmap(c);
      const t = new OffscreenCanvas(bmp.width, bmp.height).getContext('2d');
      t.drawImage(bmp, 0, 0);
      return t.getImageData(0, 0, bmp.width, bmp.height).data;
    })();
    for (let i = 3; i < data.length; i += 4) if (data[i] > 0) return true;
    return false;
  });
  // What the labels must say: the core's cells at step 0, named by the model's legend.
  const sim = new wasm.Sim(json);
  const entries = sim.layout().cells;
  const expected = [...sim.cells()].filter((c) => c !== 0).map((c) => entries.find((e) => e.code === c).name);
  sim.free();
  const labels = await page.evaluate(
    readLabels,
    entries.map((e) => e.name),
  );
  assert.deepEqual(labels.map((l) => l.read).sort(), expected.sort(), 'one label per unit, naming its type');
  const rgb = (hex) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
  for (const l of labels) {
    assert.ok(l.score > 0.8 && l.score - l.runnerUp > 0.15, `label ${l.read} read clearly (${l.score} against ${l.runnerUp})`);
    // The renderer filled the cell under the label with the colour of the type the label names.
    const want = rgb(entries.find((e) => e.name === l.read).color);
    assert.ok(
      l.colour.every((v, i) => Math.abs(v - want[i]) <= 12),
      `label ${l.read} sits on ${l.colour}, not on its type's colour ${want}`,
    );
  }
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
  await page.click('button[title="Apply the goal statements"]');
  assert.equal(await page.inputValue('#fracta-goal'), 'o{K, K}\nK{o, K, Q, s}', 'the typed text is kept');
  assert.equal((await scenario(page)).goal, before, 'a bad goal does not reach the scenario');

  // Draw the 10-unit triangle as the goal shape and derive its statements.
  await page.click('summary:has-text("Derive statements from goal shapes")');
  const text = page.locator('details:has(#fracta-priority) textarea');
  await page.click('details:has(#fracta-priority) summary:has-text("As text")');
  await text.fill('. . # .\n . # # .\n. # # #\n # # # #\n');
  await page.click('details:has(#fracta-priority) button[title="Replace the drawing with the text"]');
  await page.click('button[title="Derive the goal statements from the goal shapes"]');
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
  // The undone shape reaches the scenario once the page has applied it.
  await page.waitForFunction((n) => (JSON.parse(document.querySelector('#scenario-json').value).start.match(/#/g) ?? []).length === n, units(start));
  const restored = wasm.shape_parse('hex', (await scenario(page)).start);
  const original = wasm.shape_parse('hex', start);
  assert.equal(units((await scenario(page)).start), units(start));
  assert.deepEqual(restored.cells.slice(0, 6), original.cells.slice(0, 6));
  await context.close();
});
