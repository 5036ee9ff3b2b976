// Grading time per hand-in: a class of hand-ins of lesson-amas-robots (fair ones, ones that miss
// the goal, ones with a changed lock), each replayed and judged as the Grade view's workers do
// (the lab module's grade_handin, wasm in Node, one thread) and as `kumiki check` does (native, on every core).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const LESSON = 'lesson-amas-robots';

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

/**
 * Milliseconds per hand-in, in wasm (Node, one thread; links made with the page's module `wasm`,
 * graded with the lab module `lab`) and natively (`kumiki check`, all cores).
 */
export function benchGrade(wasm, lab, root, count = 60) {
  const links = handins(wasm, count);
  // Warm up on the whole class once: the first calls include the engine tiering up the wasm.
  for (const link of links) lab.grade_handin(link, LESSON);
  const started = performance.now();
  for (const link of links) lab.grade_handin(link, LESSON);
  const wasmMs = (performance.now() - started) / count;
  const dir = mkdtempSync(join(tmpdir(), 'kumiki-bench-grade-'));
  const list = join(dir, 'handins.txt');
  writeFileSync(list, `${links.join('\n')}\n`);
  const t0 = performance.now();
  execFileSync(`${root}target/release/kumiki`, ['check', '--file', list, '--exercise', LESSON], { cwd: root, stdio: ['ignore', 'ignore', 'ignore'] });
  const nativeMs = (performance.now() - t0) / count;
  rmSync(dir, { recursive: true });
  return { count, wasmMs, nativeMs };
}
