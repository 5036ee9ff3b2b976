// The Grade view: a class of 30 hand-ins (fair ones, ones that miss the goal, ones that changed a
// locked field, ones that edited the exercise, broken links and a row with no link) pasted as a
// form's CSV export, graded against a lesson in wasm workers, the same as `kumiki check` grades
// them, and exported as CSV.
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, test } from 'node:test';
import { kumiki, loadWasm, openPage, session } from './harness.mjs';

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

    const shown = await page.$$eval('#grade-rows tr', (trs) => trs.map((tr) => [...tr.cells].map((c) => c.textContent)));
    assert.equal(shown.length, 30);
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
    assert.match(exported[0], /^handin,student,name,met,because,completed,steps,hash,locked_edited,changed,exercise_edited,/);

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
      const [, , goal, steps, , why, hash] = shown[i];
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
    assert.ok(shown[4][5].startsWith("not replayed: its exercise is not the class's (locked.collision differs)"), shown[4][5]);
    assert.match(shown[3][5], /seed: 1 → 2/);
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
    await page.waitForFunction(() => document.querySelectorAll('#grade-rows tr:not(.pending)').length > 0, null, { timeout: 60000 });
    await page.click('#grade-cancel');
    const status = await page.textContent('#grade-status');
    assert.match(status, /^Cancelled after [\d,]+ of 2,000 hand-ins/);
    const graded = Number(/after ([\d,]+)/.exec(status)[1].replace(/,/g, ''));
    assert.ok(graded > 0 && graded < 2000, `${graded} graded`);
    // The table is paged: 200 rows at a time, whatever the class's size.
    assert.equal(await page.locator('#grade-rows tr').count(), 200);
    assert.equal(await page.textContent('#grade-page'), 'Rows 1 to 200 of 2,000');
    await page.click('#grade-next');
    assert.equal(await page.textContent('#grade-page'), 'Rows 201 to 400 of 2,000');
    assert.equal(await page.isDisabled('#grade-start'), false);
    await context.close();
  });
});
