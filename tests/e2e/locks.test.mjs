// An exercise's locks hold everywhere in the page: a student tries every way to change a locked
// field (the form, the shape editor, the seed box and New seed, the keyboard, the JSON editor, a
// file, undo, a link whose values differ from the teacher's) and none of them shows "Goal met".
// The one change the exercise leaves open does meet the goal, so the test could tell.
import assert from 'node:assert/strict';
import { writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, test } from 'node:test';
import { loadWasm, openPage, session } from './harness.mjs';

const wasm = loadWasm();
const s = session();

/** amas-L with its robots, shape and seed locked; the goal is only to complete. */
function exercise() {
  const doc = JSON.parse(wasm.preset_json('amas-L'));
  doc.exercise = {
    title: 'Build the L, your way',
    instructions: 'Choose any **collision rule**.',
    locked: { robots: doc.robots, target: doc.target, seed: doc.seed },
    goal: 'completed and metrics.collisions >= 0',
    hints: [],
  };
  return doc;
}
const link = (doc) => wasm.encode_link(JSON.stringify(doc));

const result = (page) => page.textContent('#exercise-result');

/** The scenario in force, as the student's Hand in gives it to the teacher. */
async function handedIn(page) {
  await page.click('#tab-run');
  await page.evaluate(() => document.querySelector('#exercise-handin-out').replaceChildren());
  await page.click('#exercise-handin');
  await page.waitForFunction(() => document.querySelector('#exercise-handin-out').textContent.includes('#k1.'));
  const url = /(http\S+#k1\.\S+)/.exec(await page.textContent('#exercise-handin-out'))[1];
  return JSON.parse(wasm.decode_link(url.slice(url.indexOf('#') + 1)));
}

/** Plays the run to its end at full speed and returns the verdict shown. */
async function playToEnd(page) {
  await page.click('#tab-run');
  await page.$eval('#speed', (el) => {
    el.value = '8';
    el.dispatchEvent(new Event('input'));
  });
  await page.click('#play');
  await page.waitForFunction(() => /^(Goal met|Not met)/.test(document.querySelector('#exercise-result').textContent), null, { timeout: 60000 });
  return result(page);
}

/** The locked fields are the teacher's, and the run is the one the link gave. */
async function stillLocked(page, teacher, what) {
  const doc = await handedIn(page);
  for (const key of ['robots', 'target', 'seed']) assert.deepEqual(doc[key], teacher[key], `${what}: ${key} stays the teacher's`);
  assert.deepEqual(doc.exercise, teacher.exercise, `${what}: the exercise stays the teacher's`);
  assert.doesNotMatch(await result(page), /^Goal met/, `${what}: no "Goal met"`);
}

describe('locks', () => {
  test('no way of changing a locked field shows "Goal met"', async () => {
    const teacher = JSON.parse(new wasm.Draft(2 ** 18).open(JSON.stringify(exercise()), false).text);
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${link(teacher)}`);
    await page.waitForSelector('#exercise:not([hidden])');

    // Run: the seed box is read-only, New seed cannot be pressed, typing changes nothing.
    assert.equal(await page.$eval('#seed', (i) => i.readOnly), true);
    assert.equal(await page.isDisabled('#new-seed'), true);
    await page.click('#new-seed', { force: true });
    await page.locator('#seed').focus();
    await page.keyboard.type('7');
    await page.keyboard.press('Enter');
    await page.keyboard.press('Tab');
    await stillLocked(page, teacher, 'the seed box and New seed');

    // Scenario tab: the form's locked field is disabled; the shape editor is read-only.
    await page.click('#tab-scenario');
    assert.equal(await page.isDisabled('#param-robots'), true);
    assert.equal(await page.$eval('#model-editor > div', (d) => d.inert), true, 'the shape editor is inert');
    assert.match(await page.textContent('#model-editor .locked-note'), /Locked by the exercise: target/);
    const grid = page.locator('#model-editor canvas').first();
    const box = await grid.boundingBox();
    await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
    await page.keyboard.press('Delete');
    await stillLocked(page, teacher, 'the shape editor');

    // The JSON editor: a changed seed, an erased cell, then the lock changed to match.
    await page.click('#tab-scenario');
    await page.click('.json-editor summary');
    const tries = [
      [
        'seed',
        (d) => {
          d.seed = 7;
        },
      ],
      [
        'target',
        (d) => {
          d.target = d.target.replace('#', '.');
        },
      ],
      [
        'seed and its lock',
        (d) => {
          d.seed = 7;
          d.exercise.locked.seed = 7;
        },
      ],
      [
        'the exercise removed',
        (d) => {
          delete d.exercise;
        },
      ],
    ];
    for (const [what, edit] of tries) {
      const doc = structuredClone(teacher);
      edit(doc);
      await page.fill('#scenario-json', JSON.stringify(doc, null, 1));
      await page.click('#apply-json');
      await page.waitForFunction(() => document.querySelector('#json-error').textContent !== '');
      assert.match(await page.textContent('#json-error'), /locked by the exercise|the exercise itself cannot be changed/, what);
    }
    await stillLocked(page, teacher, 'the JSON editor');
    // A file with a changed seed.
    await page.click('#tab-scenario');
    const changed = structuredClone(teacher);
    changed.seed = 9;
    const file = join(tmpdir(), `kumiki-locks-${process.pid}.json`);
    writeFileSync(file, JSON.stringify(changed));
    await page.setInputFiles('#open-json', file);
    await page.waitForFunction(() => document.querySelector('#json-error').textContent.includes('locked by the exercise'));
    assert.match(await page.textContent('#json-error'), /seed: 1 → 9/);
    // Undo, from the keyboard, has nothing of the exercise's to bring back.
    await page.locator('#view').focus();
    await page.keyboard.press('Control+z');
    await stillLocked(page, teacher, 'a file and undo');

    // The run of the teacher's values, with the one open field changed, meets the goal.
    await page.click('#tab-scenario');
    await page.selectOption('#param-collision', 'relay');
    await page.waitForFunction(() => document.querySelector('#scenario-json').value.includes('"relay"'));
    const doc = await handedIn(page);
    assert.equal(doc.collision, 'relay');
    for (const key of ['robots', 'target', 'seed']) assert.deepEqual(doc[key], teacher[key]);
    assert.match(await playToEnd(page), /^Goal met/, 'the open field meets the goal: the test can see "Goal met"');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test("a link whose locked values differ from its exercise is not met, and says which field and the teacher's value", async () => {
    const tampered = exercise();
    tampered.seed = 7;
    const { page, context } = await openPage(s.browser, `${s.server.url}#${link(tampered)}`);
    await page.waitForSelector('#exercise:not([hidden])');
    const verdict = await playToEnd(page);
    assert.match(verdict, /^Not met/);
    assert.match(verdict, /the exercise does not allow what this scenario changed \(seed: 1 → 7\)/);
    // The completion badge carries no colour of its own beside a goal not met.
    assert.equal(await page.$eval('#run-status', (e) => e.classList.contains('plain')), true);
    await context.close();
  });

  test('an exercise link opens as the exercise: its title, its instructions, its goal in words', async () => {
    const doc = exercise();
    const { page, context } = await openPage(s.browser, `${s.server.url}#${link(doc)}`, { keepIntro: true });
    await page.waitForSelector('#intro[open]');
    assert.equal(await page.textContent('#intro-title'), 'Build the L, your way');
    const intro = await page.textContent('#intro-description');
    assert.match(intro, /Choose any collision rule\./);
    assert.match(intro, /Goal: Completed, and collisions at least 0\./);
    assert.doesNotMatch(intro, new RegExp(doc.description.slice(0, 30).replace(/[.*+?^${}()|[\]\\]/g, '\\$&')), "never the preset's description");
    await page.click('#intro button.primary');
    assert.equal(await page.textContent('#scenario-name'), 'Build the L, your way');
    assert.equal(await page.title(), 'Build the L, your way · Kumiki');
    assert.equal(await page.textContent('#exercise-goal-words'), 'Completed, and collisions at least 0.');
    assert.equal(await page.isVisible('#exercise-goal'), false, 'the code is shown on request');
    await page.click('#exercise .goal-code summary');
    assert.equal(await page.textContent('#exercise-goal'), 'completed and metrics.collisions >= 0');
    await context.close();
  });
});
