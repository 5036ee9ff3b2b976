// A grading worker: grades the rows of a class's file it is handed, each as `kumiki check` does
// (the core's grading::Replay through the lab's RowReplay): replayed within the exercise's budget
// in slices, and judged by the class's exercise. Between slices it reads its clock (the time
// budget) and, for a row that runs long, tells the page which row and which step, so the teacher
// sees a stuck row and can skip it (the page then ends this worker). Graded rows go back in
// batches, not one message a row, each row as JSON with its verdict: the page parses only the rows
// it shows. The first worker of a pool reads the class's file first. It runs the page's compiled
// lab module, handed over at setup: nothing is downloaded, and no hand-in leaves the machine.
import type { ClassExercise, Handin2 } from '../../contract.gen';
import init, { class_exercise, panic_message, RowReplay, read_handins } from '../../pkg/kumiki_lab.js';
import { type GradeRow, type Verdict, verdict } from './handins';

/** A graded row as it crosses to the page: its place in the table, the row as JSON, and its verdict (for the tally). */
export interface GradedRow {
  index: number;
  json: string;
  verdict: Verdict;
}

export type ToGradeWorker =
  /** The lab module. */
  | { type: 'setup'; module: WebAssembly.Module }
  /** The class's exercise (its `ClassExercise.teacher`), before the first rows. */
  | { type: 'teacher'; teacher: string }
  /** Rows of the class's file (`Handin2` records as JSON), each with its place in the table. */
  | { type: 'grade'; rows: { index: number; handin: string }[] }
  /** A class's file to read, and the teacher's exercise (null: the one most hand-ins carry). */
  | { type: 'read'; bytes: Uint8Array; exercise: string | null };
export type FromGradeWorker =
  | { type: 'ready' }
  /** Rows graded since the last batch, in the order they were handed out. */
  | { type: 'graded'; rows: GradedRow[] }
  /** The row this worker has been replaying for a while, and its step. */
  | { type: 'running'; index: number; steps: number }
  | { type: 'failed'; message: string }
  /**
   * The file's hand-ins (each `Handin2` as JSON, one after another as UTF-8, `ends` saying
   * where each ends), their students' names, and the class's exercise; or why not (`exercise`:
   * the exercise is what is wrong).
   */
  | { type: 'read'; handins: Uint8Array; ends: Uint32Array; students: string[]; cls: ClassExercise | null }
  | { type: 'refused'; message: string; exercise: boolean };

/** Graded rows are sent at least this often, in milliseconds (and whenever the worker runs out of rows). */
const BATCH_MS = 100;
/** A row running longer than this, in milliseconds, is reported, and again this often. */
const REPORT_MS = 250;
/** The first slice of a row, in steps; a slice shorter than SLICE_MS doubles the next, up to MAX_SLICE. */
const FIRST_SLICE = 64;
const SLICE_MS = 10;
const MAX_SLICE = 1 << 16;

const scope = self as unknown as DedicatedWorkerGlobalScope;
const post = (m: FromGradeWorker) => scope.postMessage(m);
let teacher = '';
/** The lab module's instantiation (a file to read may arrive before it is done). */
let loaded: Promise<unknown> = Promise.resolve();
/** Rows handed out and not graded yet, in order. */
const queue: { index: number; handin: string }[] = [];
/** Rows graded and not sent yet. */
let graded: GradedRow[] = [];
let sent = 0;
let working = false;

/** Sends the rows graded so far. */
function flush() {
  if (graded.length) post({ type: 'graded', rows: graded });
  graded = [];
  sent = performance.now();
}

/** Grades one row in slices within its time budget, reporting it when it runs long. */
function gradeOne(index: number, handin: string): GradeRow {
  const started = performance.now();
  const replay = new RowReplay(handin, teacher);
  const budget = replay.time_budget();
  let slice = FIRST_SLICE;
  let reported = started;
  for (;;) {
    const before = performance.now();
    if (replay.advance(slice)) return replay.finish(false) as GradeRow;
    const now = performance.now();
    if (budget !== undefined && (now - started) / 1000 > budget) return replay.finish(true) as GradeRow;
    if (now - before < SLICE_MS) slice = Math.min(slice * 2, MAX_SLICE);
    if (now - reported > REPORT_MS) {
      reported = now;
      // The rows graded before it go first: the page then knows this one is the one running.
      flush();
      post({ type: 'running', index, steps: replay.steps() });
    }
  }
}

/** Adds a graded row to the next batch. */
function add(index: number, row: GradeRow) {
  graded.push({ index, json: JSON.stringify(row), verdict: verdict(row) });
}

/** Grades the queue; messages that arrive meanwhile (more rows) wait for it, as the page expects. */
function work() {
  working = true;
  while (queue.length) {
    const { index, handin } = queue.shift() as { index: number; handin: string };
    try {
      // Graded first, then added: a long row sends the rows before it (and replaces `graded`) as it runs.
      add(index, gradeOne(index, handin));
    } catch (err) {
      // A panic stops this instance: the row is named, and the worker is not reused.
      const panic = panic_message();
      if (panic) {
        flush();
        post({ type: 'failed', message: `row ${index + 1}: ${panic}` });
        queue.length = 0;
        break;
      }
      add(index, { handin: index + 1, error: err instanceof Error ? err.message : String(err) });
    }
    if (performance.now() - sent > BATCH_MS) flush();
  }
  flush();
  working = false;
}

/** Reads a class's file and finds its exercise, off the page's thread (a class of 10,000 takes a while). */
function read(bytes: Uint8Array, exercise: string | null): FromGradeWorker {
  const why = (err: unknown) => (err instanceof Error ? err.message : String(err));
  let handins: Handin2[];
  try {
    handins = read_handins(bytes) as Handin2[];
  } catch (err) {
    return { type: 'refused', message: why(err), exercise: false };
  }
  const encoder = new TextEncoder();
  const rows = handins.map((h) => encoder.encode(JSON.stringify(h)));
  const ends = new Uint32Array(rows.length);
  let end = 0;
  for (const [i, r] of rows.entries()) {
    end += r.length;
    ends[i] = end;
  }
  const utf8 = new Uint8Array(end);
  for (const [i, r] of rows.entries()) utf8.set(r, i ? ends[i - 1] : 0);
  const students = handins.map((h) => h.student);
  const read = { type: 'read' as const, handins: utf8, ends, students };
  if (!handins.length) return { ...read, cls: null };
  try {
    // The links are read only to find the exercise most of them carry: none when the teacher names it.
    const links = exercise?.trim() ? [] : handins.flatMap((h) => (h.link ? [h.link] : []));
    const cls = class_exercise(exercise, links) as ClassExercise;
    return { ...read, cls };
  } catch (err) {
    return { type: 'refused', message: why(err), exercise: true };
  }
}

scope.onmessage = async (e: MessageEvent<ToGradeWorker>) => {
  const msg = e.data;
  if (msg.type === 'setup') {
    try {
      loaded = init({ module_or_path: msg.module });
      await loaded;
      post({ type: 'ready' });
    } catch (err) {
      post({ type: 'failed', message: err instanceof Error ? err.message : String(err) });
    }
    return;
  }
  if (msg.type === 'teacher') {
    teacher = msg.teacher;
    return;
  }
  if (msg.type === 'read') {
    try {
      await loaded;
    } catch {
      // Said at setup.
      return;
    }
    const answer = read(msg.bytes, msg.exercise);
    if (answer.type === 'read') scope.postMessage(answer, [answer.handins.buffer, answer.ends.buffer]);
    else post(answer);
    return;
  }
  queue.push(...msg.rows);
  if (!working) work();
};
