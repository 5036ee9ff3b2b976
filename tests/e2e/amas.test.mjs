// AMAS in the page: the collision heat map (section 5.2) is one of the model's field overlays,
// chosen from the overlay list by its name; its colour bar counts what the core counted, and the
// view draws the hottest cell in another colour than a module no robot ever fought over.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { loadWasm, openPage, session, settle, stepCount } from './harness.mjs';

const wasm = loadWasm();
const s = session('/');

const STEPS = 120;

/** The L of figure 23 with ten robots, stopping after STEPS steps. */
const scenario = () => ({ ...JSON.parse(wasm.preset_json('amas-L')), robots: 10, field: 'discrete', max_steps: STEPS });

/** The colour of the view's pixel at a page point. */
const pixel = (page, x, y) =>
  page.$eval(
    '#view',
    async (c, [px, py]) => {
      const r = c.getBoundingClientRect();
      const bmp = await createImageBitmap(c);
      const t = new OffscreenCanvas(bmp.width, bmp.height).getContext('2d');
      t.drawImage(bmp, 0, 0);
      const d = t.getImageData(Math.round(((px - r.left) * bmp.width) / r.width), Math.round(((py - r.top) * bmp.height) / r.height), 1, 1).data;
      return [d[0], d[1], d[2]];
    },
    [x, y],
  );

/** A page point over each of `cells`, found through the inspector's hover read-out. */
async function findCells(page, cells) {
  const box = await page.locator('#view').boundingBox();
  const found = new Map();
  for (let gy = 1; gy < 32 && found.size < cells.length; gy++) {
    for (let gx = 1; gx < 40 && found.size < cells.length; gx++) {
      const x = box.x + (box.width * gx) / 40;
      const y = box.y + (box.height * gy) / 32;
      await page.mouse.move(x, y);
      const cell = Number((await page.textContent('#inspector'))?.match(/^cell(\d+) /)?.[1]);
      if (cells.includes(cell) && !found.has(cell)) found.set(cell, { x, y });
    }
  }
  for (const c of cells) assert.ok(found.has(c), `no point of the view shows cell ${c}`);
  return cells.map((c) => found.get(c));
}

test('the collision heat map is an overlay of its own and counts what the core counts', async () => {
  const doc = scenario();
  // What the core records over the same steps.
  const sim = new wasm.Sim(JSON.stringify(doc));
  sim.advance(STEPS);
  const heat = [...sim.field('collisions')];
  const agents = [...sim.agents()];
  sim.free();
  const max = Math.max(...heat.filter((v) => !Number.isNaN(v)));
  assert.ok(max >= 2, `ten robots on the L collide more than once on some cell in ${STEPS} steps (max ${max})`);
  // Cells no robot stands on at the end, so that the pixels compared are the overlay's.
  const robots = new Set(agents.filter((_, i) => i % 2 === 0));
  const hottest = Math.max(...heat.filter((v, i) => !robots.has(i) && !Number.isNaN(v)));
  const hot = heat.findIndex((v, i) => v === hottest && !robots.has(i));
  const cold = heat.findIndex((v, i) => v === 0 && !robots.has(i));
  assert.ok(hottest >= 2 && cold >= 0);

  const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${wasm.encode_link(JSON.stringify(doc))}`);
  const options = await page.$$eval('#overlay option', (o) => o.map((x) => [x.value, x.textContent]));
  const option = options.find(([value]) => value === 'collisions');
  assert.ok(option, `the overlay list offers the heat map: ${options.map(([v]) => v).join(', ')}`);
  assert.match(option[1], /collisions per cell/, 'the option is named in words');
  await page.selectOption('#overlay', 'collisions');
  await page.click('#play');
  await page.waitForFunction((n) => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) >= n, STEPS, { timeout: 60000 });
  await settle(page);
  assert.equal(await stepCount(page), STEPS, 'the run stops at its max_steps');
  assert.equal(await page.isVisible('#colorbar'), true, 'the heat map has its colour bar');
  assert.equal(Number((await page.textContent('#colorbar-max')).replace(/,/g, '')), max, 'the colour bar tops at the core’s largest count');
  assert.equal(Number(await page.textContent('#colorbar-min')), 0);

  // The inspector reads the count; the hottest cell and a cell with none are drawn differently.
  const [at, away] = await findCells(page, [hot, cold]);
  await page.mouse.click(at.x, at.y);
  await page.waitForFunction((n) => /collisions\s*(\d+)/.exec(document.querySelector('#inspector').textContent)?.[1] === String(n), hottest);
  await page.mouse.move(0, 0);
  await settle(page);
  const [a, b] = [await pixel(page, at.x, at.y), await pixel(page, away.x, away.y)];
  assert.ok(
    a.some((v, i) => Math.abs(v - b[i]) > 40),
    `hot cell ${a} against cold cell ${b}`,
  );
  assert.deepEqual(problems, []);
  await context.close();
});
