// Rules you can write, in the browser: a scenario without a script never fetches the rules module;
// the Rules tab loads it and the editor; a syntax error typed is marked at its line, fixed, run,
// shared by link, and `kumiki run` on that link prints the page's state hash; an endless loop is
// stopped with a message naming the rule, the line and the cap while the page stays responsive.
// The room's logic without a browser is tests/unit/rules.test.ts's.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { audit, kumiki, loadWasm, openPage, session, stepCount } from './harness.mjs';

const wasm = loadWasm();
const s = session();

/**
 * The paper's leader rule, changed: a robot that heard from top or bottom but from neither side
 * leads too, as a row's end. On chobie-form-a it changes the run within 12 steps.
 */
const MINE = `fn leader(robot) {
  let first = robot.first;
  let second = robot.second;
  if !first.up && !first.down {
    return ();
  }
  let vertical = if first.up { "top" } else { "bottom" };
  if second.right {
    vertical + "_right"
  } else if second.left {
    vertical + "_left"
  } else {
    "row_end"
  }
}`;
/** The same with line 3 broken. */
const BROKEN = MINE.replace('let second = robot.second;', 'let second = ;');

const linkOf = (name) => `#${wasm.encode_link(wasm.preset_json(name))}`;

/**
 * Replaces the editor's text as a person types it, key by key (Enter indents the next line, so
 * the lines start with more spaces than `text`'s: its lines stay where they are).
 */
async function replaceText(page, text) {
  await page.click('#rules-editor .cm-content');
  await page.keyboard.press('Control+A');
  await page.keyboard.press('Delete');
  await page.keyboard.type(text);
}

async function stepTo(page, steps) {
  const from = await stepCount(page);
  await page.locator('#view').focus();
  for (let i = from; i < steps; i++) await page.keyboard.press('ArrowRight');
  await page.waitForFunction((n) => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) === n, steps);
  await page.waitForFunction(() => document.querySelector('#state-hash').textContent.length === 16);
  return page.textContent('#state-hash');
}

describe('rules you can write', () => {
  test('edit a rule: its error marked at its line, fixed, run, linked, and kumiki run agrees', async () => {
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}${linkOf('chobie-form-a')}`, { serviceWorkers: 'block' });
    const fetched = [];
    context.on('request', (r) => fetched.push(new URL(r.url()).pathname));
    const rulesModule = () => fetched.filter((p) => /kumiki_wasm_rules/.test(p));
    // A scenario without a script runs on the page's module: the rules module is never fetched.
    const paperHash = await stepTo(page, 12);
    await page.keyboard.press('r');
    await page.waitForFunction(() => document.querySelector('#step-count').textContent === '0');
    assert.deepEqual(rulesModule(), []);
    const before = new Set(fetched);

    // The Rules tab, from the keyboard: the editor and the rules module load now.
    await page.focus('#tab-run');
    while ((await page.evaluate(() => document.activeElement?.id)) !== 'tab-rules') await page.keyboard.press('ArrowRight');
    await page.keyboard.press('Enter');
    await page.waitForSelector('#rules-editor .cm-content');
    assert.equal(rulesModule().length > 0, true, 'the rules module is fetched when the Rules tab opens');
    assert.equal(fetched.filter((p) => p.endsWith('.js') && !before.has(p)).length > 0, true, "the editor's code is a chunk of its own");
    assert.equal(await page.inputValue('#rules-slot'), 'leader');
    assert.match(await page.textContent('#rules-editor .cm-content'), /fn leader\(robot\)/);

    // A syntax error, typed: marked at its line as you type.
    await replaceText(page, BROKEN);
    await page.waitForFunction(() => /^Line 3/.test(document.querySelector('#rules-problem').textContent));
    const marked = await page.$$eval('#rules-editor .cm-line', (lines) =>
      lines.map((l, i) => (l.querySelector('.cm-lintRange-error') ? i + 1 : 0)).filter((n) => n > 0),
    );
    assert.deepEqual(marked, [3]);
    assert.equal(await page.isDisabled('#rules-run'), true);
    assert.deepEqual(await audit(page, 'the Rules tab with an error marked'), []);
    // Tab indents in the editor; Escape, then Tab, leaves it for the tab's next control.
    await page.click('#rules-editor .cm-content');
    await page.keyboard.press('Escape');
    await page.keyboard.press('Tab');
    assert.equal(await page.evaluate(() => document.activeElement?.id), 'rules-reset');

    // Fixed, and run with it: the scenario carries it.
    await replaceText(page, MINE);
    await page.waitForFunction(() => document.querySelector('#rules-problem').textContent === '');
    await page.waitForSelector('#rules-run:not([disabled])');
    await page.click('#rules-run');
    await page.waitForFunction(() => /uses your leader rule/.test(document.querySelector('#rules-note').textContent));
    await page.waitForFunction(() => document.querySelector('#step-count').textContent === '0');
    const mineHash = await stepTo(page, 12);
    assert.notEqual(mineHash, paperHash, 'the rule changes the run');

    // The link carries the rule; the command line replays it to the page's hash.
    await page.click('#copy-link');
    await page.waitForFunction(() => location.hash.startsWith('#k1.'));
    const link = await page.evaluate(() => location.href);
    const row = JSON.parse(kumiki(['run', link, '--max-steps', '12']).trim().split('\n')[0]);
    assert.equal(row.steps, 12);
    assert.equal(row.hash, mineHash, 'kumiki run on the link prints the page state hash');
    // Opened in a fresh page, the link runs its rule at once: the worker switches as it opens it.
    const second = await openPage(s.browser, link, { serviceWorkers: 'block' });
    assert.equal(await stepTo(second.page, 12), mineHash);
    assert.deepEqual(second.problems, []);
    await second.context.close();

    // The paper's rule beside mine: the second run (the paper's, on the page's module) follows the first.
    await page.click('#tab-rules');
    await page.click('#rules-compare');
    await page.waitForSelector('body.comparing #compare-wrap:not([hidden])');
    assert.equal(await page.textContent('#run-label-second'), "the paper's rule");
    assert.equal(await stepTo(page, 12), mineHash);
    await page.waitForFunction(() => document.querySelector('#compare-wrap').dataset.steps === '12' && document.querySelector('#compare-wrap').dataset.hash);
    assert.equal(await page.getAttribute('#compare-wrap', 'data-hash'), paperHash);
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('an endless loop is stopped with a message naming the rule, the line and the cap; the page stays responsive', async () => {
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}${linkOf('chobie-form-a')}`, { serviceWorkers: 'block' });
    await page.click('#tab-rules');
    await page.waitForSelector('#rules-editor .cm-content');
    await replaceText(page, 'fn leader(robot) {\n  let n = 0;\n  loop {\n    n += 1;\n  }\n}');
    await page.waitForFunction(() => document.querySelector('#rules-problem').textContent === '');
    await page.waitForSelector('#rules-run:not([disabled])');
    await page.click('#rules-run');
    await page.waitForFunction(() => document.querySelector('#scenario-json').value.includes('loop'));
    const started = Date.now();
    await page.click('#play');
    await page.waitForFunction(() => /stopped/.test(document.querySelector('#banner-text').textContent), null, { timeout: 10000 });
    const message = await page.textContent('#banner-text');
    assert.match(message, /rule 'leader' stopped at line \d/);
    assert.match(message, /cap/);
    assert.ok(Date.now() - started < 10000);
    // Responsive: the page's own thread answers, and the worker takes the next scenario at once.
    assert.equal(await page.evaluate(() => 1 + 1), 2);
    await page.click('#rules-paper');
    await page.waitForFunction(() => !document.querySelector('#scenario-json').value.includes('"rules"'));
    await stepTo(page, 3);
    assert.deepEqual(
      problems.filter((p) => !/stopped/.test(p)),
      [],
    );
    await context.close();
  });
});
