// The Scenario tab: the model's own editor, the parameter form, the JSON text, undo and redo; and
// the scenario's name at the top of the page.
import type { MountedEditor } from '../../editors/editor';
import { modelEditors, scenarioTitle } from '../../models/index';
import type { PageContext } from '../../page/context';
import { onShortcut } from '../../page/keys';
import type { Exercise } from '../../scenario.gen';
import { byId, clear, displayText, download, el } from '../../widgets/dom';
import { renderParams } from '../../widgets/params';
import * as core from '../../wasm';
import panelHtml from './panel.html?raw';

/** Where the Scenario tab's own section goes (the exercise editor's button is above it). */
const ORDER = 20;

export function setupScenarioPanel(page: PageContext) {
  const { session, tabs } = page;
  tabs.section('scenario', panelHtml, ORDER);
  let editor: MountedEditor | null = null;
  let editorModel = '';

  const jsonEditor = byId<HTMLTextAreaElement>('scenario-json');
  const jsonError = byId('json-error');
  let jsonDirty = false;
  jsonEditor.addEventListener('input', () => (jsonDirty = true));
  function syncJsonEditor() {
    if (!jsonDirty) jsonEditor.value = session.scenario;
  }

  // ---- the form, the model's editor and the JSON ----

  function renderScenarioPanel() {
    // A copy for the form and the editor, which may keep it.
    const doc = JSON.parse(session.scenario) as Record<string, unknown>;
    const exercise = doc.exercise as Exercise | undefined;
    // An exercise goes by its title, not by the preset it was made from; a built-in scenario by
    // its title in words, its code name beside it.
    const code = displayText(String(doc.name ?? ''), 100);
    const name = displayText(exercise?.title ?? scenarioTitle(code) ?? code, 100);
    byId('scenario-name').textContent = name || 'untitled scenario';
    byId('scenario-model').textContent = exercise ? `exercise · ${String(doc.model ?? '')}` : String(doc.model ?? '');
    byId('scenario-code').textContent = code !== name ? code : '';
    document.title = `${name || 'untitled'} · Kumiki`;
    const model = String(doc.model);
    const spec = modelEditors[model];
    renderParams(
      byId<HTMLFormElement>('param-form'),
      doc,
      (key, value) => session.set(key, value),
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
      if (spec) {
        root.append(el('h3', { text: spec.title }));
        const mount = el('div');
        root.append(mount);
        editor = spec.mount(mount, {
          scenario: () => JSON.parse(session.scenario) as Record<string, unknown>,
          change: (changes) => session.edit(changes),
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

  /** Opens the editor's text, held to the exercise's locks; when it cannot run, the reason shows beside the editor. */
  async function loadEdited(text: string, source = '') {
    // Cleared first: the editor shows the opened scenario only when it holds no unsaved edit.
    const wasDirty = jsonDirty;
    jsonDirty = false;
    jsonError.textContent = '';
    const opened = await session.open(text, {
      onProblem: (message) => {
        jsonError.textContent = `${source}${message}`;
      },
    });
    if (!opened) jsonDirty = wasDirty;
  }

  byId('apply-json').addEventListener('click', () => void loadEdited(jsonEditor.value));
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
    void loadEdited(text, `${file.name}: `);
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
    if (prev) void session.open(prev, { record: false, opens: true });
  }
  function redo() {
    const next = session.redo();
    if (next) void session.open(next, { record: false, opens: true });
  }
  undoButton.addEventListener('click', undo);
  redoButton.addEventListener('click', redo);
  onShortcut((e) => {
    if (e.key.toLowerCase() !== 'z') return;
    e.preventDefault();
    if (e.shiftKey) redo();
    else undo();
  });

  session.on('loaded', renderScenarioPanel);
  session.on('recorded', syncJsonEditor);
}
