// The Grade view (from the gallery): a teacher pastes the class's hand-in links or drops a form's
// CSV or text export, names the exercise (its link or a lesson; or each hand-in's own), and gets a
// table graded as `kumiki check` grades: every hand-in replayed in wasm workers on this machine,
// with progress, cancel and a CSV export. Nothing is sent anywhere.
import type { Graded } from '../../contract.gen';
import { exerciseTitle, labModule, loadLab } from '../../lab';
import type { PageContext } from '../../page/context';
import { byId, clear, download, el, formatNumber, markup } from '../../widgets/dom';
import * as core from '../../wasm';
import dialogHtml from './dialog.html?raw';
import { type GradedRow, gradesCsv, type Handin, parseHandins } from './handins';
import type { FromGradeWorker, ToGradeWorker } from './worker';

/**
 * Rows the table shows at a time: a class of 10 000 is paged, so the page's memory and its work
 * per frame stay the same however large the class (the CSV export has every row).
 */
const PAGE_ROWS = 200;
/**
 * Hand-ins each worker holds at once: the next one is already there when it finishes, so the
 * workers never wait for the page's thread to hand one out.
 */
const IN_FLIGHT = 4;

/** Grades `handins` on `size` workers; `row` hears each one as it comes, in any order. */
class GradePool {
  private workers: Worker[] = [];
  private next = 0;
  private stopped = false;

  constructor(
    private readonly handins: Handin[],
    private readonly exercise: string | null,
    private readonly on: { row(index: number, row: Graded): void; failed(message: string): void },
  ) {}

  async start(size: number) {
    const module = await labModule();
    if (this.stopped) return;
    const n = Math.max(1, Math.min(size, this.handins.length));
    for (let w = 0; w < n; w++) this.spawn(module, w);
  }

  private spawn(module: WebAssembly.Module, w: number) {
    const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: `kumiki-grade-${w}` });
    worker.onmessage = (e: MessageEvent<FromGradeWorker>) => {
      if (this.stopped) return;
      const msg = e.data;
      if (msg.type === 'failed') {
        this.stop();
        this.on.failed(msg.message);
        return;
      }
      if (msg.type === 'ready') for (let k = 1; k < IN_FLIGHT; k++) this.handOut(worker);
      this.handOut(worker);
      if (msg.type === 'graded') this.on.row(msg.index, msg.row);
    };
    worker.onerror = (e) => {
      this.stop();
      this.on.failed(`a grading worker failed: ${e.message}`);
    };
    worker.postMessage({ type: 'setup', module, exercise: this.exercise } satisfies ToGradeWorker);
    this.workers.push(worker);
  }

  private handOut(worker: Worker) {
    // Rows without a link are graded on the page at once; the workers take only links.
    while (this.next < this.handins.length && this.handins[this.next].link === null) this.next++;
    if (this.stopped || this.next >= this.handins.length) return;
    const index = this.next++;
    worker.postMessage({ type: 'grade', index, link: this.handins[index].link as string } satisfies ToGradeWorker);
  }

  stop() {
    this.stopped = true;
    for (const w of this.workers) w.terminate();
    this.workers = [];
  }
}

export function setupGrade(page: PageContext) {
  document.body.append(markup(dialogHtml));
  const dialog = byId<HTMLDialogElement>('grade');
  const input = byId<HTMLTextAreaElement>('grade-input');
  const file = byId<HTMLInputElement>('grade-file');
  const exerciseInput = byId<HTMLInputElement>('grade-exercise');
  const exerciseNote = byId('grade-exercise-note');
  const start = byId<HTMLButtonElement>('grade-start');
  const cancel = byId<HTMLButtonElement>('grade-cancel');
  const exportCsv = byId<HTMLButtonElement>('grade-export');
  const progress = byId('grade-progress');
  const status = byId('grade-status');
  const body = byId('grade-rows');

  const prev = byId<HTMLButtonElement>('grade-prev');
  const next = byId<HTMLButtonElement>('grade-next');
  const pageLabel = byId('grade-page');

  let pool: GradePool | null = null;
  let rows: GradedRow[] = [];
  /** The first row of the page of the table in view. */
  let pageStart = 0;
  /** A row of the page in view was graded since the table was drawn. */
  let pageDirty = false;

  // The gallery's "Grade hand-ins…" opens it.
  page.events.on('open', ({ what }) => {
    if (what !== 'grade') return;
    dialog.showModal();
    input.focus();
  });

  const readFile = async (f: File) => {
    input.value = await f.text();
  };
  file.addEventListener('change', () => {
    const f = file.files?.[0];
    if (f) void readFile(f);
    file.value = '';
  });
  input.addEventListener('dragover', (e) => e.preventDefault());
  input.addEventListener('drop', (e) => {
    const f = e.dataTransfer?.files[0];
    if (!f) return;
    e.preventDefault();
    void readFile(f);
  });

  /** The teacher's exercise, checked: null for each hand-in's own; false when it cannot grade. */
  const exercise = async (): Promise<string | null | false> => {
    const text = exerciseInput.value.trim();
    exerciseNote.textContent = '';
    exerciseInput.setAttribute('aria-invalid', 'false');
    if (!text) return null;
    try {
      await loadLab();
      exerciseNote.textContent = `Graded by “${exerciseTitle(text)}”: its goal and its locks.`;
      return text;
    } catch (e) {
      exerciseNote.textContent = core.message(e);
      exerciseInput.setAttribute('aria-invalid', 'true');
      return false;
    }
  };
  exerciseInput.addEventListener('change', () => void exercise());

  const setProgress = (done: number, total: number) => {
    const pct = total ? (100 * done) / total : 0;
    (progress.firstElementChild as HTMLElement).style.width = `${pct}%`;
    progress.setAttribute('aria-valuenow', pct.toFixed(0));
  };

  /** Draws the page of the table in view: its graded rows, and those still to come. */
  const showPage = () => {
    pageDirty = false;
    clear(body);
    const end = Math.min(rows.length, pageStart + PAGE_ROWS);
    for (let i = pageStart; i < end; i++) body.append(rows[i] ? tableRow(rows[i]) : pendingRow(i + 1, pool !== null));
    pageLabel.textContent = rows.length
      ? `Rows ${(pageStart + 1).toLocaleString('en-US')} to ${end.toLocaleString('en-US')} of ${rows.length.toLocaleString('en-US')}`
      : '';
    prev.disabled = pageStart === 0;
    next.disabled = end >= rows.length;
  };
  prev.addEventListener('click', () => {
    pageStart = Math.max(0, pageStart - PAGE_ROWS);
    showPage();
  });
  next.addEventListener('click', () => {
    if (pageStart + PAGE_ROWS < rows.length) pageStart += PAGE_ROWS;
    showPage();
  });

  const finish = (text: string) => {
    pool?.stop();
    pool = null;
    start.disabled = false;
    cancel.disabled = true;
    exportCsv.disabled = !rows.some(Boolean);
    showPage();
    status.textContent = text;
  };

  start.addEventListener('click', async () => {
    const teacher = await exercise();
    if (teacher === false) return;
    const handins = parseHandins(input.value);
    if (!handins.length) {
      status.textContent = 'Paste the hand-in links first, one a line, or open an export.';
      return;
    }
    rows = new Array(handins.length);
    pageStart = 0;
    let done = 0;
    const total = handins.length;
    const tally = { met: 0, unmet: 0, errors: 0 };
    // The page shows progress once a frame, not once a hand-in: a row a message would keep the
    // page's thread, which hands out the work, busy laying out the table.
    let drawing = 0;
    const draw = () => {
      drawing = 0;
      // Finished or cancelled meanwhile: the final status stays.
      if (!pool) return;
      setProgress(done, total);
      status.textContent = `Graded ${done.toLocaleString('en-US')} of ${total.toLocaleString('en-US')}: ${tally.met} met, ${tally.unmet} not met, ${tally.errors} could not be graded.`;
      if (pageDirty) showPage();
    };
    const record = (index: number, graded: Graded) => {
      const h = handins[index];
      const row: GradedRow = { ...graded, handin: index + 1, student: h.student || ('name' in graded ? graded.name : ''), link: h.link };
      rows[index] = row;
      if (index >= pageStart && index < pageStart + PAGE_ROWS) pageDirty = true;
      if (row.error !== undefined) tally.errors++;
      else if (row.met) tally.met++;
      else tally.unmet++;
      done++;
      if (done === total) {
        setProgress(done, total);
        finish(`${total.toLocaleString('en-US')} hand-ins: ${tally.met} met, ${tally.unmet} not met, ${tally.errors} could not be graded.`);
      } else if (!drawing) drawing = requestAnimationFrame(draw);
    };
    start.disabled = true;
    cancel.disabled = false;
    exportCsv.disabled = true;
    setProgress(0, total);
    showPage();
    status.textContent = `Grading ${total.toLocaleString('en-US')} hand-ins on this machine…`;
    for (const [i, h] of handins.entries()) if (h.link === null) record(i, { error: `row ${h.row} holds no Kumiki link: ${h.text.slice(0, 80)}` });
    if (done === total) return;
    const size = Math.max(1, Math.min(8, (navigator.hardwareConcurrency || 2) - 1));
    pool = new GradePool(handins, teacher, {
      row: record,
      failed: (message) => finish(`Grading stopped: ${message}`),
    });
    pool.start(size).catch((e: unknown) => finish(`Grading could not start: ${core.message(e)}`));
  });

  cancel.addEventListener('click', () => {
    const done = rows.reduce((n, r) => n + (r ? 1 : 0), 0);
    finish(`Cancelled after ${done.toLocaleString('en-US')} of ${rows.length.toLocaleString('en-US')} hand-ins; those graded are in the table and the export.`);
  });
  dialog.addEventListener('close', () => {
    if (pool) finish('Cancelled.');
  });

  exportCsv.addEventListener('click', () => download('kumiki-grades.csv', gradesCsv(rows.filter(Boolean)), 'text/csv'));
}

/** A row not graded yet: still to come, or left when grading was cancelled. */
function pendingRow(handin: number, grading: boolean): HTMLTableRowElement {
  return el(
    'tr',
    { class: 'pending' },
    el('td', { text: String(handin) }),
    el('td', { colspan: '7', class: 'hint', text: grading ? 'being graded…' : 'not graded' }),
  );
}

function tableRow(r: GradedRow): HTMLTableRowElement {
  const verdict = r.error !== undefined ? 'could not be graded' : r.met ? 'met' : 'not met';
  const metrics = Object.entries(r.goal_metrics ?? {})
    .map(([k, v]) => `${k.replace(/_/g, ' ')} ${formatNumber(v)}`)
    .join(', ');
  const open = r.link
    ? el('a', {
        href: r.link.startsWith('http') ? r.link : `${location.pathname}${r.link.startsWith('#') ? '' : '#'}${r.link}`,
        target: '_blank',
        rel: 'noopener',
        text: 'open',
        'aria-label': `Open hand-in ${r.handin}`,
      })
    : '';
  const reason = r.error ?? [r.because, r.changed?.length ? `changed: ${r.changed.join(', ')}` : ''].filter(Boolean).join('. ');
  return el(
    'tr',
    { class: r.error !== undefined ? 'error' : r.met ? 'met' : 'unmet' },
    el('td', { text: String(r.handin) }),
    el('td', { text: r.student || '(no name)' }),
    el('td', { class: 'grade-verdict', text: verdict }),
    el('td', { text: r.steps === undefined ? '' : r.steps.toLocaleString('en-US') }),
    el('td', { text: metrics }),
    el('td', { class: 'reason', text: reason }),
    el('td', {}, el('code', { text: r.hash ?? '' })),
    el('td', {}, open),
  );
}
