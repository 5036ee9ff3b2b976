// Kumiki's page: wires the simulation worker, the session, the lattice view and the panels
// (web/panels/) together, and opens the first scenario.
import { type LoadOptions, type Page, setupInspector, setupKeys, setupRunPanel, setupScenarioPanel, setupSharePanel, TABS } from './panels/index';
import { View } from './render/view';
import { Session } from './session';
import { SimClient } from './sim/client';
import { loadPrefs, noteOpening, openedScenario, openingScenario, savePrefs, saveScenario, savedScenario } from './store';
import { Announcer, type Disturbance } from './ui/announce';
import { Banner } from './ui/banner';
import { setupCompare } from './ui/compare';
import { byId, displayText, download } from './ui/dom';
import { Embed, embedEditRequested, embedRequested } from './ui/embed';
import { setupExperiments } from './ui/experiments';
import { setupGallery } from './ui/gallery';
import { setupGrade } from './ui/grade';
import { registerOffline } from './ui/offline';
import { LARGE_CELLS, LargeOpening } from './ui/opening';
import { setupRecordDialog } from './ui/record';
import { setupClaimLinks } from './ui/reproduction';
import { StructureViews } from './ui/structure';
import { setupWelcome } from './ui/welcome';
import type { Proposal } from './contract.gen';
import * as core from './wasm';

const DEFAULT_PRESET = 'amas-L';
/** The lesson the first screen's "Compare two runs" opens: two runs side by side. */
const COMPARE_LESSON = 'lesson-amas-compare';

/** In a course page's iframe (?embed): the view, the run controls and the exercise panel only. */
const embedded = embedRequested();
if (embedded) document.body.dataset.embed = embedEditRequested() ? 'edit' : 'true';
/** The postMessage API, in embed mode. */
let embed: Embed | null = null;

const prefs = loadPrefs();
const persistPrefs = () => savePrefs(prefs);
const session = new Session();
/** The scenario in view, held in the wasm between edits. */
const draft = new core.Draft(LARGE_CELLS);
const banner = new Banner();
/** Frames received and drawn, read by the page benchmark. */
let framesDrawn = 0;

// ---- the view and the worker ------------------------------------------------------------------

const view = new View(byId<HTMLCanvasElement>('view'), byId<HTMLCanvasElement>('annotations'), byId('canvas-wrap'), () => sim, {
  click: (cell, hit) => void inspector.click(cell, hit),
  hover: (cell) => inspector.hover(cell),
  drawn: () => {
    document.body.dataset.frames = String(framesDrawn);
    sim.ack();
  },
});
// The view follows the session before any panel does: the panels read its overlay range.
session.on('loaded', ({ layout, shapeChanged }) => {
  view.setLayout(layout);
  if (shapeChanged) view.fit();
});
session.on('frame', (frame) => view.setFrame(frame));

const sim = new SimClient({
  loaded(layout, json) {
    // The worker checked and wrote back a scenario the page did not check (a large one).
    if (json !== session.scenario) draft.ran(json);
    large.loaded(json);
    // A scenario opened or the run was reset: an earlier message no longer applies.
    if (!banner.keep) banner.dismiss();
    banner.keep = false;
    loadedOpening = opening !== null;
    session.loaded(layout, json);
    structure.loaded();
    const doc = session.doc() as { name?: string; disturbances?: Disturbance[] };
    announcer.loaded(displayText(doc.name ?? '', 100) || 'The scenario', doc.disturbances ?? []);
  },
  frame(frame) {
    if (opening !== null && loadedOpening) {
      // It opened and drew: now it may be restored after a reload.
      saveScenario(opening);
      openedScenario();
      opening = null;
    }
    document.body.dataset.ready = 'true';
    framesDrawn++;
    document.body.dataset.work = JSON.stringify(frame.work);
    document.body.dataset.wasmBytes = String(core.wasmBytes());
    session.setFrame(frame);
    announcer.frame(frame, run.playing, run.chartedMetric(), inspector.cellText);
    structure.frame(frame.steps);
    embed?.frame(frame);
  },
  playing: (on) => run.setPlaying(on),
  viewer: (kind) => view.started(kind),
  drew(work) {
    document.body.dataset.work = JSON.stringify(work);
  },
  scenario(json) {
    // A click recorded a disturbance (and, in the past, forked the run): undo brings back the
    // scenario before it.
    draft.ran(json);
    session.recorded(json);
    saveScenario(json);
    announcer.disturbed((session.doc().disturbances as Disturbance[] | undefined) ?? [], inspector.cellText);
  },
  error(message, context) {
    if (context === 'load' && large.active) {
      large.failed();
      if (!session.scenario) loadDefault();
    }
    if (context === 'apply') banner.report(`That did not work: ${message}`);
    else if (context === 'load') banner.report(`This scenario cannot run: ${message}`);
    else banner.report(message);
  },
  goal(met, because, steps) {
    const out = byId('exercise-result');
    out.textContent = met
      ? `Goal met at step ${steps.toLocaleString('en-US')}: ${because}.`
      : `Not met yet (step ${steps.toLocaleString('en-US')}): ${because}.`;
    out.classList.toggle('met', met);
    out.classList.toggle('unmet', !met);
    announcer.say(met ? `Goal met: ${because}.` : `Goal not met yet: ${because}.`);
    embed?.goal(met, because, steps);
  },
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
    banner.keep = true;
    const model = session.layout ? String(session.doc().model ?? 'the model') : 'the model';
    const bug = [
      `Kumiki ${core.version()} hit an internal error in ${model}.`,
      message,
      `Scenario: ${share.scenarioLink()}`,
      `Browser: ${navigator.userAgent}`,
    ].join('\n');
    banner.report(`Kumiki hit an internal error in ${model}; your scenario is kept and was restarted from its start.\n${message}`, {
      label: 'Copy the report',
      run: () => void navigator.clipboard?.writeText(bug).catch(() => download('kumiki-error-report.txt', bug, 'text/plain')),
    });
  },
});
const structure = new StructureViews(view, (cell) => sim.inspect(cell));

const large = new LargeOpening(
  () => {
    sim.recover();
    if (!session.scenario) loadDefault();
  },
  () => {
    share.leaveLink();
    if (!session.scenario) loadDefault();
  },
);

// ---- opening a scenario -----------------------------------------------------------------------

/** Opens the default preset, as a fresh start (not an edit, not in the undo history). */
function loadDefault(): boolean {
  return load(core.presetJson(DEFAULT_PRESET), { record: false, opens: true });
}

/** Loads a scenario text: checked first, so a bad one never replaces a good run. */
function load(json: string, { opens = false, ...options }: LoadOptions = {}): boolean {
  // An edit keeps the exercise in force and its locked fields at the teacher's values.
  return proceed(draft.open(json, !opens), options);
}

/**
 * Runs what an opening or an edit proposed, or says why it cannot run: the proposal's own problem
 * in brief, with the whole of it a click away when it says more.
 */
function proceed(proposal: Proposal, { record = true, quiet = false, onProblem }: LoadOptions = {}): boolean {
  if (proposal.problem) {
    if (onProblem) onProblem(proposal.problem);
    else if (!quiet) reportProblem(proposal.problem, proposal.in_full ?? '');
    return false;
  }
  const opened = (normal: string) => {
    if (record) session.remember(session.scenario, normal);
    share.leaveLink();
  };
  if (proposal.large_cells > 0) {
    large.begin(proposal.large_cells, opened, () => open(proposal.text));
    return true;
  }
  opened(proposal.text);
  session.scenario = proposal.text;
  open(proposal.text);
  return true;
}

/** Says why a scenario cannot run, briefly; when the whole message says more, the rest is a click away. */
function reportProblem(brief: string, full: string) {
  const text = (message: string) => `This scenario cannot run: ${message}`;
  banner.report(text(brief), full && full !== brief ? { label: 'Show all of it', run: () => banner.report(text(full)) } : undefined);
}

/** The scenario being opened; saved for reloads only once it has drawn a frame. */
let opening: string | null = null;
/** The worker has loaded the scenario being opened; its next frame is the new run's. */
let loadedOpening = false;
function open(json: string) {
  opening = json;
  loadedOpening = false;
  noteOpening(json);
  sim.load(json);
}

// ---- the panels -------------------------------------------------------------------------------

const page: Page = {
  session,
  sim,
  view,
  banner,
  prefs,
  persistPrefs,
  draft,
  load,
  applyChange(key, valueJson, onError) {
    let problem: string | null = null;
    proceed(draft.edit(key, valueJson), { onProblem: (message) => (problem = message) });
    if (problem) onError?.(problem);
    return problem;
  },
  applyChanges(changes) {
    let problem: string | null = null;
    proceed(draft.editAll(changes), { onProblem: (message) => (problem = message) });
    return problem;
  },
};
const announcer = new Announcer(byId('run-live'));
const run = setupRunPanel(page);
const inspector = setupInspector(page, run, announcer);
const scenario = setupScenarioPanel(
  page,
  (name) => keys.selectTab(name),
  (link, name) => embed?.handin(link, name),
);
const keys = setupKeys(page, run, scenario);
setupCompare(page, run);
const share = setupSharePanel(page, { large, open, embedded });

// ---- diagnostics ------------------------------------------------------------------------------

const rendererChoice = byId<HTMLSelectElement>('renderer-choice');
rendererChoice.value = prefs.renderer;
async function useRenderer() {
  try {
    await view.useRenderer(prefs.renderer);
  } catch (e) {
    banner.report(core.message(e));
  }
  byId('diag-renderer').textContent = view.rendererKind === 'webgl2' ? '(using WebGL2)' : '(using Canvas 2D)';
  document.body.dataset.renderer = view.rendererKind ?? '';
}
rendererChoice.addEventListener('change', () => {
  prefs.renderer = rendererChoice.value as typeof prefs.renderer;
  persistPrefs();
  void useRenderer();
});
// A debug control, shown only with `?debug` in the address (README, "Using the page").
byId('simulate-crash').hidden = !new URLSearchParams(location.search).has('debug');
byId('simulate-crash').addEventListener('click', () => sim.crash());

// ---- start ------------------------------------------------------------------------------------

async function start() {
  registerOffline((reload) => {
    banner.keep = true;
    banner.report('A new version of Kumiki is ready.', { label: 'Reload', run: reload });
  });
  await core.loadCore();
  // The worker reports its renderer when its view is ready; the first scenario need not wait.
  void useRenderer();
  byId('diag-version').textContent = core.version();
  const openGallery = setupGallery(
    core.presets(),
    core.lessons(),
    (name) => load(core.presetJson(name), { opens: true }),
    // A lesson opens on the run tab, where its exercise panel is.
    (name) => load(core.lessonJson(name), { opens: true }) && keys.selectTab('run'),
  );
  const welcome = setupWelcome({
    watch: () => openGallery('scenarios'),
    lesson: () => openGallery('lessons'),
    build: () => keys.selectTab('scenario', true),
    compare: () => load(core.lessonJson(COMPARE_LESSON), { opens: true }) && keys.selectTab('run'),
  });
  setupExperiments(
    prefs,
    persistPrefs,
    (text) => banner.report(text),
    () => keys.selectTab('experiments'),
  );
  setupGrade();
  setupRecordDialog({
    describe: () => {
      const doc = session.doc() as { name?: string; seed?: number };
      return { name: String(doc.name || 'scenario'), seed: Number(doc.seed ?? 0) };
    },
    legend: () => {
      const layout = session.layout;
      if (!layout) return [];
      return [
        ...layout.cells.map((c) => ({ name: c.name, color: c.color, round: false })),
        ...layout.agents.map((a) => ({ name: a.name, color: a.color, round: true })),
      ];
    },
    setScale: (scale) => view.setCaptureScale(scale),
    record: (settings, signal, progress) => sim.record(settings, signal, progress),
  });
  keys.selectTab(!embedded && TABS.includes(prefs.tab) ? prefs.tab : 'run');
  if (!embedded) setupClaimLinks(() => keys.selectTab('about'));
  if (embedded) {
    embed = new Embed(
      {
        load: (payload) => {
          try {
            let problem: string | null = null;
            load(core.unpackLink(payload).scenario, {
              opens: true,
              onProblem: (message) => {
                problem = message;
              },
            });
            return problem;
          } catch (e) {
            return core.message(e);
          }
        },
        play: () => sim.play(),
        pause: () => sim.pause(),
        step: (count) => sim.step(count),
        reset: run.reset,
        check: () => sim.check(),
      },
      core.version(),
    );
    // An embedded page shows its link or the default scenario, never what this browser last edited.
    if (!share.openHash()) loadDefault();
    return;
  }
  const unfinished = openingScenario();
  if (unfinished !== null) {
    // The page was closed or stopped while a scenario was opening: it may be what stopped it.
    openedScenario();
    loadDefault();
    share.leaveLink();
    banner.keep = true;
    banner.report('The last scenario did not finish opening before the page closed, so the default one is shown. It may be too large for this device.', {
      label: 'Open it anyway',
      run: () => load(unfinished, { opens: true }),
    });
    return;
  }
  // A first visit opens on what Kumiki is and where to start; a shared link has its own introduction.
  // Shown once, it is seen: a reload does not bring it back ("Start here" does).
  if (!prefs.welcomed && !location.hash.slice(1)) {
    welcome.show();
    prefs.welcomed = true;
    persistPrefs();
  }
  if (share.openHash()) return;
  // A link that could not be opened is explained in the banner; the scenario shown instead keeps it.
  banner.keep = banner.shown;
  const saved = savedScenario();
  if (!(saved && load(saved, { record: false, quiet: true, opens: true }))) loadDefault();
}

start().catch((e: unknown) => banner.report(`Kumiki could not start: ${core.message(e)}`));
