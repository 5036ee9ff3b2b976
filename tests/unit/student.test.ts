// @vitest-environment happy-dom
// The student's side of an exercise (web/features/exercise/), on the real core: the points each
// credit part gives, shown before hand-in and as the last Check judged them; the question answered
// in words; and the hand-in's record (when, how many Checks and hints, the answer) in its link.
import { describe, expect, it } from 'vitest';
import { handinRecord, partText } from '../../web/features/exercise/exercise';
import { FEATURES } from '../../web/features/index';
import * as wasm from '../../web/pkg/kumiki_wasm.js';
import { lesson, testPage } from './page';

const $ = <T extends HTMLElement = HTMLElement>(selector: string) => {
  const e = document.querySelector<T>(selector);
  if (!e) throw new Error(`no ${selector}`);
  return e;
};
const parts = () => [...document.querySelectorAll('#exercise-parts li')].map((li) => li.textContent);

/** lesson-amas-robots with points for three parts and a question. */
function creditLesson() {
  const doc = JSON.parse(lesson('lesson-amas-robots'));
  doc.exercise.credit = [
    { goal: 'completed', points: 5 },
    { goal: 'steps <= 300', points: 3 },
    { goal: 'scenario.robots <= 6', points: 1 },
  ];
  doc.exercise.question = 'Why do more robots not always help?';
  return JSON.stringify(doc);
}

describe("the student's side", () => {
  it('a part in words, before and after it is judged; a record to the second in UTC', () => {
    const words = (g: string) => g.toUpperCase();
    expect(partText({ goal: 'completed', points: 1 }, undefined, words)).toBe('1 point: COMPLETED');
    expect(partText({ goal: 'steps < 3', points: 3 }, { goal: 'steps < 3', points: 3, earned: 0, because: '' }, words)).toBe('0 of 3 points: STEPS < 3');
    const at = new Date(Date.UTC(2026, 10, 28, 10, 15, 0, 456));
    expect(handinRecord(at, 2, 1, '  ')).toEqual({ made: '2026-11-28T10:15:00Z', checks: 2, hints: 1 });
    expect(handinRecord(at, 0, 0, 'Six.').answer).toBe('Six.');
  });

  it('shows the points per part before hand-in, then as Check judged them', async () => {
    const { page, until } = testPage([...FEATURES]);
    await page.session.open(creditLesson(), { record: false, opens: true });
    await until(() => page.session.frame !== null && !$('#exercise').hidden, 'the exercise');
    expect($('#exercise-points').hidden).toBe(false);
    expect($('#exercise-points-head').textContent).toBe('Points: up to 9');
    expect(parts()).toEqual([
      `5 points: ${wasm.goal_words('completed')}`,
      `3 points: ${wasm.goal_words('steps <= 300')}`,
      `1 point: ${wasm.goal_words('scenario.robots <= 6')}`,
    ]);
    // At step 0 the run has not completed: the steps' and the robots' parts are met.
    $('#exercise-check').click();
    await until(() => $('#exercise-points-head').textContent !== 'Points: up to 9', 'the verdict');
    expect($('#exercise-points-head').textContent).toBe('Points: 4 of 9');
    expect(parts()[0]).toMatch(/^0 of 5 points: /);
    expect(parts()[1]).toMatch(/^3 of 3 points: /);
    expect(parts()[2]).toMatch(/^1 of 1 point: /);
  });

  it('hands in the answer with the link, and when, how many Checks and hints it took', async () => {
    const { page, until } = testPage([...FEATURES]);
    await page.session.open(creditLesson(), { record: false, opens: true });
    await until(() => page.session.frame !== null && !$('#exercise').hidden, 'the exercise');
    expect($('#exercise-question-box').hidden).toBe(false);
    expect($('label[for="exercise-answer"]').textContent).toBe('Question: Why do more robots not always help?');
    $<HTMLTextAreaElement>('#exercise-answer').value = 'They collide\nat the corner.';
    $('#exercise-check').click();
    $('#exercise-check').click();
    $('#exercise-hint').click();
    $<HTMLInputElement>('#exercise-student').value = 'Ada';
    const before = Date.now();
    $('#exercise-handin').click();
    await until(() => /#k1\./.test($('#exercise-handin-out').textContent ?? ''), 'the hand-in');
    const link = /#(k1\.\S+)/.exec($('#exercise-handin-out').textContent ?? '')?.[1] ?? '';
    const doc = JSON.parse(wasm.decode_link(link));
    expect(doc.name).toBe('Ada');
    expect(doc.handin).toMatchObject({ checks: 2, hints: 1, answer: 'They collide\nat the corner.' });
    expect(Math.abs(Date.parse(doc.handin.made) - before)).toBeLessThan(60_000);
  });
});
