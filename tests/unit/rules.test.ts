// @vitest-environment happy-dom
// The Rules tab without a browser: the room mounted with every feature on the real page context,
// its editor the real CodeMirror, the worker's answers from the real rules module
// (tests/unit/page.ts). What a person does end to end (typing, the link, `kumiki run`, a hostile
// script) is the browser test's (tests/e2e/rules.test.mjs).
import { EditorView } from '@codemirror/view';
import { describe, expect, it } from 'vitest';
import { FEATURES } from '../../web/features/index';
import { place, scriptIn, slotsOf, span, withoutScript } from '../../web/features/rules/problems';
import { carriesRules, editsRules } from '../../web/sim/rules';
import { preset, startRules, testPage } from './page';

const $ = <T extends HTMLElement = HTMLElement>(selector: string) => {
  const e = document.querySelector<T>(selector);
  if (!e) throw new Error(`no ${selector}`);
  return e;
};
const text = (selector: string) => $(selector).textContent ?? '';

describe('where a problem is marked', () => {
  it("reads the rules module's place off the reason", () => {
    expect(place('line 3, column 5: expecting an expression')).toEqual({ line: 3, column: 5, message: 'expecting an expression' });
    expect(place('line 2: a statement outside a function')).toEqual({ line: 2, column: null, message: 'a statement outside a function' });
    expect(place('16385 bytes is too long')).toEqual({ line: null, column: null, message: '16385 bytes is too long' });
  });

  it('marks from the column to the end of the line, and never nothing', () => {
    const source = 'fn leader(robot) {\n  let x = ;\n}';
    const at = span(source, { line: 2, column: 11, message: '' });
    expect(source.slice(at.from, at.to)).toBe(';');
    expect(source.slice(...Object.values(span(source, { line: 2, column: null, message: '' })))).toBe('  let x = ;');
    // Past the end of a line, or of the text: its last character.
    const end = span(source, { line: 3, column: 9, message: '' });
    expect(source.slice(end.from, end.to)).toBe('}');
    expect(span(source, { line: 99, column: 1, message: '' })).toEqual({ from: source.length - 1, to: source.length });
    // No place: the first line.
    expect(span(source, { line: null, column: null, message: '' })).toEqual({ from: 0, to: 18 });
    expect(span('', { line: 1, column: 1, message: '' })).toEqual({ from: 0, to: 0 });
  });
});

describe("the scenario's scripts", () => {
  it('finds a slot, its script, and the scenario without it', () => {
    const all = startRules().rule_slots() as { model: string; slot: { name: string } }[];
    expect(slotsOf(all as never, 'chobie').map((s) => s.name)).toContain('leader');
    expect(slotsOf(all as never, 'no-such-model')).toEqual([]);
    const doc = { model: 'chobie', rules: { leader: 'fn leader(r) { () }' }, compare: { path: 'rules.leader', value: null } };
    expect(scriptIn(doc, 'leader')).toBe('fn leader(r) { () }');
    expect(scriptIn({ model: 'chobie' }, 'leader')).toBeNull();
    expect(withoutScript(doc, 'leader')).toEqual({ model: 'chobie' });
    const other = { model: 'm', rules: { a: 'x', b: 'y' }, compare: { path: 'seed', value: 2 } };
    expect(withoutScript(other, 'a')).toEqual({ model: 'm', rules: { b: 'y' }, compare: { path: 'seed', value: 2 } });
  });

  it("the worker fetches its rules module only for a script, never for the paper's rule", () => {
    expect(carriesRules(preset('chobie-form-a'))).toBe(false);
    expect(carriesRules('{"model": "chobie", "rules": {"leader": "fn leader(r) { () }"}}')).toBe(true);
    expect(carriesRules('{"model": "chobie", "rules": {"leader": null}}')).toBe(false);
    expect(carriesRules('{"model": "chobie", "name": "\\"rules\\": in a name"}')).toBe(false);
    expect(carriesRules('{"rules": ')).toBe(false);
    expect(editsRules('{"rules.leader": "fn leader(r) { () }"}')).toBe(true);
    expect(editsRules('{"rules.leader": null}')).toBe(false);
    expect(editsRules('{"rules": {"leader": "x"}}')).toBe(true);
    expect(editsRules('{"compare": {"path": "rules.leader", "value": null}}')).toBe(false);
    expect(editsRules('{"robots": 3}')).toBe(false);
  });
});

/** The editor of the test before: destroyed, so that it no longer listens to the document the next test uses. */
let previous: EditorView | null = null;

/** The page with every feature and the rules module behind its worker, on a CHOBIE II scenario, with the Rules tab open. */
async function rulesOpen() {
  previous?.destroy();
  history.replaceState(null, '', window.location.pathname);
  // The comparison's second run is a worker of its own, which the DOM library cannot start: the
  // comparison is checked here by the scenario the session holds, its two runs in the browser.
  const t = testPage(
    FEATURES.filter((f) => f.name !== 'compare'),
    { rules: true },
  );
  await t.page.session.open(preset('chobie-form-a'), { record: false, opens: true });
  await t.until(() => t.page.session.frame !== null, 'the first frame');
  $('#tab-rules').click();
  await t.until(() => !$('#rules-room').hidden, 'the rule editor');
  // The editor lives in the host's shadow root (its styles are constructed, as the page's CSP asks).
  const dom = $('#rules-editor').shadowRoot?.querySelector<HTMLElement>('.cm-editor');
  const editor = dom ? EditorView.findFromDOM(dom) : null;
  if (!editor) throw new Error('no editor');
  previous = editor;
  return { ...t, editor };
}

/** Replaces the editor's text as typing would (a user event), and waits for the check. */
async function type(t: Awaited<ReturnType<typeof rulesOpen>>, source: string) {
  const checks = t.worker.sent.filter((m) => m.startsWith('check-rule')).length;
  t.editor.dispatch({ changes: { from: 0, to: t.editor.state.doc.length, insert: source }, userEvent: 'input.type' });
  await t.until(() => t.worker.sent.filter((m) => m.startsWith('check-rule')).length > checks, 'the check');
  await new Promise((r) => setTimeout(r, 10));
}

describe('the Rules tab', () => {
  it("shows the model's slot documented beside the paper's rule", async () => {
    const t = await rulesOpen();
    const paper = (startRules().rule_slots() as { model: string; slot: { name: string; paper: string } }[]).find((s) => s.model === 'chobie')?.slot;
    expect($<HTMLSelectElement>('#rules-slot').value).toBe('leader');
    expect(t.editor.state.doc.toString()).toBe(paper?.paper);
    expect(text('#rules-slot-input')).toContain('first');
    expect(text('#rules-slot-input')).toContain('second');
    expect(text('#rules-slot-output')).toMatch(/top_right/);
    // The editor is named as its visible label says.
    expect(t.editor.contentDOM.getAttribute('aria-label')).toBe(text('#rules-editor-label'));
    expect(text('#rules-keys')).toMatch(/Escape, then Tab/);
  });

  it('marks a syntax error at its line as you type, and clears it once fixed', async () => {
    const t = await rulesOpen();
    await type(t, 'fn leader(robot) {\n  let x = ;\n  ()\n}');
    await t.until(() => text('#rules-problem') !== '', 'the problem');
    expect(text('#rules-problem')).toMatch(/^Line 2, column \d+: /);
    expect($<HTMLButtonElement>('#rules-run').disabled).toBe(true);
    // The diagnostic sits on line 2.
    const { forEachDiagnostic } = await import('@codemirror/lint');
    const lines: number[] = [];
    forEachDiagnostic(t.editor.state, (d) => lines.push(t.editor.state.doc.lineAt(d.from).number));
    expect(lines).toEqual([2]);
    await type(t, 'fn leader(robot) {\n  ()\n}');
    await t.until(() => text('#rules-problem') === '', 'the problem cleared');
    const after: number[] = [];
    forEachDiagnostic(t.editor.state, (d) => after.push(d.from));
    expect(after).toEqual([]);
    expect($<HTMLButtonElement>('#rules-run').disabled).toBe(false);
  });

  it('runs the rule through the session: the scenario carries it, and undo takes it back', async () => {
    const t = await rulesOpen();
    const before = t.page.session.scenario;
    const hashBefore = t.page.session.frame?.hash;
    const mine = 'fn leader(robot) {\n  ()\n}';
    await type(t, mine);
    $('#rules-run').click();
    await t.until(() => t.page.session.scenario !== before, 'the run with the rule');
    expect((t.page.session.doc().rules as Record<string, string>).leader).toBe(mine);
    expect(t.worker.sent.at(-1)).toBe(`edit ${JSON.stringify({ 'rules.leader': mine })}`);
    expect(text('#rules-note')).toMatch(/uses your leader rule/);
    expect(t.page.session.frame?.hash).toBeDefined();
    expect(hashBefore).toBeDefined();
    // Undo brings back the scenario without it, and the editor follows the scenario.
    expect(t.page.session.canUndo).toBe(true);
    const previous = t.page.session.undo();
    expect(previous).toBe(before);
    await t.page.session.open(previous ?? '', { record: false, opens: true });
    await t.until(() => t.page.session.scenario === before, 'the undo');
    expect(t.editor.state.doc.toString()).not.toBe(mine);
  });

  it("compares the paper's rule with mine through the scenario's comparison", async () => {
    const t = await rulesOpen();
    await type(t, 'fn leader(robot) {\n  ()\n}');
    $('#rules-compare').click();
    await t.until(() => t.page.session.comparison.kind === 'pair', 'the comparison');
    const doc = t.page.session.doc();
    expect(doc.compare).toEqual({ path: 'rules.leader', value: null, label: "the paper's rule", base_label: 'my rule' });
    const pair = t.page.session.comparison as { labels: string[]; second: string };
    expect(pair.labels).toEqual(['my rule', "the paper's rule"]);
    // The second run is the paper's: its worker never fetches the rules module.
    expect(JSON.parse(pair.second).rules).toEqual({ leader: null });
    expect(carriesRules(pair.second)).toBe(false);
    // The paper's rule again: the script and its comparison go, in one opening.
    $('#rules-paper').click();
    await t.until(() => t.page.session.doc().rules === undefined, "the paper's rule");
    expect(t.page.session.doc().compare).toBeUndefined();
    expect(t.page.session.comparison.kind).toBe('none');
  });

  it("resets the editor to the paper's rule without running it", async () => {
    const t = await rulesOpen();
    const paper = t.editor.state.doc.toString();
    await type(t, 'fn leader(robot) { () }');
    const scenario = t.page.session.scenario;
    $('#rules-reset').click();
    expect(t.editor.state.doc.toString()).toBe(paper);
    expect(t.page.session.scenario).toBe(scenario);
    expect(text('#rules-note')).toMatch(/paper's rule again/);
  });

  it('says so for a model without slots', async () => {
    const t = await rulesOpen();
    await t.page.session.open(preset('amas-L'), { opens: true });
    await t.until(() => t.page.session.doc().model === 'amas', 'the AMAS scenario');
    const amas = slotsOf(startRules().rule_slots() as never, 'amas');
    if (amas.length === 0) {
      expect($('#rules-room').hidden).toBe(true);
      expect(text('#rules-status')).toBe('The amas model has no rule slots yet.');
    } else expect($<HTMLSelectElement>('#rules-slot').value).toBe(amas[0].name);
  });
});
