// Kumiki's page: wires the simulation worker, the lattice view and the panels together.
import { modelEditors, type MountedEditor } from './models/index';
import { renderReproduction } from './ui/reproduction';
import type { Hit } from './render/camera';
import { cellCoords, sameLattice } from './render/geometry';
import { View } from './render/view';
import { SimClient } from './sim/client';
import { History, loadPrefs, noteOpening, openedScenario, openingScenario, savePrefs, saveScenario, savedScenario } from './store';
import type { Frame, Layout, Metrics } from './types';
import { Announcer, type Disturbance } from './ui/announce';
import { MetricChart } from './ui/chart';
import { KeyCursor } from './ui/cursor';
import { byId, clear, displayText, download, el, formatNumber, typingIn } from './ui/dom';
import { setupExperiments } from './ui/experiments';
import { setupGallery } from './ui/gallery';
import { renderMarkdown } from './ui/markdown';
import { Embed, embedRequested } from './ui/embed';
import { registerOffline } from './ui/offline';
import { change, LargeOpening } from './ui/opening';
import { renderParams } from './ui/params';
import { setupRecordDialog } from './ui/record';
import { Probe, reachOf, type Facts } from './ui/probe';
import { STRUCTURE_FACTS, StructureViews } from './ui/structure';
import type { Exercise } from './scenario.gen';
import * as core from './wasm';

const SPEEDS = [1, 3, 10, 30, 100, 300, 1000, 10000, Infinity];
const DEFAULT_PRESET = 'amas-L';

/** In a course page's iframe (?embed): the view, the run controls and the exercise panel only. */
const embedded = embedRequested();
if (embedded) document.body.dataset.embed = 'true';
/** The postMessage API, in embed mode. */
let embed: Embed | null = null;

const prefs = loadPrefs();
const persistPrefs = () => savePrefs(prefs);
const history = new History();

/** The scenario the run was started from (canonical JSON); clicked disturbances are added to it. */
let scenario = '';
let layout: Layout | null = null;
let lastFrame: Frame | null = null;
let playing = false;
let tool = 'inspect';
let editor: MountedEditor | null = null;
let editorModel = '';
/** Frames received and drawn, read by the page benchmark. */
let framesDrawn = 0;

// ---- messages ---------------------------------------------------------------------------------

const banner = byId('banner');
const bannerText = byId('banner-text');
const linkNotice = byId('link-notice');
const bannerAction = byId<HTMLButtonElement>('banner-action');
/** Shows a message, with one button that offers a way out when `action` is given. */
function report(text: string, action?: { label: string; run: () => void }) {
  bannerText.textContent = text;
  bannerAction.hidden = !action;
  if (action) bannerAction.textContent = action.label;
  bannerAction.onclick = action
    ? () => {
        dismiss();
        action.run();
      }
    : null;
  banner.hidden = false;
}
function dismiss() {
  banner.hidden = true;
}
/** Set while the banner explains the load that follows (a restart, a link that could not be
 * opened), so that load does not clear it. */
let keepBanner = false;
/** The banner is showing the watchdog's message. */
let stallShown = false;
byId('banner-close').addEventListener('click', dismiss);

// ---- simulation -------------------------------------------------------------------------------

/** Called once with the next frame from the worker that the view draws (the recorder waits on them). */
const drawnWaiters: ((frame: Frame) => void)[] = [];

const view = new View(byId<HTMLCanvasElement>('view'), byId<HTMLCanvasElement>('annotations'), byId('canvas-wrap'), {
  click: (cell, hit) => void clickCell(cell, hit),
  hover: (cell) => showHover(cell),
  drawn: () => {
    document.body.dataset.frames = String(framesDrawn);
    sim.ack();
    if (lastFrame) for (const waiter of drawnWaiters.splice(0)) waiter(lastFrame);
  },
});

/** Steps the run and resolves once the frame `count` steps on (or the run's last) has been drawn. */
function stepAndDraw(count: number): Promise<{ steps: number; finished: boolean }> {
  const target = (lastFrame?.steps ?? 0) + count;
  return new Promise((resolve) => {
    const wait = (frame: Frame) => (frame.steps >= target || frame.finished ? resolve({ steps: frame.steps, finished: frame.finished }) : drawnWaiters.push(wait));
    drawnWaiters.push(wait);
    sim.step(count);
  });
}

const sim = new SimClient({
  loaded(newLayout, json) {
    large.loaded(json);
    // A scenario opened or the run was reset: an earlier message no longer applies.
    if (!keepBanner) dismiss();
    keepBanner = false;
    loadedOpening = opening !== null;
    const shapeChanged = !sameLattice(layout, newLayout);
    layout = newLayout;
    scenario = json;
    view.setLayout(newLayout);
    if (shapeChanged) {
      view.fit();
      keyCursor.hide();
    }
    clearSelection();
    renderRunPanel();
    renderScenarioPanel();
    chartMetric(prefs.chartMetric);
    structure.loaded();
    const doc = JSON.parse(json) as { name?: string; disturbances?: Disturbance[] };
    announcer.loaded(displayText(doc.name ?? '', 100) || 'The scenario', doc.disturbances ?? []);
  },
  frame(frame) {
    if (opening !== null && loadedOpening) {
      // It opened and drew: now it may be restored after a reload.
      saveScenario(opening);
      openedScenario();
      opening = null;
    }
    lastFrame = frame;
    document.body.dataset.ready = 'true';
    framesDrawn++;
    view.setFrame(frame);
    showFrame(frame);
    announcer.frame(frame, playing, chartSelect.value, cellText);
    refreshProbes();
    structure.frame(frame.steps);
    embed?.frame(frame);
  },
  playing(on) {
    playing = on;
    const button = byId('play');
    button.textContent = on ? 'Pause' : 'Play';
    button.setAttribute('aria-label', on ? 'Pause (Space)' : 'Play (Space)');
    button.setAttribute('aria-pressed', String(on));
  },
  scenario(json) {
    // A click recorded a disturbance (and, in the past, forked the run): undo brings back the
    // scenario before it.
    if (scenario && json !== scenario) history.push(scenario);
    scenario = json;
    updateUndo();
    saveScenario(json);
    announcer.disturbed((JSON.parse(json) as { disturbances?: Disturbance[] }).disturbances ?? [], cellText);
    renderDisturbanceNote();
    syncJsonEditor();
  },
  error(message, context) {
    if (context === 'load' && large.active) {
      large.failed();
      if (!scenario) load(core.presetJson(DEFAULT_PRESET), { record: false });
    }
    if (context === 'apply') report(`That did not work: ${message}`);
    else if (context === 'load') report(`This scenario cannot run: ${message}`);
    else report(message);
  },
  goal(met, because, steps) {
    const out = byId('exercise-result');
    out.textContent = met ? `Goal met at step ${steps.toLocaleString('en-US')}: ${because}.` : `Not met yet (step ${steps.toLocaleString('en-US')}): ${because}.`;
    out.classList.toggle('met', met);
    out.classList.toggle('unmet', !met);
    announcer.say(met ? `Goal met: ${because}.` : `Goal not met yet: ${because}.`);
    embed?.goal(met, because, steps);
  },
  stalled(ms) {
    // The opening notice says what the worker is busy with and offers its own way to stop.
    if (large.active && ms > 0) return;
    if (ms === 0) {
      if (stallShown) {
        dismiss();
        keepBanner = false;
      }
      stallShown = false;
      return;
    }
    stallShown = true;
    keepBanner = true;
    report(`The simulation has not answered for ${Math.round(ms / 1000)} s. It may be busy with a large scenario; your last good scenario is kept.`, {
      label: 'Stop it and reload the last good scenario',
      run: () => sim.recover(),
    });
  },
  panic(message) {
    large.failed();
    keepBanner = true;
    const model = layout ? String((JSON.parse(scenario) as { model?: string }).model ?? 'the model') : 'the model';
    const bug = [
      `Kumiki ${core.version()} hit an internal error in ${model}.`,
      message,
      `Scenario: ${scenarioLink()}`,
      `Browser: ${navigator.userAgent}`,
    ].join('\n');
    report(`Kumiki hit an internal error in ${model}; your scenario is kept and was restarted from its start.\n${message}`, {
      label: 'Copy the report',
      run: () => void navigator.clipboard?.writeText(bug).catch(() => download('kumiki-error-report.txt', bug, 'text/plain')),
    });
  },
});
const structure = new StructureViews(view, (cell) => sim.inspect(cell));

const large = new LargeOpening(() => {
  sim.recover();
  if (!scenario) load(core.presetJson(DEFAULT_PRESET), { record: false });
});

/** A link to the scenario in view, or its JSON when it cannot be encoded. */
function scenarioLink(): string {
  try {
    return `${location.origin}${location.pathname}#${core.encodeLink(scenario)}`;
  } catch {
    return scenario;
  }
}

/** Loads a scenario text: validated first, so a bad one never replaces a good run. */
function load(json: string, { record = true, quiet = false } = {}): boolean {
  const opened = (normal: string) => {
    if (record && scenario && normal !== scenario) history.push(scenario);
    if (location.hash) history_replace('');
    linkNotice.hidden = true;
    updateUndo();
  };
  if (large.begin(json, opened)) {
    open(json);
    return true;
  }
  let normal: string;
  try {
    normal = core.normalize(json);
  } catch (e) {
    if (!quiet) report(`This scenario cannot run: ${core.message(e)}`);
    return false;
  }
  if (record && scenario && normal !== scenario) history.push(scenario);
  scenario = normal;
  open(normal);
  if (location.hash) history_replace('');
  linkNotice.hidden = true;
  updateUndo();
  return true;
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

/** Whoever opens a shared link sees its name and description first. */
function introduce(json: string) {
  // An embedding course page introduces the scenario itself.
  if (embedded) return;
  const doc = JSON.parse(json) as { name?: string; description?: string; model?: string };
  byId('intro-title').textContent = displayText(doc.name ?? '', 100) || 'A shared scenario';
  byId('intro-model').textContent = String(doc.model ?? '');
  byId('intro-description').textContent = displayText(doc.description ?? '', 4000, true) || 'It comes with no description.';
  const dialog = byId<HTMLDialogElement>('intro');
  if (!dialog.open) dialog.showModal();
}

function history_replace(hash: string) {
  const url = `${location.pathname}${location.search}${hash ? `#${hash}` : ''}`;
  window.history.replaceState(null, '', url);
}

// ---- transport --------------------------------------------------------------------------------

const speed = byId<HTMLInputElement>('speed');
const speedOut = byId('speed-out');
function applySpeed() {
  const i = Math.max(0, Math.min(SPEEDS.length - 1, Number(speed.value)));
  const v = SPEEDS[i];
  const text = Number.isFinite(v) ? `${v.toLocaleString('en-US')}/s` : 'max';
  speedOut.textContent = text;
  speed.setAttribute('aria-valuetext', Number.isFinite(v) ? `${v} steps per second` : 'as fast as possible');
  sim.setSpeed(v);
  prefs.speedIndex = i;
  persistPrefs();
}
speed.value = String(prefs.speedIndex);
speed.addEventListener('input', applySpeed);
applySpeed();

const timeline = byId<HTMLInputElement>('timeline');
/** While the timeline is dragged, frames do not move its thumb under the pointer. */
let timelineDragging = false;
timeline.addEventListener('input', () => sim.seek(Number(timeline.value)));
timeline.addEventListener('pointerdown', () => (timelineDragging = true));
timeline.addEventListener('pointerup', () => (timelineDragging = false));
timeline.addEventListener('pointercancel', () => (timelineDragging = false));
const stepBack = () => lastFrame && lastFrame.steps > 0 && sim.seek(lastFrame.steps - 1);

const togglePlay = () => (playing ? sim.pause() : sim.play());
const stepOnce = () => sim.step(1);
const reset = () => {
  if (scenario) sim.load(scenario);
};
byId('play').addEventListener('click', togglePlay);
byId('step').addEventListener('click', stepOnce);
byId('reset').addEventListener('click', reset);

const seedInput = byId<HTMLInputElement>('seed');
function setSeed(seed: number) {
  applyChange('seed', String(seed), (problem) => report(`Seed: ${problem}`));
}
seedInput.addEventListener('change', () => {
  const v = Number(seedInput.value);
  if (!Number.isSafeInteger(v) || v < 0) {
    report('The seed is a whole number from 0 to 9007199254740991.');
    return;
  }
  setSeed(v);
});
byId('new-seed').addEventListener('click', () => setSeed(core.freshSeed()));

// ---- frames -----------------------------------------------------------------------------------

const chart = new MetricChart(byId('metric-chart'));
const chartSelect = byId<HTMLSelectElement>('chart-metric');
/** Charts `metric`: the worker sends its record of every step with each frame. */
function chartMetric(metric: string) {
  chart.reset(metric);
  sim.setChart(metric || null, chart.points);
}
chartSelect.addEventListener('change', () => {
  prefs.chartMetric = chartSelect.value;
  persistPrefs();
  chartMetric(chartSelect.value);
});

function showFrame(frame: Frame) {
  byId('step-count').textContent = frame.steps.toLocaleString('en-US');
  if (frame.hash) byId('state-hash').textContent = frame.hash;
  const status = byId('run-status');
  const goal = layout?.goal ?? true;
  status.textContent = frame.completed ? `completed in ${frame.steps.toLocaleString('en-US')} steps` : frame.finished ? (goal ? 'step limit reached' : `ran ${frame.steps.toLocaleString('en-US')} steps`) : '';
  status.classList.toggle('failed', frame.finished && !frame.completed && goal);
  if (!timelineDragging) {
    timeline.max = String(frame.furthest);
    timeline.value = String(frame.steps);
  }
  timeline.setAttribute('aria-valuetext', `step ${frame.steps} of ${frame.furthest}`);
  byId('timeline-out').textContent = `${frame.steps.toLocaleString('en-US')} / ${frame.furthest.toLocaleString('en-US')}`;
  const bar = byId('run-progress');
  const pct = frame.completed ? 100 : Math.min(100, (100 * frame.steps) / Math.max(1, frame.maxSteps));
  (bar.firstElementChild as HTMLElement).style.width = `${pct}%`;
  bar.setAttribute('aria-valuenow', pct.toFixed(0));
  renderMetrics(frame.metrics);
  if (frame.chart) chart.set(frame.chart);
  chart.render();
  byId('diag-rate').textContent = frame.stepsPerSecond ? `${formatNumber(frame.stepsPerSecond)} steps/s` : 'paused';
  const range = view.overlayRange;
  const colorbar = byId('colorbar');
  colorbar.hidden = !range;
  if (range) {
    byId('colorbar-min').textContent = formatNumber(range[0]);
    byId('colorbar-max').textContent = formatNumber(range[1]);
  }
}

const metricsBox = byId('metrics');
const metricNodes = new Map<string, HTMLElement>();
function renderMetrics(metrics: Metrics) {
  const names = Object.keys(metrics);
  if (names.join() !== [...metricNodes.keys()].join()) {
    clear(metricsBox);
    metricNodes.clear();
    for (const name of names) {
      const value = el('strong');
      metricsBox.append(el('div', { class: 'metric' }, el('span', { text: name.replace(/_/g, ' ') }), value));
      metricNodes.set(name, value);
    }
    const numeric = names.filter((n) => typeof metrics[n] === 'number');
    clear(chartSelect);
    for (const n of numeric) chartSelect.append(el('option', { value: n, text: n.replace(/_/g, ' ') }));
    const preferred = layout && numeric.includes(layout.chart) ? layout.chart : numeric[0] ?? '';
    const want = numeric.includes(prefs.chartMetric) ? prefs.chartMetric : preferred;
    chartSelect.value = want;
    if (want !== prefs.chartMetric) {
      prefs.chartMetric = want;
      chartMetric(want);
    }
  }
  for (const [name, node] of metricNodes) node.textContent = formatNumber(metrics[name]);
}

// ---- run panel: overlays, tools, legend -------------------------------------------------------

const overlay = byId<HTMLSelectElement>('overlay');
const arrows = byId<HTMLInputElement>('arrows');
const labels = byId<HTMLInputElement>('labels');
overlay.addEventListener('change', () => {
  prefs.overlay = overlay.value;
  persistPrefs();
  sim.setOverlay(overlay.value || null);
});
arrows.checked = prefs.arrows;
labels.checked = prefs.labels;
view.marks.arrows = prefs.arrows;
view.marks.labels = prefs.labels;
arrows.addEventListener('change', () => {
  prefs.arrows = view.marks.arrows = arrows.checked;
  persistPrefs();
  view.request();
});
labels.addEventListener('change', () => {
  prefs.labels = view.marks.labels = labels.checked;
  persistPrefs();
  view.request();
});

const showGhost = byId<HTMLInputElement>('show-ghost');
const showBonds = byId<HTMLInputElement>('show-bonds');
showGhost.addEventListener('change', () => {
  view.marks.ghost = showGhost.checked;
  view.request();
});
showBonds.addEventListener('change', () => {
  view.marks.bonds = showBonds.checked;
  view.request();
});

function renderRunPanel() {
  if (!layout) return;
  byId('view3d-options').hidden = !view.is3d;
  clear(overlay);
  overlay.append(el('option', { value: '', text: 'none' }));
  for (const f of layout.fields) overlay.append(el('option', { value: f.name, text: f.label }));
  overlay.value = layout.fields.some((f) => f.name === prefs.overlay) ? prefs.overlay : '';
  sim.setOverlay(overlay.value || null);

  const tools = byId('tools');
  clear(tools);
  const all = [{ name: 'inspect', label: 'Inspect' }, ...layout.tools];
  if (!all.some((t) => t.name === tool)) tool = 'inspect';
  for (const t of all) {
    const b = el('button', { type: 'button', role: 'radio', 'aria-checked': String(t.name === tool), 'data-tool': t.name, text: t.label });
    b.addEventListener('click', () => {
      tool = t.name;
      for (const other of tools.querySelectorAll('button')) other.setAttribute('aria-checked', String(other.dataset.tool === tool));
    });
    tools.append(b);
  }
  // A number in a tool's action (a load's force, say) can be set before clicking; the value
  // typed is what the recorded action carries.
  const values = byId('tool-values');
  clear(values);
  for (const t of layout.tools) {
    for (const [key, value] of Object.entries(t.action)) {
      if (typeof value !== 'number') continue;
      const input = el('input', { type: 'number', step: 'any', value: String(value), id: `tool-${t.name}-${key}`, 'data-tool': t.name, 'data-key': key, 'aria-label': `${t.label}: ${key}` });
      values.append(el('label', { class: 'row' }, `${t.label}: ${key} `, input));
    }
  }
  renderDisturbanceNote();

  const legend = byId('legend');
  clear(legend);
  const swatch = (color: string, round = false) => {
    const i = el('i', { class: round ? 'round' : '' });
    i.style.background = color;
    return i;
  };
  for (const c of layout.cells) legend.append(el('span', {}, swatch(c.color), c.name));
  for (const a of layout.agents) legend.append(el('span', {}, swatch(a.color, true), a.name));
  for (const e of layout.events) {
    const i = swatch('transparent', true);
    i.style.border = `2px solid ${e.color}`;
    legend.append(el('span', {}, i, e.name));
  }
}

/** The numbers typed next to a tool, by action key. */
function toolValues(name: string): Record<string, number> {
  const out: Record<string, number> = {};
  for (const input of byId('tool-values').querySelectorAll<HTMLInputElement>('input')) {
    if (input.dataset.tool === name && input.dataset.key && input.value !== '') out[input.dataset.key] = Number(input.value);
  }
  return out;
}

function renderDisturbanceNote() {
  const tools = byId('tools');
  tools.parentElement?.querySelector('.recorded')?.remove();
  const count = (JSON.parse(scenario || '{}') as { disturbances?: unknown[] }).disturbances?.length ?? 0;
  if (!count) return;
  const clearButton = el('button', { type: 'button', text: 'Clear them' });
  clearButton.addEventListener('click', () => applyChange('disturbances', '[]', report));
  tools.after(el('p', { class: 'hint recorded' }, `${count} scheduled or recorded disturbance${count > 1 ? 's' : ''}. `, clearButton));
}

async function clickCell(cell: number, hit: Hit | null) {
  if (!layout) return;
  if (cell < 0) {
    if (view.is3d && tool === 'inspect') {
      clearSelection();
      showReach();
    }
    return;
  }
  const t = layout.tools.find((x) => x.name === tool);
  if (t) {
    // In 3-D an added unit goes on the clicked face, in the empty cell in front of it.
    const target = t.action.kind === 'add' && hit && hit.front >= 0 ? hit.front : cell;
    sim.apply({ ...t.action, ...toolValues(t.name), cells: [target] });
    return;
  }
  const facts = await sim.inspect(cell);
  showInspector(cell, facts);
}

const inspector = byId('inspector');
const cellText = (cell: number) => `cell ${coords(cell)}`;
function cellName(cell: number): string {
  if (!layout || !lastFrame) return '';
  const code = lastFrame.cells[cell];
  return layout.cells.find((c) => c.code === code)?.name ?? (code ? `code ${code}` : 'empty');
}
function coords(cell: number): string {
  return layout ? cellCoords(layout, cell) : '';
}
function showHover(cell: number) {
  if (cell < 0) {
    inspector.hidden = true;
  } else {
    inspector.hidden = false;
    inspector.replaceChildren(el('dl', {}, el('dt', { text: 'cell' }), el('dd', { text: `${cell} ${coords(cell)}` }), el('dt', { text: 'state' }), el('dd', { text: cellName(cell) })));
  }
  if (view.is3d) hoverProbe.request(cell);
}

// In 3-D the unit under the pointer (else the selected one) shows where it could move: the worker
// is asked, throttled, and its answer drawn as highlighted cells with the difference at each.
let hoverReach: ReturnType<typeof reachOf> = null;
let selectReach: ReturnType<typeof reachOf> = null;
const hoverProbe = new Probe(
  (cell) => sim.inspect(cell),
  (cell, facts) => {
    if (cell !== view.marks.hover) return;
    hoverReach = reachOf(facts);
    if (facts && cell >= 0) showHoverFacts(cell, facts);
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
function showHoverFacts(cell: number, facts: Facts) {
  const dl = el('dl', {}, el('dt', { text: 'cell' }), el('dd', { text: `${cell} ${coords(cell)}` }), el('dt', { text: 'state' }), el('dd', { text: cellName(cell) }));
  if (typeof facts.type_list === 'string') dl.append(el('dt', { text: 'type-list' }), el('dd', { text: facts.type_list }));
  if (typeof facts.difference === 'number') dl.append(el('dt', { text: 'difference' }), el('dd', { text: formatNumber(facts.difference) }));
  if (Array.isArray(facts.reachable)) dl.append(el('dt', { text: 'reachable' }), el('dd', { text: facts.movable === false ? 'cannot move' : `${facts.reachable.length} position${facts.reachable.length === 1 ? '' : 's'}` }));
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
function showInspector(cell: number, facts: Record<string, unknown>) {
  const dl = el('dl', {}, el('dt', { text: 'cell' }), el('dd', { text: `${cell} ${coords(cell)}` }), el('dt', { text: 'state' }), el('dd', { text: cellName(cell) }));
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

// ---- the run in words, and the keyboard cursor -------------------------------------------------

const announcer = new Announcer(byId('run-live'));
const keyCursor = new KeyCursor(byId('canvas-wrap'), {
  layout: () => layout,
  cells: () => lastFrame?.cells ?? null,
  show(cell) {
    view.marks.cursor = cell >= 0 ? { cell, kind: 'cursor' } : null;
    view.request();
    byId('view').dataset.cursor = String(cell);
    if (cell >= 0) showHover(cell);
  },
  click: (cell) => void clickCell(cell, null),
  announce(cell) {
    if (cell < 0) {
      announcer.say('Cursor hidden; the arrows step the run again.');
      return;
    }
    const label = layout?.tools.find((t) => t.name === tool)?.label ?? 'Inspect';
    announcer.say(`Cursor at ${cellText(cell)}, ${cellName(cell)}. Enter: ${label}.`);
  },
});

// ---- scenario panel ---------------------------------------------------------------------------

const jsonEditor = byId<HTMLTextAreaElement>('scenario-json');
const jsonError = byId('json-error');
let jsonDirty = false;
jsonEditor.addEventListener('input', () => (jsonDirty = true));
function syncJsonEditor() {
  if (!jsonDirty) jsonEditor.value = scenario;
}

/** Changes one top-level key through the core; returns the problem, or null when applied. */
function applyChange(key: string, valueJson: string, onError?: (problem: string) => void): string | null {
  try {
    const next = change(scenario, key, valueJson);
    load(next);
    return null;
  } catch (e) {
    const problem = core.message(e);
    onError?.(problem);
    return problem;
  }
}

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
  renderExercise((JSON.parse(scenario) as { exercise?: Exercise }).exercise);
});
byId('exercise-check').addEventListener('click', () => sim.check());
byId('exercise-handin').addEventListener('click', async () => {
  const student = byId<HTMLInputElement>('exercise-student').value.trim();
  const out = byId('exercise-handin-out');
  try {
    const handin = student ? core.override(scenario, 'name', JSON.stringify(student)) : scenario;
    const url = `${location.origin}${location.pathname}#${core.encodeLink(handin)}`;
    out.textContent = url;
    await navigator.clipboard?.writeText(url).then(
      () => (out.textContent = `Copied. Send this link to your teacher: ${url}`),
      () => undefined,
    );
  } catch (e) {
    out.textContent = core.message(e);
  }
});

// ---- the teacher's exercise editor -------------------------------------------------------------

const exerciseDialog = byId<HTMLDialogElement>('exercise-editor');
const goalInput = byId<HTMLInputElement>('ex-goal');
function showGoalProblem(): boolean {
  const problem = goalInput.value.trim() ? core.goalProblem(goalInput.value) : 'write the goal the run must meet';
  byId('ex-goal-problem').textContent = problem ?? '';
  goalInput.setAttribute('aria-invalid', problem ? 'true' : 'false');
  return !problem;
}
goalInput.addEventListener('input', showGoalProblem);
byId('make-exercise').addEventListener('click', () => {
  const doc = JSON.parse(scenario) as Record<string, unknown>;
  const current = doc.exercise as Exercise | undefined;
  byId<HTMLInputElement>('ex-title').value = current?.title ?? displayText(String(doc.name ?? ''), 100);
  byId<HTMLTextAreaElement>('ex-instructions').value = current?.instructions ?? '';
  goalInput.value = current?.goal ?? 'completed';
  byId<HTMLTextAreaElement>('ex-hints').value = (current?.hints ?? []).join('\n\n');
  const locked = byId('ex-locked');
  clear(locked);
  for (const key of Object.keys(doc).filter((k) => !['version', 'model', 'exercise', 'disturbances'].includes(k))) {
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
  const doc = JSON.parse(scenario) as Record<string, unknown>;
  if (exerciseDialog.returnValue === 'remove') {
    delete doc.exercise;
    load(JSON.stringify(doc));
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
  if (load(JSON.stringify(doc))) selectTab('run');
});

function renderScenarioPanel() {
  const doc = JSON.parse(scenario) as Record<string, unknown>;
  const name = displayText(String(doc.name ?? ''), 100);
  byId('scenario-name').textContent = name || 'untitled scenario';
  byId('scenario-model').textContent = String(doc.model ?? '');
  document.title = `${name || 'untitled'} · Kumiki`;
  seedInput.value = String(doc.seed ?? 0);
  const model = String(doc.model);
  const spec = modelEditors[model];
  const exercise = doc.exercise as Exercise | undefined;
  renderExercise(exercise);
  renderParams(byId<HTMLFormElement>('param-form'), doc, (key, value) => applyChange(key, value), spec?.owns, new Set(Object.keys(exercise?.locked ?? {})), core.modelSchema(model));
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
        scenario: () => JSON.parse(scenario) as Record<string, unknown>,
        change: (changes) => {
          let next = scenario;
          try {
            for (const [k, v] of Object.entries(changes)) next = change(next, k, JSON.stringify(v));
          } catch (e) {
            return core.message(e);
          }
          load(next);
          return null;
        },
        layout: () => layout,
      });
    }
  }
  editor?.update(doc);
}

byId('apply-json').addEventListener('click', () => {
  try {
    core.normalize(jsonEditor.value);
  } catch (e) {
    jsonError.textContent = core.message(e);
    return;
  }
  jsonDirty = false;
  jsonError.textContent = '';
  load(jsonEditor.value);
});
byId('download-json').addEventListener('click', () => {
  const name = (JSON.parse(scenario) as { name?: string }).name || 'scenario';
  download(`${name}.json`, `${scenario}\n`, 'application/json');
});
byId<HTMLInputElement>('open-json').addEventListener('change', async (e) => {
  const file = (e.target as HTMLInputElement).files?.[0];
  if (!file) return;
  const text = await file.text();
  jsonEditor.value = text;
  jsonDirty = true;
  const details = jsonEditor.closest('details');
  if (details) details.open = true;
  try {
    core.normalize(text);
    jsonDirty = false;
    jsonError.textContent = '';
    load(text);
  } catch (err) {
    jsonError.textContent = `${file.name}: ${core.message(err)}`;
  }
  (e.target as HTMLInputElement).value = '';
});

function updateUndo() {
  (byId('undo') as HTMLButtonElement).disabled = !history.canUndo;
  (byId('redo') as HTMLButtonElement).disabled = !history.canRedo;
}
function undo() {
  const prev = history.undo(scenario);
  if (prev) load(prev, { record: false });
  updateUndo();
}
function redo() {
  const next = history.redo(scenario);
  if (next) load(next, { record: false });
  updateUndo();
}
byId('undo').addEventListener('click', undo);
byId('redo').addEventListener('click', redo);

// ---- sharing ----------------------------------------------------------------------------------

byId('copy-link').addEventListener('click', async () => {
  let payload: string;
  try {
    payload = core.encodeLink(scenario);
  } catch (e) {
    report(`No link can be made: ${core.message(e)}`);
    return;
  }
  const url = `${location.origin}${location.pathname}${location.search}#${payload}`;
  history_replace(payload);
  const button = byId('copy-link');
  try {
    await navigator.clipboard.writeText(url);
    button.textContent = 'Link copied';
  } catch {
    button.textContent = 'Link in address bar';
  }
  button.dataset.link = url;
  setTimeout(() => (button.textContent = 'Copy link'), 2000);
});

function openHash(): boolean {
  const hash = location.hash.slice(1);
  if (!hash) return false;
  try {
    const unpacked = core.unpackLink(hash);
    const previous = scenario;
    const remember = (json: string) => {
      if (previous && json !== previous) history.push(previous);
      updateUndo();
      introduce(json);
    };
    // A large scenario is validated by the worker as it opens; a small one here, at once.
    if (!large.begin(unpacked.scenario, remember)) {
      const json = core.normalize(unpacked.scenario);
      remember(json);
      scenario = json;
    }
    // A link made with another behaviour of its model opens, but its run may not be its maker's.
    const { made_with, current } = unpacked;
    linkNotice.textContent = `This link was made with ${made_with < current ? 'an earlier' : 'a newer'} Kumiki; results may differ.`;
    linkNotice.hidden = made_with === current;
    open(large.active ? unpacked.scenario : scenario);
    dismiss();
    return true;
  } catch (e) {
    report(`This link could not be opened, so your last scenario is shown instead.\n${core.message(e)}`);
    return false;
  }
}
window.addEventListener('hashchange', () => {
  if (location.hash.length > 1 && core.encodeLink(scenario) !== location.hash.slice(1)) openHash();
});

// ---- tabs and keyboard ------------------------------------------------------------------------

const tabs = ['run', 'scenario', 'experiments', 'about'];
function selectTab(name: string, focus = false) {
  for (const t of tabs) {
    const tab = byId(`tab-${t}`);
    const on = t === name;
    tab.setAttribute('aria-selected', String(on));
    tab.tabIndex = on ? 0 : -1;
    byId(`panel-${t}`).hidden = !on;
    if (on && focus) tab.focus();
  }
  prefs.tab = name;
  document.body.dataset.tab = name;
  persistPrefs();
  chart.render();
}
for (const t of tabs) {
  const tab = byId(`tab-${t}`);
  tab.addEventListener('click', () => selectTab(t));
  tab.addEventListener('keydown', (e) => {
    const i = tabs.indexOf(t);
    if (e.key === 'ArrowRight' || e.key === 'ArrowLeft') {
      e.preventDefault();
      e.stopPropagation();
      selectTab(tabs[(i + (e.key === 'ArrowRight' ? 1 : tabs.length - 1)) % tabs.length], true);
    }
  });
}

document.addEventListener('keydown', (e) => {
  if (e.defaultPrevented || typingIn(e.target) || (document.querySelector('dialog[open]') && e.key !== 'Escape')) return;
  if ((e.ctrlKey || e.metaKey) && e.key.toLowerCase() === 'z') {
    e.preventDefault();
    if (e.shiftKey) redo();
    else undo();
    return;
  }
  if (e.ctrlKey || e.metaKey || e.altKey) return;
  // The page's keys act only when no control has the focus: Space on a checkbox ticks it, and
  // the arrows move sliders and tool groups. Left steps back only from the view.
  const onView = e.target === byId('view');
  if (!onView && e.target instanceof HTMLElement && e.target !== document.body && e.target.closest('input, select, textarea, button, a, summary, [role="radiogroup"], [role="tablist"], [tabindex]')) return;
  switch (e.key) {
    case ' ':
      e.preventDefault();
      togglePlay();
      return;
    case 'ArrowRight':
      e.preventDefault();
      stepOnce();
      return;
    case 'ArrowLeft':
      if (!onView) return;
      e.preventDefault();
      stepBack();
      return;
    case 'r':
    case 'R':
      e.preventDefault();
      reset();
      return;
    case '+':
    case '=':
      view.zoom(1.25);
      return;
    case '-':
      view.zoom(0.8);
      return;
    case '0':
      view.fit();
      return;
  }
});
byId('zoom-in').addEventListener('click', () => view.zoom(1.25));
byId('zoom-out').addEventListener('click', () => view.zoom(0.8));
byId('zoom-fit').addEventListener('click', () => view.fit());

// ---- diagnostics ------------------------------------------------------------------------------

const rendererChoice = byId<HTMLSelectElement>('renderer-choice');
rendererChoice.value = prefs.renderer;
async function useRenderer() {
  try {
    await view.useRenderer(prefs.renderer);
  } catch (e) {
    report(core.message(e));
  }
  byId('diag-renderer').textContent = view.rendererKind === 'webgl2' ? '(using WebGL2)' : '(using Canvas 2D)';
  document.body.dataset.renderer = view.rendererKind ?? '';
}
rendererChoice.addEventListener('change', () => {
  prefs.renderer = rendererChoice.value as typeof prefs.renderer;
  persistPrefs();
  void useRenderer();
});
byId('simulate-crash').addEventListener('click', () => sim.crash());

// ---- start ------------------------------------------------------------------------------------

async function start() {
  registerOffline((reload) => {
    keepBanner = true;
    report('A new version of Kumiki is ready.', { label: 'Reload', run: reload });
  });
  await core.loadCore();
  await useRenderer();
  byId('diag-version').textContent = core.version();
  setupGallery(
    core.presets(),
    core.lessons(),
    (name) => load(core.presetJson(name)),
    // A lesson opens on the run tab, where its exercise panel is.
    (name) => load(core.lessonJson(name)) && selectTab('run'),
  );
  setupExperiments(prefs, persistPrefs, report);
  setupRecordDialog({
    describe: () => {
      const doc = JSON.parse(scenario) as { name?: string; seed?: number };
      return { name: String(doc.name || 'scenario'), seed: Number(doc.seed ?? 0), steps: lastFrame?.steps ?? 0 };
    },
    pause: () => sim.pause(),
    advance: stepAndDraw,
    setScale: (scale) => view.setCaptureScale(scale),
    captureFrame: () => view.captureFrame(),
  });
  selectTab(tabs.includes(prefs.tab) ? prefs.tab : 'run');
  if (embedded) {
    embed = new Embed(
      {
        load: (payload) => {
          try {
            const json = core.unpackLink(payload).scenario;
            if (load(json, { quiet: true })) return null;
            // Only a scenario small enough to check here fails at once: say why.
            core.normalize(json);
            return 'This scenario cannot run.';
          } catch (e) {
            return core.message(e);
          }
        },
        play: () => sim.play(),
        pause: () => sim.pause(),
        step: (count) => sim.step(count),
        reset,
        check: () => sim.check(),
      },
      core.version(),
    );
    // An embedded page shows its link or the default scenario, never what this browser last edited.
    if (!openHash()) load(core.presetJson(DEFAULT_PRESET), { record: false });
    return;
  }
  const unfinished = openingScenario();
  if (unfinished !== null) {
    // The page was closed or stopped while a scenario was opening: it may be what stopped it.
    openedScenario();
    load(core.presetJson(DEFAULT_PRESET), { record: false });
    if (location.hash) history_replace('');
    keepBanner = true;
    report('The last scenario did not finish opening before the page closed, so the default one is shown. It may be too large for this device.', {
      label: 'Open it anyway',
      run: () => load(unfinished),
    });
    return;
  }
  if (openHash()) return;
  // A link that could not be opened is explained in the banner; the scenario shown instead keeps it.
  keepBanner = !banner.hidden;
  const saved = savedScenario();
  if (!(saved && load(saved, { record: false, quiet: true }))) load(core.presetJson(DEFAULT_PRESET), { record: false });
}

start().catch((e: unknown) => report(`Kumiki could not start: ${core.message(e)}`));
