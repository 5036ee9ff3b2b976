// The Grade view (from the gallery): a teacher pastes the class's hand-in links or opens a form's
// export (CSV, text or .xlsx, read by the lab's reader as `kumiki check --file` reads it: quoted
// cells over several lines, a workbook's first sheet; any other file refused with one message),
// names the exercise (its link or a lesson; left empty, the one most hand-ins carry, shown), and
// gets a table graded as `kumiki check` grades: every row replayed within the exercise's budget in
// wasm workers on this machine, with its points per credit part, the student's answer and record,
// progress, cancel and the CLI's CSV. Nothing is sent anywhere.
import type { ClassExercise, Handin2 } from '../../contract.gen';
import { classExercise, gradeTableCsv, labModule, loadLab, readHandins } from '../../lab';
import type { PageContext } from '../../page/context';
import { byId, clear, download, el, formatNumber, markup } from '../../widgets/dom';
import * as core from '../../wasm';
import dialogHtml from './dialog.html?raw';
import {
  answerText,
  count,
  emptyTally,
  type GradeRow,
  isGraded,
  nameText,
  partsText,
  pointsText,
  reasonText,
  recordText,
  studentOf,
  tallyText,
  verdict,
} from './handins';
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
/** The table's columns: a row not graded yet spans those after its number. */
const COLUMNS = 10;

/** Grades `handins` by the class's exercise (`teacher`) on `size` workers; `row` hears each one as it comes, in any order. */
class GradePool {
  private workers: Worker[] = [];
  private next = 0;
  private stopped = false;

  constructor(
    private readonly handins: Handin2[],
    private readonly teacher: string,
    private readonly on: { row(index: number, row: GradeRow): void; failed(message: string): void },
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
    worker.postMessage({ type: 'setup', module, teacher: this.teacher } satisfies ToGradeWorker);
    this.workers.push(worker);
  }

  private handOut(worker: Worker) {
    if (this.stopped || this.next >= this.handins.length) return;
    const index = this.next++;
    worker.postMessage({ type: 'grade', index, handin: JSON.stringify(this.handins[index]) } satisfies ToGradeWorker);
  }

  stop() {
    this.stopped = true;
    for (const w of this.workers) w.terminate();
    this.workers = [];
  }
}

/** A file's text when it is UTF-8 text (shown in the box); null for anything else (read as bytes). */
function utf8Text(bytes: Uint8Array): string | null {
  try {
    const text = new TextDecoder('utf-8', { fatal: true }).decode(bytes);
    return text.includes('\0') ? null : text;
  } catch {
    return null;
  }
}

export function setupGrade(page: PageContext) {
  document.body.append(markup(dialogHtml));
  const dialog = byId<HTMLDialogElement>('grade');
  const input = byId<HTMLTextAreaElement>('grade-input');
  const file = byId<HTMLInputElement>('grade-file');
  const fileNote = byId('grade-file-note');
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
  let rows: GradeRow[] = [];
  /** The class's exercise the rows in the table were graded by. */
  let graded: ClassExercise | null = null;
  /** The first row of the page of the table in view. */
  let pageStart = 0;
  /** A row of the page in view was graded since the table was drawn. */
  let pageDirty = false;
  /** A file that is not UTF-8 text (a workbook, a UTF-16 export), read as it is; null: the box's text. */
  let opened: { name: string; bytes: Uint8Array } | null = null;

  // The gallery's "Grade hand-ins…" opens it.
  page.events.on('open', ({ what }) => {
    if (what !== 'grade') return;
    dialog.showModal();
    input.focus();
  });

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

  /** A grading refused before it started: the previous table and tally go, and `message` says why. */
  const refuse = (message: string) => {
    pool?.stop();
    pool = null;
    rows = [];
    graded = null;
    pageStart = 0;
    setProgress(0, 0);
    finish(message);
  };

  const readFile = async (f: File) => {
    const bytes = new Uint8Array(await f.arrayBuffer());
    const text = utf8Text(bytes);
    if (text !== null) {
      opened = null;
      input.value = text;
      fileNote.textContent = '';
      return;
    }
    // A workbook, a UTF-16 export, or something else: the lab's reader says which, at once.
    try {
      await loadLab();
      const found = readHandins(bytes);
      opened = { name: f.name, bytes };
      input.value = '';
      fileNote.textContent = `${f.name}: ${found.length.toLocaleString('en-US')} hand-in${found.length === 1 ? '' : 's'}, read as it is (typing in the box above replaces it).`;
    } catch (e) {
      opened = null;
      fileNote.textContent = '';
      refuse(`${f.name}: ${core.message(e)}`);
    }
  };
  file.addEventListener('change', () => {
    const f = file.files?.[0];
    if (f) void readFile(f);
    file.value = '';
  });
  input.addEventListener('input', () => {
    opened = null;
    fileNote.textContent = '';
  });
  input.addEventListener('dragover', (e) => e.preventDefault());
  input.addEventListener('drop', (e) => {
    const f = e.dataTransfer?.files[0];
    if (!f) return;
    e.preventDefault();
    void readFile(f);
  });

  /** Shows the class's exercise, or why it cannot grade. */
  const showExercise = (found: ClassExercise | string) => {
    const ok = typeof found !== 'string';
    exerciseInput.setAttribute('aria-invalid', String(!ok));
    exerciseNote.textContent = ok ? `Graded by ${found.describe}${found.question ? `. It asks: ${found.question}` : ''}.` : found;
  };
  exerciseInput.addEventListener('change', async () => {
    const text = exerciseInput.value.trim();
    if (!text) {
      exerciseInput.setAttribute('aria-invalid', 'false');
      exerciseNote.textContent = 'None given: the exercise most hand-ins carry grades them all.';
      return;
    }
    try {
      await loadLab();
      showExercise(classExercise(text, []));
    } catch (e) {
      showExercise(core.message(e));
    }
  });

  start.addEventListener('click', async () => {
    if (!opened && !input.value.trim()) {
      refuse('Paste the hand-in links first, one a line, or open an export.');
      return;
    }
    let handins: Handin2[];
    let cls: ClassExercise;
    try {
      await loadLab();
      handins = readHandins(opened ? opened.bytes : new TextEncoder().encode(input.value));
    } catch (e) {
      refuse(`Not graded: ${core.message(e)}`);
      return;
    }
    if (!handins.length) {
      refuse('Not graded: there is no hand-in in it (blank lines and # comments are skipped).');
      return;
    }
    try {
      cls = classExercise(
        exerciseInput.value.trim() || null,
        handins.flatMap((h) => (h.link ? [h.link] : [])),
      );
    } catch (e) {
      showExercise(core.message(e));
      refuse(`Not graded: ${core.message(e)}`);
      return;
    }
    showExercise(cls);
    graded = cls;
    rows = new Array(handins.length);
    pageStart = 0;
    let done = 0;
    const total = handins.length;
    const tally = emptyTally();
    // The page shows progress once a frame, not once a hand-in: a row a message would keep the
    // page's thread, which hands out the work, busy laying out the table.
    let drawing = 0;
    const draw = () => {
      drawing = 0;
      // Finished or cancelled meanwhile: the final status stays.
      if (!pool) return;
      setProgress(done, total);
      status.textContent = `Graded ${done.toLocaleString('en-US')} of ${total.toLocaleString('en-US')}: ${tallyText(tally)}.`;
      if (pageDirty) showPage();
    };
    const record = (index: number, row: GradeRow) => {
      rows[index] = row;
      if (index >= pageStart && index < pageStart + PAGE_ROWS) pageDirty = true;
      count(tally, row);
      done++;
      if (done === total) {
        setProgress(done, total);
        finish(`${total.toLocaleString('en-US')} hand-ins: ${tallyText(tally)}.`);
      } else if (!drawing) drawing = requestAnimationFrame(draw);
    };
    start.disabled = true;
    cancel.disabled = false;
    exportCsv.disabled = true;
    setProgress(0, total);
    const size = Math.max(1, Math.min(8, (navigator.hardwareConcurrency || 2) - 1));
    pool = new GradePool(handins, cls.teacher, {
      row: record,
      failed: (message) => finish(`Grading stopped: ${message}`),
    });
    showPage();
    status.textContent = `Grading ${total.toLocaleString('en-US')} hand-ins on this machine…`;
    pool.start(size).catch((e: unknown) => finish(`Grading could not start: ${core.message(e)}`));
  });

  cancel.addEventListener('click', () => {
    const done = rows.reduce((n, r) => n + (r ? 1 : 0), 0);
    finish(`Cancelled after ${done.toLocaleString('en-US')} of ${rows.length.toLocaleString('en-US')} hand-ins; those graded are in the table and the export.`);
  });
  dialog.addEventListener('close', () => {
    if (pool) finish('Cancelled.');
  });

  exportCsv.addEventListener('click', () => {
    if (graded) download('kumiki-grades.csv', gradeTableCsv(JSON.stringify(rows.filter(Boolean)), graded.teacher), 'text/csv');
  });
}

/** A row not graded yet: still to come, or left when grading was cancelled. */
function pendingRow(handin: number, grading: boolean): HTMLTableRowElement {
  return el(
    'tr',
    { class: 'pending' },
    el('td', { text: String(handin) }),
    el('td', { colspan: String(COLUMNS - 1), class: 'hint', text: grading ? 'being graded…' : 'not graded' }),
  );
}

/** Text a student wrote (a name, an answer), isolated from the table's direction and cut, whole on hover. */
function studentText(text: { shown: string; full: string }): HTMLElement {
  return el('bdi', { dir: 'auto', title: text.full !== text.shown ? text.full : undefined, text: text.shown });
}

function tableRow(r: GradeRow): HTMLTableRowElement {
  const v = verdict(r);
  const metrics = isGraded(r)
    ? Object.entries(r.goal_metrics)
        .map(([k, value]) => `${k.replace(/_/g, ' ')} ${formatNumber(value)}`)
        .join(', ')
    : '';
  const open = r.link
    ? el('a', {
        href: r.link.startsWith('http') ? r.link : `${location.pathname}${r.link.startsWith('#') ? '' : '#'}${r.link}`,
        target: '_blank',
        rel: 'noopener',
        text: 'open',
        'aria-label': `Open hand-in ${r.handin}`,
      })
    : '';
  const parts = partsText(r);
  const points = el('td', { class: 'grade-points' }, pointsText(r));
  if (parts.length) points.append(el('ul', {}, ...parts.map((p) => el('li', { text: p }))));
  const answer = answerText(r);
  const answerCell = el('td', { class: 'grade-answer' });
  if (answer.shown) answerCell.append(studentText(answer));
  const said = recordText(r);
  if (said) answerCell.append(el('span', { class: 'hint', text: said }));
  return el(
    'tr',
    { class: v === 'could not be graded' ? 'error' : v === 'met' ? 'met' : v === 'over budget' ? 'over' : 'unmet' },
    el('td', { text: String(r.handin) }),
    el('td', { class: 'grade-student' }, studentText(nameText(studentOf(r)))),
    el('td', { class: 'grade-verdict', text: v }),
    points,
    el('td', { text: isGraded(r) ? r.steps.toLocaleString('en-US') : '' }),
    el('td', { text: metrics }),
    el('td', { class: 'reason', text: reasonText(r) }),
    answerCell,
    el('td', {}, el('code', { text: isGraded(r) ? r.hash : '' })),
    el('td', {}, open),
  );
}
