// The Grade view's pool of grading workers: the class's rows handed out in chunks, each worker
// kept a chunk ahead so it never waits for the page's thread, the graded rows heard in batches,
// and a stuck row skipped by ending the worker that runs it (its other rows go to the others, and
// a fresh worker takes its place).
import type { Handin2 } from '../../contract.gen';
import { labModule } from '../../lab';
import { type GradeRow, SKIPPED } from './handins';
import type { FromGradeWorker, ToGradeWorker } from './worker';

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
  /** The rows handed to it and not graded yet, in the order it grades them. */
  held: number[];
  /** When its first held row became its first (ms), and its step when it last said. */
  since: number;
  steps: number | null;
}

export interface PoolEvents {
  /** Rows graded, in any order. */
  rows(rows: { index: number; row: GradeRow }[]): void;
  failed(message: string): void;
}

/** What reading a class's file gives: its hand-ins and exercise, or why not. */
export type ReadClass = Extract<FromGradeWorker, { type: 'read' } | { type: 'refused' }>;

/** Reads a class's file (its bytes) and finds its exercise in a worker, off the page's thread. */
export async function readClass(bytes: Uint8Array, exercise: string | null): Promise<ReadClass> {
  const module = await labModule();
  const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: 'kumiki-grade-read' });
  try {
    return await new Promise<ReadClass>((resolve, reject) => {
      worker.onmessage = (e: MessageEvent<FromGradeWorker>) => {
        const msg = e.data;
        if (msg.type === 'ready') worker.postMessage({ type: 'read', bytes, exercise } satisfies ToGradeWorker);
        else if (msg.type === 'read' || msg.type === 'refused') resolve(msg);
        else if (msg.type === 'failed') reject(new Error(msg.message));
      };
      worker.onerror = (e) => reject(new Error(`the reading worker failed: ${e.message}`));
      worker.postMessage({ type: 'setup', module, teacher: '' } satisfies ToGradeWorker);
    });
  } finally {
    worker.terminate();
  }
}

/** Grades `handins` (each a `Handin2` as JSON) by the class's exercise (`teacher`) on a pool of workers. */
export class GradePool {
  private members: Member[] = [];
  /** Rows to hand out next: those of a skipped row's worker first, then the rest in order. */
  private returned: number[] = [];
  private next = 0;
  private stopped = false;
  private module: WebAssembly.Module | null = null;

  constructor(
    private readonly handins: string[],
    private readonly teacher: string,
    private readonly on: PoolEvents,
  ) {}

  async start(size: number) {
    this.module = await labModule();
    if (this.stopped) return;
    const n = Math.max(1, Math.min(size, Math.ceil(this.handins.length / CHUNK)));
    for (let w = 0; w < n; w++) this.spawn(w);
  }

  private spawn(w: number) {
    const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: `kumiki-grade-${w}` });
    const member: Member = { worker, held: [], since: performance.now(), steps: null };
    worker.onmessage = (e: MessageEvent<FromGradeWorker>) => {
      if (this.stopped) return;
      const msg = e.data;
      if (msg.type === 'failed') {
        this.stop();
        this.on.failed(msg.message);
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
        // Ready: two chunks, so the second is there when it finishes the first.
        this.handOut(member);
        this.handOut(member);
      }
    };
    worker.onerror = (e) => {
      this.stop();
      this.on.failed(`a grading worker failed: ${e.message}`);
    };
    worker.postMessage({ type: 'setup', module: this.module as WebAssembly.Module, teacher: this.teacher } satisfies ToGradeWorker);
    this.members.push(member);
  }

  private take(): number | undefined {
    if (this.returned.length) return this.returned.shift();
    if (this.next < this.handins.length) return this.next++;
    return undefined;
  }

  private handOut(member: Member) {
    if (this.stopped || member.held.length >= AHEAD) return;
    const rows: { index: number; handin: string }[] = [];
    while (rows.length < CHUNK) {
      const index = this.take();
      if (index === undefined) break;
      rows.push({ index, handin: this.handins[index] });
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
    if (this.stopped || at < 0) return null;
    const [member] = this.members.splice(at, 1);
    member.worker.terminate();
    this.returned.unshift(...member.held.slice(1));
    const steps = member.steps === null ? '' : ` at step ${member.steps.toLocaleString('en-US')}`;
    const seconds = ((performance.now() - member.since) / 1000).toFixed(1);
    this.spawn(this.members.length);
    const handin = JSON.parse(this.handins[index]) as Handin2;
    return { handin: handin.row, student: handin.student, link: handin.link, error: `${SKIPPED}the teacher skipped it after ${seconds} s${steps}` };
  }

  stop() {
    this.stopped = true;
    for (const m of this.members) m.worker.terminate();
    this.members = [];
  }
}
