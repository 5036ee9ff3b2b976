// The cubes3d page in headless Chromium: the 3-D view (orbit, Fit, ghost, light, reachable
// positions), the voxel editor (add, remove, undo, layer slice, keyboard), the type-list editor
// (errors that name the line, derive from shape), links, the Canvas 2D fallback and a tablet.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { afterDraw, loadWasm, openPage, session, settle } from './harness.mjs';

const wasm = loadWasm();

const s = session('/');

const linkTo = (preset, edit = (s) => s) => `${s.server.url}#${wasm.encode_link(JSON.stringify(edit(JSON.parse(wasm.preset_json(preset)))))}`;
const scenarioOf = async (page) => JSON.parse(await page.$eval('#scenario-json', (t) => t.value));
const unitsIn = (shape) => (shape.match(/#/g) ?? []).length;
const stats = async (page, selector = '#view') => JSON.parse((await page.getAttribute(selector, 'data-scene')) || '{}');

/** Opens a preset and waits until the 3-D view has drawn its units. */
async function openCubes(preset, options = {}) {
  const opened = await openPage(s.browser, linkTo(preset, options.edit), options);
  await opened.page.waitForFunction(() => JSON.parse(document.querySelector('#view').dataset.scene || '{}').units > 0);
  return opened;
}

/** The canvas scaled to 160×120: its RGBA bytes. */
function pixels(page, selector = '#view') {
  return page.$eval(selector, (canvas) => {
    const probe = document.createElement('canvas');
    probe.width = 160;
    probe.height = 120;
    const ctx = probe.getContext('2d');
    ctx.drawImage(canvas, 0, 0, 160, 120);
    return Array.from(ctx.getImageData(0, 0, 160, 120).data);
  });
}
function changed(a, b) {
  let n = 0;
  for (let i = 0; i < a.length; i += 4) if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 24) n++;
  return n / (a.length / 4);
}
/** Share of strongly coloured pixels (units, the lamp), as opposed to the dark stage and the grid. */
function colourful(px, test = (r, g, b) => Math.max(r, g, b) - Math.min(r, g, b) > 70) {
  let n = 0;
  for (let i = 0; i < px.length; i += 4) if (test(px[i], px[i + 1], px[i + 2], px[i + 3])) n++;
  return n / (px.length / 4);
}
async function stepTo(page, steps) {
  await page.locator('#view').focus();
  for (let i = 0; i < steps; i++) await page.keyboard.press('ArrowRight');
  await page.waitForFunction((n) => Number(document.querySelector('#step-count').textContent) === n, steps);
  await page.waitForFunction(() => document.querySelector('#state-hash').textContent.length === 16);
  await settle(page);
}

describe('the 3-D view', () => {
  test('draws instanced units and bonds, turns when dragged, and Fit frames the units', async () => {
    const { page, context, problems } = await openCubes('cubes-cube8-zigzag');
    const s = await stats(page);
    assert.equal(s.units, 8);
    assert.equal(s.bonds, 7, 'the zigzag is a chain: seven bonds');
    await settle(page);
    const framed = await pixels(page);
    assert.ok(colourful(framed) > 0.02, `units fill ${(100 * colourful(framed)).toFixed(1)}% of the view after loading`);
    const box = await page.locator('#view').boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 + 140, box.y + box.height / 2 + 30, { steps: 6 });
    await page.mouse.up();
    await settle(page);
    const turned = await pixels(page);
    assert.ok(changed(framed, turned) > 0.02, 'orbiting changes the picture');
    for (let i = 0; i < 9; i++) await page.click('#zoom-out');
    await afterDraw(page, () => page.click('#zoom-out'));
    const far = colourful(await pixels(page));
    await afterDraw(page, () => page.click('#zoom-fit'));
    const fitted = colourful(await pixels(page));
    assert.ok(fitted > 0.02 && fitted > 4 * far, `Fit brings the units back (${far} → ${fitted})`);
    assert.equal(Number(await page.textContent('#step-count')), 0, 'dragging does not step');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('cubes-light: the ground, the lamp of the light and, after the switch, the ladder ghost', async () => {
    // Seed 2: most units hold the ladder from step 30 to 60.
    const { page, context, problems } = await openCubes('cubes-light', { edit: (s) => ({ ...s, seed: 2 }) });
    let s = await stats(page);
    assert.equal(s.light, true);
    assert.equal(s.ground, true);
    await settle(page);
    const lamp = colourful(await pixels(page), (r, g, b) => r > 200 && g > 150 && b < 130);
    assert.ok(lamp > 0.003, `the lamp and its arrow are drawn (${lamp})`);
    // Each unit switches to the ladder once its own D_0 has stayed under the cube's threshold for
    // 30 steps, so its ghost shows: the plank upright in the plane of the lit face, whose four
    // cells beside the cube are empty at step 45.
    await stepTo(page, 45);
    s = await stats(page);
    assert.ok(s.ghost >= 4, `the ladder's ghost cells outside the cube are drawn (${s.ghost})`);
    const withGhost = await pixels(page);
    await page.check('#show-ghost');
    await page.uncheck('#show-ghost');
    await settle(page);
    assert.equal((await stats(page)).ghost, 0);
    assert.ok(changed(withGhost, await pixels(page)) > 0.002, 'hiding the ghost changes the picture');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('hovering a unit shows its reachable positions, with the difference at each', async () => {
    const { page, context, problems } = await openCubes('cubes-cube8-zigzag');
    const box = await page.locator('#view').boundingBox();
    const inked = async () => colourful(await pixels(page, '#annotations'), (_r, _g, _b, a) => a > 0);
    assert.equal(await inked(), 0, 'nothing is written over the view before a unit is hovered');
    let found = false;
    for (let k = 0; k < 80 && !found; k++) {
      await page.mouse.move(box.x + box.width * (0.3 + (0.4 * ((k * 7) % 80)) / 80), box.y + box.height * (0.3 + (0.4 * ((k * 13) % 80)) / 80));
      // A unit under the pointer shows in the inspector at once, and where it can move once the
      // worker has answered: drawn as highlighted cells, or said to be nowhere.
      if (await page.isHidden('#inspector')) continue;
      await page.waitForFunction(() => {
        const said = document.querySelector('#inspector').textContent;
        const drawn = JSON.parse(document.querySelector('#view').dataset.scene).highlight > 0;
        return /reachable/.test(said) && (drawn || /cannot move|reachable\s*0 positions/.test(said));
      });
      found = (await stats(page)).highlight > 0;
    }
    assert.ok(found, 'some unit under the pointer shows reachable cells');
    assert.match(await page.textContent('#inspector'), /reachable\s*\d+ positions?/);
    assert.match(await page.textContent('#inspector'), /type-list\s*C\d+\[/);
    assert.ok((await inked()) > 0, 'the differences are written over the view');
    await page.mouse.move(box.x + 4, box.y + 4);
    await page.waitForFunction(() => JSON.parse(document.querySelector('#view').dataset.scene).highlight === 0);
    // The layer is left alone while it is empty, so it must have been cleared once the labels went.
    await page.waitForTimeout(200);
    assert.equal(await inked(), 0, 'the differences are gone with the hover');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('the Add unit tool puts the new unit on the clicked face, and the link records it', async () => {
    const { page, context, problems } = await openCubes('cubes-light');
    await page.click('#tools button[data-tool="add"]');
    const box = await page.locator('#view').boundingBox();
    let added = null;
    for (let k = 0; k < 60 && !added; k++) {
      const x = box.x + box.width * (0.45 + (0.3 * ((k * 7) % 60)) / 60);
      const y = box.y + box.height * (0.3 + (0.4 * ((k * 13) % 60)) / 60);
      // Only a unit under the pointer (shown in the inspector as it is hovered) takes a click.
      await page.mouse.move(x, y);
      if (await page.isHidden('#inspector')) continue;
      await page.mouse.click(x, y);
      await page.waitForFunction(() => JSON.parse(document.querySelector('#scenario-json').value).disturbances?.some((d) => d.kind === 'add'));
      added = (await scenarioOf(page)).disturbances.find((d) => d.kind === 'add');
    }
    assert.ok(added, 'a click on a unit adds one');
    await page.waitForFunction(() => JSON.parse(document.querySelector('#view').dataset.scene).units === 9);
    assert.ok(await page.isHidden('#banner'), 'no error was reported');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('the Canvas 2D fallback draws cubic lattices and turns', async () => {
    const { page, context, problems } = await openCubes('cubes-light');
    await page.click('#tab-about');
    await page.selectOption('#renderer-choice', 'canvas2d');
    await page.waitForFunction(() => document.body.dataset.renderer === 'canvas2d');
    await page.waitForFunction(() => JSON.parse(document.querySelector('#view').dataset.scene || '{}').units === 8);
    await settle(page);
    const before = await pixels(page);
    const seen = new Set();
    for (let i = 0; i < before.length; i += 4) seen.add(`${before[i] >> 4},${before[i + 1] >> 4},${before[i + 2] >> 4}`);
    assert.ok(seen.size >= 6, `canvas2d drew ${seen.size} colours`);
    assert.ok(colourful(before) > 0.01, 'units are visible');
    assert.ok(colourful(before, (r, g, b) => r > 200 && g > 150 && b < 130) > 0.002, 'the lamp is drawn');
    await page.locator('#view').focus();
    await page.keyboard.press('Shift+ArrowLeft');
    await page.keyboard.press('Shift+ArrowLeft');
    await settle(page);
    assert.ok(changed(before, await pixels(page)) > 0.02, 'Shift+arrows turn the view');
    assert.equal(Number(await page.textContent('#step-count')), 0, 'Shift+arrows do not step');
    await page.selectOption('#renderer-choice', 'auto');
    assert.deepEqual(problems, []);
    await context.close();
  });
});

/** Opens the Scenario tab and waits for the 3-D editor to show `units` units. */
async function openEditor(page, units) {
  await page.click('#tab-scenario');
  await page.waitForSelector('.voxel-canvas[data-scene]');
  await page.waitForFunction((n) => document.querySelector('.voxel-canvas').dataset.units === String(n), units);
  await settle(page);
}

/** Moves over the editor until its hint says `pattern`; returns the point. */
async function findInEditor(page, pattern) {
  const box = await page.locator('.voxel-canvas').boundingBox();
  for (let k = 0; k < 120; k++) {
    const x = box.x + box.width * (0.2 + (0.6 * ((k * 7) % 120)) / 120);
    const y = box.y + box.height * (0.2 + (0.6 * ((k * 17) % 120)) / 120);
    await page.mouse.move(x, y);
    if (pattern.test((await page.textContent('.voxel-hint')) ?? '')) return { x, y };
  }
  throw new Error(`nothing in the editor matched ${pattern}`);
}

describe('the voxel editor', () => {
  test('a click on a face adds a unit, Alt-click removes it, undo restores it', async () => {
    const { page, context, problems } = await openCubes('cubes-cube8-zigzag');
    await openEditor(page, 8);
    const at = await findInEditor(page, /^add a unit at .*layer 2$/);
    await page.mouse.click(at.x, at.y);
    await page.waitForFunction(() => (JSON.parse(document.querySelector('#scenario-json').value).shape.match(/#/g) || []).length === 9);
    assert.match((await scenarioOf(page)).shape, /---/, 'the unit went on top, in a second layer');
    await page.keyboard.down('Alt');
    await page.mouse.move(at.x + 1, at.y);
    await page.mouse.click(at.x, at.y);
    await page.keyboard.up('Alt');
    await page.waitForFunction(() => (JSON.parse(document.querySelector('#scenario-json').value).shape.match(/#/g) || []).length === 8);
    await page.click('.voxel-editor button[aria-label="Undo the last shape edit"]');
    await page.waitForFunction(() => (JSON.parse(document.querySelector('#scenario-json').value).shape.match(/#/g) || []).length === 9);
    assert.equal(await page.getAttribute('.voxel-canvas', 'data-units'), '9');
    // A unit that touches nothing is refused by the core; the drawing keeps it and says why.
    await page.selectOption('.voxel-slice select', 'one');
    await page.fill('.voxel-slice input[type="range"]', '0');
    await page.dispatchEvent('.voxel-slice input[type="range"]', 'input');
    const corner = await page.locator('.voxel-canvas').boundingBox();
    let refused = false;
    for (let k = 0; k < 30 && !refused; k++) {
      const x = corner.x + corner.width * (0.08 + 0.03 * (k % 6));
      const y = corner.y + corner.height * (0.55 + 0.07 * Math.floor(k / 6));
      await page.mouse.move(x, y);
      if (!/^add a unit/.test((await page.textContent('.voxel-hint')) ?? '')) continue;
      await page.mouse.click(x, y);
      refused = /not all connected/.test((await page.textContent('.voxel-editor .error')) ?? '');
      if (!refused) await page.click('.voxel-editor button[aria-label="Undo the last shape edit"]');
    }
    assert.ok(refused, 'a lone unit is refused with the core’s reason');
    assert.equal(unitsIn((await scenarioOf(page)).shape), 9, 'the scenario keeps its last valid shape');
    assert.equal(await page.getAttribute('.voxel-canvas', 'data-units'), '10', 'the drawing keeps the refused unit');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('touch: a long press removes a unit, two fingers pinch to zoom', async () => {
    const { page, context, problems } = await openCubes('cubes-light');
    await openEditor(page, 8);
    await page.keyboard.down('Alt');
    const at = await findInEditor(page, /^remove the unit at .*layer 2$/);
    await page.keyboard.up('Alt');
    await page.mouse.move(1, 1);
    const cdp = await context.newCDPSession(page);
    const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) });
    await touch('touchStart', [[at.x, at.y]]);
    // Held down, the press removes the unit once it has lasted long enough; then the finger lifts.
    await page.waitForFunction(() => (JSON.parse(document.querySelector('#scenario-json').value).shape.match(/#/g) || []).length === 7);
    await touch('touchEnd', []);
    await settle(page);
    assert.equal(await page.getAttribute('.voxel-canvas', 'data-units'), '7', 'the long press removed one unit and the lift added none');
    await settle(page);
    const before = await pixels(page, '.voxel-canvas');
    const box = await page.locator('.voxel-canvas').boundingBox();
    const cx = box.x + box.width / 2;
    const cy = box.y + box.height / 2;
    await touch('touchStart', [
      [cx - 20, cy],
      [cx + 20, cy],
    ]);
    for (let k = 1; k <= 6; k++)
      await touch('touchMove', [
        [cx - 20 - 12 * k, cy],
        [cx + 20 + 12 * k, cy],
      ]);
    await touch('touchEnd', []);
    await settle(page);
    const zoomed = await pixels(page, '.voxel-canvas');
    assert.ok(colourful(zoomed) > 1.3 * colourful(before), 'spreading two fingers zooms in');
    assert.equal(await page.getAttribute('.voxel-canvas', 'data-units'), '7', 'a pinch edits nothing');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('the layer slice shows the layers up to k, or layer k alone', async () => {
    const { page, context, problems } = await openCubes('cubes-light');
    await openEditor(page, 8);
    assert.equal(await page.getAttribute('.voxel-canvas', 'data-visible'), '8');
    await page.selectOption('.voxel-slice select', 'one');
    await page.fill('.voxel-slice input[type="range"]', '1');
    await page.dispatchEvent('.voxel-slice input[type="range"]', 'input');
    await page.waitForFunction(() => document.querySelector('.voxel-canvas').dataset.visible === '4');
    await page.waitForFunction(() => JSON.parse(document.querySelector('.voxel-canvas').dataset.scene).ghost === 4);
    assert.match(await page.textContent('.level-out'), /layer 2 of/);
    await page.selectOption('.voxel-slice select', 'below');
    await page.fill('.voxel-slice input[type="range"]', '0');
    await page.dispatchEvent('.voxel-slice input[type="range"]', 'input');
    await page.waitForFunction(() => document.querySelector('.voxel-canvas').dataset.visible === '4');
    // Hidden layers cannot be picked: the top layer's units are out of reach.
    await settle(page);
    const box = await page.locator('.voxel-canvas').boundingBox();
    await page.keyboard.down('Alt');
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    const hint = await page.textContent('.voxel-hint');
    await page.keyboard.up('Alt');
    assert.doesNotMatch(hint ?? '', /layer 2/);
    await page.selectOption('.voxel-slice select', 'all');
    await page.waitForFunction(() => document.querySelector('.voxel-canvas').dataset.visible === '8');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('keyboard only: the cursor adds a unit with Space and Ctrl+Z takes it back', async () => {
    const { page, context, problems } = await openCubes('cubes-light');
    await openEditor(page, 8);
    await page.focus('#cubes-subject');
    let tabs = 0;
    while (!(await page.evaluate(() => document.activeElement?.classList.contains('voxel-canvas'))) && tabs++ < 12) await page.keyboard.press('Tab');
    assert.ok(tabs < 12, 'the editor is reachable with Tab');
    await page.keyboard.press('Space');
    await page.waitForFunction(() => (JSON.parse(document.querySelector('#scenario-json').value).shape.match(/#/g) || []).length === 9);
    assert.equal(Number(await page.textContent('#step-count')), 0, 'Space in the editor does not play');
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('PageUp');
    assert.match(await page.textContent('.voxel-hint'), /cursor \(\d+, \d+, layer \d\)/);
    await page.keyboard.press('Control+z');
    await page.waitForFunction(() => (JSON.parse(document.querySelector('#scenario-json').value).shape.match(/#/g) || []).length === 8);
    assert.equal(Number(await page.textContent('#step-count')), 0, 'arrows in the editor do not step');
    assert.deepEqual(problems, []);
    await context.close();
  });
});

describe('the type-list editor', () => {
  test('"derive from shape" writes C31[C31, C31, C31] for a 2×2×2 cube; a link keeps shapes and type-lists', async () => {
    const { page, context, problems } = await openCubes('cubes-box12-ladder');
    await openEditor(page, 12);
    await page.click('.voxel-text summary');
    await page.fill('#cubes-voxel-text', '##\n##\n---\n##\n##\n');
    await page.click('.voxel-text button');
    await page.waitForFunction(() => JSON.parse(document.querySelector('#scenario-json').value).shape === '##\n##\n---\n##\n##\n');
    await page.click('button[title="Derive the type-lists of target 1 from the shape in the 3-D editor"]');
    await page.waitForFunction(() => JSON.parse(document.querySelector('#scenario-json').value).targets[0].type_lists === 'C31[C31, C31, C31]\n');
    assert.equal((await page.inputValue('#cubes-target-0-lists')).trim(), 'C31[C31, C31, C31]');
    // Edit the target's own shape too: the 3-D editor switches to it.
    await page.selectOption('#cubes-subject', '0');
    await page.waitForFunction(() => document.querySelector('.voxel-canvas').dataset.units === '12');
    await page.fill('#cubes-voxel-text', '###\n###\n');
    await page.click('.voxel-text button');
    await page.waitForFunction(() => JSON.parse(document.querySelector('#scenario-json').value).targets[0].shape === '###\n###\n');
    const edited = await scenarioOf(page);
    await page.click('#copy-link');
    await page.waitForFunction(() => location.hash.startsWith('#k1.'));
    const link = await page.evaluate(() => location.href);
    const second = await openPage(s.browser, link);
    const opened = await scenarioOf(second.page);
    assert.equal(opened.shape, edited.shape);
    assert.deepEqual(opened.targets, edited.targets);
    assert.equal(opened.targets[0].type_lists, 'C31[C31, C31, C31]\n');
    await openEditor(second.page, 8);
    assert.equal(await second.page.inputValue('#cubes-target-0-lists'), 'C31[C31, C31, C31]\n');
    assert.deepEqual(problems, []);
    assert.deepEqual(second.problems, []);
    await second.context.close();
    await context.close();
  });
});

test('on a tablet (820×1180) the 3-D view and the editors fit without sideways scrolling, every control named', async () => {
  const { page, context, problems } = await openCubes('cubes-light', { width: 820, height: 1180 });
  await openEditor(page, 8);
  const m = await page.evaluate(() => ({
    scroll: document.documentElement.scrollWidth,
    width: window.innerWidth,
    view: document.querySelector('#view').getBoundingClientRect().height,
    editor: document.querySelector('.voxel-canvas').getBoundingClientRect(),
  }));
  assert.ok(m.scroll <= m.width, `page is ${m.scroll}px wide in a ${m.width}px window`);
  assert.ok(m.view >= 400, `the 3-D view is ${m.view}px tall`);
  assert.ok(m.editor.width >= 300 && m.editor.right <= m.width, `the editor is ${m.editor.width}px wide`);
  assert.ok(m.editor.height >= 220, `the editor is ${m.editor.height}px tall`);
  const unnamed = await page.evaluate(() =>
    [...document.querySelectorAll('#model-editor :is(button, input, select, textarea, canvas, [role="radio"])')]
      .filter((e) => !(e.getAttribute('aria-label') || e.labels?.length || (e.tagName === 'BUTTON' && e.textContent.trim())))
      .map((e) => e.outerHTML.slice(0, 80)),
  );
  assert.deepEqual(unnamed, [], 'every control of the editors has an accessible name');
  assert.deepEqual(problems, []);
  await context.close();
});
