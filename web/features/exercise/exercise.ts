// Classroom exercises: the student's panel at the top of the Run tab (instructions, goal in words,
// Check, hints, the verdict, Hand in) and the teacher's editor that makes one from the scenario in
// view (the Scenario tab's "Make an exercise…").
import { type Credit, ENVELOPE } from '../../contract.gen';
import type { PageContext } from '../../page/context';
import type { Exercise, Part } from '../../scenario.gen';
import { byId, clear, displayText, el, markup } from '../../widgets/dom';
import { renderMarkdown } from '../../widgets/markdown';
import * as core from '../../wasm';
import buttonHtml from './button.html?raw';
import editorHtml from './editor.html?raw';
import panelHtml from './panel.html?raw';

/** Where the student's panel goes in the Run tab (first), and the teacher's button in the Scenario tab (first). */
const ORDER = { panel: 10, button: 10 };

/** A credit part in words, before it is judged ("3 points: steps ≤ 300") and once it is ("3 of 3 points: …"). */
export function partText(part: Part, judged: Credit | undefined, words: (goal: string) => string): string {
  const said = words(part.goal);
  if (!judged) return `${part.points} point${part.points === 1 ? '' : 's'}: ${said}`;
  return `${judged.earned} of ${part.points} point${part.points === 1 ? '' : 's'}: ${said}`;
}

/** The hand-in's record of itself: when (to the second, UTC), how many checks and hints, and the answer. */
export function handinRecord(now: Date, checks: number, hints: number, answer: string) {
  const made = now.toISOString().replace(/\.\d+Z$/, 'Z');
  return answer.trim() ? { made, checks, hints, answer } : { made, checks, hints };
}

/** Parts of the outcome and their points from the editor's lines ("5: completed"); a string says which line is wrong. */
export function readCredit(text: string): Part[] | string {
  const parts: Part[] = [];
  for (const [i, line] of text.split('\n').entries()) {
    if (!line.trim()) continue;
    const m = /^\s*(\d+)\s*:\s*(.+?)\s*$/.exec(line);
    if (!m) return `line ${i + 1}: write the points, a colon, then the part as a goal ("5: completed")`;
    parts.push({ points: Number(m[1]), goal: m[2] });
  }
  return parts;
}

export function setupStudentPanel(page: PageContext) {
  const { session, sim, tabs, events } = page;
  tabs.section('run', panelHtml, ORDER.panel);

  /** Hints revealed so far, Checks pressed, the parts as last judged, and the exercise they belong to. */
  let hintsShown = 0;
  let checks = 0;
  let judged: Credit[] = [];
  let exerciseShown = '';
  const words = (goal: string) => core.goalWords(goal) ?? goal;

  /** The points each part gives, before hand-in: as judged by the last verdict, once there is one. */
  function renderPoints(exercise: Exercise) {
    const parts = exercise.credit ?? [];
    byId('exercise-points').hidden = parts.length === 0;
    const list = byId('exercise-parts');
    clear(list);
    if (!parts.length) return;
    const most = parts.reduce((n, p) => n + p.points, 0);
    const earned = judged.length === parts.length ? judged.reduce((n, c) => n + c.earned, 0) : null;
    byId('exercise-points-head').textContent = earned === null ? `Points: up to ${most}` : `Points: ${earned} of ${most}`;
    for (const [i, part] of parts.entries()) list.append(el('li', { text: partText(part, judged.length === parts.length ? judged[i] : undefined, words) }));
  }

  function renderExercise(exercise: Exercise | undefined) {
    const panel = byId('exercise');
    panel.hidden = !exercise;
    // The page's layout keeps the run's controls beside the exercise on a phone (static/style.css).
    document.body.classList.toggle('exercise-open', Boolean(exercise));
    if (!exercise) return;
    const key = JSON.stringify(exercise);
    if (key !== exerciseShown) {
      exerciseShown = key;
      hintsShown = 0;
      checks = 0;
      judged = [];
      byId('exercise-result').textContent = '';
      byId<HTMLTextAreaElement>('exercise-answer').value = '';
    }
    byId('exercise-title').textContent = displayText(exercise.title, 100);
    const instructions = byId('exercise-instructions');
    clear(instructions);
    instructions.append(...renderMarkdown(exercise.instructions));
    byId('exercise-goal').textContent = exercise.goal;
    byId('exercise-goal-words').textContent = words(exercise.goal);
    renderPoints(exercise);
    const question = exercise.question ?? '';
    byId('exercise-question-box').hidden = !question;
    byId('exercise-question').textContent = displayText(question, 2000, true);
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
  byId('exercise-check').addEventListener('click', () => {
    checks++;
    sim.check();
  });
  byId('exercise-handin').addEventListener('click', async () => {
    const student = byId<HTMLInputElement>('exercise-student').value.trim();
    const answer = byId<HTMLTextAreaElement>('exercise-answer').value;
    const out = byId('exercise-handin-out');
    try {
      const record = handinRecord(new Date(), checks, hintsShown, answer);
      const url = `${location.origin}${location.pathname}#${await sim.link(student, record)}`;
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
  events.on('goal', ({ met, because, steps, credit }) => {
    const out = byId('exercise-result');
    out.textContent = met
      ? `Goal met at step ${steps.toLocaleString('en-US')}: ${because}.`
      : `Not met yet (step ${steps.toLocaleString('en-US')}): ${because}.`;
    out.classList.toggle('met', met);
    out.classList.toggle('unmet', !met);
    judged = credit;
    const exercise = session.doc().exercise as Exercise | undefined;
    if (exercise) renderPoints(exercise);
  });
  session.on('loaded', () => renderExercise(session.doc().exercise as Exercise | undefined));
}

/** What the editor adds to an exercise beside its goal and locks: allowances, points, question, budget (each left out when empty). */
function extras(credit: Part[]): Partial<Exercise> {
  const out: Partial<Exercise> = {};
  const allow: Record<string, number> = {};
  for (const input of byId('ex-allow').querySelectorAll<HTMLInputElement>('input')) {
    const n = Number(input.value);
    if (input.dataset.kind && input.value !== '' && n > 0) allow[input.dataset.kind] = n;
  }
  if (Object.keys(allow).length) out.disturbances = allow;
  if (credit.length) out.credit = credit;
  const question = byId<HTMLTextAreaElement>('ex-question').value.trim();
  if (question) out.question = question;
  const steps = byId<HTMLInputElement>('ex-budget-steps').value;
  const seconds = byId<HTMLInputElement>('ex-budget-seconds').value;
  if (steps || seconds) out.budget = { ...(steps ? { steps: Number(steps) } : {}), ...(seconds ? { seconds: Number(seconds) } : {}) };
  return out;
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
    // Each click tool's allowance: how many of its kind students may add (none unless allowed).
    const allow = byId('ex-allow');
    clear(allow);
    for (const t of session.layout?.tools ?? []) {
      const kind = String(t.action.kind ?? '');
      const input = el('input', {
        type: 'number',
        min: 0,
        max: 10000,
        step: 1,
        inputmode: 'numeric',
        'data-kind': kind,
        value: String(current?.disturbances?.[kind] ?? 0),
      });
      allow.append(el('label', { class: 'row' }, `${t.label}: at most`, input));
    }
    byId<HTMLTextAreaElement>('ex-credit').value = (current?.credit ?? []).map((p) => `${p.points}: ${p.goal}`).join('\n');
    byId('ex-credit-problem').textContent = '';
    byId<HTMLTextAreaElement>('ex-question').value = current?.question ?? '';
    byId<HTMLInputElement>('ex-budget-steps').value = current?.budget?.steps ? String(current.budget.steps) : '';
    byId<HTMLInputElement>('ex-budget-seconds').value = current?.budget?.seconds ? String(current.budget.seconds) : '';
    byId('ex-remove').hidden = !current;
    void showGoalProblem();
    // With an exercise open (a student's page), the editor first says what it will do.
    byId('ex-confirm').hidden = !current;
    byId('ex-fields').hidden = Boolean(current);
    dialog.showModal();
    if (current) byId('ex-confirm-go').focus();
  });
  byId('ex-confirm-go').addEventListener('click', () => {
    byId('ex-confirm').hidden = true;
    byId('ex-fields').hidden = false;
    byId('ex-title').focus();
  });
  // The exercise is made only with a goal that reads well: checked first when it was not yet.
  /** The credit's parts, each goal checked against the model in view; null (with the problem shown) when one is wrong. */
  async function creditParts(): Promise<Part[] | null> {
    const problem = byId('ex-credit-problem');
    const parts = readCredit(byId<HTMLTextAreaElement>('ex-credit').value);
    let why = typeof parts === 'string' ? parts : null;
    const metrics = Object.keys(session.frame?.metrics ?? {});
    for (const p of typeof parts === 'string' ? [] : parts) {
      const wrong = await session.goalProblem(p.goal, metrics);
      if (wrong) {
        why = `“${p.goal}”: ${wrong}`;
        break;
      }
    }
    problem.textContent = why ?? '';
    byId('ex-credit').setAttribute('aria-invalid', why ? 'true' : 'false');
    return why || typeof parts === 'string' ? null : parts;
  }
  let credit: Part[] = [];
  byId('ex-apply').addEventListener('click', (e) => {
    e.preventDefault();
    void Promise.all([checked.goal === goalInput.value && checked.ok ? true : showGoalProblem(), creditParts()]).then(([ok, parts]) => {
      if (!ok || !parts) return;
      credit = parts;
      dialog.close('apply');
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
      ...extras(credit),
    };
    void session.open(JSON.stringify(doc), { opens: true }).then((opened) => {
      if (opened) page.tabs.select('run');
    });
  });
}
