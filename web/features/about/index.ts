// The About tab: what Kumiki is, the keyboard, and the diagnostics (version, renderer, speed); with
// `?debug`, a button that makes the simulation panic on purpose to show how the page recovers.
import type { Feature } from '../../page/context';
import { debugRequested } from '../../page/address';
import type { RendererChoice } from '../../sim/protocol';
import { byId, formatNumber } from '../../widgets/dom';
import * as core from '../../wasm';
import diagnosticsHtml from './diagnostics.html?raw';
import introHtml from './intro.html?raw';

export const about: Feature = {
  name: 'about',
  tab: 'About',
  mount(page) {
    const { tabs, prefs, sim, session, events } = page;
    tabs.section('about', introHtml, 10);
    tabs.section('about', diagnosticsHtml, 30);
    byId('diag-version').textContent = core.version();
    const choice = byId<HTMLSelectElement>('renderer-choice');
    choice.value = prefs.renderer;
    choice.addEventListener('change', () => {
      prefs.renderer = choice.value as RendererChoice;
      page.persistPrefs();
      void page.useRenderer(prefs.renderer);
    });
    events.on('renderer', (kind) => {
      byId('diag-renderer').textContent = kind === 'webgl2' ? '(using WebGL2)' : '(using Canvas 2D)';
    });
    session.on('frame', () => {
      const rate = session.drawn?.stepsPerSecond ?? 0;
      byId('diag-rate').textContent = rate ? `${formatNumber(rate)} steps/s` : 'paused';
    });
    // A debug control, shown only with `?debug` in the address (README, "Using the page").
    const crash = byId('simulate-crash');
    crash.hidden = !debugRequested();
    crash.addEventListener('click', () => sim.crash());
  },
};
