// Inspecting and disturbing the run: what a click on the lattice does (the click tools), the
// facts of the cell under the pointer or the keyboard cursor, in 3-D where a unit could move, and
// the last step in detail (signals slot by slot, the deflected shape) for models that describe it.
import type { Feature } from '../../page/context';
import { setupInspector } from './inspector';
import { StructureViews } from './structure';
import structureHtml from './structure.html?raw';
import { setupTools } from './tools';

/** Where the last step's detail goes in the Run tab, among other features' sections. */
const STRUCTURE_ORDER = 50;

export const inspect: Feature = {
  name: 'inspect',
  mount(page) {
    const { session, sim, view, tabs } = page;
    const tools = setupTools(page);
    setupInspector(page, tools);
    tabs.section('run', structureHtml, STRUCTURE_ORDER);
    const structure = new StructureViews(view, (cell) => sim.inspect(cell));
    session.on('loaded', () => structure.loaded());
    session.on('frame', (frame) => structure.frame(frame.steps));
  },
};
