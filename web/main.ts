// Kumiki's page: the shell. It makes the page context (the session, the simulation worker, the
// view, the banner, the tabs and the page's events: web/page/context.ts), mounts the features of
// web/features/index.ts on it, and opens the first scenario (web/page/start.ts).
import { FEATURES } from './features/index';
import { embedEditRequested, embedRequested } from './page/address';
import { EarlyInput } from './page/early';
import type { PageContext, PageEvents } from './page/context';
import { Events } from './page/events';
import { LargeOpening } from './page/opening';
import { Session } from './page/session';
import { sessionHost, workerEvents } from './page/shell';
import { openDefault, start } from './page/start';
import { loadPrefs, savePrefs } from './page/store';
import { Tabs } from './page/tabs';
import { View } from './render/view';
import { SimClient } from './sim/client';
import { Banner } from './widgets/banner';
import { byId } from './widgets/dom';
import * as core from './wasm';

// First of all: a Play pressed from now on, while the wasm module arrives, is kept (web/page/early.ts).
const early = new EarlyInput();

/** In a course page's iframe (?embed): the view, the run controls and the exercise panel only. */
const embedded = embedRequested();
if (embedded) document.body.dataset.embed = embedEditRequested() ? 'edit' : 'true';

const prefs = loadPrefs();
const persistPrefs = () => savePrefs(prefs);
const banner = new Banner();
const events = new Events<PageEvents>();

const view = new View(byId<HTMLCanvasElement>('view'), byId<HTMLCanvasElement>('annotations'), byId('canvas-wrap'), () => sim, {
  click: (cell, hit) => events.emit('cell-click', { cell, hit }),
  hover: (cell) => events.emit('cell-hover', cell),
  drawn: () => sim.ack(),
});

const large = new LargeOpening(
  () => {
    session.failed();
    sim.recover();
    if (!session.scenario) void openDefault(page);
  },
  () => {
    session.declined();
    if (!session.scenario) void openDefault(page);
  },
);
const sim: SimClient = new SimClient(workerEvents(() => page, large));
const session = new Session(sim, sessionHost(banner, large));
// The view follows the session before any feature does: they read its overlay range.
session.on('loaded', ({ layout, shapeChanged }) => {
  view.setLayout(layout);
  if (shapeChanged) view.fit();
});
session.on('frame', () => view.setFrame(session.drawn));

const page: PageContext = {
  session,
  sim,
  view,
  banner,
  prefs,
  persistPrefs,
  tabs: new Tabs(prefs, persistPrefs, events),
  events,
  embedded,
  early,
  async useRenderer(choice) {
    try {
      await view.useRenderer(choice);
    } catch (e) {
      banner.report(core.message(e));
    }
    document.body.dataset.renderer = view.rendererKind ?? '';
    events.emit('renderer', view.rendererKind);
  },
};

for (const feature of FEATURES) if (feature.tab) page.tabs.add(feature.name, feature.tab);

start(page, FEATURES).catch((e: unknown) => banner.report(`Kumiki could not start: ${core.message(e)}`));
