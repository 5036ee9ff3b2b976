// The Rules tab: pick a rule slot of the model in view, read what its script is given and must
// answer, edit the script (the paper's rule to start with), see a problem marked at its line as
// you type (checked in the simulation worker by its rules module), and run it: the script goes in
// the scenario's `rules.<slot>` through the session, so undo, the link and `kumiki run` carry it.
// "Compare" runs the paper's rule beside it, through the scenario's `compare` section (a `rules`
// path with null: the paper's rule). The editor and the worker's rules module load when the tab
// first opens, never before.
import type { SlotDoc, SlotInfo } from '../../contract.gen';
import type { PageContext } from '../../page/context';
import { ruleQueries } from '../../sim/rules';
import { byId, clear, el } from '../../widgets/dom';
import type { RuleEditor } from './editor';
import panelHtml from './panel.html?raw';
import { place, scriptIn, slotsOf, withoutScript } from './problems';

/** How long typing may pause before the script is checked. */
export const CHECK_AFTER_MS = 250;

/** The second run's and the first's names when the paper's rule is compared with the script. */
export const COMPARE_LABELS = { label: "the paper's rule", base_label: 'my rule' } as const;

export function setupRules(page: PageContext) {
  const { session, sim, events } = page;
  // Answered by the worker's rules module, which it fetches for the first question.
  const rules = ruleQueries((message) => sim.ask(message));
  page.tabs.section('rules', panelHtml, 10);
  const status = byId('rules-status');
  const room = byId('rules-room');
  const slotSelect = byId<HTMLSelectElement>('rules-slot');
  const problemOut = byId('rules-problem');
  const note = byId('rules-note');
  const runButton = byId<HTMLButtonElement>('rules-run');
  const compareButton = byId<HTMLButtonElement>('rules-compare');
  const resetButton = byId<HTMLButtonElement>('rules-reset');
  const paperButton = byId<HTMLButtonElement>('rules-paper');

  let opened: Promise<void> | null = null;
  let all: SlotDoc[] = [];
  let editor: RuleEditor | null = null;
  /** The model and slot the editor shows, and the scenario's script for it when it was shown. */
  let shown: { model: string; slot: SlotInfo; scenario: string } | null = null;
  /** The latest check asked: an older answer is dropped. */
  let checking = 0;
  let timer: ReturnType<typeof setTimeout> | null = null;

  const model = () => String(session.doc().model ?? '');
  const slotNamed = (name: string) => slotsOf(all, model()).find((s) => s.name === name) ?? null;
  /** The text the editor starts with for a slot: the scenario's script, else the paper's rule. */
  const starting = (slot: SlotInfo) => scriptIn(session.doc(), slot.name) ?? slot.paper;

  /** Loads the editor (its own chunk) and every slot, once; the tab shows them when both have come. */
  function open(): Promise<void> {
    opened ??= (async () => {
      status.textContent = 'Loading the rule editor…';
      try {
        const [code, slots] = await Promise.all([import('./editor'), rules.slots()]);
        all = slots;
        editor = code.ruleEditor(byId('rules-editor'), '', scheduleCheck, "The rule's script (Rhai)");
        follow();
      } catch (e) {
        opened = null;
        status.textContent = `The rule editor could not load: ${e instanceof Error ? e.message : String(e)}`;
      }
    })();
    return opened;
  }

  /** Shows the slots of the model in view, keeping the slot and the text in the editor where they still apply. */
  function follow() {
    if (!editor) return;
    const slots = slotsOf(all, model());
    room.hidden = slots.length === 0;
    status.textContent = slots.length === 0 ? `The ${model()} model has no rule slots yet.` : '';
    if (slots.length === 0) {
      shown = null;
      return;
    }
    const keep = shown?.model === model() ? shown.slot.name : slots[0].name;
    clear(slotSelect);
    for (const s of slots) slotSelect.append(el('option', { value: s.name, text: `${s.title} (${s.name})` }));
    slotSelect.value = keep;
    const slot = slotNamed(keep) ?? slots[0];
    const scenario = starting(slot);
    // The user's unsaved edit stays, unless the scenario's own script for the slot changed (undo, a link).
    if (shown?.model !== model() || shown.slot.name !== slot.name || shown.scenario !== scenario) show(slot, scenario);
  }

  /** Shows `slot`'s documentation and puts `text` in the editor. */
  function show(slot: SlotInfo, text: string) {
    shown = { model: model(), slot, scenario: starting(slot) };
    byId('rules-slot-title').textContent = slot.title;
    byId('rules-slot-about').textContent = slot.about;
    const input = byId('rules-slot-input');
    clear(input);
    for (const f of slot.input) input.append(el('dt', {}, el('code', { text: f.name }), ` (${f.kind})`), el('dd', { text: f.about }));
    byId('rules-slot-output').textContent = slot.output;
    byId('rules-slot-random').textContent = slot.random
      ? "It may draw from the model's seeded generator: random() and random_int(n)."
      : 'It draws no random numbers: the same input gives the same answer.';
    if (editor && editor.text() !== text) editor.setText(text);
    else scheduleCheck();
  }

  function scheduleCheck() {
    if (timer !== null) clearTimeout(timer);
    timer = setTimeout(() => {
      timer = null;
      void check();
    }, CHECK_AFTER_MS);
  }

  /** Checks the editor's text in the worker's rules module and marks its problem; resolves to it. */
  async function check(): Promise<string | null> {
    if (!editor || !shown) return null;
    const asked = ++checking;
    const text = editor.text();
    let problem: string | null;
    try {
      problem = await rules.check(shown.model, shown.slot.name, text);
    } catch (e) {
      problem = e instanceof Error ? e.message : String(e);
    }
    if (asked !== checking || !editor) return problem;
    const placed = problem === null ? null : place(problem);
    editor.mark(placed);
    problemOut.textContent =
      placed === null
        ? ''
        : placed.line === null
          ? placed.message
          : `Line ${placed.line}${placed.column ? `, column ${placed.column}` : ''}: ${placed.message}`;
    runButton.disabled = compareButton.disabled = problem !== null;
    return problem;
  }

  /** Sets scenario paths through the session (undo and the link carry them); says what came of it. */
  async function edit(changes: Record<string, unknown>, done: string) {
    note.textContent = '';
    const problem = await session.edit(changes, { onProblem: (brief) => (problemOut.textContent = brief) });
    note.textContent = problem ? '' : done;
  }

  slotSelect.addEventListener('change', () => {
    const slot = slotNamed(slotSelect.value);
    if (slot) show(slot, starting(slot));
  });
  runButton.addEventListener('click', async () => {
    if (!editor || !shown || (await check()) !== null) return;
    const slot = shown.slot.name;
    await edit({ [`rules.${slot}`]: editor.text() }, `The run uses your ${slot} rule. Copy the link to share it.`);
  });
  compareButton.addEventListener('click', async () => {
    if (!editor || !shown || (await check()) !== null) return;
    const slot = shown.slot.name;
    const path = `rules.${slot}`;
    await edit(
      { [path]: editor.text(), compare: { path, value: null, ...COMPARE_LABELS } },
      "Your rule runs beside the paper's, in the Run tab; both move together.",
    );
  });
  resetButton.addEventListener('click', () => {
    if (!editor || !shown) return;
    editor.setText(shown.slot.paper);
    note.textContent = "The editor holds the paper's rule again; Run with this rule to use it.";
    editor.focus();
  });
  paperButton.addEventListener('click', async () => {
    if (!shown) return;
    const slot = shown.slot.name;
    // An opening of the scenario without the script (and without a comparison with it, which
    // would then compare the paper's rule with itself): undo brings the script back.
    const doc = withoutScript(session.doc(), slot);
    note.textContent = '';
    const ok = await session.open(JSON.stringify(doc), { onProblem: (brief) => (problemOut.textContent = brief) });
    if (ok) note.textContent = `The run uses the paper's ${slot} rule.`;
  });

  events.on('tab', (tab) => {
    if (tab === 'rules') void open();
  });
  session.on('loaded', follow);
}
