// The inspector: what a click on the lattice does (inspect a cell or apply the selected tool), the
// facts of the cell under the pointer or the keyboard cursor, and, in 3-D, where the unit under
// the pointer (else the selected one) could move.
import type { Facts } from '../../contract.gen';
import type { PageContext } from '../../page/context';
import { cellCoords } from '../../render/geometry';
import type { Hit } from '../../render/view';
import { byId, el, formatNumber } from '../../widgets/dom';
import { KeyCursor } from './cursor';
import { Probe, reachOf } from './probe';
import { STRUCTURE_FACTS } from './structure';
import type { Tools } from './tools';

export function setupInspector(page: PageContext, tools: Tools) {
  const { session, sim, view, events } = page;
  const inspector = byId('inspector');

  const coords = (cell: number): string => (session.layout ? cellCoords(session.layout, cell) : '');
  const cellText = (cell: number) => `cell ${coords(cell)}`;
  /** What is on a cell as the run stands, asked of the worker (which holds the lattice). */
  async function cellName(cell: number): Promise<string> {
    const code = await sim.code(cell);
    return session.layout?.cells.find((c) => c.code === code)?.name ?? (code ? `code ${code}` : 'empty');
  }
  const cellFacts = (cell: number, name: string) =>
    el('dl', {}, el('dt', { text: 'cell' }), el('dd', { text: `${cell} ${coords(cell)}` }), el('dt', { text: 'state' }), el('dd', { text: name }));
  /** The cell whose facts the panel shows (or is about to): answers for another arrive too late. */
  let shown = -1;

  async function click(cell: number, hit: Hit | null) {
    const layout = session.layout;
    if (!layout) return;
    if (cell < 0) {
      if (view.is3d && tools.tool === 'inspect') {
        clearSelection();
        showReach();
      }
      return;
    }
    const t = layout.tools.find((x) => x.name === tools.tool);
    if (t) {
      // In 3-D an added unit goes on the clicked face, in the empty cell in front of it.
      const target = t.action.kind === 'add' && hit && hit.front >= 0 ? hit.front : cell;
      const why = await tools.click(t.name, { ...t.action, ...tools.values(t.name), cells: [target] });
      // Refused by the exercise: the reason where the click was made, and said.
      if (why) {
        shown = -1;
        inspector.hidden = false;
        inspector.replaceChildren(el('p', { class: 'refused', text: why }));
        events.emit('say', why);
      }
      return;
    }
    const facts = await sim.inspect(cell);
    await showInspector(cell, facts);
  }

  function hover(cell: number) {
    shown = cell;
    if (cell < 0) {
      inspector.hidden = true;
    } else {
      void cellName(cell).then((name) => {
        if (shown !== cell) return;
        inspector.hidden = false;
        inspector.replaceChildren(cellFacts(cell, name));
      });
    }
    if (view.is3d) hoverProbe.request(cell);
  }

  // In 3-D the unit under the pointer (else the selected one) shows where it could move: the
  // worker is asked, throttled, and its answer drawn as highlighted cells with the difference at
  // each.
  let hoverReach: ReturnType<typeof reachOf> = null;
  let selectReach: ReturnType<typeof reachOf> = null;
  const hoverProbe = new Probe(
    (cell) => sim.inspect(cell),
    (cell, facts) => {
      if (cell !== view.marks.hover) return;
      hoverReach = reachOf(facts);
      if (facts && cell >= 0) void showHoverFacts(cell, facts);
      showReach();
    },
  );
  const selectProbe = new Probe(
    (cell) => sim.inspect(cell),
    (cell, facts) => {
      if (cell !== view.marks.selected) return;
      // The selected unit moved away: the selection ends with it.
      if (facts && facts.unit !== true) view.marks.selected = -1;
      selectReach = reachOf(facts);
      showReach();
    },
  );
  function showReach() {
    const reach = hoverReach ?? selectReach;
    view.marks.highlight = reach?.cells ?? [];
    view.marks.highlightValues = reach?.values ?? [];
    view.request();
  }
  async function showHoverFacts(cell: number, facts: Facts) {
    shown = cell;
    const dl = cellFacts(cell, await cellName(cell));
    if (shown !== cell) return;
    if (typeof facts.type_list === 'string') dl.append(el('dt', { text: 'type-list' }), el('dd', { text: facts.type_list }));
    if (typeof facts.difference === 'number') dl.append(el('dt', { text: 'difference' }), el('dd', { text: formatNumber(facts.difference) }));
    if (Array.isArray(facts.reachable))
      dl.append(
        el('dt', { text: 'reachable' }),
        el('dd', { text: facts.movable === false ? 'cannot move' : `${facts.reachable.length} position${facts.reachable.length === 1 ? '' : 's'}` }),
      );
    inspector.hidden = false;
    inspector.replaceChildren(dl);
  }
  function refreshProbes() {
    if (!view.is3d) return;
    if (view.marks.hover >= 0) hoverProbe.request(view.marks.hover);
    if ((view.marks.selected ?? -1) >= 0) selectProbe.request(view.marks.selected ?? -1);
  }
  function clearSelection() {
    view.marks.selected = -1;
    view.marks.highlight = [];
    view.marks.highlightValues = [];
    hoverReach = null;
    selectReach = null;
  }
  async function showInspector(cell: number, facts: Facts) {
    shown = cell;
    const dl = cellFacts(cell, await cellName(cell));
    if (shown !== cell) return;
    for (const [k, v] of Object.entries(facts)) {
      if (STRUCTURE_FACTS.includes(k)) continue;
      dl.append(el('dt', { text: k.replace(/_/g, ' ') }), el('dd', { text: typeof v === 'object' ? JSON.stringify(v) : formatNumber(v) }));
    }
    inspector.hidden = false;
    inspector.replaceChildren(dl);
    const reach = reachOf(facts);
    if (view.is3d) {
      view.marks.selected = facts.unit === true ? cell : -1;
      selectReach = reach;
      showReach();
      return;
    }
    const list = facts.reachable;
    view.marks.highlight = Array.isArray(list) ? (list.filter((x) => typeof x === 'number') as number[]) : [];
    view.request();
  }

  // The keyboard way to click: a cursor cell moved with the arrows.
  const keyCursor = new KeyCursor(byId('canvas-wrap'), {
    layout: () => session.layout,
    middle: () => sim.middle(),
    show(cell) {
      view.marks.cursor = cell >= 0 ? { cell, kind: 'cursor' } : null;
      view.request();
      byId('view').dataset.cursor = String(cell);
      if (cell >= 0) hover(cell);
    },
    click: (cell) => void click(cell, null),
    announce(cell) {
      if (cell < 0) {
        events.emit('say', 'Cursor hidden; the arrows step the run again.');
        return;
      }
      void cellName(cell).then((name) => events.emit('say', `Cursor at ${cellText(cell)}, ${name}. Enter: ${tools.label()}.`));
    },
  });

  session.on('loaded', ({ shapeChanged }) => {
    if (shapeChanged) keyCursor.hide();
    clearSelection();
  });
  session.on('frame', refreshProbes);
  events.on('cell-click', ({ cell, hit }) => void click(cell, hit));
  events.on('cell-hover', hover);
}
