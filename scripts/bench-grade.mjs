// Grading time: a class of hand-ins of lesson-amas-robots (fair ones, ones that miss the goal,
// ones with a changed lock), each replayed and judged as the Grade view's workers do (the lab
// module's class_exercise and grade_row, wasm in Node, one thread) and as `kumiki check` does
// (native, on every core): a hand-in's time in both, and a class of 10,000 graded by `kumiki check`
// from a form's CSV export, the whole command timed (reading the file, finding the class's
// exercise, grading, writing the table). The page's own side of a class of 10,000 (its pool of
// workers and the table) is timed in the page's bench once the Grade view runs on these calls.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const LESSON = 'lesson-amas-robots';
/** The class `kumiki check` grades in one command. */
export const CLASS = 10_000;

/** `count` hand-in links of the lesson, made with the loaded wasm module. */
export function handins(wasm, count) {
  const lesson = JSON.parse(wasm.lesson_json(LESSON));
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
export function benchGrade(wasm, lab, root, count = 60) {
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
    execFileSync(`${root}target/release/kumiki`, ['check', '--file', file, '--exercise', LESSON, '--format', 'csv'], {
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
  const classSeconds = median(3, () => check(form)) / 1000;
  rmSync(dir, { recursive: true });
  return { count, wasmMs, nativeMs, classCount: CLASS, classSeconds };
}
