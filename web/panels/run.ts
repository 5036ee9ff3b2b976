// The run panel: the transport (play, step, reset, speed, timeline, seed), the step count, status,
// metrics and chart of each frame, and the overlays, tools and legend of the model in view.
import * as core from '../wasm';
import type { MetricInfo, Metrics } from '../contract.gen';
import type { Frame } from '../types';
import { MetricChart, type RunLabels } from '../ui/chart';
import { byId, clear, el, formatNumber } from '../ui/dom';
import { SPEED_MAX, speedText, stepsPerSecond } from '../ui/speed';
import type { Page } from './page';

export interface RunPanel {
  /** The tool a click on the lattice applies ('inspect' or one of the layout's tools). */
  readonly tool: string;
  /** The label of that tool. */
  toolLabel(): string;
  /** The numbers typed next to a tool, by action key. */
  toolValues(name: string): Record<string, number>;
  readonly playing: boolean;
  /** The worker started or stopped playing. */
  setPlaying(on: boolean): void;
  togglePlay(): void;
  stepOnce(): void;
  /** Goes `count` steps back (1 unless given) from where the last back press led. */
  stepBack(count?: number): void;
  reset(): void;
  /** The metric charted now. */
  chartedMetric(): string;
  /** Draws the chart again (its size may have changed with the tab). */
  renderChart(): void;
  /** Compares two runs, named in words (the first run's first): the chart and the metric cards show both; null: one again. */
  compare(runs: RunLabels | null): void;
  /** A frame of the second run of a comparison. */
  secondFrame(frame: Frame): void;
}

export function setupRunPanel(page: Page): RunPanel {
  const { session, sim, view, prefs } = page;
  let playing = false;
  let tool = 'inspect';

  /** The scenario's locked fields, when it is an exercise. */
  const lockedFields = () => Object.keys((session.doc().exercise as { locked?: Record<string, unknown> } | undefined)?.locked ?? {});

  // ---- transport ----

  const speed = byId<HTMLInputElement>('speed');
  const speedOut = byId('speed-out');
  function applySpeed() {
    const position = Math.max(0, Math.min(SPEED_MAX, Number(speed.value)));
    const v = stepsPerSecond(position);
    const text = speedText(v);
    speedOut.textContent = text.short;
    speed.setAttribute('aria-valuetext', text.spoken);
    sim.setSpeed(v);
    prefs.speedIndex = position;
    page.persistPrefs();
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
  /**
   * Where the back presses sent so far lead. Each press goes back from the last one sent, not from
   * the frame in view: a rewind takes the worker a while, and presses made meanwhile must count.
   * Cleared once a frame shows that step, and whenever the run moves another way.
   */
  let backTarget: number | null = null;
  const stepBack = (count = 1) => {
    const frame = session.frame;
    if (!frame) return;
    const from = backTarget !== null && !playing ? backTarget : frame.steps;
    if (from <= 0) return;
    backTarget = Math.max(0, from - count);
    sim.seek(backTarget);
  };
  const forget = () => (backTarget = null);
  timeline.addEventListener('input', forget);

  const togglePlay = () => {
    forget();
    if (playing) sim.pause();
    else sim.play();
  };
  const stepOnce = () => {
    forget();
    sim.step(1);
  };
  const reset = () => {
    forget();
    if (session.scenario) sim.load(session.scenario);
  };
  byId('play').addEventListener('click', togglePlay);
  byId('step').addEventListener('click', stepOnce);
  byId('reset').addEventListener('click', reset);

  const seedInput = byId<HTMLInputElement>('seed');
  /** Sets the seed as written: the core checks it (a whole number it can carry exactly) and says why not. */
  function setSeed(seed: string) {
    page.applyChange('seed', seed || '""', (problem) => page.banner.report(`The seed was not changed: ${problem}`));
  }
  seedInput.addEventListener('change', () => setSeed(seedInput.value.trim()));
  byId('new-seed').addEventListener('click', () => setSeed(String(core.freshSeed())));

  // ---- frames ----

  const chart = new MetricChart(byId('metric-chart'), byId('chart-legend'));
  /** The two runs' names while comparing. */
  let runs: RunLabels | null = null;
  const chartSelect = byId<HTMLSelectElement>('chart-metric');
  /** Charts `metric`: the worker sends its record of every step with each frame. */
  function chartMetric(metric: string) {
    chart.reset(metric);
    sim.setChart(metric || null, chart.points);
  }
  chartSelect.addEventListener('change', () => {
    prefs.chartMetric = chartSelect.value;
    page.persistPrefs();
    chartMetric(chartSelect.value);
  });

  function showFrame(frame: Frame) {
    if (frame.steps === backTarget) backTarget = null;
    byId('step-count').textContent = frame.steps.toLocaleString('en-US');
    if (frame.hash) byId('state-hash').textContent = frame.hash;
    const status = byId('run-status');
    const goal = session.layout?.goal ?? true;
    status.textContent = frame.completed
      ? `completed in ${frame.steps.toLocaleString('en-US')} steps`
      : frame.finished
        ? goal
          ? 'step limit reached'
          : `ran ${frame.steps.toLocaleString('en-US')} steps`
        : '';
    status.classList.toggle('failed', frame.finished && !frame.completed && goal);
    // In an exercise the goal's verdict is the one in colour: completing may not be meeting it.
    status.classList.toggle('plain', session.doc().exercise !== undefined);
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

  /** The model's metric table (name, unit, meaning), from the core: the same one the CLI and the docs use. */
  function explanations(): Map<string, MetricInfo> {
    try {
      return new Map(core.metricTable(String(session.doc().model ?? '')).map((m) => [m.name, m]));
    } catch {
      return new Map();
    }
  }

  const metricsBox = byId('metrics');
  const metricNodes = new Map<string, HTMLElement>();
  /** While comparing, each card's second value: the second run's. */
  const secondNodes = new Map<string, HTMLElement>();
  function renderMetrics(metrics: Metrics) {
    const names = Object.keys(metrics);
    if (names.join() !== [...metricNodes.keys()].join()) {
      clear(metricsBox);
      metricNodes.clear();
      secondNodes.clear();
      const about = explanations();
      for (const name of names) {
        const value = el('strong');
        const info = about.get(name);
        // The explanation shows on hover and on focus (a card with one is in the Tab order) and
        // is the card's description for a screen reader. It sits between the name and the value
        // (it is drawn apart from both), so the card still starts with its name and ends with
        // its value.
        const tip = info ? [el('span', { class: 'metric-about', role: 'tooltip', id: `metric-about-${name}`, text: `${info.about} Unit: ${info.unit}.` })] : [];
        // While comparing, the card holds both runs' values, each named for a screen reader.
        const secondValue = el('strong', { class: 'second' });
        const pair = runs
          ? [el('span', { class: 'sr-only', text: `${runs[0]}: ` }), value, el('span', { class: 'sr-only', text: `, ${runs[1]}: ` }), secondValue]
          : [value];
        metricsBox.append(
          el(
            'div',
            { class: 'metric', tabindex: info ? 0 : undefined, 'aria-describedby': info ? `metric-about-${name}` : undefined },
            el('span', { text: name.replace(/_/g, ' ') }),
            ...tip,
            ...pair,
          ),
        );
        metricNodes.set(name, value);
        if (runs) secondNodes.set(name, secondValue);
      }
      const numeric = names.filter((n) => typeof metrics[n] === 'number');
      clear(chartSelect);
      for (const n of numeric) chartSelect.append(el('option', { value: n, text: n.replace(/_/g, ' ') }));
      const layout = session.layout;
      const preferred = layout && numeric.includes(layout.chart) ? layout.chart : (numeric[0] ?? '');
      const want = numeric.includes(prefs.chartMetric) ? prefs.chartMetric : preferred;
      chartSelect.value = want;
      if (want !== prefs.chartMetric) {
        prefs.chartMetric = want;
        chartMetric(want);
      }
    }
    for (const [name, node] of metricNodes) node.textContent = formatNumber(metrics[name]);
  }

  // ---- overlays, tools, legend ----

  const overlay = byId<HTMLSelectElement>('overlay');
  const arrows = byId<HTMLInputElement>('arrows');
  const labels = byId<HTMLInputElement>('labels');
  overlay.addEventListener('change', () => {
    prefs.overlay = overlay.value;
    page.persistPrefs();
    sim.setOverlay(overlay.value || null);
  });
  arrows.checked = prefs.arrows;
  labels.checked = prefs.labels;
  view.marks.arrows = prefs.arrows;
  view.marks.labels = prefs.labels;
  arrows.addEventListener('change', () => {
    prefs.arrows = view.marks.arrows = arrows.checked;
    page.persistPrefs();
    view.request();
  });
  labels.addEventListener('change', () => {
    prefs.labels = view.marks.labels = labels.checked;
    page.persistPrefs();
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
    const layout = session.layout;
    if (!layout) return;
    byId('view3d-options').hidden = !view.is3d;
    clear(overlay);
    overlay.append(el('option', { value: '', text: 'none' }));
    for (const f of layout.fields) overlay.append(el('option', { value: f.name, text: f.label }));
    overlay.value = layout.fields.some((f) => f.name === prefs.overlay) ? prefs.overlay : '';
    sim.setOverlay(overlay.value || null);

    const tools = byId('tools');
    clear(tools);
    // Clicked disturbances are recorded in the scenario: not when the exercise locks them.
    const clickable = lockedFields().includes('disturbances') ? [] : layout.tools;
    const all = [{ name: 'inspect', label: 'Inspect' }, ...clickable];
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
    for (const t of clickable) {
      for (const [key, value] of Object.entries(t.action)) {
        if (typeof value !== 'number') continue;
        const input = el('input', {
          type: 'number',
          step: 'any',
          value: String(value),
          id: `tool-${t.name}-${key}`,
          'data-tool': t.name,
          'data-key': key,
          'aria-label': `${t.label}: ${key}`,
        });
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
    for (const c of layout.cells) {
      // A code the view marks in every view (a ring or a cross over its cells) shows the mark on its swatch.
      const i = swatch(c.color);
      if (c.mark) i.dataset.mark = c.mark;
      legend.append(el('span', {}, i, c.name));
    }
    for (const a of layout.agents) legend.append(el('span', {}, swatch(a.color, true), a.name));
    for (const e of layout.events) {
      const i = swatch('transparent', true);
      i.style.border = `2px solid ${e.color}`;
      legend.append(el('span', {}, i, e.name));
    }
  }

  function toolValues(name: string): Record<string, number> {
    const out: Record<string, number> = {};
    for (const input of byId('tool-values').querySelectorAll<HTMLInputElement>('input')) {
      if (input.dataset.tool === name && input.dataset.key && input.value !== '') out[input.dataset.key] = Number(input.value);
    }
    return out;
  }

  /** Shows how many disturbances the scenario carries, with a way to clear them. */
  function renderDisturbanceNote() {
    const tools = byId('tools');
    tools.parentElement?.querySelector('.recorded')?.remove();
    const count = (session.doc().disturbances as unknown[] | undefined)?.length ?? 0;
    if (!count || lockedFields().includes('disturbances')) return;
    const clearButton = el('button', { type: 'button', text: 'Clear them' });
    clearButton.addEventListener('click', () => page.applyChange('disturbances', '[]', (problem) => page.banner.report(problem)));
    tools.after(el('p', { class: 'hint recorded' }, `${count} scheduled or recorded disturbance${count > 1 ? 's' : ''}. `, clearButton));
  }

  session.on('loaded', () => {
    forget();
    renderRunPanel();
    seedInput.value = String(session.doc().seed ?? 0);
    // A locked seed is read-only, and New seed cannot replace it by accident.
    const seedLocked = lockedFields().includes('seed');
    seedInput.readOnly = seedLocked;
    seedInput.setAttribute('aria-label', seedLocked ? 'Random seed, locked by the exercise' : 'Random seed');
    const newSeed = byId<HTMLButtonElement>('new-seed');
    newSeed.disabled = seedLocked;
    newSeed.title = seedLocked ? 'The exercise locks the seed' : '';
    chartMetric(prefs.chartMetric);
  });
  session.on('frame', showFrame);
  session.on('recorded', renderDisturbanceNote);

  return {
    get tool() {
      return tool;
    },
    toolLabel: () => session.layout?.tools.find((t) => t.name === tool)?.label ?? 'Inspect',
    toolValues,
    get playing() {
      return playing;
    },
    setPlaying(on) {
      playing = on;
      const button = byId('play');
      button.textContent = on ? 'Pause' : 'Play';
      button.setAttribute('aria-label', on ? 'Pause (Space)' : 'Play (Space)');
      button.setAttribute('aria-pressed', String(on));
    },
    togglePlay,
    stepOnce,
    stepBack,
    reset,
    chartedMetric: () => chartSelect.value,
    renderChart: () => chart.render(),
    compare(labels) {
      if (JSON.stringify(labels) === JSON.stringify(runs)) return;
      runs = labels;
      chart.compare(labels);
      // The cards are built again, with or without the second value.
      metricNodes.clear();
      clear(metricsBox);
      if (session.frame) renderMetrics(session.frame.metrics);
    },
    secondFrame(frame) {
      for (const [name, node] of secondNodes) node.textContent = formatNumber(frame.metrics[name]);
      if (frame.chart) chart.setSecond(frame.chart);
      chart.render();
    },
  };
}
