// @vitest-environment happy-dom
// The teacher's exercise editor (web/features/exercise/), on the real core: it locks each click
// tool or allows a number of its kind, gives points for parts of the outcome, asks a question and
// sets a budget per hand-in; an exercise edited again keeps them; a wrong part is refused by line.
import { describe, expect, it } from 'vitest';
import { readCredit } from '../../web/features/exercise/exercise';
import { FEATURES } from '../../web/features/index';
import { preset, testPage } from './page';

const $ = <T extends HTMLElement = HTMLElement>(selector: string) => {
  const e = document.querySelector<T>(selector);
  if (!e) throw new Error(`no ${selector}`);
  return e;
};
const set = (selector: string, value: string) => {
  $<HTMLInputElement | HTMLTextAreaElement>(selector).value = value;
};

async function opened() {
  const t = testPage([...FEATURES]);
  await t.page.session.open(preset('amas-L'), { record: false, opens: true });
  await t.until(() => t.page.session.frame !== null, 'the first frame');
  return t;
}

describe('the exercise editor', () => {
  it('reads points, a colon and a goal on each line, and names a line that is not', () => {
    expect(readCredit('5: completed\n\n3 :  steps < 300 \n')).toEqual([
      { points: 5, goal: 'completed' },
      { points: 3, goal: 'steps < 300' },
    ]);
    expect(readCredit('5 completed')).toBe('line 1: write the points, a colon, then the part as a goal ("5: completed")');
  });

  it('allows a number of one tool and locks the others, with points, a question and a budget', async () => {
    const { page, until } = await opened();
    $('#make-exercise').click();
    const allow = [...document.querySelectorAll<HTMLInputElement>('#ex-allow input')];
    expect(allow.map((i) => i.dataset.kind)).toEqual(['remove', 'break', 'dismantle', 'extend']);
    expect(allow.every((i) => i.value === '0' && i.closest('label'))).toBe(true);
    set('#ex-allow input[data-kind="remove"]', '2');
    set('#ex-goal', 'completed');
    set('#ex-credit', '5: completed\n3: steps < 3000');
    set('#ex-question', 'Why does the corner slow them down?');
    set('#ex-budget-steps', '5000');
    $('#ex-apply').click();
    await until(() => Boolean((page.session.doc().exercise as { credit?: unknown } | undefined)?.credit), 'the exercise');
    expect(page.session.doc().exercise).toMatchObject({
      disturbances: { remove: 2 },
      credit: [
        { points: 5, goal: 'completed' },
        { points: 3, goal: 'steps < 3000' },
      ],
      question: 'Why does the corner slow them down?',
      budget: { steps: 5000 },
    });
    await until(() => $('#tools button[data-tool="remove"]').textContent?.endsWith('(2 left)') ?? false, 'the allowance');
    expect($('#tools button[data-tool="break"]').getAttribute('aria-disabled')).toBe('true');
    // Edited again, the exercise keeps what it had, once the editor has said what it does: it
    // starts a new exercise, not graded as the one open.
    $('#make-exercise').click();
    expect($('#ex-confirm').hidden).toBe(false);
    expect($('#ex-fields').hidden).toBe(true);
    expect($('#ex-confirm-text').textContent).toMatch(/^This starts a new exercise from your scenario; it will not be graded as the teacher's exercise\./);
    $('#ex-confirm-go').click();
    expect($('#ex-fields').hidden).toBe(false);
    expect($<HTMLInputElement>('#ex-allow input[data-kind="remove"]').value).toBe('2');
    expect($<HTMLTextAreaElement>('#ex-credit').value).toBe('5: completed\n3: steps < 3000');
    expect($<HTMLInputElement>('#ex-budget-steps').value).toBe('5000');
  });

  it('refuses a part whose goal does not read, naming it, and keeps the editor open', async () => {
    const { until } = await opened();
    $('#make-exercise').click();
    // No exercise open: the editor opens on its fields at once.
    expect($('#ex-confirm').hidden).toBe(true);
    set('#ex-goal', 'completed');
    set('#ex-credit', '5: metrics.nonsense > 1');
    $('#ex-apply').click();
    await until(() => $('#ex-credit-problem').textContent !== '', 'the problem');
    expect($('#ex-credit-problem').textContent).toMatch(/^“metrics\.nonsense > 1”: /);
    expect($('#ex-credit').getAttribute('aria-invalid')).toBe('true');
    expect($<HTMLDialogElement>('#exercise-editor').open).toBe(true);
  });
});
