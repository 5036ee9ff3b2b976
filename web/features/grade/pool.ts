// The Grade view's pool of grading workers. They start at the click on Grade, while the first of
// them reads the class's file (so their start overlaps the reading, and the reader then grades
// too); the class's rows are handed out in chunks, each worker kept a chunk ahead so it never
// waits for the page's thread; the graded rows come back in batches, each row as JSON; and a
// stuck row is skipped by ending the worker that runs it (its other rows go to the others, and a
// fresh worker takes its place).
import type { ClassExercise, Handin2 } from '../../contract.gen';
import { labModule } from '../../lab';
import { type GradeRow, SKIPPED } from './handins';
import type { FromGradeWorker, GradedRow, ToGradeWorker } from './worker';

/** Rows handed to a worker at once. */
const CHUNK = 32;
/** A worker is handed another chunk when it holds fewer rows than this. */
const AHEAD = 2 * CHUNK;

/** A row a worker is replaying: its place in the table, its step when last heard, and since when (ms). */
export interface Running {
  index: number;
  steps: number | null;
  since: number;
}

interface Member {
  worker: Worker;
  /** Whether its lab module is instantiated. */
  ready: boolean;
  /** The rows handed to it and not graded yet, in the order it grades them. */
  held: number[];
  /** When its first held row became its first (ms), and its step when it last said. */
  since: number;
  steps: number | null;
}

export interface PoolEvents {
  /** Rows graded, in any order. */
  rows(rows: GradedRow[]): void;
  failed(message: string): void;
}

/**
 * A class's hand-ins (each `Handin2` as JSON) as the reading worker sends them: the records one
 * after another as UTF-8, and where each ends. Two buffers are handed over, not copied, where
 * 10,000 strings took the page's thread a third of a second to receive.
 */
export class Handins {
  private readonly decoder = new TextDecoder();

  constructor(
    private readonly utf8: Uint8Array,
    private readonly ends: Uint32Array,
  ) {}

  get length(): number {
    return this.ends.length;
  }

  /** Hand-in `index` as JSON. */
  at(index: number): string {
    return this.decoder.decode(this.utf8.subarray(index ? this.ends[index - 1] : 0, this.ends[index]));
  }
}

/** What reading a class's file gives: its hand-ins, their students' names and the class's exercise; or why not. */
export type ReadClass = { type: 'read'; handins: Handins; students: string[]; cls: ClassExercise | null } | Extract<FromGradeWorker, { type: 'refused' }>;

/** Grades a class on a pool of workers: `read` its file, then `grade` its hand-ins by its exercise. */
export class GradePool {
  private members: Member[] = [];
  /** Rows to hand out next: those of a skipped row's worker first, then the rest in order. */
  private returned: number[] = [];
  private next = 0;
  private stopped = false;
  private module: WebAssembly.Module | null = null;
  private handins: Handins | null = null;
  private teacher = '';
  /** The reading's answer, while the first worker reads. */
  private reading: { resolve(r: ReadClass): void; reject(e: Error): void } | null = null;

  constructor(private readonly on: PoolEvents) {}

  /**
   * Starts `size` workers and reads the class's file (`bytes`; `exercise`: the teacher's, or null
   * for the one most hand-ins carry) in the first, off the page's thread; the others meanwhile
   * instantiate the lab module. The workers stay for `grade`.
   */
  async read(bytes: Uint8Array, exercise: string | null, size: number): Promise<ReadClass> {
    this.module = await labModule();
    if (this.stopped) throw new Error('cancelled');
    for (let w = 0; w < size; w++) this.spawn(w);
    // A copy, handed over rather than copied again: the page keeps its own for another grading.
    const copy = bytes.slice();
    const read = new Promise<ReadClass>((resolve, reject) => (this.reading = { resolve, reject }));
    this.members[0].worker.postMessage({ type: 'read', bytes: copy, exercise } satisfies ToGradeWorker, [copy.buffer]);
    return read;
  }

  /** Grades the hand-ins read by the class's exercise (`teacher`: its `ClassExercise.teacher`). */
  grade(handins: Handins, teacher: string) {
    if (this.stopped) return;
    this.handins = handins;
    this.teacher = teacher;
    // A small class needs fewer workers than were started: those beyond a chunk each go.
    const needed = Math.max(1, Math.ceil(handins.length / CHUNK));
    for (const m of this.members.splice(needed)) m.worker.terminate();
    for (const m of this.members) this.begin(m);
  }

  /** Gives a ready worker the class's exercise and two chunks, so the second is there when it finishes the first. */
  private begin(member: Member) {
    if (!this.handins || !member.ready) return;
    member.worker.postMessage({ type: 'teacher', teacher: this.teacher } satisfies ToGradeWorker);
    this.handOut(member);
    this.handOut(member);
  }

  private spawn(w: number) {
    const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: `kumiki-grade-${w}` });
    const member: Member = { worker, ready: false, held: [], since: performance.now(), steps: null };
    worker.onmessage = (e: MessageEvent<FromGradeWorker>) => {
      if (this.stopped) return;
      const msg = e.data;
      if (msg.type === 'failed') {
        this.fail(msg.message);
      } else if (msg.type === 'read') {
        this.reading?.resolve({ type: 'read', handins: new Handins(msg.handins, msg.ends), students: msg.students, cls: msg.cls });
        this.reading = null;
      } else if (msg.type === 'refused') {
        this.reading?.resolve(msg);
        this.reading = null;
      } else if (msg.type === 'running') {
        if (member.held[0] === msg.index) member.steps = msg.steps;
      } else if (msg.type === 'graded') {
        const done = new Set(msg.rows.map((r) => r.index));
        member.held = member.held.filter((i) => !done.has(i));
        member.since = performance.now();
        member.steps = null;
        this.handOut(member);
        this.on.rows(msg.rows);
      } else {
        member.ready = true;
        this.begin(member);
      }
    };
    worker.onerror = (e) => this.fail(`a grading worker failed: ${e.message}`);
    worker.postMessage({ type: 'setup', module: this.module as WebAssembly.Module } satisfies ToGradeWorker);
    this.members.push(member);
  }

  private fail(message: string) {
    const reading = this.reading;
    this.reading = null;
    this.stop();
    if (reading) reading.reject(new Error(message));
    else this.on.failed(message);
  }

  private take(): number | undefined {
    if (this.returned.length) return this.returned.shift();
    if (this.handins && this.next < this.handins.length) return this.next++;
    return undefined;
  }

  private handOut(member: Member) {
    const handins = this.handins;
    if (this.stopped || !handins || member.held.length >= AHEAD) return;
    // Near the end, smaller chunks: no worker is left holding rows while another has none.
    const left = this.returned.length + handins.length - this.next;
    const size = Math.max(1, Math.min(CHUNK, Math.ceil(left / (2 * this.members.length))));
    const rows: { index: number; handin: string }[] = [];
    while (rows.length < size) {
      const index = this.take();
      if (index === undefined) break;
      rows.push({ index, handin: handins.at(index) });
    }
    if (!rows.length) return;
    if (!member.held.length) member.since = performance.now();
    member.held.push(...rows.map((r) => r.index));
    member.worker.postMessage({ type: 'grade', rows } satisfies ToGradeWorker);
  }

  /** The row running longest (the one to show, and to skip when stuck); null when none is. */
  running(): Running | null {
    let found: Member | null = null;
    for (const m of this.members) if (m.held.length && (!found || m.since < found.since)) found = m;
    return found ? { index: found.held[0], steps: found.steps, since: found.since } : null;
  }

  /**
   * Skips row `index` if a worker is running it: the worker is ended and replaced, its other rows
   * handed out again. Its row, marked skipped; null when no worker runs it (graded meanwhile).
   */
  skip(index: number): GradeRow | null {
    const at = this.members.findIndex((m) => m.held[0] === index);
    if (this.stopped || !this.handins || at < 0) return null;
    const [member] = this.members.splice(at, 1);
    member.worker.terminate();
    this.returned.unshift(...member.held.slice(1));
    const steps = member.steps === null ? '' : ` at step ${member.steps.toLocaleString('en-US')}`;
    const seconds = ((performance.now() - member.since) / 1000).toFixed(1);
    this.spawn(this.members.length);
    const handin = JSON.parse(this.handins.at(index)) as Handin2;
    return { handin: handin.row, student: handin.student, link: handin.link, error: `${SKIPPED}the teacher skipped it after ${seconds} s${steps}` };
  }

  stop() {
    this.stopped = true;
    for (const m of this.members) m.worker.terminate();
    this.members = [];
    this.reading?.reject(new Error('cancelled'));
    this.reading = null;
  }
}
