// A class graded in the page: the form's CSV export that `kumiki check` grades in
// scripts/bench-grade.mjs, opened in the Grade view in headless Chromium and graded by the same
// lesson, timed from the click on Grade to the tally (reading the file, finding the class's
// exercise, grading on the page's workers, drawing the table), as the CLI's whole command is.
// Meanwhile the page's main thread is watched: every long task (a PerformanceObserver of
// "longtask": any task over 50 ms), and a key pressed every 100 ms whose delay until its
// handler ran is read from the Event Timing API (events slower than 16 ms are reported) and
// from the round trip of the key press itself. Under load (`busy`), as many processes as the
// machine has cores spin meanwhile, as another program (a build, a video call) would: the page's
// thread must still answer.
import { spawn } from 'node:child_process';
import { availableParallelism } from 'node:os';
import { performance } from 'node:perf_hooks';
import { launch, openPage, serve } from '../tests/e2e/harness.mjs';

/** How often a key is pressed while the class grades, in milliseconds. */
const PRESS_MS = 100;

/** Processes that spin on every core until killed. */
function spinners() {
  return Array.from({ length: availableParallelism() }, () => spawn(process.execPath, ['-e', 'for (;;) {}'], { stdio: 'ignore' }));
}

/**
 * Grades `file` (a form's export of `count` hand-ins) in the page by `exercise`; its seconds and the
 * main thread's delays. `busy`: with every core kept busy by other processes meanwhile.
 */
export async function gradeInPage(file, count, exercise, { busy = false } = {}) {
  const server = await serve('/');
  const browser = await launch();
  let spinning = [];
  try {
    const { page, context } = await openPage(browser, server.url);
    await page.click('#open-gallery');
    await page.click('#open-grade');
    await page.waitForSelector('#grade[open]');
    await page.setInputFiles('#grade-file', file);
    await page.waitForFunction(() => /read as it is/.test(document.querySelector('#grade-file-note').textContent), null, { timeout: 60000 });
    await page.fill('#grade-exercise', exercise);
    const workers = await page.evaluate(() => navigator.hardwareConcurrency);
    await page.evaluate(() => {
      const seen = { longest: 0, longTasks: 0, inputDelay: 0, slowInputs: 0, tasks: [], t0: 0 };
      document.querySelector('#grade-start').addEventListener('click', () => (seen.t0 = performance.now()), { capture: true });
      window.__gradeBench = seen;
      new PerformanceObserver((list) => {
        for (const e of list.getEntries()) {
          seen.longTasks++;
          seen.longest = Math.max(seen.longest, e.duration);
          seen.tasks.push([Math.round(e.startTime - seen.t0), Math.round(e.duration)]);
        }
      }).observe({ type: 'longtask' });
      new PerformanceObserver((list) => {
        for (const e of list.getEntries()) {
          seen.slowInputs++;
          seen.inputDelay = Math.max(seen.inputDelay, e.processingStart - e.startTime);
        }
      }).observe({ type: 'event', durationThreshold: 16 });
      // A handler for the key presses, on the element that has them.
      document.querySelector('#grade-exercise').addEventListener('keydown', () => undefined);
    });
    const done = `${count.toLocaleString('en-US')} hand-ins:`;
    if (busy) spinning = spinners();
    const t0 = performance.now();
    await page.click('#grade-start');
    // Keys pressed while it grades (Shift: it types nothing), each press's round trip timed.
    await page.focus('#grade-exercise');
    let pressing = true;
    const roundTrips = [];
    const presses = (async () => {
      while (pressing) {
        const t = performance.now();
        await page.keyboard.press('Shift');
        roundTrips.push(performance.now() - t);
        await new Promise((r) => setTimeout(r, PRESS_MS));
      }
    })();
    await page.waitForFunction(
      (d) => {
        const text = document.querySelector('#grade-status').textContent;
        return text.startsWith(d) || /^(Grading stopped|Grading could not start|Not graded)/.test(text);
      },
      done,
      { timeout: 1_800_000, polling: 200 },
    );
    const seconds = (performance.now() - t0) / 1000;
    for (const p of spinning) p.kill();
    pressing = false;
    await presses;
    const status = await page.textContent('#grade-status');
    if (!status.startsWith(done)) throw new Error(`the page did not grade the class: ${status}`);
    const seen = await page.evaluate(() => window.__gradeBench);
    await context.close();
    return {
      count,
      busy,
      spinners: spinning.length,
      seconds,
      workers,
      status,
      longestTaskMs: seen.longest,
      longTasks: seen.longTasks,
      /** Each long task: its start (ms after the click on Grade) and its length (ms). */
      tasks: seen.tasks,
      inputDelayMs: seen.inputDelay,
      slowInputs: seen.slowInputs,
      keyPresses: roundTrips.length,
      keyRoundTripMs: Math.max(0, ...roundTrips),
    };
  } finally {
    for (const p of spinning) p.kill();
    await browser.close();
    await server.close();
  }
}
