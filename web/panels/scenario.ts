// The scenario panel: the parameter form, the model's own editor, the JSON text, undo and redo,
// and the classroom exercise (the student's panel on the run tab and the teacher's editor).
import { ENVELOPE } from '../contract.gen';
import { modelEditors, type MountedEditor } from '../models/index';
import type { Exercise } from '../scenario.gen';
import { byId, clear, displayText, download, el } from '../ui/dom';
import { renderMarkdown } from '../ui/markdown';
import { renderParams } from '../ui/params';
import { renderReproduction } from '../ui/reproduction';
import * as core from '../wasm';
import type { Page } from './page';

export interface ScenarioPanel {
  undo(): void;
  redo(): void;
}

export function setupScenarioPanel(page: Page, selectTab: (name: string) => void, handedIn: (link: string, name: string) => void): ScenarioPanel {
  const { session, sim } = page;
  let editor: MountedEditor | null = null;
  let editorModel = '';

  const jsonEditor = byId<HTMLTextAreaElement>('scenario-json');
  const jsonError = byId('json-error');
  let jsonDirty = false;
  jsonEditor.addEventListener('input', () => (jsonDirty = true));
  function syncJsonEditor() {
    if (!jsonDirty) jsonEditor.value = session.scenario;
  }

  // ---- the exercise, as the student sees it ----

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
      const url = `${location.origin}${location.pathname}#${page.draft.link(student || undefined)}`;
      out.textContent = url;
      handedIn(url, student);
      await navigator.clipboard?.writeText(url).then(
        () => (out.textContent = `Copied. Send this link to your teacher: ${url}`),
        () => undefined,
      );
    } catch (e) {
      out.textContent = core.message(e);
    }
  });

  // ---- the teacher's exercise editor ----

  const exerciseDialog = byId<HTMLDialogElement>('exercise-editor');
  const goalInput = byId<HTMLInputElement>('ex-goal');
  function showGoalProblem(): boolean {
    // The goal's names are checked against the model in view: its metrics and its scenario.
    const metrics = Object.keys(session.frame?.metrics ?? {});
    const problem = goalInput.value.trim() ? page.draft.goalProblem(goalInput.value, metrics) : 'write the goal the run must meet';
    byId('ex-goal-problem').textContent = problem ?? '';
    goalInput.setAttribute('aria-invalid', problem ? 'true' : 'false');
    return !problem;
  }
  goalInput.addEventListener('input', showGoalProblem);
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
    showGoalProblem();
    exerciseDialog.showModal();
  });
  byId('ex-apply').addEventListener('click', (e) => {
    if (!showGoalProblem()) e.preventDefault();
  });
  exerciseDialog.addEventListener('close', () => {
    // A copy: the session's parsed scenario is shared.
    const doc = JSON.parse(session.scenario) as Record<string, unknown>;
    if (exerciseDialog.returnValue === 'remove') {
      delete doc.exercise;
      page.load(JSON.stringify(doc), { opens: true });
      return;
    }
    if (exerciseDialog.returnValue !== 'apply') return;
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
    if (page.load(JSON.stringify(doc), { opens: true })) selectTab('run');
  });

  // ---- the form, the model's editor and the JSON ----

  function renderScenarioPanel() {
    // A copy for the form and the editor, which may keep it.
    const doc = JSON.parse(session.scenario) as Record<string, unknown>;
    const exercise = doc.exercise as Exercise | undefined;
    // An exercise goes by its title, not by the preset it was made from.
    const name = displayText(exercise?.title ?? String(doc.name ?? ''), 100);
    byId('scenario-name').textContent = name || 'untitled scenario';
    byId('scenario-model').textContent = exercise ? `exercise · ${String(doc.model ?? '')}` : String(doc.model ?? '');
    document.title = `${name || 'untitled'} · Kumiki`;
    const model = String(doc.model);
    const spec = modelEditors[model];
    renderExercise(exercise);
    renderParams(
      byId<HTMLFormElement>('param-form'),
      doc,
      (key, value) => page.applyChange(key, value),
      spec?.owns,
      new Set(Object.keys(exercise?.locked ?? {})),
      core.modelSchema(model),
    );
    jsonDirty = false;
    syncJsonEditor();
    jsonError.textContent = '';

    const root = byId('model-editor');
    if (model !== editorModel) {
      editor?.destroy();
      editor = null;
      clear(root);
      editorModel = model;
      renderReproduction(byId('paper-report'), model);
      if (spec) {
        root.append(el('h3', { text: spec.title }));
        const mount = el('div');
        root.append(mount);
        editor = spec.mount(mount, {
          scenario: () => JSON.parse(session.scenario) as Record<string, unknown>,
          change: (changes) => page.applyChanges(changes),
          layout: () => session.layout,
        });
      }
    }
    editor?.update(doc);
    // A shape the exercise locks makes the model's editor read-only (its shapes are drawn
    // together, so one locked shape locks the editor), and says so.
    const lockedHere = (spec?.owns ?? []).filter((k) => k in (exercise?.locked ?? {}));
    const editorBody = root.querySelector<HTMLElement>(':scope > div');
    if (editorBody) editorBody.inert = lockedHere.length > 0;
    root.querySelector('.locked-note')?.remove();
    if (lockedHere.length)
      root.append(
        el('p', {
          class: 'locked-note',
          text: `Locked by the exercise: ${lockedHere.map((k) => k.replace(/_/g, ' ')).join(', ')}. The editor shows them read-only.`,
        }),
      );
  }

  /** Opens the editor's text; false, with the reason beside the editor, when it cannot run. */
  function loadEdited(text: string, source = ''): boolean {
    // Cleared first: the editor shows the opened scenario only when it holds no unsaved edit.
    const wasDirty = jsonDirty;
    jsonDirty = false;
    jsonError.textContent = '';
    const opened = page.load(text, {
      onProblem: (message) => {
        jsonError.textContent = `${source}${message}`;
      },
    });
    if (!opened) jsonDirty = wasDirty;
    return opened;
  }

  byId('apply-json').addEventListener('click', () => loadEdited(jsonEditor.value));
  byId('download-json').addEventListener('click', () => {
    const name = (session.doc().name as string | undefined) || 'scenario';
    download(`${name}.json`, `${session.scenario}\n`, 'application/json');
  });
  byId<HTMLInputElement>('open-json').addEventListener('change', async (e) => {
    const file = (e.target as HTMLInputElement).files?.[0];
    if (!file) return;
    const text = await file.text();
    jsonEditor.value = text;
    jsonDirty = true;
    const details = jsonEditor.closest('details');
    if (details) details.open = true;
    loadEdited(text, `${file.name}: `);
    (e.target as HTMLInputElement).value = '';
  });

  // ---- undo and redo ----

  const undoButton = byId<HTMLButtonElement>('undo');
  const redoButton = byId<HTMLButtonElement>('redo');
  session.on('history', () => {
    undoButton.disabled = !session.canUndo;
    redoButton.disabled = !session.canRedo;
  });
  function undo() {
    const prev = session.undo();
    if (prev) page.load(prev, { record: false, opens: true });
  }
  function redo() {
    const next = session.redo();
    if (next) page.load(next, { record: false, opens: true });
  }
  undoButton.addEventListener('click', undo);
  redoButton.addEventListener('click', redo);

  session.on('loaded', renderScenarioPanel);
  session.on('recorded', syncJsonEditor);

  return { undo, redo };
}
