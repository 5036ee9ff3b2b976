// The Grade view: a class of 30 hand-ins (fair ones, ones that miss the goal, ones that changed a
// locked field, ones that edited the exercise, broken links and a row with no link) pasted as a
// form's CSV export, graded against a lesson in wasm workers, the same as `kumiki check` grades
// them, and exported as CSV; a form's export with answers over several lines and the same class
// as an .xlsx workbook, graded by the exercise the links carry, with points per part, the answers
// and an over-budget row, the same verdicts and points as `kumiki check` on the same files; a file
// that is neither refused with one message, the previous table gone.
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, test } from 'node:test';
import { audit, kumiki, loadWasm, openPage, session } from './harness.mjs';
import { xlsx } from './xlsx.mjs';

const wasm = loadWasm();
const s = session();
const LESSON = 'lesson-amas-robots';

/** The class: 30 rows of a form's export, with what each hand-in did. */
function classExport(base) {
  const lesson = JSON.parse(wasm.lesson_json(LESSON));
  const variant = (i) => {
    const doc = structuredClone(lesson);
    doc.name = `Student ${i + 1}`;
    switch (i % 6) {
      case 0: // fair: few robots, quickly
        doc.robots = 5;
        break;
      case 1: // misses the goal: too few robots to be quick
        doc.robots = 2;
        break;
      case 2: // more robots than the goal allows
        doc.robots = 8;
        break;
      case 3: // changed a locked field
        doc.robots = 5;
        doc.seed = 2;
        break;
      case 4: // tampered: changed a locked field and its lock to match
        doc.robots = 5;
        doc.collision = 'relay';
        doc.exercise.locked.collision = 'relay';
        break;
      default: // broken: a link cut short
        return `${base}#${wasm.encode_link(JSON.stringify(doc)).slice(0, 20)}`;
    }
    return `${base}#${wasm.encode_link(JSON.stringify(doc))}`;
  };
  const rows = ['Timestamp,Full name,Kumiki link'];
  const links = [];
  for (let i = 0; i < 30; i++) {
    const link = i === 29 ? 'I could not copy it' : variant(i);
    links.push(link);
    rows.push(`2026-11-25 10:${String(i).padStart(2, '0')}:00,"Pupil ${i + 1}",${link}`);
  }
  return { csv: `${rows.join('\n')}\n`, links };
}

/** The lesson with points for each part, a question, and a budget of 500 steps. */
function creditExercise() {
  const doc = JSON.parse(wasm.lesson_json(LESSON));
  doc.exercise.credit = [
    { goal: 'completed', points: 5 },
    { goal: 'steps <= 300', points: 3 },
    { goal: 'scenario.robots <= 6', points: 2 },
  ];
  doc.exercise.question = 'Why do more robots not always help?';
  doc.exercise.budget = { steps: 500 };
  return doc;
}

/** A student's hand-in of the exercise with `robots`, their name and answer, made by the page's Draft. */
function handIn(base, teacher, robots, name, answer) {
  const doc = structuredClone(teacher);
  doc.robots = robots;
  const draft = new wasm.Draft(2 ** 18);
  assert.equal(draft.open(JSON.stringify(doc), false).problem ?? null, null);
  return `${base}#${draft.handin(name, JSON.stringify({ made: '2026-11-28T10:15:00Z', checks: 2, hints: 1, answer }))}`;
}

/** A form's class: five rows, their answers over several lines, one row without a link. */
function formClass(base) {
  const teacher = creditExercise();
  const students = [
    [5, 'Ada', 'They collide at the corner.\nSix was best, "really".'],
    [3, 'Grace', 'Three is slow.\n\nFour is enough.'],
    [2, 'Linus', 'Two robots, so\nmany steps.'],
    [8, 'Alan', "More is faster,\nisn't it?"],
  ];
  const rows = [['Timestamp', 'Full name', 'Kumiki link', teacher.exercise.question]];
  for (const [i, [robots, name, answer]] of students.entries())
    rows.push([`2026-11-28 10:1${i}:00`, name, handIn(base, teacher, robots, name, answer), answer]);
  rows.push(['2026-11-28 10:19:00', 'Bob', 'I lost it', 'No idea,\nsorry.']);
  const cell = (c) => (/[",\n]/.test(c) ? `"${c.replace(/"/g, '""')}"` : c);
  return { rows, csv: `${rows.map((r) => r.map(cell).join(',')).join('\r\n')}\r\n` };
}

/**
 * Every row of the (virtualised) grade table, scrolled through from the top: its cells' text, and
 * whether it is marked over budget.
 */
async function tableRows(page) {
  const found = new Map();
  await page.$eval('#grade-scroller', (s) => (s.scrollTop = 0));
  for (;;) {
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const seen = await page.$$eval('#grade-rows tr[aria-rowindex]', (trs) =>
      trs.map((tr) => [Number(tr.getAttribute('aria-rowindex')), { cells: [...tr.cells].map((c) => c.textContent), over: tr.classList.contains('over') }]),
    );
    for (const [i, v] of seen) found.set(i, v);
    const more = await page.$eval('#grade-scroller', (s) => {
      const before = s.scrollTop;
      s.scrollTop += s.clientHeight;
      return s.scrollTop > before;
    });
    if (!more) break;
  }
  return [...found.keys()].sort((a, b) => a - b).map((i) => found.get(i));
}

/** Opens `file` in the Grade view, grades it by the exercise the links carry, and returns the table's cells. */
async function gradeFile(page, file, rows) {
  await page.setInputFiles('#grade-file', file);
  if (file.endsWith('.xlsx')) await page.waitForFunction(() => /hand-ins?, read as it is/.test(document.querySelector('#grade-file-note').textContent));
  else await page.waitForFunction(() => document.querySelector('#grade-input').value.includes('Full name'));
  await page.fill('#grade-exercise', '');
  await page.click('#grade-start');
  await page.waitForFunction((n) => new RegExp(`^${n} hand-ins:`).test(document.querySelector('#grade-status').textContent), rows, { timeout: 120000 });
  return tableRows(page);
}

/** kumiki check on the same file, by the exercise the links carry: one record a row. */
function checked(file) {
  return kumiki(['check', '--file', file])
    .trim()
    .split('\n')
    .map((l) => JSON.parse(l));
}

const verdictOf = (r) => (r.error !== undefined ? 'could not be graded' : r.over_budget ? 'over budget' : r.met ? 'met' : 'not met');

describe('the Grade view', () => {
  test('grades a class of 30 in one go, the same as kumiki check, and exports CSV', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    const { csv, links } = classExport(s.server.url);
    await page.click('#open-gallery');
    await page.click('#open-grade');
    await page.waitForSelector('#grade[open]');
    const file = join(tmpdir(), `kumiki-class-${process.pid}.csv`);
    writeFileSync(file, csv);
    await page.setInputFiles('#grade-file', file);
    await page.waitForFunction(() => document.querySelector('#grade-input').value.includes('Pupil 30'));
    await page.fill('#grade-exercise', LESSON);
    await page.click('#grade-start');
    await page.waitForFunction(() => /^30 hand-ins:/.test(document.querySelector('#grade-status').textContent), null, { timeout: 120000 });
    const status = await page.textContent('#grade-status');
    assert.equal(await page.getAttribute('#grade-progress', 'aria-valuenow'), '100');

    const shown = (await tableRows(page)).map((r) => r.cells);
    assert.equal(shown.length, 30);
    assert.equal(await page.getAttribute('#grade-table', 'aria-rowcount'), '31');
    assert.deepEqual(
      shown.map((r) => r[1]),
      links.map((_, i) => `Pupil ${i + 1}`),
      "the export's names, in order",
    );

    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#grade-export')]);
    const exported = readFileSync(await download.path(), 'utf8')
      .trim()
      .split('\n');
    assert.equal(exported.length, 31);
    assert.match(exported[0], /^handin,student,name,met,points,max_points,because,completed,steps,over_budget,hash,/);

    // kumiki check on the same links, graded against the same lesson.
    const list = join(tmpdir(), `kumiki-class-${process.pid}.txt`);
    writeFileSync(list, `${links.join('\n')}\n`);
    const out = kumiki(['check', '--file', list, '--exercise', LESSON]);
    const cli = out
      .trim()
      .split('\n')
      .map((l) => JSON.parse(l));
    assert.equal(cli.length, 30);
    const verdict = (r) => (r.error !== undefined ? 'could not be graded' : r.met ? 'met' : 'not met');
    for (const [i, row] of cli.entries()) {
      const [, , goal, , steps, , why, , hash] = shown[i];
      assert.equal(goal, verdict(row), `hand-in ${i + 1}: the verdict`);
      if (row.error !== undefined) continue;
      assert.equal(steps, row.steps.toLocaleString('en-US'), `hand-in ${i + 1}: steps`);
      assert.equal(hash, row.hash, `hand-in ${i + 1}: the replayed hash`);
      assert.ok(why.startsWith(row.because), `hand-in ${i + 1}: ${why} / ${row.because}`);
    }
    const counts = { met: 0, 'not met': 0, 'could not be graded': 0 };
    for (const r of cli) counts[verdict(r)]++;
    assert.equal(status, `30 hand-ins: ${counts.met} met, ${counts['not met']} not met, ${counts['could not be graded']} could not be graded.`);
    // Every kind of hand-in is in the class: the fair ones meet the goal, and only they.
    assert.equal(counts.met, 5);
    assert.equal(counts['could not be graded'], 5);
    assert.ok(shown[4][6].startsWith("not replayed: its exercise is not the class's (locked.collision differs)"), shown[4][6]);
    assert.match(shown[3][6], /seed: 1 → 2/);
    assert.deepEqual(problems, []);
    await context.close();
  });

  test("a form's export with answers over several lines, and the same class as .xlsx, grade as kumiki check grades them", async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    const { rows, csv } = formClass(s.server.url);
    const csvFile = join(tmpdir(), `kumiki-form-${process.pid}.csv`);
    const xlsxFile = join(tmpdir(), `kumiki-form-${process.pid}.xlsx`);
    writeFileSync(csvFile, csv);
    writeFileSync(xlsxFile, xlsx(rows));
    await page.click('#open-gallery');
    await page.click('#open-grade');
    await page.waitForSelector('#grade[open]');

    for (const file of [csvFile, xlsxFile]) {
      const shown = await gradeFile(page, file, 5);
      const cli = checked(file);
      assert.equal(shown.length, 5, `${file}: one row a hand-in, however many lines its answer takes`);
      assert.equal(cli.length, 5);
      assert.deepEqual(
        shown.map((r) => r.cells[1]),
        ['Ada', 'Grace', 'Linus', 'Alan', 'Bob'],
      );
      for (const [i, row] of cli.entries()) {
        const [number, , goal, points] = shown[i].cells;
        assert.equal(number, String(i + 1));
        assert.equal(goal, verdictOf(row), `${file}, row ${i + 1}: the verdict`);
        assert.equal(shown[i].over, row.over_budget === true, `${file}, row ${i + 1}: marked over budget`);
        if (row.error !== undefined) continue;
        assert.ok(points.startsWith(`${row.points} of ${row.max_points}`), `${file}, row ${i + 1}: ${points} / ${row.points} of ${row.max_points}`);
      }
      // Every kind of row is there: met with every point, parts earned, over budget, no link.
      assert.deepEqual(
        shown.map((r) => r.cells[2]),
        ['met', 'not met', 'over budget', 'not met', 'could not be graded'],
      );
      assert.ok(shown[0].cells[3].startsWith('10 of 10'));
      assert.match(shown[1].cells[3], /^7 of 10.*0 of 3: steps <= 300/);
      // Named by the line it starts on: after answers over several lines in the CSV, a workbook's row.
      assert.ok(shown[4].cells[6].startsWith(`holds no Kumiki link (line ${file.endsWith('.xlsx') ? 6 : 11} of the file)`), shown[4].cells[6]);
      // The answer, as the hand-in carries it, and its record.
      assert.equal(
        await page.$eval('#grade-rows tr[aria-rowindex="2"] .grade-answer bdi', (b) => b.textContent),
        'They collide at the corner.\nSix was best, "really".',
      );
      assert.match(shown[0].cells[7], /handed in 2026-11-28T10:15:00Z, 2 checks, 1 hint$/);
      // No exercise was given: the one the links carry, named, with its question.
      assert.match(
        await page.textContent('#grade-exercise-note'),
        /^Graded by “How many robots build the L quickly\?”, which 4 of the 4 hand-ins with an exercise carry \(none was given\)\. It asks: Why do more robots not always help\?/,
      );
      assert.equal(await page.textContent('#grade-status'), '5 hand-ins: 1 met, 3 not met (1 over budget), 1 could not be graded.');
      // The export is the CSV kumiki check writes for the same file, byte for byte.
      const [download] = await Promise.all([page.waitForEvent('download'), page.click('#grade-export')]);
      assert.equal(readFileSync(await download.path(), 'utf8'), kumiki(['check', '--file', file, '--format', 'csv']), `${file}: the export`);
    }
    assert.deepEqual(await audit(page, 'the graded table'), [], 'axe, with the graded table');

    // A file that is neither text nor a workbook: one message, and the previous table and tally go.
    const junk = join(tmpdir(), `kumiki-junk-${process.pid}.png`);
    writeFileSync(junk, Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0, 0, 0, 13, 0xff, 0xfe, 0]));
    await page.setInputFiles('#grade-file', junk);
    await page.waitForFunction(() => /neither text/.test(document.querySelector('#grade-status').textContent));
    assert.match(await page.textContent('#grade-status'), /^kumiki-junk-\d+\.png: this file is neither text .* nor a workbook/);
    assert.equal(await page.locator('#grade-rows tr[aria-rowindex]').count(), 0);
    assert.equal(await page.isDisabled('#grade-export'), true);
    assert.equal(await page.getAttribute('#grade-progress', 'aria-valuenow'), '0');
    // A mistyped exercise: refused by its name, the table empty again.
    await page.fill('#grade-input', csv);
    await page.fill('#grade-exercise', 'lesson-amas-robotz');
    await page.click('#grade-start');
    await page.waitForFunction(() => /^Not graded: /.test(document.querySelector('#grade-status').textContent));
    assert.equal(await page.locator('#grade-rows tr[aria-rowindex]').count(), 0);
    assert.equal(await page.getAttribute('#grade-exercise', 'aria-invalid'), 'true');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('cancel stops the workers and keeps what was graded, in order', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    const lesson = JSON.parse(wasm.lesson_json(LESSON));
    lesson.robots = 2;
    const link = `${s.server.url}#${wasm.encode_link(JSON.stringify(lesson))}`;
    await page.click('#open-gallery');
    await page.click('#open-grade');
    // Pasted at once (typing 2.5 MB of links into the box would be the test's own slowness).
    await page.$eval('#grade-input', (t, text) => (t.value = text), Array.from({ length: 2000 }, () => link).join('\n'));
    await page.click('#grade-start');
    await page.waitForFunction(() => document.querySelectorAll('#grade-rows tr[aria-rowindex]:not(.pending)').length > 0, null, { timeout: 60000 });
    await page.click('#grade-cancel');
    const status = await page.textContent('#grade-status');
    assert.match(status, /^Cancelled after [\d,]+ of 2,000 hand-ins/);
    const graded = Number(/after ([\d,]+)/.exec(status)[1].replace(/,/g, ''));
    assert.ok(graded > 0 && graded < 2000, `${graded} graded`);
    // The table is virtualised: only the rows in view (and a few either side) are in the page,
    // numbered for screen readers among all 2,000; scrolling to the end draws the last.
    assert.equal(await page.getAttribute('#grade-table', 'aria-rowcount'), '2001');
    const drawn = await page.locator('#grade-rows tr[aria-rowindex]').count();
    assert.ok(drawn > 0 && drawn < 60, `${drawn} rows drawn`);
    await page.focus('#grade-scroller');
    await page.keyboard.press('End');
    await page.waitForSelector('#grade-rows tr[aria-rowindex="2001"]');
    assert.match(await page.textContent('#grade-rows tr[aria-rowindex="2001"]'), /^2000(not graded|met|not met)/);
    assert.ok((await page.locator('#grade-rows tr[aria-rowindex]').count()) < 60);
    assert.equal(await page.locator('#grade-rows tr[aria-rowindex="2"]').count(), 0);
    assert.equal(await page.isDisabled('#grade-start'), false);
    await context.close();
  });

  test('a stuck row is shown by its number and name, and skipped: its worker replaced, the rest graded', async () => {
    const { page, context, problems } = await openPage(s.browser, s.server.url);
    // The class's exercise leaves the target open; one student hands in a 200x200 one, which
    // takes seconds to replay, among 39 fair hand-ins.
    const teacher = JSON.parse(wasm.lesson_json(LESSON));
    delete teacher.exercise.locked.target;
    teacher.max_steps = 100000;
    teacher.robots = 5;
    const huge = structuredClone(teacher);
    huge.target = `${Array.from({ length: 200 }, () => '#'.repeat(200)).join('\n')}\n`;
    const link = (doc) => `${s.server.url}#${wasm.encode_link(JSON.stringify(doc))}`;
    const lines = ['Full name,Kumiki link', ...Array.from({ length: 40 }, (_, i) => `Pupil ${i + 1},${link(i === 1 ? huge : teacher)}`)];
    await page.click('#open-gallery');
    await page.click('#open-grade');
    await page.$eval('#grade-input', (t, text) => (t.value = text), lines.join('\n'));
    await page.click('#grade-start');
    await page.waitForFunction(() => /^Grading row 2: Pupil 2\b/.test(document.querySelector('#grade-running').textContent), null, { timeout: 60000 });
    assert.equal(await page.isDisabled('#grade-skip'), false);
    await page.click('#grade-skip');
    await page.waitForFunction(() => /^40 hand-ins:/.test(document.querySelector('#grade-status').textContent), null, { timeout: 120000 });
    assert.equal(await page.textContent('#grade-status'), '40 hand-ins: 39 met, 0 not met, 0 could not be graded, 1 skipped.');
    assert.equal(await page.textContent('#grade-running'), '');
    assert.equal(await page.isDisabled('#grade-skip'), true);
    const shown = (await tableRows(page)).map((r) => r.cells);
    assert.equal(shown.length, 40);
    assert.equal(shown[1][2], 'skipped');
    assert.match(shown[1][6], /^skipped: the teacher skipped it after [\d.]+ s/);
    assert.deepEqual(new Set(shown.filter((_, i) => i !== 1).map((r) => r[2])), new Set(['met']));
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#grade-export')]);
    const exported = readFileSync(await download.path(), 'utf8')
      .trim()
      .split('\n');
    assert.equal(exported.length, 41);
    assert.match(exported[2], /^2,Pupil 2,.*skipped: the teacher skipped it after/);
    assert.deepEqual(await audit(page, 'the table with a skipped row'), [], 'axe, with a skipped row');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test("a student's own exercise: the editor says so first, and its hand-in fails in the page and with kumiki check", async () => {
    const lesson = JSON.parse(wasm.lesson_json(LESSON));
    const link = (doc) => `${s.server.url}#${wasm.encode_link(JSON.stringify(doc))}`;
    const { page, context, problems } = await openPage(s.browser, link(lesson));
    await page.waitForSelector('#exercise:not([hidden])');
    await page.click('#tab-scenario');
    await page.click('#make-exercise');
    await page.waitForSelector('#exercise-editor[open]');
    // With an exercise open, the editor first says what it will do.
    assert.equal(await page.isVisible('#ex-fields'), false);
    assert.match(
      await page.textContent('#ex-confirm-text'),
      /^This starts a new exercise from your scenario; it will not be graded as the teacher's exercise\./,
    );
    assert.deepEqual(await audit(page, 'the editor, saying what it will do'), []);
    await page.click('#ex-confirm-go');
    // The student unlocks the seed, and changes it.
    await page.uncheck('#ex-locked input[value="seed"]');
    await page.click('#ex-apply');
    await page.waitForSelector('#exercise-editor', { state: 'hidden' });
    await page.waitForFunction(() => !document.querySelector('#seed').readOnly);
    await page.fill('#seed', '2');
    await page.$eval('#seed', (i) => i.dispatchEvent(new Event('change')));
    await page.waitForFunction(() => JSON.parse(document.querySelector('#scenario-json').value).seed === 2);
    await page.fill('#exercise-student', 'Mallory');
    await page.click('#exercise-handin');
    await page.waitForFunction(() => document.querySelector('#exercise-handin-out').textContent.includes('#k1.'));
    const own = /(http\S+#k1\.\S+)/.exec(await page.textContent('#exercise-handin-out'))[1];
    const fair = structuredClone(lesson);
    fair.robots = 5;
    const links = [link(fair), own, link(fair)];

    // Graded with no exercise given: the class's is the one most links carry, and Mallory's fails.
    await page.click('#open-gallery');
    await page.click('#open-grade');
    await page.fill('#grade-input', links.join('\n'));
    await page.fill('#grade-exercise', '');
    await page.click('#grade-start');
    await page.waitForFunction(() => /^3 hand-ins:/.test(document.querySelector('#grade-status').textContent), null, { timeout: 60000 });
    const shown = (await tableRows(page)).map((r) => r.cells);
    assert.deepEqual(
      shown.map((r) => r[2]),
      ['met', 'not met', 'met'],
    );
    assert.ok(shown[1][6].startsWith("not replayed: its exercise is not the class's (locked.seed differs)"), shown[1][6]);
    const cli = kumiki(['check', ...links])
      .trim()
      .split('\n')
      .map((l) => JSON.parse(l));
    assert.deepEqual(
      cli.map((r) => r.met),
      [true, false, true],
    );
    assert.equal(cli[1].exercise_edited, true);
    assert.ok(cli[1].because.startsWith("not replayed: its exercise is not the class's (locked.seed differs)"), cli[1].because);
    assert.deepEqual(problems, []);
    await context.close();
  });
});
