// Grading time: a class of hand-ins of lesson-amas-robots (fair ones, ones that miss the goal,
// ones with a changed lock), each replayed and judged as the Grade view's workers do (the lab
// module's class_exercise and grade_row, wasm in Node, one thread) and as `kumiki check` does
// (native, on every core): a hand-in's time in both, and a class of 10,000 graded by `kumiki check`
// from a form's CSV export, the whole command timed (reading the file, finding the class's
// exercise, grading, writing the table), and the same file graded in the page's Grade view
// (scripts/bench-grade-page.mjs), once on the machine as it is and once with every core kept busy
// by other processes: the page's time over the CLI's, and the page's main thread's longest task
// and input delay while it grades, against their goals (issue 39).
// Alone: node scripts/bench-grade.mjs (KUMIKI_BIN: the CLI to time, default target/release/kumiki).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { loadavg, tmpdir } from 'node:os';
import { join } from 'node:path';
import { readCatalogue } from './catalog.mjs';

const LESSON = 'lesson-amas-robots';
/** The class `kumiki check` grades in one command. */
export const CLASS = 10_000;
/** Goals: the page grades the class within this many times the CLI's time... */
export const PAGE_OVER_CLI_GOAL = 3;
/** ...its main thread's tasks and input delays below this, in milliseconds. */
export const MAIN_THREAD_GOAL_MS = 100;

/** `count` hand-in links of the lesson (its text as the page fetches it: scripts/catalog.mjs), made with the loaded wasm module. */
export function handins(wasm, count) {
  const lesson = JSON.parse(readCatalogue().lessonText[LESSON]);
  return Array.from({ length: count }, (_, i) => {
    const doc = structuredClone(lesson);
    doc.name = `Student ${i + 1}`;
    doc.robots = [5, 2, 8][i % 3];
    if (i % 7 === 0) doc.seed = 2;
    return `http://localhost:8080/#${wasm.encode_link(JSON.stringify(doc))}`;
  });
}

/** The links as a form's CSV export: a time, a name, the link and an answer over two lines. */
function formExport(links) {
  const rows = links.map((link, i) => `2026-11-28T10:${String(i % 60).padStart(2, '0')}:00Z,Student ${i + 1},${link},"Fewer robots,\nfewer collisions."`);
  return `Timestamp,Name,Link,Why?\n${rows.join('\n')}\n`;
}

/** Median of `runs` timings of `f`, in milliseconds. */
function median(runs, f) {
  const times = Array.from({ length: runs }, () => {
    const t0 = performance.now();
    f();
    return performance.now() - t0;
  }).sort((a, b) => a - b);
  return times[Math.floor(runs / 2)];
}

/**
 * Milliseconds per hand-in, in wasm (Node, one thread; links made with the page's module `wasm`,
 * graded with the lab module `lab`) and natively (`kumiki check`, all cores), and the seconds
 * `kumiki check` takes for a class of 10,000 (median of 3 runs).
 */
export async function benchGrade(wasm, lab, root, count = 60) {
  const links = handins(wasm, count);
  const { teacher } = lab.class_exercise(LESSON, []);
  const rows = links.map((link, i) => JSON.stringify({ row: i + 1, line: i + 2, student: `Student ${i + 1}`, link, text: link }));
  // Warm up on the whole class once: the first calls include the engine tiering up the wasm.
  for (const row of rows) lab.grade_row(row, teacher);
  const started = performance.now();
  for (const row of rows) lab.grade_row(row, teacher);
  const wasmMs = (performance.now() - started) / count;
  const dir = mkdtempSync(join(tmpdir(), 'kumiki-bench-grade-'));
  const check = (file) =>
    execFileSync(process.env.KUMIKI_BIN ?? `${root}target/release/kumiki`, ['check', '--file', file, '--exercise', LESSON, '--format', 'csv'], {
      cwd: root,
      stdio: ['ignore', 'ignore', 'ignore'],
    });
  const list = join(dir, 'handins.txt');
  writeFileSync(list, `${links.join('\n')}\n`);
  const t0 = performance.now();
  check(list);
  const nativeMs = (performance.now() - t0) / count;
  const form = join(dir, 'class.csv');
  writeFileSync(form, formExport(handins(wasm, CLASS)));
  // The machine's load average (one minute) before each timing: on a shared machine the CLI's and
  // the page's times, and the page's delays, follow what else runs.
  const cliLoad = loadavg()[0];
  const classSeconds = median(3, () => check(form)) / 1000;
  const { gradeInPage } = await import('./bench-grade-page.mjs');
  const page = { load: loadavg()[0], ...(await gradeInPage(form, CLASS, LESSON)) };
  const busy = { load: loadavg()[0], ...(await gradeInPage(form, CLASS, LESSON, { busy: true })) };
  rmSync(dir, { recursive: true });
  const pageOverCli = page.seconds / classSeconds;
  // On a machine as it is, no task over the goal and no input waiting that long; with every core
  // busy, a task is stretched by the other processes' turns, but input must still be answered.
  const mainThreadMs = Math.max(page.longestTaskMs, page.inputDelayMs, busy.inputDelayMs);
  return {
    count,
    wasmMs,
    nativeMs,
    classCount: CLASS,
    classSeconds,
    cli: process.env.KUMIKI_BIN ?? 'target/release/kumiki',
    cliLoad,
    page,
    busy,
    pageOverCli,
    mainThreadMs,
    goals: { pageOverCli: PAGE_OVER_CLI_GOAL, mainThreadMs: MAIN_THREAD_GOAL_MS },
    met: pageOverCli <= PAGE_OVER_CLI_GOAL && mainThreadMs < MAIN_THREAD_GOAL_MS,
  };
}

/** The grading bench in words, with its goals. */
export function gradingReport(g) {
  const p = g.page;
  const verdict = (ok) => (ok ? 'met' : 'NOT met');
  const mainThread = (p) =>
    `longest task ${p.longestTaskMs.toFixed(0)} ms (${p.longTasks} over 50 ms), ` +
    `(at ${p.tasks.map(([t, d]) => `${(t / 1000).toFixed(1)} s: ${d} ms`).join(', ') || 'none'}), ` +
    `longest input delay ${p.inputDelayMs.toFixed(0)} ms (${p.slowInputs} input events over 16 ms, of ${p.keyPresses} key presses; longest round trip of a press ${p.keyRoundTripMs.toFixed(0)} ms)`;
  return [
    `grading (${g.count} hand-ins of lesson-amas-robots): ${g.wasmMs.toFixed(1)} ms a hand-in in wasm (one worker's share), ` +
      `${g.nativeMs.toFixed(1)} ms a hand-in with kumiki check on every core`,
    `a class of ${g.classCount.toLocaleString('en-US')} from a form's CSV export: ${g.classSeconds.toFixed(2)} s with kumiki check (${g.cli}, median of 3, load average ${g.cliLoad.toFixed(1)}), ` +
      `${p.seconds.toFixed(2)} s in the page on ${p.workers} workers (one run, load average ${p.load.toFixed(1)}): ${g.pageOverCli.toFixed(2)} times the CLI's ` +
      `(goal: at most ${g.goals.pageOverCli}, ${verdict(g.pageOverCli <= g.goals.pageOverCli)})`,
    `  the page's main thread while grading: ${mainThread(p)}`,
    `  with ${g.busy.spinners} processes spinning on the machine's cores meanwhile (load average ${g.busy.load.toFixed(1)} before): ${g.busy.seconds.toFixed(2)} s in the page, ${mainThread(g.busy)}`,
    `  goal: the page's tasks and input delays under ${g.goals.mainThreadMs} ms, and its input delay with the cores busy: ` +
      `${g.mainThreadMs.toFixed(0)} ms, ${verdict(g.mainThreadMs < g.goals.mainThreadMs)}`,
    `  the page's tally: ${p.status}`,
  ].join('\n');
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const root = new URL('..', import.meta.url).pathname;
  const { readFileSync } = await import('node:fs');
  const wasm = await import('../web/pkg/kumiki_wasm.js');
  const lab = await import('../web/pkg/kumiki_lab.js');
  wasm.initSync({ module: readFileSync(`${root}web/pkg/kumiki_wasm_bg.wasm`) });
  lab.initSync({ module: readFileSync(`${root}web/pkg/kumiki_lab_bg.wasm`) });
  const g = await benchGrade(wasm, lab, root);
  console.log(gradingReport(g));
  if (!g.met) process.exitCode = 1;
}
