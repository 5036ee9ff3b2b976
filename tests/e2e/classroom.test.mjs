// The classroom in the page: rewind (the timeline goes back to any step reached with the identical
// state, the view's Left arrow steps back), keys that leave focused controls alone, and a student
// doing an exercise: instructions, locked fields, the goal judged, a hand-in the CLI grades.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { kumiki, loadWasm, openPage, session, stepCount } from './harness.mjs';

const wasm = loadWasm();

const s = session();

const hash = (page) => page.textContent('#state-hash');
async function atStep(page, n) {
  await page.waitForFunction((k) => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) === k, n);
  await page.waitForFunction(() => document.querySelector('#state-hash').textContent.length === 16);
  return hash(page);
}
async function stepBy(page, n) {
  const from = await stepCount(page);
  await page.locator('#view').focus();
  for (let i = 0; i < n; i++) await page.keyboard.press('ArrowRight');
  return atStep(page, from + n);
}

describe('rewind', () => {
  test('the timeline and the Left arrow go back to identical states, and forward again', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    const at10 = await stepBy(page, 10);
    const at40 = await stepBy(page, 30);
    assert.equal(await page.getAttribute('#timeline', 'max'), '40');

    await page.locator('#timeline').fill('10');
    assert.equal(await atStep(page, 10), at10, 'the timeline returns the state first passed through');
    assert.equal(await page.textContent('#timeline-out'), '10 / 40');

    await page.locator('#view').focus();
    await page.keyboard.press('ArrowLeft');
    await atStep(page, 9);
    assert.equal(await stepBy(page, 31), at40, 'forward again gives the same hash');

    await page.locator('#timeline').fill('0');
    await atStep(page, 0);
    await page.click('#play');
    await page.waitForFunction(() => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) > 40);
    await page.click('#play');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('a click in the past forks the run: the timeline ends there', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    await stepBy(page, 150);
    await page.locator('#timeline').fill('120');
    await atStep(page, 120);
    const tools = await page.$$eval('#tools button', (bs) => bs.map((b) => b.dataset.tool));
    await page.click(`#tools button[data-tool="${tools[1]}"]`);
    // Click cells until one holds a module the tool applies to (the page's own picking decides).
    const box = await page.locator('#view').boundingBox();
    const clicked = () => document.querySelector('#scenario-json').value.includes('"disturbances"');
    for (let k = 0; k < 40 && !(await page.evaluate(clicked)); k++) {
      await page.mouse.click(box.x + box.width * (0.2 + (0.6 * ((k * 7) % 40)) / 40), box.y + box.height * (0.5 + (0.45 * ((k * 13) % 40)) / 40));
      // The click was refused (a cell with nothing to act on), recorded, or missed the lattice.
      await page
        .waitForFunction(() => !document.querySelector('#banner').hidden || document.querySelector('#scenario-json').value.includes('"disturbances"'), null, {
          timeout: 1000,
        })
        .catch(() => {});
      if (await page.isVisible('#banner')) await page.click('#banner-close');
    }
    await page.waitForFunction(() => document.querySelector('#timeline').max === '120');
    assert.equal(await stepCount(page), 120);
    assert.match(await page.$eval('#scenario-json', (t) => t.value), /"at": 120/);
    await page.locator('#view').focus();
    await page.keyboard.press('Control+z');
    await page.waitForFunction(() => !document.querySelector('#scenario-json').value.includes('"at": 120'));
    await context.close();
  });
});

describe('keys', () => {
  test('arrows and Space act on the focused control, not on the run', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    await page.locator('#speed').focus();
    const speed = await page.inputValue('#speed');
    await page.keyboard.press('ArrowRight');
    assert.notEqual(await page.inputValue('#speed'), speed, 'the slider moved');
    await page.locator('#timeline').focus();
    await page.keyboard.press('Space');
    assert.equal(await page.getAttribute('#play', 'aria-pressed'), 'false');
    assert.equal(await stepCount(page), 0, 'no step was taken');
    await page.locator('#view').focus();
    await page.keyboard.press('ArrowRight');
    await atStep(page, 1);
    await context.close();
  });
});

describe('an exercise', () => {
  const exerciseLink = (goal) => {
    const doc = JSON.parse(wasm.preset_json('amas-L'));
    doc.exercise = {
      title: 'Build the L',
      instructions: 'Build the L with **5 robots**.\n\n- press Play\n- then Check',
      locked: { robots: 5 },
      goal,
      hints: ['Section 5 of the paper.', 'Try the relay rule.'],
    };
    return wasm.encode_link(JSON.stringify(doc));
  };

  test('shows its instructions, locks its fields, judges the run, and hands in a link the CLI grades', async () => {
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${exerciseLink('completed and steps <= 100000')}`);
    await page.waitForSelector('#exercise:not([hidden])');
    assert.equal(await page.textContent('#exercise-title'), 'Build the L');
    assert.equal(
      await page.$eval('#exercise-instructions', (d) => d.innerHTML),
      '<p>Build the L with <strong>5 robots</strong>.</p><ul><li>press Play</li><li>then Check</li></ul>',
    );
    assert.equal(await page.textContent('#exercise-goal'), 'completed and steps <= 100000');
    await page.click('#exercise-hint');
    assert.equal(await page.locator('#exercise-hints li').count(), 1);
    assert.equal(await page.textContent('#exercise-hint'), 'Show a hint (1 left)');

    await page.click('#exercise-check');
    await page.waitForFunction(() => document.querySelector('#exercise-result').textContent.startsWith('Not met yet (step 0)'));
    assert.match(await page.textContent('#exercise-result'), /the run did not complete/);

    await page.click('#tab-scenario');
    assert.equal(await page.isDisabled('#param-robots'), true, 'a locked field is read-only');
    await page.click('#tab-run');

    await page.$eval('#speed', (el) => {
      el.value = '8';
      el.dispatchEvent(new Event('input'));
    });
    await page.click('#play');
    await page.waitForFunction(() => document.querySelector('#exercise-result').textContent.startsWith('Goal met'), null, { timeout: 60000 });

    await page.fill('#exercise-student', 'Ada');
    await page.click('#exercise-handin');
    await page.waitForFunction(() => document.querySelector('#exercise-handin-out').textContent.includes('#k1.'));
    const link = /(http\S+#k1\.\S+)/.exec(await page.textContent('#exercise-handin-out'))[1];
    const out = kumiki(['check', link]);
    const row = JSON.parse(out.trim());
    assert.equal(row.name, 'Ada');
    assert.equal(row.met, true, row.because);
    assert.equal(row.steps, await stepCount(page));
    assert.equal(row.hash, await page.textContent('#state-hash'));
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('a teacher makes one from the scenario in view, with the goal checked as it is typed', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    await page.click('#tab-scenario');
    await page.click('#make-exercise');
    await page.waitForSelector('#exercise-editor[open]');
    await page.fill('#ex-title', 'Five robots');
    await page.fill('#ex-instructions', 'Finish with **five** robots.');
    // The goal is checked as it is typed (the core reads it): its problem shows, then clears.
    const problem = (text) => page.waitForFunction((t) => document.querySelector('#ex-goal-problem').textContent === t, text);
    await page.fill('#ex-goal', 'steps = 3');
    await problem("column 7: '=' alone is not a comparison; write '=='");
    await page.click('#ex-apply');
    assert.equal(await page.isVisible('#exercise-editor'), true, 'a goal with a problem is not applied');
    await page.fill('#ex-goal', 'completed and steps < 5000');
    await problem('');
    await page.check('#ex-locked input[value="robots"]');
    await page.fill('#ex-hints', 'Read section 5.\n\nPress Play.');
    // One tool allowed twice, the others locked; points for two parts; a question.
    await page.fill('#ex-allow input[data-kind="remove"]', '2');
    await page.fill('#ex-credit', '5: completed\n3: steps < 3000');
    await page.fill('#ex-question', 'Why five?');
    await page.click('#ex-apply');
    await page.waitForSelector('#exercise:not([hidden])');
    assert.equal(await page.textContent('#exercise-title'), 'Five robots');
    const doc = JSON.parse(await page.$eval('#scenario-json', (t) => t.value));
    assert.deepEqual(doc.exercise, {
      title: 'Five robots',
      instructions: 'Finish with **five** robots.',
      // The scenario's own disturbances (none) are the teacher's, kept as the core reads an exercise.
      locked: { robots: doc.robots, disturbances: [] },
      goal: 'completed and steps < 5000',
      hints: ['Read section 5.', 'Press Play.'],
      disturbances: { remove: 2 },
      credit: [
        { goal: 'completed', points: 5 },
        { goal: 'steps < 3000', points: 3 },
      ],
      question: 'Why five?',
    });
    await page.click('#tab-run');
    await page.waitForFunction(() => document.querySelector('#tools button[data-tool="remove"]').textContent.endsWith('(2 left)'));
    assert.equal(await page.getAttribute('#tools button[data-tool="break"]', 'aria-disabled'), 'true');
    assert.equal(await page.textContent('#exercise-points-head'), 'Points: up to 8');
    assert.equal(await page.isVisible('#exercise-answer'), true);
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('a run that misses the goal is told why', async () => {
    const { page, context } = await openPage(s.browser, `${s.server.url}#${exerciseLink('completed and metrics.collisions < 0')}`);
    await page.$eval('#speed', (el) => {
      el.value = '8';
      el.dispatchEvent(new Event('input'));
    });
    await page.click('#play');
    await page.waitForFunction(() => document.querySelector('#exercise-result').textContent.startsWith('Not met yet'), null, { timeout: 60000 });
    assert.match(await page.textContent('#exercise-result'), /metrics\.collisions is \d+, but it must be < 0/);
    await context.close();
  });
});
