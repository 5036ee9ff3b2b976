// Classroom exercises: the student's panel at the top of the Run tab (instructions, goal in words,
// Check, hints, the verdict, Hand in) and the teacher's editor that makes one from the scenario in
// view (the Scenario tab's "Make an exercise…").
import { ENVELOPE } from '../../contract.gen';
import type { PageContext } from '../../page/context';
import type { Exercise } from '../../scenario.gen';
import { byId, clear, displayText, el, markup } from '../../widgets/dom';
import { renderMarkdown } from '../../widgets/markdown';
import * as core from '../../wasm';
import buttonHtml from './button.html?raw';
import editorHtml from './editor.html?raw';
import panelHtml from './panel.html?raw';

/** Where the student's panel goes in the Run tab (first), and the teacher's button in the Scenario tab (first). */
const ORDER = { panel: 10, button: 10 };

export function setupStudentPanel(page: PageContext) {
  const { session, sim, tabs, events } = page;
  tabs.section('run', panelHtml, ORDER.panel);

  /** Hints revealed so far, and the exercise they belong to. */
  let hintsShown = 0;
  let exerciseShown = '';
  function renderExercise(exercise: Exercise | undefined) {
    const panel = byId('exercise');
    panel.hidden = !exercise;
    if (!exercise) return;
    const key = JSON.stringify(exercise);
    if (key !== exerciseShown) {
      exerciseShown = key;
      hintsShown = 0;
      byId('exercise-result').textContent = '';
    }
    byId('exercise-title').textContent = displayText(exercise.title, 100);
    const instructions = byId('exercise-instructions');
    clear(instructions);
    instructions.append(...renderMarkdown(exercise.instructions));
    byId('exercise-goal').textContent = exercise.goal;
    byId('exercise-goal-words').textContent = core.goalWords(exercise.goal) ?? exercise.goal;
    const hints = byId('exercise-hints');
    clear(hints);
    for (const h of exercise.hints.slice(0, hintsShown)) hints.append(el('li', {}, ...renderMarkdown(h)));
    const more = byId<HTMLButtonElement>('exercise-hint');
    const left = exercise.hints.length - hintsShown;
    more.hidden = exercise.hints.length === 0;
    more.disabled = left === 0;
    more.textContent = left ? `Show a hint (${left} left)` : 'No more hints';
  }
  byId('exercise-hint').addEventListener('click', () => {
    hintsShown++;
    renderExercise(session.doc().exercise as Exercise | undefined);
  });
  byId('exercise-check').addEventListener('click', () => sim.check());
  byId('exercise-handin').addEventListener('click', async () => {
    const student = byId<HTMLInputElement>('exercise-student').value.trim();
    const out = byId('exercise-handin-out');
    try {
      const url = `${location.origin}${location.pathname}#${await session.link(student || undefined)}`;
      out.textContent = url;
      events.emit('handin', { link: url, name: student });
      await navigator.clipboard?.writeText(url).then(
        () => (out.textContent = `Copied. Send this link to your teacher: ${url}`),
        () => undefined,
      );
    } catch (e) {
      out.textContent = core.message(e);
    }
  });
  events.on('goal', ({ met, because, steps }) => {
    const out = byId('exercise-result');
    out.textContent = met
      ? `Goal met at step ${steps.toLocaleString('en-US')}: ${because}.`
      : `Not met yet (step ${steps.toLocaleString('en-US')}): ${because}.`;
    out.classList.toggle('met', met);
    out.classList.toggle('unmet', !met);
  });
  session.on('loaded', () => renderExercise(session.doc().exercise as Exercise | undefined));
}

export function setupExerciseEditor(page: PageContext) {
  const { session, tabs } = page;
  tabs.section('scenario', buttonHtml, ORDER.button);
  document.body.append(markup(editorHtml));
  const dialog = byId<HTMLDialogElement>('exercise-editor');
  const goalInput = byId<HTMLInputElement>('ex-goal');
  /** The goal as last checked, and whether it read well; a check on its way is the latest asked. */
  let checked = { goal: '', ok: false };
  let asked = 0;
  async function showGoalProblem(): Promise<boolean> {
    const goal = goalInput.value;
    const ask = ++asked;
    // The goal's names are checked against the model in view: its metrics and its scenario.
    const metrics = Object.keys(session.frame?.metrics ?? {});
    const problem = goal.trim() ? await session.goalProblem(goal, metrics) : 'write the goal the run must meet';
    if (ask !== asked) return checked.goal === goalInput.value && checked.ok;
    checked = { goal, ok: !problem };
    byId('ex-goal-problem').textContent = problem ?? '';
    goalInput.setAttribute('aria-invalid', problem ? 'true' : 'false');
    return !problem;
  }
  goalInput.addEventListener('input', () => void showGoalProblem());
  byId('make-exercise').addEventListener('click', () => {
    const doc = session.doc();
    const current = doc.exercise as Exercise | undefined;
    byId<HTMLInputElement>('ex-title').value = current?.title ?? displayText(String(doc.name ?? ''), 100);
    byId<HTMLTextAreaElement>('ex-instructions').value = current?.instructions ?? '';
    goalInput.value = current?.goal ?? 'completed';
    byId<HTMLTextAreaElement>('ex-hints').value = (current?.hints ?? []).join('\n\n');
    const locked = byId('ex-locked');
    clear(locked);
    // Every setting may be locked: the model's keys and the envelope's texts and settings.
    const fixed = new Set(ENVELOPE.filter((k) => k.role === 'format' || k.role === 'section').map((k) => k.key));
    for (const key of Object.keys(doc).filter((k) => !fixed.has(k))) {
      const box = el('input', { type: 'checkbox', value: key });
      box.checked = key in (current?.locked ?? {});
      locked.append(el('label', { class: 'check' }, box, ` ${key.replace(/_/g, ' ')}`));
    }
    byId('ex-remove').hidden = !current;
    void showGoalProblem();
    dialog.showModal();
  });
  // The exercise is made only with a goal that reads well: checked first when it was not yet.
  byId('ex-apply').addEventListener('click', (e) => {
    if (checked.goal === goalInput.value && checked.ok) return;
    e.preventDefault();
    void showGoalProblem().then((ok) => {
      if (ok) dialog.close('apply');
    });
  });
  dialog.addEventListener('close', () => {
    // A copy: the session's parsed scenario is shared.
    const doc = JSON.parse(session.scenario) as Record<string, unknown>;
    if (dialog.returnValue === 'remove') {
      delete doc.exercise;
      void session.open(JSON.stringify(doc), { opens: true });
      return;
    }
    if (dialog.returnValue !== 'apply') return;
    const locked: Record<string, unknown> = {};
    for (const box of byId('ex-locked').querySelectorAll<HTMLInputElement>('input:checked')) locked[box.value] = doc[box.value];
    doc.exercise = {
      title: byId<HTMLInputElement>('ex-title').value.trim() || 'Exercise',
      instructions: byId<HTMLTextAreaElement>('ex-instructions').value,
      locked,
      goal: goalInput.value.trim(),
      hints: byId<HTMLTextAreaElement>('ex-hints')
        .value.split(/\n\s*\n/)
        .map((h) => h.trim())
        .filter(Boolean),
    };
    void session.open(JSON.stringify(doc), { opens: true }).then((opened) => {
      if (opened) page.tabs.select('run');
    });
  });
}
