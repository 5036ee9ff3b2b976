// Kumiki's page: the shell. It makes the page context (the session, the simulation worker, the
// view, the banner, the tabs and the page's events: web/page/context.ts), mounts the features of
// web/features/index.ts on it, and opens the first scenario (web/page/start.ts).
import { FEATURES } from './features/index';
import { embedEditRequested, embedRequested } from './page/address';
import type { PageContext, PageEvents } from './page/context';
import { Events } from './page/events';
import { LargeOpening } from './page/opening';
import { Session } from './page/session';
import { openDefault, start } from './page/start';
import { loadPrefs, savePrefs } from './page/store';
import { Tabs } from './page/tabs';
import { View } from './render/view';
import { SimClient } from './sim/client';
import { Banner } from './widgets/banner';
import { byId, download } from './widgets/dom';
import * as core from './wasm';

/** In a course page's iframe (?embed): the view, the run controls and the exercise panel only. */
const embedded = embedRequested();
if (embedded) document.body.dataset.embed = embedEditRequested() ? 'edit' : 'true';

const prefs = loadPrefs();
const persistPrefs = () => savePrefs(prefs);
const banner = new Banner();
const events = new Events<PageEvents>();
/** Frames received and drawn, read by the page benchmark. */
let framesDrawn = 0;

const view = new View(byId<HTMLCanvasElement>('view'), byId<HTMLCanvasElement>('annotations'), byId('canvas-wrap'), () => sim, {
  click: (cell, hit) => events.emit('cell-click', { cell, hit }),
  hover: (cell) => events.emit('cell-hover', cell),
  drawn: () => {
    document.body.dataset.frames = String(framesDrawn);
    sim.ack();
  },
});

const sim: SimClient = new SimClient({
  loaded(id, layout, text, comparison) {
    large.loaded();
    // A scenario opened or the run was reset: an earlier message no longer applies.
    if (!banner.keep) banner.dismiss();
    banner.keep = false;
    session.loaded(id, layout, text, comparison);
  },
  frame(frame, drawn) {
    document.body.dataset.ready = 'true';
    framesDrawn++;
    document.body.dataset.work = JSON.stringify(drawn.work);
    document.body.dataset.wasmBytes = String(core.wasmBytes());
    session.setFrame(frame, drawn);
  },
  playing: (on) => session.setPlaying(on),
  viewer: (kind) => view.started(kind),
  drew(work) {
    document.body.dataset.work = JSON.stringify(work);
  },
  scenario: (text, comparison) => session.recorded(text, comparison),
  error(message, context) {
    if (context === 'load' && large.active) {
      large.failed();
      session.failed();
      if (!session.scenario) openDefault(page);
    }
    if (context === 'apply') banner.report(`That did not work: ${message}`);
    else if (context === 'load') banner.report(`This scenario cannot run: ${message}`);
    else banner.report(message);
  },
  goal: (met, because, steps) => events.emit('goal', { met, because, steps }),
  stalled(ms) {
    // The opening notice says what the worker is busy with and offers its own way to stop.
    if (large.active && ms > 0) return;
    if (ms === 0) {
      if (banner.stallShown) {
        banner.dismiss();
        banner.keep = false;
      }
      banner.stallShown = false;
      return;
    }
    banner.stallShown = true;
    banner.keep = true;
    banner.report(`The simulation has not answered for ${Math.round(ms / 1000)} s. It may be busy with a large scenario; your last good scenario is kept.`, {
      label: 'Stop it and reload the last good scenario',
      run: () => sim.recover(),
    });
  },
  panic(message) {
    large.failed();
    session.failed();
    banner.keep = true;
    const model = session.layout ? String(session.doc().model ?? 'the model') : 'the model';
    const report = (link: string) =>
      [`Kumiki ${core.version()} hit an internal error in ${model}.`, message, `Scenario: ${link}`, `Browser: ${navigator.userAgent}`].join('\n');
    banner.report(`Kumiki hit an internal error in ${model}; your scenario is kept and was restarted from its start.\n${message}`, {
      label: 'Copy the report',
      run: () =>
        void session
          .link()
          .then((payload) => `${location.origin}${location.pathname}#${payload}`)
          .catch(() => session.scenario)
          .then((link) => navigator.clipboard?.writeText(report(link)).catch(() => download('kumiki-error-report.txt', report(link), 'text/plain'))),
    });
  },
});

const large = new LargeOpening(
  () => {
    session.failed();
    sim.recover();
    if (!session.scenario) openDefault(page);
  },
  () => {
    session.declined();
    if (!session.scenario) openDefault(page);
  },
);

const session = new Session(sim, {
  refused(brief, full) {
    const text = (message: string) => `This scenario cannot run: ${message}`;
    banner.report(text(brief), full && full !== brief ? { label: 'Show all of it', run: () => banner.report(text(full)) } : undefined);
  },
  large: (cells, build) => large.begin(cells, build),
});
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
