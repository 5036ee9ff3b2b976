// The Grade view (from the gallery): a teacher pastes the class's hand-in links or opens a form's
// export (CSV, text or .xlsx, read by the lab's reader as `kumiki check --file` reads it: quoted
// cells over several lines, a workbook's first sheet; any other file refused with one message),
// names the exercise (its link or a lesson; left empty, the one most hand-ins carry, shown), and
// gets a table graded as `kumiki check` grades: every row replayed within the exercise's budget in
// wasm workers on this machine, with its points per credit part, the student's answer and record,
// progress, cancel and the CLI's CSV. Nothing is sent anywhere.
import type { ClassExercise } from '../../contract.gen';
import { classExercise, gradeTableCsv, loadLab, readHandins } from '../../lab';
import type { PageContext } from '../../page/context';
import { byId, download, markup } from '../../widgets/dom';
import * as core from '../../wasm';
import dialogHtml from './dialog.html?raw';
import { nameText, tallyText, verdict } from './handins';
import { GradePool, type ReadClass } from './pool';
import { GradedRows } from './rows';
import type { GradedRow } from './worker';
import { GradeTable } from './table';

/** How often the progress bar and the rows in view are drawn while grading, in milliseconds. */
const DRAW_MS = 250;
/** How often the tally and the row running longest are said while grading, in milliseconds. */
const SAY_MS = 1000;
/** The largest text file shown in the box, in bytes; a larger one is graded as it is, unshown. */
const BOX_BYTES = 1 << 20;

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
  const running = byId('grade-running');
  const skip = byId<HTMLButtonElement>('grade-skip');
  const table = new GradeTable(byId('grade-scroller'), byId<HTMLTableElement>('grade-table'), byId('grade-rows'));

  let pool: GradePool | null = null;
  let rows = new GradedRows(0);
  /** The students' names in the class's file, for the row being graded. */
  let students: string[] = [];
  /** The row shown as being graded (the one Skip skips); null when none. */
  let current: number | null = null;
  /** The class's exercise the rows in the table were graded by. */
  let graded: ClassExercise | null = null;
  /** A file that is not UTF-8 text (a workbook, a UTF-16 export), read as it is; null: the box's text. */
  let opened: { name: string; bytes: Uint8Array } | null = null;

  // The gallery's "Grade hand-ins…" opens it.
  page.events.on('open', ({ what }) => {
    if (what !== 'grade') return;
    dialog.showModal();
    input.focus();
  });

  // The bar grows by scaling, on its own layer: a change of width (and its transition) laid out
  // and painted the dialog every frame, a fifth of the page's thread while a class graded.
  const bar = progress.firstElementChild as HTMLElement;
  Object.assign(bar.style, { width: '100%', transformOrigin: 'left', transform: 'scaleX(0)', transition: 'none', willChange: 'transform' });
  const setProgress = (done: number, total: number) => {
    const pct = total ? (100 * done) / total : 0;
    bar.style.transform = `scaleX(${pct / 100})`;
    // Said in whole percents: changed only when it changes (each change restyles the page).
    const said = pct.toFixed(0);
    if (progress.getAttribute('aria-valuenow') !== said) progress.setAttribute('aria-valuenow', said);
  };

  /** Shows the row running longest ("Grading row 12: Ada, step 40,000, 3.2 s"), the one Skip skips. */
  const showRunning = () => {
    const r = pool?.running() ?? null;
    current = r?.index ?? null;
    skip.disabled = r === null;
    if (!r) {
      running.textContent = '';
      return;
    }
    const name = nameText(students[r.index] ?? '').shown;
    const seconds = (performance.now() - r.since) / 1000;
    const step = r.steps === null ? '' : `, step ${r.steps.toLocaleString('en-US')}`;
    const text = `Grading row ${(r.index + 1).toLocaleString('en-US')}: ${name}${step}${seconds >= 1 ? `, ${seconds.toFixed(0)} s` : ''}`;
    if (running.textContent !== text) running.textContent = text;
  };

  const finish = (text: string) => {
    pool?.stop();
    pool = null;
    start.disabled = false;
    cancel.disabled = true;
    exportCsv.disabled = rows.done === 0;
    showRunning();
    table.setGrading(false);
    status.textContent = text;
  };

  /** A grading refused before it started: the previous table and tally go, and `message` says why. */
  const refuse = (message: string) => {
    pool?.stop();
    pool = null;
    rows = new GradedRows(0);
    graded = null;
    table.reset(rows, false);
    setProgress(0, 0);
    finish(message);
  };

  const readFile = async (f: File) => {
    const bytes = new Uint8Array(await f.arrayBuffer());
    const text = bytes.length <= BOX_BYTES ? utf8Text(bytes) : null;
    if (text !== null) {
      opened = null;
      input.value = text;
      fileNote.textContent = '';
      return;
    }
    if (bytes.length > BOX_BYTES && utf8Text(bytes) !== null) {
      // A large class's export stays out of the box (laying out megabytes of text there takes the
      // page's thread for seconds): it is read as it is, in the grading workers.
      opened = { name: f.name, bytes };
      input.value = '';
      fileNote.textContent = `${f.name} (${(bytes.length / 2 ** 20).toFixed(1)} MB of text), read as it is (typing in the box above replaces it).`;
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
    let read: ReadClass;
    start.disabled = true;
    status.textContent = 'Reading the hand-ins…';
    // A worker a core, started now: the first reads the file while the others load, then all grade.
    const size = Math.max(1, Math.min(8, navigator.hardwareConcurrency || 2));
    /** What the pool hears, set once the class is read. */
    let heard = (_batch: GradedRow[]) => {};
    pool?.stop();
    const reading = new GradePool({
      rows: (batch) => heard(batch),
      failed: (message) => finish(`Grading stopped: ${message}`),
    });
    pool = reading;
    try {
      read = await reading.read(opened ? opened.bytes : new TextEncoder().encode(input.value), exerciseInput.value.trim() || null, size);
    } catch (e) {
      if (pool === reading) refuse(`Not graded: ${core.message(e)}`);
      return;
    }
    if (read.type === 'refused') {
      if (read.exercise) showExercise(read.message);
      refuse(`Not graded: ${read.message}`);
      return;
    }
    const handins = read.handins;
    students = read.students;
    const cls = read.cls;
    if (!handins.length || !cls) {
      refuse('Not graded: there is no hand-in in it (blank lines and # comments are skipped).');
      return;
    }
    showExercise(cls);
    graded = cls;
    const total = handins.length;
    const classRows = new GradedRows(total);
    rows = classRows;
    // The page shows progress four times a second, not once a batch of rows nor once a frame: each
    // change is the page's thread's work (style, layout, paint) and the compositor's, on the cores
    // the workers grade on, and a key pressed meanwhile waits for it. The bar scales on its own
    // layer; the table redraws only when a row in view was graded; the texts change once a second.
    let drawing = 0;
    const tick = () => {
      drawing = window.setTimeout(() => requestAnimationFrame(draw), DRAW_MS);
    };
    const draw = () => {
      // Finished or cancelled meanwhile: the final status stays.
      if (!pool) return;
      const done = classRows.done;
      if (done !== shown) {
        shown = done;
        setProgress(done, total);
        table.refresh();
      }
      // The tally (a live region) and the row running longest (its seconds): once a second.
      if (performance.now() - said > SAY_MS) {
        said = performance.now();
        if (told !== done) {
          told = done;
          status.textContent = `Graded ${done.toLocaleString('en-US')} of ${total.toLocaleString('en-US')}: ${tallyText(classRows.tally)}.`;
        }
        showRunning();
      }
      tick();
    };
    /** The rows graded when the page last drew, and when it last said the tally. */
    let shown = 0;
    let said = 0;
    /** The rows graded when the tally was last said. */
    let told = 0;
    heard = (batch) => {
      for (const r of batch) classRows.record(r.index, r.json, r.verdict);
      if (classRows.done === total) {
        clearTimeout(drawing);
        setProgress(total, total);
        finish(`${total.toLocaleString('en-US')} hand-ins: ${tallyText(classRows.tally)}.`);
      }
    };
    skipRow = () => {
      const index = current;
      const row = index === null ? null : pool?.skip(index);
      if (index !== null && row) heard([{ index, json: JSON.stringify(row), verdict: verdict(row) }]);
      if (pool) showRunning();
    };
    // The workers first; the table in a task of its own, so the page's thread never holds
    // receiving the class and drawing its first rows in one.
    reading.grade(handins, cls.teacher);
    await new Promise((r) => setTimeout(r));
    if (pool !== reading) {
      // Finished or stopped meanwhile: its status stays.
      table.reset(classRows, false);
      return;
    }
    cancel.disabled = false;
    exportCsv.disabled = true;
    setProgress(0, total);
    table.reset(classRows, true);
    tick();
    status.textContent = `Grading ${total.toLocaleString('en-US')} hand-ins on this machine…`;
  });

  /** Skips the row shown as being graded (set for each grading). */
  let skipRow = () => {};
  skip.addEventListener('click', () => skipRow());

  cancel.addEventListener('click', () => {
    const done = rows.done;
    finish(`Cancelled after ${done.toLocaleString('en-US')} of ${rows.length.toLocaleString('en-US')} hand-ins; those graded are in the table and the export.`);
  });
  dialog.addEventListener('close', () => {
    if (pool) finish('Cancelled.');
  });

  exportCsv.addEventListener('click', async () => {
    // The rows were read and graded in workers: the page's own copy of the lab writes the CSV.
    await loadLab();
    if (graded) download('kumiki-grades.csv', gradeTableCsv(rows.toJson(), graded.teacher), 'text/csv');
  });
}
