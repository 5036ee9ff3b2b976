// Every click tool of every model under an exercise that allows no disturbance: each tool is
// listed, looks locked, is described by the exercise's reason and says it when pressed (by pointer
// or keyboard); clicks on the lattice with the pointer and the keyboard cursor add nothing to the
// scenario, and "Goal met" never shows. The goal is met by any added disturbance
// (`scenario.disturbances.0.at >= 0`), and a control exercise that allows one click of a kind
// meets it with that click and then counts the tool down to locked: so the test could tell.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { audit, kumiki, loadWasm, openPage, session, stepCount } from './harness.mjs';

const wasm = loadWasm();
const s = session();

/** Met by the run of any scenario that carries a disturbance, by none that carries none. */
const GOAL = 'scenario.disturbances.0.at >= 0';

/** For each model, its built-in scenario with the most click tools. */
function scenariosByModel() {
  const best = new Map();
  for (const p of wasm.presets()) {
    const draft = new wasm.Draft(2 ** 18);
    if (draft.open(wasm.preset_json(p.name), false).problem) continue;
    const sim = wasm.Sim.start(draft);
    const tools = sim.layout().tools.length;
    sim.free();
    if (!best.has(p.model) || best.get(p.model).tools < tools) best.set(p.model, { name: p.name, tools });
  }
  return [...best].map(([model, { name }]) => ({ model, name }));
}

/** The preset `name` as an exercise (`allow`: the disturbances it lets students add). */
function exerciseLink(name, allow = {}) {
  const doc = JSON.parse(wasm.preset_json(name));
  doc.exercise = { title: `Do not disturb ${name}`, instructions: 'Leave the run as it is.', goal: GOAL, disturbances: allow, hints: [] };
  return wasm.encode_link(JSON.stringify(doc));
}

/** The disturbances the scenario in view carries, as the JSON editor shows it. */
const disturbances = (page) => page.$eval('#scenario-json', (t) => JSON.parse(t.value).disturbances ?? []);

/** Presses Check and returns the verdict shown. */
async function verdict(page) {
  await page.evaluate(() => {
    document.querySelector('#exercise-result').textContent = '';
  });
  await page.click('#exercise-check');
  await page.waitForFunction(() => /^(Goal met|Not met)/.test(document.querySelector('#exercise-result').textContent), null, { timeout: 30000 });
  return page.textContent('#exercise-result');
}

/** Clicks a 5×5 grid of points over the view, then the keyboard cursor's cell with Enter. */
async function clickEverywhere(page) {
  const box = await page.locator('#view').boundingBox();
  for (let i = 0; i < 5; i++) {
    for (let j = 0; j < 5; j++) await page.mouse.click(box.x + box.width * (0.1 + 0.2 * i), box.y + box.height * (0.1 + 0.2 * j));
  }
  await page.locator('#view').focus();
  await page.keyboard.press('c');
  await page.waitForFunction(() => Number(document.querySelector('#view').dataset.cursor) >= 0);
  await page.keyboard.press('Enter');
  await page.keyboard.press('Escape');
}

describe('click tools under an exercise', () => {
  for (const { model, name } of scenariosByModel()) {
    test(`${model} (${name}): every tool is locked with the reason, and no click meets the goal`, async () => {
      const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${exerciseLink(name)}`);
      await page.waitForSelector('#exercise:not([hidden])');
      await page.click('#tab-run');
      const tools = await page.$$eval('#tools button', (bs) => bs.map((b) => b.dataset.tool).filter((t) => t !== 'inspect'));
      assert.ok(tools.length > 0, 'the model has click tools, and they are listed');
      await page.waitForFunction((n) => document.querySelectorAll('#tools button[aria-disabled="true"]').length === n, tools.length);
      assert.deepEqual(await audit(page, 'the tools locked'), [], 'axe, with the tools locked');

      for (const t of tools) {
        const button = page.locator(`#tools button[data-tool="${t}"]`);
        const why = await button.evaluate((b) => document.getElementById(b.getAttribute('aria-describedby')).textContent);
        assert.match(why, /is locked by the exercise: it allows no '[a-z0-9_-]+' disturbance$/, `${t}: its reason`);
        assert.match(await button.textContent(), /\(locked\)$/);
        // Pressed with the pointer, then from the keyboard: the reason is said, the tool not taken up.
        await page.evaluate(() => {
          document.querySelector('#tool-problem').textContent = '';
        });
        await button.click({ force: true });
        assert.equal(await page.textContent('#tool-problem'), why);
        await page.evaluate(() => {
          document.querySelector('#tool-problem').textContent = '';
        });
        await button.focus();
        await page.keyboard.press('Enter');
        assert.equal(await page.textContent('#tool-problem'), why, `${t}: Enter on the locked tool says why`);
        assert.equal(await button.getAttribute('aria-checked'), 'false');
        await clickEverywhere(page);
        await page.click('#tab-scenario');
        assert.deepEqual(await disturbances(page), [], `${t}: nothing was added`);
        await page.click('#tab-run');
        assert.doesNotMatch(await verdict(page), /^Goal met/, `${t}: no "Goal met"`);
      }
      // Played on, the run never meets the goal either.
      await page.click('#step');
      assert.doesNotMatch(await verdict(page), /^Goal met/);
      assert.deepEqual(problems, []);
      await context.close();
    });
  }

  test('the control: an allowed click meets the goal, and its tool then counts down to locked', async () => {
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${exerciseLink('fracta-hexagon7', { fault: 1 })}`);
    await page.waitForSelector('#exercise:not([hidden])');
    await page.click('#tab-run');
    const fault = page.locator('#tools button[data-tool="fault"]');
    await page.waitForFunction(() => document.querySelector('#tools button[data-tool="fault"]').textContent.endsWith('(1 left)'));
    assert.match(await verdict(page), /^Not met/);
    await fault.click();
    assert.equal(await fault.getAttribute('aria-checked'), 'true');
    // The keyboard cursor starts on the structure: Enter cuts that unit's power.
    await page.locator('#view').focus();
    await page.keyboard.press('c');
    await page.waitForFunction(() => Number(document.querySelector('#view').dataset.cursor) >= 0);
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => document.querySelector('#tools button[data-tool="fault"]').getAttribute('aria-disabled') === 'true');
    assert.equal(await fault.textContent(), 'Fault (cut power) (locked)');
    assert.match(await verdict(page), /^Goal met/, 'the allowed click meets the goal: the test can tell');
    // The next click is refused where it is made, with the reason.
    await page.locator('#view').focus();
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => /is locked by the exercise/.test(document.querySelector('#inspector').textContent));
    assert.equal(await page.textContent('#inspector'), "Fault (cut power) is locked by the exercise: it allows one 'fault' disturbance, and it is used");
    await page.keyboard.press('Escape');
    await page.click('#tab-scenario');
    assert.equal((await disturbances(page)).length, 1);
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('a click rewound past no longer counts: the tool is free again before its step, and page and kumiki check agree', async () => {
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${exerciseLink('fracta-hexagon7', { fault: 1 })}`);
    await page.waitForSelector('#exercise:not([hidden])');
    await page.click('#tab-run');
    const text = (t) => page.textContent(`#tools button[data-tool="${t}"]`);
    const until = (t, end) => page.waitForFunction(([t, e]) => document.querySelector(`#tools button[data-tool="${t}"]`).textContent.endsWith(e), [t, end]);
    await until('fault', '(1 left)');
    const view = page.locator('#view');
    await view.focus();
    for (let i = 0; i < 6; i++) await page.keyboard.press('ArrowRight');
    await page.waitForFunction(() => document.querySelector('#step-count').textContent === '6');
    // The allowance's one click, at step 6.
    await page.click('#tools button[data-tool="fault"]');
    await view.focus();
    await page.keyboard.press('c');
    await page.waitForFunction(() => Number(document.querySelector('#view').dataset.cursor) >= 0);
    await page.keyboard.press('Enter');
    await until('fault', '(locked)');
    await page.keyboard.press('Escape');
    // Rewound past it: the click at step 6 would be dropped by a click now, so it no longer counts.
    for (let i = 0; i < 3; i++) await page.keyboard.press('ArrowLeft');
    await page.waitForFunction(() => document.querySelector('#step-count').textContent === '3');
    await until('fault', '(1 left)');
    assert.equal(await page.getAttribute('#tools button[data-tool="fault"]', 'aria-disabled'), null);
    // Played past it again, it counts again.
    for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowRight');
    await page.waitForFunction(() => document.querySelector('#step-count').textContent === '7');
    await until('fault', '(locked)');
    // Back at step 3, a click is made and replaces the later one; the tool is used up again.
    for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowLeft');
    await page.waitForFunction(() => document.querySelector('#step-count').textContent === '3');
    await until('fault', '(1 left)');
    await page.keyboard.press('c');
    await page.waitForFunction(() => Number(document.querySelector('#view').dataset.cursor) >= 0);
    await page.keyboard.press('Enter');
    await until('fault', '(locked)');
    await page.keyboard.press('Escape');
    assert.equal(await stepCount(page), 3);
    await page.click('#tab-scenario');
    assert.deepEqual(
      (await disturbances(page)).map((d) => [d.at, d.kind]),
      [[3, 'fault']],
    );
    // The hand-in: kumiki check counts the same one click, within the allowance.
    await page.click('#tab-run');
    await page.fill('#exercise-student', 'Ada');
    await page.click('#exercise-handin');
    await page.waitForFunction(() => document.querySelector('#exercise-handin-out').textContent.includes('#k1.'));
    const handin = /(http\S+#k1\.\S+)/.exec(await page.textContent('#exercise-handin-out'))[1];
    const row = JSON.parse(kumiki(['check', handin, '--exercise', `#${exerciseLink('fracta-hexagon7', { fault: 1 })}`]).trim());
    assert.deepEqual(row.disturbances, []);
    assert.equal(row.met, true, row.because);
    assert.match(await text('fault'), /\(locked\)$/);
    assert.deepEqual(problems, []);
    await context.close();
  });
});
