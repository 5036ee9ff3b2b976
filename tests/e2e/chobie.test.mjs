// chobie in the page (that every preset opens with its robots and terrain is
// tests/unit/rooms.test.ts's): the crawl moves the structure; a load with a typed
// magnitude is placed by clicking a robot, recorded for the link, and shows in the stress field
// and the overload count; the exaggerated deflected shape; the last step's signals, slot by slot;
// the view follows the growing bridge until the user zooms; overloaded and failed robots are
// marked over the stress field; the lesson whose bridge stands only with load adaptation; figure
// 13's step 7 and a bridge that stops overloaded; a bridge that tips over the edge. Each of the
// new states passes the accessibility audit (axe-core: no serious or critical violation).
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { test } from 'node:test';
import { loadWasm, openPage, session, settle, stepCount, waitForSteps } from './harness.mjs';

const wasm = loadWasm();
const s = session('/');
const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');

/** Serious and critical axe-core violations on the page as it stands, one line each. */
async function audit(page, where) {
  if (!(await page.evaluate(() => 'axe' in window))) await page.evaluate(AXE);
  const violations = await page.evaluate(async () => {
    const result = await window.axe.run(document, {
      runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'best-practice'] },
      resultTypes: ['violations'],
    });
    return result.violations
      .filter((v) => v.impact === 'serious' || v.impact === 'critical')
      .map((v) => `${v.id} (${v.impact}) at ${v.nodes.map((n) => n.target.join(' ')).slice(0, 5)}`);
  });
  return violations.map((v) => `${where}: ${v}`);
}

const open = (preset, change = (x) => x) =>
  openPage(s.browser, `${s.server.url}#${wasm.encode_link(JSON.stringify(change(JSON.parse(wasm.preset_json(preset)))))}`);
const scenario = async (page) => JSON.parse(await page.$eval('#scenario-json', (t) => t.value));
const metric = (page, name) =>
  page.$$eval(
    '#metrics .metric',
    (nodes, n) => {
      const m = nodes.find((x) => x.firstChild.textContent === n);
      // A card holds its name, where the metric table explains it a tooltip, and its value (strong).
      return m ? Number(m.querySelector('strong').textContent.replace(/,/g, '')) : Number.NaN;
    },
    name.replace(/_/g, ' '),
  );

/** The annotation layer's pixels, as one string to compare, and how many are drawn. */
const annotations = (page) =>
  page.$eval('#annotations', async (c) => {
    const d = await (async () => {
      const bmp = await createImageBitmap(c);
      const t = new OffscreenCanvas(bmp.width, bmp.height).getContext('2d');
      t.drawImage(bmp, 0, 0);
      return t.getImageData(0, 0, bmp.width, bmp.height).data;
    })();
    let inked = 0;
    let sum = 0;
    for (let i = 3; i < d.length; i += 4) {
      if (d[i] > 0) inked++;
      sum = (sum * 31 + d[i - 3] + 7 * d[i - 2] + 13 * d[i - 1] + 17 * d[i]) % 1000000007;
    }
    return { inked, sum };
  });

/** Pixels of the view's outermost columns, left and right, that are not the background: what is cut off at the sides. */
const cutOff = (page) =>
  page.$eval('#view', async (c) => {
    const bmp = await createImageBitmap(c);
    const t = new OffscreenCanvas(bmp.width, bmp.height).getContext('2d');
    t.drawImage(bmp, 0, 0);
    const { width, height, data } = t.getImageData(0, 0, bmp.width, bmp.height);
    let count = 0;
    for (let y = 0; y < height; y++) {
      for (const x of [0, 1, width - 2, width - 1]) {
        const i = 4 * (y * width + x);
        // The background is rgb(27, 35, 44).
        if (Math.abs(data[i] - 27) + Math.abs(data[i + 1] - 35) + Math.abs(data[i + 2] - 44) > 12) count++;
      }
    }
    return count;
  });

/** Annotation pixels of one colour (within a small tolerance): a mark drawn in a legend colour. */
const inked = (page, rgb) =>
  page.$eval(
    '#annotations',
    async (c, [r, g, b]) => {
      const bmp = await createImageBitmap(c);
      const t = new OffscreenCanvas(bmp.width, bmp.height).getContext('2d');
      t.drawImage(bmp, 0, 0);
      const { data } = t.getImageData(0, 0, bmp.width, bmp.height);
      let count = 0;
      for (let i = 0; i < data.length; i += 4) {
        if (data[i + 3] > 200 && Math.abs(data[i] - r) + Math.abs(data[i + 1] - g) + Math.abs(data[i + 2] - b) < 24) count++;
      }
      return count;
    },
    rgb,
  );

async function fullSpeed(page) {
  await page.$eval('#speed', (el) => {
    el.value = el.max;
    el.dispatchEvent(new Event('input'));
  });
}

/** Moves the pointer over the view until the inspector names cell `cell`; returns that point. */
async function findCell(page, cell) {
  const box = await page.locator('#view').boundingBox();
  // The worlds used here are small: a cell is far wider than the grid's pitch.
  for (let gy = 1; gy < 24; gy++) {
    for (let gx = 1; gx < 32; gx++) {
      const x = box.x + (box.width * gx) / 32;
      const y = box.y + (box.height * gy) / 24;
      await page.mouse.move(x, y);
      const text = await page.textContent('#inspector');
      if (text?.startsWith(`cell${cell} `)) return { x, y };
    }
  }
  throw new Error(`no point of the view shows cell ${cell}`);
}

test('the crawl moves the structure right, step after step', async () => {
  const { page, context, problems } = await open('chobie-crawl5');
  assert.equal(await metric(page, 'distance'), 0);
  const distances = [];
  for (let k = 1; k <= 8; k++) {
    await page.click('#step');
    await waitForSteps(page, k);
    await settle(page);
    if (k % 4 === 0) distances.push(await metric(page, 'distance'));
  }
  // One crawl cycle (four transformations) moves the structure one cell.
  assert.deepEqual(distances, [1, 2]);
  assert.deepEqual(problems, []);
  await context.close();
});

test('a load with a typed magnitude is put on the clicked robot, recorded for the link, and overloads the root', async () => {
  // Figure 14's cantilever without its load: the tip robot is cell 19 (x 3, y 2).
  const { page, context, problems } = await open('chobie-load5', (doc) => ({ ...doc, disturbances: [] }));
  await page.selectOption('#overlay', 'stress');
  await settle(page);
  assert.equal(await metric(page, 'overloads'), 0);
  const bare = await metric(page, 'peak_stress');
  const tip = await findCell(page, 19);
  // Inspecting the robot lists its own facts; the whole-structure ones stay in their panel.
  await page.mouse.click(tip.x, tip.y);
  await page.waitForFunction(() => document.querySelector('#inspector').textContent.includes('stress mpa'));
  assert.ok(!(await page.textContent('#inspector')).includes('meaning'), 'no slot trace in the cell inspector');
  await page.click('#tools button[data-tool="load"]');
  await page.fill('#tool-load-force', '300');
  await page.mouse.click(tip.x, tip.y);
  await page.waitForFunction(() => JSON.parse(document.querySelector('#scenario-json').value).disturbances?.length === 1);
  const recorded = (await scenario(page)).disturbances[0];
  assert.deepEqual([recorded.kind, recorded.cells, recorded.force], ['load', [19], 300]);
  const link = wasm.decode_link(wasm.encode_link(JSON.stringify(await scenario(page))));
  assert.equal(JSON.parse(link).disturbances[0].force, 300, 'the magnitude survives a link');
  await page.waitForFunction(() =>
    [...document.querySelectorAll('#metrics .metric')].some(
      (m) => m.firstChild.textContent === 'overloads' && Number(m.querySelector('strong').textContent) > 0,
    ),
  );
  assert.ok((await metric(page, 'peak_stress')) > 2 * bare, 'the load raises the peak stress');
  assert.equal(await page.isVisible('#colorbar'), true, 'the stress field has its colour bar');
  assert.ok(Number((await page.textContent('#colorbar-max')).replace(/,/g, '')) > 0);
  // Overloaded robots are drawn in their own colour, from the model's cell codes.
  const codes = await page.evaluate(() => {
    const legend = [...document.querySelectorAll('#legend span')].map((x) => x.textContent);
    return legend.includes('overloaded (ringed): stress over the 4 MPa threshold');
  });
  assert.ok(codes);

  // Moving the load: lift it off the tip, put it on the robot beside the root.
  await page.click('#tools button[data-tool="move"]');
  await page.mouse.click(tip.x, tip.y);
  const inner = await findCell(page, 17);
  await page.mouse.click(inner.x, inner.y);
  await page.waitForFunction(() => JSON.parse(document.querySelector('#scenario-json').value).disturbances?.length === 3);
  const moved = (await scenario(page)).disturbances.slice(1).map((d) => [d.kind, d.cells[0]]);
  assert.deepEqual(moved, [
    ['move', 19],
    ['move', 17],
  ]);
  await page.waitForFunction(() =>
    [...document.querySelectorAll('#metrics .metric')].some(
      (m) => m.firstChild.textContent === 'overloads' && Number(m.querySelector('strong').textContent) === 0,
    ),
  );
  assert.deepEqual(problems, []);
  await context.close();
});

test('the deflected shape is drawn exaggerated by the typed factor', async () => {
  const { page, context, problems } = await open('chobie-load5');
  await settle(page);
  const plain = await annotations(page);
  await page.check('#deflection-view');
  await page.waitForFunction(async (n) => {
    const c = document.querySelector('#annotations');
    const d = await (async () => {
      const bmp = await createImageBitmap(c);
      const t = new OffscreenCanvas(bmp.width, bmp.height).getContext('2d');
      t.drawImage(bmp, 0, 0);
      return t.getImageData(0, 0, bmp.width, bmp.height).data;
    })();
    let inked = 0;
    for (let i = 3; i < d.length; i += 4) if (d[i] > 0) inked++;
    return inked > n;
  }, plain.inked);
  await settle(page);
  const small = await annotations(page);
  await page.fill('#deflection-scale', '2000');
  await settle(page);
  await settle(page);
  const large = await annotations(page);
  assert.notEqual(large.sum, small.sum, 'a larger factor moves the drawn robots');
  await page.uncheck('#deflection-view');
  await settle(page);
  assert.equal((await annotations(page)).inked, plain.inked);
  assert.deepEqual(problems, []);
  await context.close();
});

test('stepping slowly shows each slot of the last step: its meaning and its senders', async () => {
  const { page, context, problems } = await open('chobie-crawl5');
  await page.check('#slot-view');
  await page.click('#step');
  await page.waitForFunction(() => document.querySelector('#slot-label').textContent.startsWith('Slot 1 of'));
  assert.equal(await stepCount(page), 1);
  const first = await page.textContent('#slot-label');
  assert.match(first, /rule 1: every robot signals in all four directions \(5 robots send\)/);
  await settle(page);
  const drawn = await annotations(page);
  await page.click('#slot-next');
  await page.waitForFunction(() => document.querySelector('#slot-label').textContent.startsWith('Slot 2 of'));
  assert.match(await page.textContent('#slot-label'), /rule 2/);
  await settle(page);
  assert.notEqual((await annotations(page)).sum, drawn.sum, 'another slot, other signals');
  // Through to the command and the completion signal.
  const meanings = [];
  const total = Number(await page.getAttribute('#slot-range', 'max'));
  for (let k = 2; k <= total; k++) {
    await page.click('#slot-next');
    await page.waitForFunction((n) => document.querySelector('#slot-label').textContent.startsWith(`Slot ${n} of`), k + 1);
    meanings.push(await page.textContent('#slot-label'));
  }
  for (const word of ['route', 'drive', 'direction', 'completion'])
    assert.ok(
      meanings.some((m) => m.includes(word)),
      `${word} in ${meanings.join(' | ')}`,
    );
  // The next step brings its own slots.
  await page.fill('#slot-range', '0');
  await page.dispatchEvent('#slot-range', 'input');
  await page.click('#step');
  await waitForSteps(page, 2);
  await page.waitForFunction(() => document.querySelector('#slot-label').textContent.startsWith('Slot 1 of'));
  assert.deepEqual(problems, []);
  await context.close();
});

test('the view follows the growing bridge until the user zooms, and Fit brings it back', async () => {
  // Without adaptation or a goal the lower tier slides on to a span of 19, far past the terrain the view first framed.
  const { page, context, problems } = await open('chobie-bridge', (doc) => ({ ...doc, adaptation: false, goal: undefined, max_steps: 24 }));
  await settle(page);
  assert.equal(await cutOff(page), 0, 'the first frame shows the whole structure');
  await fullSpeed(page);
  await page.click('#play');
  await waitForSteps(page, 24);
  await settle(page);
  assert.ok((await metric(page, 'span')) >= 15);
  assert.equal(await cutOff(page), 0, 'the bridge is in view at its full span');
  // A zoom is the user's: the view stays zoomed, even as the run is reset and grows again.
  await page.click('#zoom-in');
  await page.click('#zoom-in');
  await settle(page);
  assert.ok((await cutOff(page)) > 0, 'zoomed in, the structure reaches past the sides');
  await page.click('#reset');
  await page.waitForFunction(() => document.querySelector('#step-count').textContent === '0');
  await page.click('#play');
  await waitForSteps(page, 24);
  await settle(page);
  assert.ok((await cutOff(page)) > 0, 'the view was left where the user put it');
  await page.click('#zoom-fit');
  await settle(page);
  await settle(page);
  assert.equal(await cutOff(page), 0, 'Fit frames the bridge again');
  assert.deepEqual(problems, []);
  await context.close();
});

test('a bridge that stands only with load adaptation: the plain one breaks, its overloaded robots ringed and its broken ones crossed over the stress field', async () => {
  const lesson = JSON.parse(wasm.lesson_json('lesson-chobie-survive'));
  const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${wasm.encode_link(JSON.stringify(lesson))}`);
  await page.waitForSelector('#exercise:not([hidden])');
  assert.equal(await page.textContent('#exercise-title'), 'A bridge that stands only with load adaptation');
  const legend = await page.$$eval('#legend span', (spans) => spans.map((x) => [x.textContent, x.querySelector('i')?.dataset.mark ?? '']));
  assert.ok(
    legend.some(([name, mark]) => name === 'overloaded (ringed): stress over the 4 MPa threshold' && mark === 'ring'),
    JSON.stringify(legend),
  );
  assert.ok(
    legend.some(([name, mark]) => name === 'failed (crossed): broken, over 40 MPa, or tipped over the edge' && mark === 'cross'),
    JSON.stringify(legend),
  );
  await page.selectOption('#overlay', 'stress');
  await fullSpeed(page);
  await page.click('#play');
  await page.waitForFunction(() => document.querySelector('#exercise-result').textContent.startsWith('Not met yet'), null, { timeout: 30000 });
  assert.equal(await metric(page, 'failed'), 1, 'broken');
  assert.ok((await metric(page, 'max_peak_stress')) >= 40, 'past the strength of ABS (shown to three figures)');
  await settle(page);
  // Over the heat map, the rings of the overloaded robots (#db3737) and the crosses of the broken ones (#8e5cd9).
  assert.ok((await inked(page, [0xdb, 0x37, 0x37])) > 0, 'overloaded robots ringed');
  assert.ok((await inked(page, [0x8e, 0x5c, 0xd9])) > 0, 'broken robots crossed');
  assert.deepEqual(await audit(page, 'a broken bridge in the stress view'), []);
  await page.selectOption('#overlay', '');
  await settle(page);
  await settle(page);
  assert.ok((await inked(page, [0x8e, 0x5c, 0xd9])) > 0, 'and in the default view');

  await page.click('#tab-scenario');
  await page.check('#param-adaptation');
  await page.waitForFunction(() => JSON.parse(document.querySelector('#scenario-json').value).adaptation === true);
  await page.click('#tab-run');
  await page.click('#play');
  await page.waitForFunction(() => document.querySelector('#exercise-result').textContent.startsWith('Goal met'), null, { timeout: 30000 });
  assert.equal(await metric(page, 'failed'), 0, 'standing');
  assert.ok((await metric(page, 'resumed')) >= 1);
  await settle(page);
  assert.equal(await inked(page, [0x8e, 0x5c, 0xd9]), 0, 'nothing crossed');
  assert.deepEqual(problems, []);
  await context.close();
});

test('figure 13 in the page: step 7 puts reserve A into the tier and B under it, construction resumes, and the bridge stops overloaded with no reserve left', async () => {
  const { page, context, problems } = await open('chobie-fig13');
  await page.selectOption('#overlay', 'stress');
  await fullSpeed(page);
  await page.click('#play');
  // The step of the first reinforcement: the run pauses nowhere, so watch the metric.
  await page.waitForFunction(
    () =>
      [...document.querySelectorAll('#metrics .metric')].some(
        (m) => m.firstChild.textContent === 'reinforcements' && Number(m.querySelector('strong').textContent) === 1,
      ),
    null,
    { timeout: 30000 },
  );
  await waitForSteps(page, 20);
  await settle(page);
  assert.equal(await metric(page, 'reinforcements'), 1, 'step 7 fired once');
  assert.equal(await metric(page, 'resumed'), 1, 'construction resumed');
  assert.equal(await metric(page, 'span'), 10, 'the goal span');
  assert.equal(await metric(page, 'reserves'), 0, 'no reserve left');
  assert.equal(await metric(page, 'mode'), 2, 'adaptation mode');
  assert.ok((await metric(page, 'overloads')) > 0, 'still overloaded');
  // It spans its goal but is not complete: the run ends at its step limit.
  assert.equal(await page.textContent('#run-status'), 'step limit reached');
  // B is under the tier, against the cliff face: cell (10, 3) of a world 26 wide.
  const b = await findCell(page, 3 * 26 + 10);
  await page.mouse.click(b.x, b.y);
  await page.waitForFunction(() => document.querySelector('#inspector').textContent.includes('stress mpa'));
  assert.ok((await inked(page, [0xdb, 0x37, 0x37])) > 0, 'the overloaded root ringed');
  assert.deepEqual(await audit(page, 'figure 13 stopped overloaded, stress view'), []);
  assert.deepEqual(problems, []);
  await context.close();
});

test('a bridge on a base that does not hold it tips over the cliff edge: failed 2, every robot crossed', async () => {
  const { page, context, problems } = await open('chobie-bridge', (doc) => ({ ...doc, adaptation: false, anchored: false, goal: undefined, max_steps: 20 }));
  await page.selectOption('#overlay', 'stress');
  await fullSpeed(page);
  await page.click('#play');
  await waitForSteps(page, 20);
  await settle(page);
  assert.equal(await metric(page, 'failed'), 2, 'tipped');
  assert.ok((await metric(page, 'overturning')) > 0, 'the moment about the edge turns it over');
  const span = await metric(page, 'span');
  assert.ok(span > 0 && span < 19, 'it stopped where it tipped');
  assert.ok((await inked(page, [0x8e, 0x5c, 0xd9])) > 0, 'crossed over the stress field');
  assert.deepEqual(await audit(page, 'a tipped bridge, stress view'), []);
  await page.selectOption('#overlay', '');
  await settle(page);
  await settle(page);
  assert.ok((await inked(page, [0x8e, 0x5c, 0xd9])) > 0, 'and in the default view');
  assert.deepEqual(problems, []);
  await context.close();
});
