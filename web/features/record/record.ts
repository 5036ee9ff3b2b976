// The "Record…" dialog: its form, its progress bar, its Cancel button, the file's name and its
// download. The recording itself (stepping, drawing, encoding) happens in the simulation worker
// (web/sim/encode.ts), where the view is drawn; the dialog receives the finished file.
import type { PageContext } from '../../page/context';
import { Cancelled, frameCount, type LegendEntry, type Progress, type Recorded, type RecordFormat, type RecordSettings } from '../../sim/record';
import { byId, displayText, download, markup } from '../../widgets/dom';
import dialogHtml from './dialog.html?raw';

/** What the dialog needs from the page. */
export interface RecordPage {
  /** The scenario's name and its seed, for the file name and the title overlay. */
  describe(): { name: string; seed: number };
  /** The colour legend of the model in view, for the legend overlay. */
  legend(): LegendEntry[];
  /** Draws at `scale` times the usual resolution (1 restores it). */
  setScale(scale: number): void;
  /** Records in the worker; rejects with Cancelled as soon as `signal` aborts. */
  record(settings: RecordSettings, signal: AbortSignal, progress: Progress): Promise<Recorded>;
}

/** A file name: letters, digits, dot, dash and underscore only, never empty. */
export function sanitizeName(name: string): string {
  const clean = name
    .normalize('NFKD')
    .replace(/[\u0300-\u036f]/g, '')
    .replace(/[^A-Za-z0-9._-]+/g, '-')
    .replace(/[-.]{2,}/g, '-')
    .replace(/^[-.]+|[-.]+$/g, '')
    .slice(0, 60);
  return clean || 'kumiki';
}

/**
 * `amas-L_seed1_steps0-400.webm`: the scenario, the seed and the steps the file shows; a 2x
 * recording ends in `_2x` (`amas-L_seed1_step0_2x.png`), so the two never take the same name.
 */
export function recordingName(name: string, seed: number, from: number, to: number, format: RecordFormat, scale = 1): string {
  const range = from === to ? `step${from}` : `steps${from}-${to}`;
  return `${sanitizeName(name)}_seed${seed}_${range}${scale === 1 ? '' : `_${scale}x`}.${format}`;
}

/** Records as set, offers the file for download, and resolves with its name. */
async function record(page: RecordPage, s: RecordSettings, signal: AbortSignal, progress: Progress): Promise<string> {
  const { name, seed } = page.describe();
  // The worker draws at the recording's scale from the next draw on: the resize reaches it first.
  page.setScale(s.scale);
  try {
    const { blob, from, to } = await page.record(s, signal, progress);
    const file = recordingName(name, seed, from, to, s.format, s.scale);
    download(file, blob, blob.type);
    return file;
  } finally {
    page.setScale(1);
  }
}

/** What the dialog needs, from the page context. */
export function recordPage({ session, view, sim }: PageContext): RecordPage {
  return {
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
  };
}

/** The "Record…" dialog: its form, its progress bar and its Cancel button. */
export function setupRecordDialog(page: RecordPage) {
  document.body.append(markup(dialogHtml));
  const dialog = byId<HTMLDialogElement>('record');
  const form = byId<HTMLFormElement>('record-form');
  const format = byId<HTMLSelectElement>('record-format');
  const steps = byId<HTMLInputElement>('record-steps');
  const every = byId<HTMLInputElement>('record-every');
  const scale = byId<HTMLSelectElement>('record-scale');
  const fps = byId<HTMLInputElement>('record-fps');
  const start = byId<HTMLButtonElement>('record-start');
  const cancel = byId<HTMLButtonElement>('record-cancel');
  const bar = byId('record-progress');
  const status = byId('record-status');
  let running: AbortController | null = null;

  const showProgress = (done: number, total: number) => {
    const pct = Math.round((100 * done) / Math.max(1, total));
    (bar.firstElementChild as HTMLElement).style.width = `${pct}%`;
    bar.setAttribute('aria-valuenow', String(pct));
    status.textContent = total > 1 ? `Frame ${done} of ${total}` : '';
  };
  const syncFields = () => {
    const still = format.value === 'png';
    byId('record-motion').hidden = still;
    for (const f of [steps, every, fps]) f.disabled = still || running !== null;
    cancel.textContent = running ? 'Cancel' : 'Close';
    const n = Math.max(1, Number(steps.value) || 1);
    const k = Math.max(1, Number(every.value) || 1);
    byId('record-summary').textContent = still
      ? 'One picture of the view as it stands.'
      : `${frameCount(n, k)} frames, ${(frameCount(n, k) / Math.max(1, Number(fps.value) || 1)).toFixed(1)} s long.`;
  };
  for (const f of [format, steps, every, fps]) f.addEventListener('input', syncFields);

  byId('open-record').addEventListener('click', () => {
    showProgress(0, 1);
    status.textContent = '';
    syncFields();
    dialog.showModal();
  });
  dialog.addEventListener('cancel', (e) => {
    // Escape during a recording cancels the recording first.
    if (running) {
      e.preventDefault();
      running.abort();
    }
  });
  cancel.addEventListener('click', () => {
    if (running) running.abort();
    else dialog.close();
  });
  form.addEventListener('submit', async (e) => {
    e.preventDefault();
    if (running || !form.reportValidity()) return;
    const settings: RecordSettings = {
      format: format.value as RecordFormat,
      steps: Math.max(1, Math.floor(Number(steps.value))),
      every: Math.max(1, Math.floor(Number(every.value))),
      scale: Number(scale.value) === 2 ? 2 : 1,
      fps: Math.min(60, Math.max(1, Number(fps.value))),
      overlays: {
        step: byId<HTMLInputElement>('record-overlay-step').checked,
        title: byId<HTMLInputElement>('record-overlay-title').checked ? displayText(page.describe().name, 100) : null,
        legend: byId<HTMLInputElement>('record-overlay-legend').checked ? page.legend() : null,
      },
    };
    running = new AbortController();
    start.disabled = true;
    scale.disabled = format.disabled = true;
    syncFields();
    status.textContent = 'Recording…';
    try {
      const file = await record(page, settings, running.signal, showProgress);
      status.textContent = `Saved ${file}`;
    } catch (err) {
      status.textContent =
        err instanceof Cancelled ? 'Cancelled: nothing was saved.' : `The recording failed: ${err instanceof Error ? err.message : String(err)}`;
    } finally {
      running = null;
      start.disabled = false;
      scale.disabled = format.disabled = false;
      syncFields();
    }
  });
}
