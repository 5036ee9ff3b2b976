// Two runs side by side. A scenario's `compare` section (crate/core/src/compare.rs) names the one
// setting a second run changes; the core checks it and gives the second run's scenario. The second
// run lives in a worker of its own, drawn in a view beside the first, and follows the first's step
// count (SimClient.pair): play, pause, step, rewind and reset move both, and the chart and the
// metric cards show both, named in words. The section travels in the scenario, so the link that
// holds the scenario holds both runs. The Run tab's "Compare two runs" writes or removes it.
import { ENVELOPE, type Frame } from '../../contract.gen';
import type { PageContext } from '../../page/context';
import { View } from '../../render/view';
import type { Drawn } from '../../types';
import { SimClient } from '../../sim/client';
import { byId, clear, el } from '../../widgets/dom';
import { choices, otherNumber, resolve } from '../../widgets/params';
import * as core from '../../wasm';
import controlsHtml from './controls.html?raw';

/** Where the comparison's controls go in the Run tab, among other features' sections. */
const ORDER = 30;

/**
 * Keys the page does not offer to vary: those of the envelope a comparison cannot vary (all but its
 * settings), and the step limit, which would only cut one run short.
 */
const NOT_COMPARED = new Set([...ENVELOPE.filter((k) => k.role !== 'setting').map((k) => k.key), 'max_steps']);

/** One setting a second run may change, and the values it may take there. */
interface Setting {
  key: string;
  /** The other values of a choice or a switch; null for a number, typed in. */
  options: unknown[] | null;
  /** A number's bounds and whether it is whole, from the model's schema. */
  bounds?: { min: number; max: number; integer: boolean };
}

export function setupCompare(page: PageContext) {
  const { session, sim, prefs, events } = page;
  page.tabs.section('run', controlsHtml, ORDER);
  const wrap = byId('compare-wrap');
  const firstLabel = byId('run-label-first');
  const secondLabel = byId('run-label-second');
  const settingSelect = byId<HTMLSelectElement>('compare-setting');
  const valueSelect = byId<HTMLSelectElement>('compare-value');
  const valueNumber = byId<HTMLInputElement>('compare-number');
  const start = byId<HTMLButtonElement>('compare-start');
  const stop = byId<HTMLButtonElement>('compare-stop');
  const error = byId('compare-error');

  let second: SimClient | null = null;
  let secondView: View | null = null;
  let settings: Setting[] = [];

  /** The second run's worker and view, made the first time a comparison opens and kept after. */
  function ensureSecond(): SimClient {
    if (second) return second;
    const client = new SimClient({
      // Framed once loaded: it may have been laid out while its view was still hidden.
      loaded: () => secondView?.fit(),
      frame: showSecond,
      // Its playing shows on the Play button through the first run's client (SimClient.pair).
      playing: () => {},
      scenario: () => {},
      error: (message) => page.banner.report(`The second run: ${message}`),
      panic: (message) => page.banner.report(`The second run hit an internal error and was restarted.\n${message}`),
      goal: () => {},
      stalled: () => {},
      viewer: (kind) => secondView?.started(kind),
      drew: () => {},
    });
    second = client;
    secondView = new View(byId<HTMLCanvasElement>('view-second'), byId<HTMLCanvasElement>('annotations-second'), wrap, () => client, {
      click: () => {},
      hover: () => {},
      drawn: () => client.ack(),
    });
    secondView.marks.arrows = prefs.arrows;
    secondView.marks.labels = prefs.labels;
    secondView.request();
    void secondView.useRenderer(prefs.renderer);
    return client;
  }

  function showSecond(frame: Frame, drawn: Drawn) {
    secondView?.setFrame(drawn);
    byId('step-count-second').textContent = frame.steps.toLocaleString('en-US');
    if (frame.hash) byId('state-hash-second').textContent = frame.hash;
    byId('run-status-second').textContent = frame.completed ? `completed in ${frame.steps.toLocaleString('en-US')} steps` : frame.finished ? 'ended' : '';
    wrap.dataset.steps = String(frame.steps);
    if (frame.hash) wrap.dataset.hash = frame.hash;
    events.emit('second-frame', frame);
  }

  /** Opens, changes or closes the comparison as the scenario in view says. */
  function follow() {
    const comparison = session.comparison;
    // A large scenario is not run twice: the second run would double the memory the page asked about.
    if (comparison.kind === 'too_large') error.textContent = 'This scenario is too large to run twice side by side; only its own run is shown.';
    const pair = comparison.kind === 'pair' ? comparison : null;
    // The first run's view changes size as the second appears or goes: it is framed again once
    // resized (the resize observer reports in the next frame, after its animation callbacks).
    if (!!pair !== document.body.classList.contains('comparing')) requestAnimationFrame(() => requestAnimationFrame(() => page.view.fit()));
    document.body.classList.toggle('comparing', !!pair);
    wrap.hidden = !pair;
    firstLabel.hidden = !pair;
    stop.hidden = !pair;
    if (!pair) {
      page.view.companion = null;
      sim.pair(null);
      second?.pause();
      events.emit('compare', null);
      return;
    }
    const client = ensureSecond();
    // The zoom buttons and keys zoom and frame both views; a drag or a pinch moves the one under it.
    page.view.companion = secondView;
    firstLabel.textContent = pair.labels[0];
    secondLabel.textContent = pair.labels[1];
    wrap.setAttribute('aria-label', `The second run: ${pair.labels[1]}`);
    byId<HTMLCanvasElement>('view-second').setAttribute('aria-label', `The second run's view, ${pair.labels[1]}; drag to pan, wheel or pinch to zoom`);
    events.emit('compare', pair.labels);
    // Loaded again on every load of the first run: a reset resets both.
    delete wrap.dataset.hash;
    client.load(pair.second);
    sim.pair(client);
  }

  // ---- the controls ----

  /** The settings of the scenario in view a second run may change, from the model's schema. */
  function offer() {
    const doc = session.doc();
    const schema = core.modelSchema(String(doc.model ?? ''));
    settings = [];
    for (const key of Object.keys(doc).sort()) {
      if (NOT_COMPARED.has(key)) continue;
      const value = doc[key];
      const options = choices(resolve(schema?.properties[key], schema));
      if (options) settings.push({ key, options: options.filter((o) => JSON.stringify(o) !== JSON.stringify(value)) });
      else if (typeof value === 'boolean') settings.push({ key, options: [!value] });
      else if (typeof value === 'number') {
        const node = resolve(schema?.properties[key], schema);
        const integer = node?.type === 'integer' || (Array.isArray(node?.type) && node.type.includes('integer'));
        settings.push({ key, options: null, bounds: { min: node?.minimum ?? -Infinity, max: node?.maximum ?? Infinity, integer } });
      }
    }
    settings = settings.filter((s) => s.options === null || s.options.length > 0);
    const current = (doc.compare as { path?: string; value?: unknown } | undefined) ?? null;
    const keep = current?.path ?? settingSelect.value;
    clear(settingSelect);
    for (const s of settings) settingSelect.append(el('option', { value: s.key, text: s.key.replace(/_/g, ' ') }));
    if (settings.some((s) => s.key === keep)) settingSelect.value = keep;
    offerValues(current?.path === settingSelect.value ? current.value : undefined);
    start.disabled = settings.length === 0;
    start.textContent = current ? 'Compare this instead' : 'Compare side by side';
  }

  function offerValues(chosen?: unknown) {
    const setting = settings.find((s) => s.key === settingSelect.value);
    const doc = session.doc();
    valueSelect.hidden = !setting?.options;
    valueNumber.hidden = !setting || !!setting.options;
    clear(valueSelect);
    if (setting?.options) {
      // The scenario's own value is listed too (it cannot be chosen): the choice reads as "this, or that".
      for (const option of setting.options) valueSelect.append(el('option', { value: JSON.stringify(option), text: words(setting.key, option) }));
      if (chosen !== undefined && setting.options.some((o) => JSON.stringify(o) === JSON.stringify(chosen))) valueSelect.value = JSON.stringify(chosen);
    } else if (setting) {
      const own = Number(doc[setting.key]);
      const bounds = setting.bounds ?? { min: -Infinity, max: Infinity, integer: false };
      valueNumber.step = bounds.integer ? '1' : 'any';
      if (Number.isFinite(bounds.min)) valueNumber.min = String(bounds.min);
      else valueNumber.removeAttribute('min');
      if (Number.isFinite(bounds.max)) valueNumber.max = String(bounds.max);
      else valueNumber.removeAttribute('max');
      valueNumber.value = String(typeof chosen === 'number' ? chosen : otherNumber(own, bounds));
    }
  }

  /** A value in words: a switch reads on or off. */
  function words(key: string, value: unknown): string {
    if (typeof value === 'boolean') return `${key.replace(/_/g, ' ')} ${value ? 'on' : 'off'}`;
    return String(value);
  }

  // The renderer chosen (the About tab's) holds for the second view too.
  events.on('renderer', () => void secondView?.useRenderer(prefs.renderer));

  settingSelect.addEventListener('change', () => offerValues());
  start.addEventListener('click', () => {
    const key = settingSelect.value;
    const setting = settings.find((s) => s.key === key);
    if (!setting) return;
    const value: unknown = setting.options ? JSON.parse(valueSelect.value) : Number(valueNumber.value);
    const section: Record<string, unknown> = { path: key, value };
    // A switch is named on and off; other settings by the core's default, the setting and its value.
    if (typeof value === 'boolean') {
      section.label = words(key, value);
      section.base_label = words(key, !value);
    }
    void session.set('compare', JSON.stringify(section)).then((problem) => {
      error.textContent = problem ?? '';
    });
  });
  stop.addEventListener('click', () => {
    const doc = { ...session.doc() };
    delete doc.compare;
    error.textContent = '';
    void session.open(JSON.stringify(doc));
    start.focus();
  });

  session.on('loaded', () => {
    error.textContent = '';
    follow();
    offer();
  });
  // A recorded click changes the first run's scenario, and the second run's with it.
  session.on('recorded', follow);
}
