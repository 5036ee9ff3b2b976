// What the Grade view shows of a graded row (web/features/grade/handins.ts): the verdict in words
// with over budget marked, points per credit part, why, the student's answer and record, and a
// name cut to fit, its direction-changing characters left out. The rows are the lab's, read and
// graded as `kumiki check` does (crate/core/src/handins, grading): tested there and in the browser.
import { describe, expect, test } from 'vitest';
import {
  answerText,
  count,
  emptyTally,
  type GradeRow,
  NAME_CHARS,
  nameText,
  partsText,
  pointsText,
  reasonText,
  recordText,
  tallyText,
  verdict,
} from '../../web/features/grade/handins';

const grade = (over: Partial<Extract<GradeRow, { met: boolean }>> = {}): GradeRow => ({
  handin: 1,
  student: 'Ada',
  link: '#k1.x',
  name: 'Ada',
  met: false,
  because: 'steps is 320, but it must be ≤ 300',
  completed: true,
  steps: 320,
  hash: 'ab',
  changed: [],
  disturbances: [],
  locked_edited: [],
  exercise_edited: false,
  goal_metrics: {},
  over_budget: false,
  ...over,
});

describe('a graded row', () => {
  test('its verdict in words, over budget apart from not met, and the tally', () => {
    const rows = [
      grade({ met: true }),
      grade(),
      grade({ over_budget: true }),
      { handin: 4, error: 'holds no Kumiki link (line 5 of the file): Bob' } as GradeRow,
      { handin: 5, error: 'skipped: the teacher skipped it after 4.0 s at step 9,000' } as GradeRow,
    ];
    expect(rows.map(verdict)).toEqual(['met', 'not met', 'over budget', 'could not be graded', 'skipped']);
    const tally = emptyTally();
    for (const r of rows) count(tally, r);
    expect(tallyText(tally)).toBe('1 met, 2 not met (1 over budget), 1 could not be graded, 1 skipped');
    expect(tallyText({ met: 2, unmet: 0, over: 0, errors: 0, skipped: 0 })).toBe('2 met, 0 not met, 0 could not be graded');
  });

  test('its points of the most, and each credit part', () => {
    expect(pointsText(grade())).toBe('');
    const credit = [
      { goal: 'completed', points: 5, earned: 5, because: 'completed' },
      { goal: 'steps < 300', points: 3, earned: 0, because: 'steps is 320' },
    ];
    const r = grade({ points: 5, max_points: 8, credit });
    expect(pointsText(r)).toBe('5 of 8');
    expect(partsText(r)).toEqual(['5 of 5: completed', '0 of 3: steps < 300']);
  });

  test('why: the reason, what was changed, and the disturbances it added', () => {
    expect(reasonText(grade({ changed: ['seed'], disturbances: ["'remove' added at step 25 (the exercise allows none)"] }))).toBe(
      "steps is 320, but it must be ≤ 300. changed: seed. 'remove' added at step 25 (the exercise allows none)",
    );
  });

  test("the student's answer over several lines, and the record", () => {
    const r = grade({ record: { made: '2026-11-28T10:15:00Z', checks: 3, hints: 1, answer: 'Five robots.\nSix was best.' } });
    expect(answerText(r).shown).toBe('Five robots.\nSix was best.');
    expect(recordText(r)).toBe('handed in 2026-11-28T10:15:00Z, 3 checks, 1 hint');
  });

  test('a long name is cut with its whole kept; a right-to-left override is left out', () => {
    const long = nameText('x'.repeat(100_000));
    expect(Array.from(long.shown).length).toBe(NAME_CHARS);
    expect(long.shown.endsWith('…')).toBe(true);
    expect(long.full.length).toBeGreaterThan(NAME_CHARS);
    expect(nameText('Ali\u202egnp.exe').shown).toBe('Alignp.exe');
    expect(nameText('').shown).toBe('(no name)');
  });
});
