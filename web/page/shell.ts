// What the page does with the simulation worker's reports, beside the session's own: the banner
// (a refusal, a stall, a panic and its report), the large opening's notice, and the page's
// readiness marks that the benchmarks and tests read.
import type { SimEvents } from '../sim/client';
import { download } from '../widgets/dom';
import * as core from '../wasm';
import type { PageContext } from './context';
import type { LargeOpening } from './opening';
import type { SessionHost } from './session';
import { openDefault } from './start';
import type { Banner } from '../widgets/banner';

/** What the session asks of the page: a refusal in the banner, briefly, and a large opening's notice. */
export function sessionHost(banner: Banner, large: Pick<LargeOpening, 'begin'>): SessionHost {
  return {
    refused(brief, full) {
      const text = (message: string) => `This scenario cannot run: ${message}`;
      banner.report(text(brief), full && full !== brief ? { label: 'Show all of it', run: () => banner.report(text(full)) } : undefined);
    },
    large: (cells, build) => large.begin(cells, build),
  };
}

/** The simulation client's events for the page `page()` (made once the client exists). */
export function workerEvents(page: () => PageContext, large: Pick<LargeOpening, 'loaded' | 'failed' | 'active'>): SimEvents {
  /** Frames received and drawn, read by the page benchmark. */
  let framesDrawn = 0;
  return {
    loaded(id, layout, text, comparison) {
      const { banner, session } = page();
      large.loaded();
      // A scenario opened or the run was reset: an earlier message no longer applies.
      if (!banner.keep) banner.dismiss();
      banner.keep = false;
      session.loaded(id, layout, text, comparison);
    },
    frame(frame, drawn) {
      document.body.dataset.ready = 'true';
      framesDrawn++;
      document.body.dataset.frames = String(framesDrawn);
      document.body.dataset.work = JSON.stringify(drawn.work);
      document.body.dataset.wasmBytes = String(core.wasmBytes());
      page().session.setFrame(frame, drawn);
    },
    playing: (on) => page().session.setPlaying(on),
    viewer: (kind) => page().view.started(kind),
    drew(work) {
      document.body.dataset.work = JSON.stringify(work);
    },
    scenario: (text, comparison) => page().session.recorded(text, comparison),
    error(message, context) {
      const { banner, session } = page();
      if (context === 'load' && large.active) {
        large.failed();
        session.failed();
        if (!session.scenario) void openDefault(page());
      }
      if (context === 'apply') banner.report(`That did not work: ${message}`);
      else if (context === 'load') banner.report(`This scenario cannot run: ${message}`);
      else banner.report(message);
    },
    goal: (met, because, steps, credit) => page().events.emit('goal', { met, because, steps, credit }),
    stalled(ms) {
      const { banner, sim } = page();
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
      const { banner, session } = page();
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
  };
}
