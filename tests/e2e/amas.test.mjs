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

/**
 * The cell under a page point as the inspector's hover read-out names it: `[cell, x, y]`, or null
 * off the lattice (no read-out within a second). The pointer first leaves the view, which hides the read-out at once, so the
 * read-out that shows next is about this point; it is taken once it holds for 100 ms.
 */
async function cellAt(page, x, y) {
  await page.mouse.move(0, 0);
  await page.waitForSelector('#inspector', { state: 'hidden' });
  await page.mouse.move(x, y);
  const read = () =>
    page.textContent('#inspector').then(
      (t) =>
        t
          ?.match(/^cell(\d+) \((\d+), (\d+)\)/)
          ?.slice(1)
          .map(Number) ?? null,
    );
  try {
    await page.waitForSelector('#inspector', { state: 'visible', timeout: 1000 });
  } catch {
    return null;
  }
  for (let last = await read(); ; ) {
    await page.waitForTimeout(100);
    const now = await read();
    if (String(now) === String(last)) return now;
    last = now;
  }
}

/**
 * A page point over each of `cells` (lattice `width` cells wide), each one confirmed by the
 * inspector. A few hovers across and down the middle of the view give the lattice's scale and offset on the page; each
 * cell is then looked for where they put it, and around there, half a cell at a time.
 */
async function findCells(page, cells, width) {
  const box = await page.locator('#view').boundingBox();
  const seen = [];
  const across = [0.3, 0.4, 0.5, 0.6, 0.7].map((f) => [f, 0.5]);
  const down = [0.2, 0.35, 0.65, 0.8].map((f) => [0.5, f]);
  for (const [fx, fy] of [...across, ...down]) {
    const [px, py] = [box.x + box.width * fx, box.y + box.height * fy];
    const read = await cellAt(page, px, py);
    if (read) seen.push({ px, py, cx: read[1], cy: read[2] });
  }
  /** Page pixels per cell along one axis, from the two hovers farthest apart on it. */
  const scale = (p, c) => {
    let best = null;
    for (const u of seen) for (const v of seen) if (v[c] !== u[c] && (!best || Math.abs(v[p] - u[p]) > Math.abs(best[1][p] - best[0][p]))) best = [u, v];
    assert.ok(best, `the hovers over the view name cells in more than one ${c === 'cx' ? 'column' : 'row'}`);
    return (best[1][p] - best[0][p]) / (best[1][c] - best[0][c]);
  };
  const [sx, sy] = [scale('px', 'cx'), scale('py', 'cy')];
  const [o] = seen;
  const points = [];
  for (const cell of cells) {
    const [tx, ty] = [cell % width, Math.floor(cell / width)];
    const [x0, y0] = [o.px + (tx - o.cx) * sx, o.py + (ty - o.cy) * sy];
    let found = null;
    const near = [[0, 0]];
    for (const r of [0.5, 1, 1.5]) near.push([r, 0], [-r, 0], [0, r], [0, -r], [r, r], [-r, -r], [r, -r], [-r, r]);
    for (const [dx, dy] of near) {
      const at = { x: x0 + dx * Math.abs(sx), y: y0 + dy * Math.abs(sy) };
      if ((await cellAt(page, at.x, at.y))?.[0] === cell) {
        found = at;
        break;
      }
    }
    assert.ok(found, `no point of the view shows cell ${cell}`);
    points.push(found);
  }
  return points;
}

test('the collision heat map is an overlay of its own and counts what the core counts', async () => {
  const doc = scenario();
  // What the core records over the same steps.
  const sim = new wasm.Sim(JSON.stringify(doc));
  sim.advance(STEPS);
  const heat = [...sim.field('collisions')];
  const agents = [...sim.agents()];
  const width = sim.layout().dims[0];
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
  const [at, away] = await findCells(page, [hot, cold], width);
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

/** The state hash of scenario `json` run alone for `steps` steps, in the wasm core under Node. */
function hashAt(json, steps) {
  const sim = new wasm.Sim(json);
  sim.advance(steps);
  const hash = sim.hash();
  sim.free();
  return hash;
}

test('the lesson about fields shows both readings of footnote 3 side by side, each its own scenario run alone', async () => {
  const lesson = JSON.parse(wasm.lesson_json('lesson-amas-fields'));
  assert.equal(lesson.direction, 'module');
  assert.equal(lesson.compare.value, 'robot');
  const alone = { ...lesson };
  delete alone.compare;
  const first = JSON.stringify(alone);
  const second = JSON.stringify({ ...alone, direction: 'robot' });
  const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${wasm.encode_link(JSON.stringify(lesson))}`);
  await page.waitForSelector('body.comparing #compare-wrap:not([hidden])');
  await page.waitForSelector('#exercise:not([hidden])');
  assert.equal(await page.textContent('#run-label-first'), 'direction module');
  assert.equal(await page.textContent('#run-label-second'), 'each robot draws among equal neighbours');
  const steps = 8;
  for (let i = 0; i < steps; i++) await page.click('#step');
  await page.waitForFunction(
    (n) => Number(document.querySelector('#step-count').textContent) === n && document.querySelector('#compare-wrap').dataset.steps === String(n),
    steps,
    { timeout: 30000 },
  );
  await page.waitForFunction(() => document.querySelector('#state-hash').textContent !== '–');
  const hashes = { first: await page.textContent('#state-hash'), second: await page.getAttribute('#compare-wrap', 'data-hash') };
  assert.equal(hashes.first, hashAt(first, steps));
  assert.equal(hashes.second, hashAt(second, steps));
  assert.notEqual(hashes.first, hashes.second, 'the two readings part within a few steps on the discrete field');
  assert.deepEqual(problems, []);
  await context.close();
});
