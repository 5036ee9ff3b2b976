// @vitest-environment happy-dom
// The click tools under an exercise's locks, on the real core (tests/unit/page.ts): every tool
// asks the scenario in view whether a click of it may be made; a refused one stays in the list,
// reachable and described by the exercise's reason, and its click on the lattice is refused with
// that reason without reaching the run; an allowance counts down as it is used.
import { describe, expect, it } from 'vitest';
import { FEATURES } from '../../web/features/index';
import { toolText } from '../../web/features/inspect/tools';
import { lesson, preset, testPage } from './page';

const $ = <T extends HTMLElement = HTMLElement>(selector: string) => {
  const e = document.querySelector<T>(selector);
  if (!e) throw new Error(`no ${selector}`);
  return e;
};
const tool = (name: string) => $<HTMLButtonElement>(`#tools button[data-tool="${name}"]`);
/** The reason a locked tool is described by. */
const described = (name: string) => {
  const id = tool(name).getAttribute('aria-describedby');
  return id ? (document.getElementById(id)?.textContent ?? '') : '';
};

/** amas-L as an exercise that lets students remove at most two modules and add nothing else. */
function twoRemovals() {
  const doc = JSON.parse(preset('amas-L'));
  doc.exercise = { title: 'Repair the L', goal: 'completed', disturbances: { remove: 2 } };
  return JSON.stringify(doc);
}

async function opened(text: string) {
  const t = testPage([...FEATURES]);
  await t.page.session.open(text, { record: false, opens: true });
  await t.until(() => t.page.session.frame !== null, 'the first frame');
  return t;
}

describe('click tools under an exercise', () => {
  it("a tool's text says it is locked, or what is left of its allowance", () => {
    expect(toolText('Remove module', undefined)).toBe('Remove module');
    expect(toolText('Remove module', { problem: null, left: null })).toBe('Remove module');
    expect(toolText('Remove module', { problem: null, left: 3 })).toBe('Remove module (3 left)');
    expect(toolText('Remove module', { problem: 'no', left: 0 })).toBe('Remove module (locked)');
  });

  it('every tool stays listed; the ones the exercise refuses are locked with its reason', async () => {
    const { until } = await opened(twoRemovals());
    await until(() => tool('remove').textContent === 'Remove module (5.4) (2 left)', 'the allowance');
    expect([...document.querySelectorAll('#tools button')].map((b) => (b as HTMLElement).dataset.tool)).toEqual([
      'inspect',
      'remove',
      'break',
      'dismantle',
      'extend',
    ]);
    expect(tool('remove').getAttribute('aria-disabled')).toBeNull();
    for (const name of ['break', 'dismantle', 'extend']) {
      expect(tool(name).getAttribute('aria-disabled')).toBe('true');
      expect(tool(name).classList.contains('locked')).toBe(true);
      expect(tool(name).textContent).toMatch(/\(locked\)$/);
      // Reachable from the keyboard: a button, never disabled.
      expect(tool(name).disabled).toBe(false);
    }
    expect(described('extend')).toBe("Add target cell is locked by the exercise: it allows no 'extend' disturbance");
    // Pressing a locked tool says why and leaves the tool in hand as it was.
    tool('break').click();
    expect($('#tool-problem').textContent).toBe("Break communication (5.5) is locked by the exercise: it allows no 'break' disturbance");
    expect(tool('break').getAttribute('aria-checked')).toBe('false');
    expect(tool('inspect').getAttribute('aria-checked')).toBe('true');
  });

  it('an allowance counts down, and the click past it is refused where it is made, never run', async () => {
    const doc = JSON.parse(preset('fracta-hexagon7'));
    doc.exercise = { title: 'Two faults', goal: 'completed', disturbances: { fault: 2 } };
    const { page, worker, until } = await opened(JSON.stringify(doc));
    await until(() => tool('fault').textContent === 'Fault (cut power) (2 left)', 'the allowance');
    tool('fault').click();
    const units = () => [...(worker.sim?.cells() ?? [])].flatMap((code, i) => (code ? [i] : []));
    const applied = () => worker.sent.filter((m) => m.startsWith('apply ')).length;

    page.events.emit('cell-click', { cell: units()[0], hit: null });
    await until(() => tool('fault').textContent === 'Fault (cut power) (1 left)', 'one fault counted');
    page.events.emit('cell-click', { cell: units()[1], hit: null });
    await until(() => tool('fault').getAttribute('aria-disabled') === 'true', 'the allowance used up');
    expect(tool('fault').textContent).toBe('Fault (cut power) (locked)');
    expect(described('fault')).toBe("Fault (cut power) is locked by the exercise: it allows 2 'fault' disturbances, and all 2 are used");
    expect((page.session.doc().disturbances as unknown[]).length).toBe(2);

    const said: string[] = [];
    page.events.on('say', (s) => said.push(s));
    page.events.emit('cell-click', { cell: units()[2], hit: null });
    await until(() => said.length > 0, 'the refusal');
    expect(said[0]).toBe(described('fault'));
    expect($('#inspector').hidden).toBe(false);
    expect($('#inspector').textContent).toBe(described('fault'));
    expect($('#tool-problem').textContent).toBe(described('fault'));
    expect(applied()).toBe(2);
    expect((page.session.doc().disturbances as unknown[]).length).toBe(2);
  });

  it("a lesson's locked tool says why and is not taken up; the scenario stays the teacher's", async () => {
    const { page, worker, until } = await opened(lesson('lesson-amas-heatmap'));
    await until(() => tool('dismantle').getAttribute('aria-disabled') === 'true', 'the lock');
    const before = page.session.scenario;
    tool('dismantle').click();
    expect($('#tool-problem').textContent).toMatch(/^Mark to be removed \(6\.2\) is locked by the exercise/);
    // The tool is not taken up: a click on the lattice inspects, and nothing reaches the run.
    page.events.emit('cell-click', { cell: worker.sim?.middle_occupied() ?? 0, hit: null });
    await until(() => $('#inspector').textContent !== '', 'the facts');
    expect($('#inspector').textContent).toMatch(/^cell/);
    expect(worker.sent.some((m) => m.startsWith('apply '))).toBe(false);
    expect(page.session.scenario).toBe(before);
  });

  it('without an exercise every tool is free and nothing is asked', async () => {
    const { worker } = await opened(preset('amas-L'));
    expect(tool('remove').textContent).toBe('Remove module (5.4)');
    expect(document.querySelector('#tools [aria-disabled]')).toBeNull();
    expect(worker.sent.some((m) => m.startsWith('clicks '))).toBe(false);
  });
});
