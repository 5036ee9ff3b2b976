// Two runs side by side: reached from the first screen by mouse and by keyboard alone, the two
// runs step, rewind and reset together; they differ where their one setting matters, each is the
// single run of its own scenario (the same state hash as that scenario run alone), and the link
// holds both.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { loadWasm, openPage, session, stepCount } from './harness.mjs';

const wasm = loadWasm();
const s = session();
const LESSON = 'lesson-amas-compare';

/** The state hash of `json` run alone for `steps` steps, in the wasm core under Node. */
function hashAt(json, steps) {
  const sim = new wasm.Sim(json);
  sim.advance(steps);
  const hash = sim.hash();
  sim.free();
  return hash;
}

/** A scenario's comparison as the page's scenario in view gives it: the second run's scenario and the two names. */
function comparison(text) {
  const draft = new wasm.Draft(2 ** 18);
  assert.equal(draft.open(text, false).problem, null);
  const pair = draft.comparison();
  draft.free();
  assert.equal(pair.kind, 'pair');
  return pair;
}

/** The first run's scenario alone (without its comparison) and the second run's. */
function scenarios() {
  const lesson = JSON.parse(wasm.lesson_json(LESSON));
  const pair = comparison(JSON.stringify(lesson));
  delete lesson.compare;
  return { first: JSON.stringify(lesson), second: pair.second, labels: pair.labels };
}

/** Waits until both runs stand at `steps`, paused, with their hashes shown; returns the hashes. */
async function bothAt(page, steps) {
  await page.waitForFunction(
    (n) => {
      const first = Number(document.querySelector('#step-count').textContent.replace(/,/g, ''));
      const wrap = document.querySelector('#compare-wrap');
      return first === n && wrap.dataset.steps === String(n) && wrap.dataset.hash && document.querySelector('#play').textContent === 'Play';
    },
    steps,
    { timeout: 30000 },
  );
  // A paused run's frame carries its hash; wait for both to be the hashes of this step.
  await page.waitForFunction(() => document.querySelector('#state-hash').textContent !== '–');
  return { first: await page.textContent('#state-hash'), second: await page.getAttribute('#compare-wrap', 'data-hash') };
}

/** Presses Tab until the element `id` has the focus. */
async function tabTo(page, id, limit = 200) {
  for (let i = 1; i <= limit; i++) {
    await page.keyboard.press('Tab');
    if ((await page.evaluate(() => document.activeElement?.id)) === id) return;
  }
  throw new Error(`#${id} was not reached in ${limit} Tab presses`);
}

async function metric(page, name) {
  const card = page.locator('#metrics .metric', { has: page.locator(`span:text-is("${name}")`) });
  const values = await card.locator('strong').allTextContents();
  return values.map((v) => Number(v.replace(/,/g, '')));
}

describe('compare two runs', () => {
  test('by mouse from the first screen: the runs step, rewind and reset together, each the single run of its scenario, and the link holds both', async () => {
    const { first, second, labels } = scenarios();
    assert.deepEqual(labels, ['collision relay', 'tokens only']);
    const { page, context, problems } = await openPage(s.browser, s.server.url, { keepWelcome: true });
    await page.waitForSelector('#welcome[open]');
    await page.click('#way-compare');
    await page.waitForSelector('body.comparing #compare-wrap:not([hidden])');
    await page.waitForSelector('#exercise:not([hidden])');
    assert.equal(await page.textContent('#run-label-first'), labels[0]);
    assert.equal(await page.textContent('#run-label-second'), labels[1]);
    assert.equal(await page.textContent('#chart-legend'), labels.join(''));
    await bothAt(page, 0);

    for (let i = 0; i < 5; i++) await page.click('#step');
    let hashes = await bothAt(page, 5);
    assert.equal(hashes.first, hashAt(first, 5));
    assert.equal(hashes.second, hashAt(second, 5));

    // About 5 steps a second (slider position 1.75): the pause below lands with eight seconds to
    // spare before the first run ends at 99, even on a loaded machine (at the default 14 a second
    // a click answered late under load saw the run at its end).
    await page.$eval('#speed', (el) => {
      el.value = '1.75';
      el.dispatchEvent(new Event('input'));
    });
    await page.click('#play');
    await page.waitForFunction(() => Number(document.querySelector('#step-count').textContent) >= 60, null, { timeout: 60000 });
    await page.click('#play');
    // A frame under way as the pause arrived may still move the count: read it once it stands.
    await page.waitForFunction(() => document.querySelector('#play').textContent === 'Play');
    await page.waitForTimeout(300);
    const paused = await stepCount(page);
    assert.ok(paused < 99, `paused before the first run ends (${paused})`);
    hashes = await bothAt(page, paused);
    assert.equal(hashes.first, hashAt(first, paused));
    assert.equal(hashes.second, hashAt(second, paused));
    // The rule matters: tokens collide more than relay by now, and the chart holds both runs.
    const [relay, tokens] = await metric(page, 'collisions');
    assert.ok(tokens > relay, `tokens only ${tokens} > relay ${relay} collisions at step ${paused}`);
    const chart = await page.$eval('#metric-chart', (c) => ({ ...c.dataset, label: c.getAttribute('aria-label') }));
    assert.equal(chart.series, JSON.stringify(labels));
    assert.ok(Number(chart.points) > 0 && Number(chart.secondPoints) > 0, JSON.stringify(chart));
    assert.match(chart.label, /collision relay \(blue\) and tokens only \(orange\)/);

    // Back with the view's ← key (every press counts): both go back.
    await page.focus('#view');
    for (let i = 0; i < 10; i++) await page.keyboard.press('ArrowLeft');
    hashes = await bothAt(page, paused - 10);
    assert.equal(hashes.second, hashAt(second, paused - 10));

    // Played to the end: the first run (relay) ends first and the second goes on alone to its own end.
    await page.click('#play');
    await page.waitForSelector('#run-status:text("completed")', { timeout: 30000 });
    await page.waitForSelector('#run-status-second:text("completed")', { timeout: 30000 });
    const ends = { first: await stepCount(page), second: Number(await page.getAttribute('#compare-wrap', 'data-steps')) };
    const alone = (json) => {
      const sim = new wasm.Sim(json);
      while (!sim.finished()) sim.advance(1000);
      const end = { steps: sim.steps(), hash: sim.hash() };
      sim.free();
      return end;
    };
    assert.equal(ends.first, alone(first).steps);
    assert.equal(ends.second, alone(second).steps);
    assert.ok(ends.second > ends.first, `tokens only (${ends.second}) ends after relay (${ends.first})`);
    await page.waitForFunction((h) => document.querySelector('#compare-wrap').dataset.hash === h, alone(second).hash);

    await page.click('#reset');
    await bothAt(page, 0);

    // The link holds both runs: reloaded, the same pair opens and runs the same.
    await page.click('#copy-link');
    await page.waitForFunction(() => location.hash.startsWith('#k1.'));
    const link = page.url();
    const again = await openPage(s.browser, link);
    await again.page.waitForSelector('body.comparing #compare-wrap:not([hidden])');
    assert.equal(await again.page.textContent('#run-label-first'), labels[0]);
    assert.equal(await again.page.textContent('#run-label-second'), labels[1]);
    for (let i = 0; i < 3; i++) await again.page.click('#step');
    hashes = await bothAt(again.page, 3);
    assert.equal(hashes.first, hashAt(first, 3));
    assert.equal(hashes.second, hashAt(second, 3));
    await again.context.close();
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('by keyboard alone: from the first screen to the compare view, stepping both, and choosing another setting', async () => {
    const { second } = scenarios();
    const { page, context, problems } = await openPage(s.browser, s.server.url, { keepWelcome: true });
    await page.waitForSelector('#welcome[open]');
    await tabTo(page, 'way-compare');
    await page.keyboard.press('Enter');
    await page.waitForSelector('body.comparing #compare-wrap:not([hidden])');
    await bothAt(page, 0);
    await page.evaluate(() => document.activeElement?.blur());
    for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowRight');
    const hashes = await bothAt(page, 4);
    assert.equal(hashes.second, hashAt(second, 4));

    // Stop comparing, then compare the field instead, all from the keyboard.
    await tabTo(page, 'compare-stop');
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => !document.body.classList.contains('comparing'));
    assert.equal(await page.isVisible('#compare-wrap'), false);
    await tabTo(page, 'compare-setting');
    // The settings are the model's choices, switches and numbers; `field` is one of them.
    const offered = await page.$$eval('#compare-setting option', (os) => os.map((o) => o.value));
    assert.ok(offered.includes('field') && offered.includes('collision') && offered.includes('seed'), offered.join());
    while ((await page.$eval('#compare-setting', (e) => e.value)) !== 'field') await page.keyboard.press('ArrowDown');
    assert.deepEqual(await page.$$eval('#compare-value option', (os) => os.map((o) => o.textContent)), ['continuous']);
    await tabTo(page, 'compare-start');
    await page.keyboard.press('Enter');
    await page.waitForSelector('body.comparing #compare-wrap:not([hidden])');
    assert.equal(await page.textContent('#run-label-first'), 'field discrete');
    assert.equal(await page.textContent('#run-label-second'), 'field continuous');
    await bothAt(page, 0);
    const doc = JSON.parse(await page.inputValue('#scenario-json'));
    assert.deepEqual(doc.compare, { path: 'field', value: 'continuous' });
    await page.evaluate(() => document.activeElement?.blur());
    for (let i = 0; i < 3; i++) await page.keyboard.press('ArrowRight');
    const field = await bothAt(page, 3);
    assert.equal(field.second, hashAt(comparison(JSON.stringify(doc)).second, 3));
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('the lesson works by keyboard alone: the student changes the rule of the first run and meets the goal beside the tokens run', async () => {
    const { second } = scenarios();
    const { page, context, problems } = await openPage(s.browser, s.server.url, { keepWelcome: true });
    await page.waitForSelector('#welcome[open]');
    await tabTo(page, 'way-compare');
    await page.keyboard.press('Enter');
    await page.waitForSelector('body.comparing #compare-wrap:not([hidden])');
    await page.waitForSelector('#exercise:not([hidden])');
    await bothAt(page, 0);

    // The tabs are one stop: the arrows choose among them.
    await page.evaluate(() => document.activeElement?.blur());
    await tabTo(page, 'tab-run');
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('Enter');
    await page.waitForSelector('#panel-scenario:not([hidden])');
    await tabTo(page, 'param-collision');
    while (!(await page.$eval('#param-collision', (e) => e.value)).includes('blackboard')) await page.keyboard.press('ArrowDown');
    await page.waitForFunction(() => document.querySelector('#run-label-first').textContent === 'collision blackboard');
    assert.equal(await page.textContent('#run-label-second'), 'tokens only');
    const doc = JSON.parse(await page.inputValue('#scenario-json'));
    assert.equal(doc.collision, 'blackboard');
    assert.deepEqual(doc.compare, JSON.parse(wasm.lesson_json(LESSON)).compare);

    await page.evaluate(() => document.activeElement?.blur());
    await tabTo(page, 'tab-scenario');
    await page.keyboard.press('ArrowLeft');
    await page.keyboard.press('Enter');
    await page.waitForSelector('#panel-run:not([hidden])');
    await tabTo(page, 'speed');
    await page.keyboard.press('End');
    await page.evaluate(() => document.activeElement?.blur());
    await page.keyboard.press('Space');
    await page.waitForSelector('#run-status:text("completed")', { timeout: 60000 });
    await page.waitForFunction(() => document.querySelector('#exercise-result').textContent.startsWith('Goal met'), null, { timeout: 30000 });
    assert.match(await page.textContent('#exercise-result'), /metrics\.collisions is 0/);
    // The second run is still the lesson's tokens run, and collides.
    await page.waitForSelector('#run-status-second:text("completed")', { timeout: 60000 });
    const sim = new wasm.Sim(second);
    while (!sim.finished()) sim.advance(1000);
    assert.equal(await page.getAttribute('#compare-wrap', 'data-hash'), sim.hash());
    sim.free();
    const [blackboard, tokens] = await metric(page, 'collisions');
    assert.equal(blackboard, 0);
    assert.ok(tokens > 0, `tokens only collides (${tokens})`);
    assert.deepEqual(problems, []);
    await context.close();
  });
});
