// Rules you can write, in the browser: a scenario without a script never fetches the rules module;
// the Rules tab loads it and the editor; in cubes3d's selection rule (the paper's script, the MRF
// on cubes-cube8-zigzag) a syntax error typed is marked at its line, fixed, run, compared with the
// paper's MRF side by side, shared by link, and `kumiki run` on that link prints the page's state
// hash; an endless loop is stopped with a message naming the rule, the line and the cap while the
// page stays responsive; and a rule exercise (lesson-cubes-rule) is graded in the Grade view with
// the verdicts `kumiki check` gives, an endless loop a failed row with its reason.
// The room's logic without a browser is tests/unit/rules.test.ts's.
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, test } from 'node:test';
import { audit, kumiki, loadWasm, openPage, session, stepCount } from './harness.mjs';

const wasm = loadWasm();
const s = session();

/** The paper's selection rule as a script: the MRF, random and steepest descent, by the scenario's `selection`. */
const PAPER = kumiki(['rules', 'cubes3d', 'select']);
/** The MRF's weight, the line the test edits: exp(-(D_i - least) / T). */
const WEIGHT = 'weights.push(exp(-(o.difference - least) / unit.temperature));';
/** The same line broken (no divisor), then fixed as a hotter MRF: T doubled. */
const BROKEN = 'weights.push(exp(-(o.difference - least) / ));';
const HOTTER = 'weights.push(exp(-(o.difference - least) / (2.0 * unit.temperature)));';
/** The edited line's number in the paper's script. */
const WEIGHT_LINE = PAPER.split('\n').findIndex((l) => l.trim() === WEIGHT) + 1;
/** Steps the page and the command line run: the hotter MRF has left the paper's run by then. */
const STEPS = 20;
const PRESET = 'cubes-cube8-zigzag';

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

/**
 * Replaces `old`, the text of an editor's line after its indentation, with `text`, as a person
 * does: a click at the line's end, `old` selected with Shift+Left (the editor wraps long lines, so
 * Home and End would stop where a line wraps), then `text` typed.
 */
async function retypeLine(page, old, text) {
  const line = page.locator('#rules-editor .cm-line', { hasText: old });
  await line.scrollIntoViewIfNeeded();
  const end = await line.evaluate((l) => {
    const texts = document.createTreeWalker(l, NodeFilter.SHOW_TEXT);
    let last = null;
    while (texts.nextNode()) if (texts.currentNode.length > 0) last = texts.currentNode;
    const range = document.createRange();
    range.setStart(last, last.length - 1);
    range.setEnd(last, last.length);
    const box = range.getBoundingClientRect();
    return { x: box.right - 1, y: box.top + box.height / 2 };
  });
  await page.mouse.click(end.x, end.y);
  await page.keyboard.press('End');
  for (let i = 0; i < old.length; i++) await page.keyboard.press('Shift+ArrowLeft');
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
  test("edit cubes3d's selection rule: its error marked at its line, fixed, run, compared with the MRF, linked, and kumiki run agrees", async () => {
    assert.ok(WEIGHT_LINE > 0, "the paper's script has the MRF's weight line");
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}${linkOf(PRESET)}`, { serviceWorkers: 'block' });
    const fetched = [];
    context.on('request', (r) => fetched.push(new URL(r.url()).pathname));
    const rulesModule = () => fetched.filter((p) => /kumiki_wasm_rules/.test(p));
    // A scenario without a script runs on the page's module: the rules module is never fetched.
    const paperHash = await stepTo(page, STEPS);
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
    assert.equal(await page.inputValue('#rules-slot'), 'select');
    assert.match(await page.textContent('#rules-editor .cm-content'), /fn select\(unit\)/);
    assert.match(await page.textContent('#rules-slot-input'), /temperature/);

    // A syntax error, typed into the paper's MRF: marked at its line as you type.
    await retypeLine(page, WEIGHT, BROKEN);
    await page.waitForFunction((n) => new RegExp(`^Line ${n}\\b`).test(document.querySelector('#rules-problem').textContent), WEIGHT_LINE);
    const marked = await page.$$eval('#rules-editor .cm-line', (lines) =>
      lines.filter((l) => l.querySelector('.cm-lintRange-error')).map((l) => l.textContent.trim()),
    );
    assert.deepEqual(marked, [BROKEN]);
    assert.equal(await page.isDisabled('#rules-run'), true);
    assert.equal(await page.isDisabled('#rules-compare'), true);
    assert.deepEqual(await audit(page, 'the Rules tab with an error marked'), []);
    // Tab indents in the editor; Escape, then Tab, leaves it for the tab's next control.
    await page.locator('#rules-editor .cm-line', { hasText: BROKEN }).click();
    await page.keyboard.press('Escape');
    await page.keyboard.press('Tab');
    assert.equal(await page.evaluate(() => document.activeElement?.id), 'rules-reset');

    // Fixed, as a hotter MRF, and run with it: the scenario carries it.
    await retypeLine(page, BROKEN, HOTTER);
    await page.waitForFunction(() => document.querySelector('#rules-problem').textContent === '');
    await page.waitForSelector('#rules-run:not([disabled])');
    await page.click('#rules-run');
    await page.waitForFunction(() => /uses your select rule/.test(document.querySelector('#rules-note').textContent));
    await page.waitForFunction(() => document.querySelector('#step-count').textContent === '0');
    const scenario = JSON.parse(await page.inputValue('#scenario-json'));
    assert.equal(scenario.rules.select, PAPER.replace(WEIGHT, HOTTER), "the scenario carries the paper's script with the one line changed");
    const mineHash = await stepTo(page, STEPS);
    assert.notEqual(mineHash, paperHash, 'the rule changes the run');

    // The paper's MRF beside mine: the second run (the paper's, on the page's module) follows the first.
    await page.click('#tab-rules');
    await page.click('#rules-compare');
    await page.waitForSelector('body.comparing #compare-wrap:not([hidden])');
    assert.equal(await page.textContent('#run-label-second'), "the paper's rule");
    assert.equal(await stepTo(page, STEPS), mineHash);
    await page.waitForFunction(
      (n) => document.querySelector('#compare-wrap').dataset.steps === String(n) && document.querySelector('#compare-wrap').dataset.hash,
      STEPS,
    );
    assert.equal(await page.getAttribute('#compare-wrap', 'data-hash'), paperHash, "the second run is the paper's MRF");

    // The link carries the rule; the command line replays it to the page's hash.
    await page.click('#copy-link');
    await page.waitForFunction(() => location.hash.startsWith('#k1.'));
    const link = await page.evaluate(() => location.href);
    // The link carries the comparison too: the command line prints both runs, as the page shows them.
    const [row, paperRow] = kumiki(['run', link, '--max-steps', String(STEPS)])
      .trim()
      .split('\n')
      .map((l) => JSON.parse(l));
    assert.equal(row.steps, STEPS);
    assert.equal(row.hash, mineHash, 'kumiki run on the link prints the page state hash');
    assert.equal(paperRow.scenario, `${PRESET} (the paper's rule)`);
    assert.equal(paperRow.hash, paperHash, "and the paper's MRF's, as the page's second run");
    // Opened in a fresh page, the link runs its rule at once: the worker switches as it opens it.
    const second = await openPage(s.browser, link, { serviceWorkers: 'block' });
    assert.equal(await stepTo(second.page, STEPS), mineHash);
    assert.deepEqual(second.problems, []);
    await second.context.close();
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

  test('a rule exercise is graded in the page as kumiki check grades it; an endless loop is a failed row with its reason', async () => {
    const LESSON = 'lesson-cubes-rule';
    // The lesson's solution (kept from the page's copy, which leaves it out) and the paper's own
    // script, which under the lesson's locked `selection` is the steepest descent that gets stuck.
    const solution = JSON.parse(readFileSync(new URL(`../../crate/models/cubes3d/lessons/${LESSON}.json`, import.meta.url), 'utf8')).solution.rules.select;
    const lesson = JSON.parse(wasm.lesson_json(LESSON));
    const handIn = (select) => {
      const doc = structuredClone(lesson);
      doc.rules = { select };
      return `${s.server.url}#${wasm.encode_link(JSON.stringify(doc))}`;
    };
    const links = [handIn(solution), handIn(PAPER), handIn('fn select(unit) {\n  let n = 0;\n  loop {\n    n += 1;\n  }\n}')];

    const list = join(tmpdir(), `kumiki-rules-class-${process.pid}.txt`);
    writeFileSync(list, `${links.join('\n')}\n`);
    const cli = kumiki(['check', '--file', list, '--exercise', LESSON])
      .trim()
      .split('\n')
      .map((l) => JSON.parse(l));
    const verdict = (r) => (r.error !== undefined ? 'could not be graded' : r.met ? 'met' : 'not met');
    assert.deepEqual(cli.map(verdict), ['met', 'not met', 'not met'], 'the solution meets the goal; steepest descent and the endless loop do not');
    assert.match(cli[2].because, /rule 'select' stopped at line 4.*cap/);

    const { page, context, problems } = await openPage(s.browser, s.server.url);
    await page.click('#open-gallery');
    await page.click('#open-grade');
    await page.waitForSelector('#grade[open]');
    await page.fill('#grade-input', links.join('\n'));
    await page.fill('#grade-exercise', LESSON);
    await page.click('#grade-start');
    await page.waitForFunction(() => /^3 hand-ins:/.test(document.querySelector('#grade-status').textContent), null, { timeout: 60000 });
    assert.equal(await page.textContent('#grade-status'), '3 hand-ins: 1 met, 2 not met, 0 could not be graded.');
    const shown = await page.$$eval('#grade-rows tr[aria-rowindex]', (trs) => trs.map((tr) => [...tr.cells].map((c) => c.textContent)));
    assert.equal(shown.length, 3);
    for (const [i, row] of cli.entries()) {
      const [, , goal, , steps, , why, , hash] = shown[i];
      assert.equal(goal, verdict(row), `hand-in ${i + 1}: the verdict`);
      assert.equal(steps, row.steps.toLocaleString('en-US'), `hand-in ${i + 1}: steps`);
      assert.equal(hash, row.hash, `hand-in ${i + 1}: the replayed hash`);
      assert.ok(why.startsWith(row.because), `hand-in ${i + 1}: ${why} / ${row.because}`);
    }
    assert.match(shown[2][6], /^a rule's script stopped the run: rule 'select' stopped at line 4.*cap/, 'the endless loop: a failed row with its reason');
    // The page went on: its own thread answers, and the Grade view takes the next class.
    assert.equal(await page.evaluate(() => 1 + 1), 2);
    assert.equal(await page.isDisabled('#grade-start'), false);
    assert.deepEqual(problems, []);
    await context.close();
  });
});
