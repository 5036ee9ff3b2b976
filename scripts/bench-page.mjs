// The page in headless Chromium: load to interactive (first frame drawn), and for workloads with
// a "page" entry ({"seconds": N}) the steps per second and frames per second while it plays at
// full speed, with where the worker's time went (stepping, uploading buffers, issuing draws), and
// then the frames per second while its view is dragged for N seconds with the run paused (panned,
// or with {"orbit": true} turned, and then not played at all): what the renderer alone keeps up
// with. With {"trace": true} the drag is then repeated under a Chromium trace, which shows where
// each process's time goes (see `profile`). After playing, the resident memory of the page's
// renderer process and of the GPU process is read from /proc (Linux), with the size of the wasm
// memory of the worker and of the page's main thread, and the same for the default page first.
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { performance } from 'node:perf_hooks';
import { DIST, launch, serve } from '../tests/e2e/harness.mjs';

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

/** Rates between two readings, and the worker's milliseconds per frame drawn. */
function rates(a, b) {
  const dt = (b.t - a.t) / 1000;
  const frames = b.work.frames - a.work.frames;
  const per = (k) => (frames > 0 ? (b.work[k] - a.work[k]) / frames : 0);
  return {
    stepsPerSecond: (b.steps - a.steps) / dt,
    framesPerSecond: frames / dt,
    stepMsPerSecond: (b.work.stepMs - a.work.stepMs) / dt,
    uploadMsPerFrame: per('uploadMs'),
    drawMsPerFrame: per('drawMs'),
  };
}

/** The browser's processes: { type, id, cpuTime } each. */
async function processes(cdp) {
  return (await cdp.send('SystemInfo.getProcessInfo')).processInfo;
}

/** How long a traced drag lasts, in seconds. */
const TRACE_SECONDS = 4;

/**
 * Drags the view for TRACE_SECONDS under a Chromium trace and sums, per second of the drag, the
 * busy time of the threads that make a frame: the worker's, the page's main thread, and the GPU
 * process's main thread, split into what it spent presenting frames (SwapBuffers, where the
 * software rasteriser's work for the whole frame is waited for) and running the WebGL commands
 * the worker sent. The CPU time of each process over the same seconds says how much of the two
 * cores each one took.
 */
async function profile(browser, drag) {
  const cdp = await browser.newBrowserCDPSession();
  // CPU seconds so far by process type (all renderers together: closed pages' stay constant).
  const cpu = async () => {
    const byType = {};
    for (const p of await processes(cdp)) byType[p.type] = (byType[p.type] ?? 0) + p.cpuTime;
    return byType;
  };
  const events = [];
  cdp.on('Tracing.dataCollected', (e) => events.push(...e.value));
  const complete = new Promise((resolve) => cdp.once('Tracing.tracingComplete', resolve));
  await cdp.send('Tracing.start', { traceConfig: { includedCategories: ['toplevel', 'gpu', 'viz', '__metadata'] }, transferMode: 'ReportEvents' });
  const before = await cpu();
  const t = performance.now();
  await drag(TRACE_SECONDS);
  const seconds = (performance.now() - t) / 1000;
  const after = await cpu();
  await cdp.send('Tracing.end');
  await complete;
  await cdp.detach();
  const thread = {};
  const process = {};
  for (const e of events) {
    if (e.ph === 'M' && e.name === 'thread_name') thread[`${e.pid}:${e.tid}`] = e.args.name;
    if (e.ph === 'M' && e.name === 'process_name') process[e.pid] = e.args.name;
  }
  // Each thread's busy time: its complete events that are not nested inside another.
  const busy = {};
  const names = {};
  const openUntil = {};
  for (const e of events.filter((x) => x.ph === 'X' && x.dur > 0).sort((a, b) => a.ts - b.ts)) {
    const key = `${process[e.pid]}/${thread[`${e.pid}:${e.tid}`]}`;
    if (key.startsWith('GPU')) names[`${key}/${e.name}`] = (names[`${key}/${e.name}`] ?? 0) + e.dur;
    if ((openUntil[key] ?? 0) > e.ts) continue;
    openUntil[key] = e.ts + e.dur;
    busy[key] = (busy[key] ?? 0) + e.dur;
  }
  const perSecond = (us) => (us ?? 0) / 1000 / seconds;
  return {
    seconds,
    gpuMainMsPerSecond: perSecond(busy['GPU Process/CrGpuMain']),
    presentMsPerSecond: perSecond(names['GPU Process/CrGpuMain/SkiaOutputSurfaceImplOnGpu::SwapBuffers']),
    webglCommandsMsPerSecond: perSecond(names['GPU Process/CrGpuMain/GpuChannel::ExecuteDeferredRequest']),
    workerMsPerSecond: perSecond(busy['Renderer/DedicatedWorker thread']),
    pageMainMsPerSecond: perSecond(busy['Renderer/CrRendererMain']),
    cpuSecondsPerSecond: Object.fromEntries(Object.entries(after).map(([k, v]) => [k, (v - (before[k] ?? 0)) / seconds])),
  };
}

/** The ids of the browser's renderer processes. */
async function rendererIds(browser) {
  const cdp = await browser.newBrowserCDPSession();
  const ids = (await processes(cdp)).filter((p) => p.type === 'renderer').map((p) => p.id);
  await cdp.detach();
  return new Set(ids);
}

/** Seconds the page plays before its rate is read, and the browser's stepper steps before its own. */
const WARM_SECONDS = 1.5;

/**
 * The workload's bare stepper (wasm.Stepper) timed as the page plays it: in a dedicated worker of
 * the same browser, on the page's own module (the build's file, compiled while it downloads, as
 * the page compiles it), from step 0, a step or a few a call as the play loop calls (about 2 ms a
 * call), read WARM_SECONDS in for `seconds`. Steps per second. The same engine, span and length
 * as the page's run: V8 in Node (the wasm figures) runs the same module up to half again as fast
 * as this browser's V8 once tiered up, and a run started fresh after others runs faster than one
 * played from the start (docs/benchmarks.md), so only this rate compares with the page's.
 */
async function browserStepperRate(browser, server, json, seconds) {
  const context = await browser.newContext();
  try {
    const page = await context.newPage();
    // A missing file: a same-origin document without the page's content security policy, so the
    // worker can be made from the glue's text.
    await page.goto(`${server.url}stepper/`);
    const glue = readFileSync(new URL('../web/pkg/kumiki_wasm.js', import.meta.url), 'utf8');
    const wasmFile = readdirSync(join(DIST, 'assets')).find((f) => /^kumiki_wasm_bg-[\w-]+\.wasm$/.test(f));
    return await page.evaluate(
      ({ glue, wasmUrl, json, warm, seconds }) => {
        const body = `onmessage = async (e) => {
          const { glue, wasmUrl, json, warm, seconds } = e.data;
          const m = await import(URL.createObjectURL(new Blob([glue], { type: 'text/javascript' })));
          m.initSync({ module: await WebAssembly.compileStreaming(fetch(wasmUrl)) });
          const run = new m.Stepper(json);
          // The play loop's pace (web/sim/host.ts: timedAdvance, stepsPerCall), which this worker cannot import.
          let perStep = 1;
          const play = (ms) => {
            const until = performance.now() + ms;
            let steps = 0;
            while (performance.now() < until) {
              const t = performance.now();
              const n = run.advance(Math.max(1, Math.floor(2 / Math.max(perStep, 1e-4))));
              if (n === 0) break;
              perStep = 0.7 * perStep + 0.3 * ((performance.now() - t) / n);
              steps += n;
            }
            return steps;
          };
          play(warm * 1000);
          const t = performance.now();
          const steps = play(seconds * 1000);
          postMessage(steps / ((performance.now() - t) / 1000));
        };`;
        const worker = new Worker(URL.createObjectURL(new Blob([body], { type: 'text/javascript' })), { type: 'module' });
        return new Promise((resolve, reject) => {
          worker.onmessage = (e) => resolve(e.data);
          worker.onerror = (e) => reject(new Error(e.message));
          worker.postMessage({ glue, wasmUrl, json, warm, seconds });
        });
      },
      { glue, wasmUrl: `${server.url}assets/${wasmFile}`, json, warm: WARM_SECONDS, seconds },
    );
  } finally {
    await context.close();
  }
}

/** Resident megabytes of a process, 0 once it has ended. */
function rss(pid) {
  try {
    const m = /VmRSS:\s+(\d+) kB/.exec(readFileSync(`/proc/${pid}/status`, 'utf8'));
    return m ? Number(m[1]) / 1024 : 0;
  } catch {
    return 0;
  }
}

/**
 * Resident megabytes of the page's renderer process (the whole process: its main thread, its
 * worker, both wasm memories, its share of the code) and of the GPU process. The page's renderer
 * is the largest of those started since `before` was read (a browser context has processes of its
 * own), so a closed page's renderer that has not ended yet is not taken for it.
 */
async function residentMb(browser, before) {
  const cdp = await browser.newBrowserCDPSession();
  const processInfo = await processes(cdp);
  await cdp.detach();
  const renderers = processInfo.filter((p) => p.type === 'renderer' && !before.has(p.id));
  return {
    renderer: Math.max(0, ...renderers.map((p) => rss(p.id))),
    gpu: Math.max(0, ...processInfo.filter((p) => p.type === 'GPU').map((p) => rss(p.id))),
  };
}

/** Waits (at most 10 s) until the renderer processes started since `before` have ended. */
async function ended(browser, before) {
  for (let i = 0; i < 100; i++) {
    if ([...(await rendererIds(browser))].every((id) => before.has(id))) return;
    await new Promise((r) => setTimeout(r, 100));
  }
}

/** The wasm memory of the worker and of the page's main thread, in megabytes. */
async function wasmMb(page) {
  return page.evaluate(() => ({
    worker: (JSON.parse(document.body.dataset.work ?? '{}').wasmBytes ?? 0) / 2 ** 20,
    page: Number(document.body.dataset.wasmBytes ?? 0) / 2 ** 20,
  }));
}

/**
 * The page's load and its workloads' runs. For a workload played at full speed, its bare stepper
 * is timed in this browser just before (browserStepperRate: `stepper.json(spec)`, the scenario's
 * JSON), and the page's rate over it is `pageOverWasm`; `stepper.node(spec)`, when given, times
 * it in wasm under Node too (`nodeStepsPerSecond`, `pageOverNode`), the page open and paused
 * for both, so the rates are taken under the same load of this shared machine. The default page
 * is loaded `loadCount` times first (its load time, then its memory).
 */
export async function benchPage(pageSpecs, linkFor, stepper, loadCount = 5) {
  const server = await serve('/');
  const browser = await launch();
  try {
    const loads = [];
    // The default page's memory, once it has drawn: what a scenario's memory adds to.
    let idle;
    for (let i = 0; i < loadCount; i++) {
      const before = await rendererIds(browser);
      const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
      const page = await context.newPage();
      const t = performance.now();
      await page.goto(server.url);
      await page.waitForSelector('body[data-ready="true"]', { timeout: 60000 });
      loads.push(performance.now() - t);
      if (i === loadCount - 1) {
        await page.waitForTimeout(1000);
        idle = { residentMb: await residentMb(browser, before), wasmMb: await wasmMb(page) };
      }
      await context.close();
      await ended(browser, before);
    }
    const runs = [];
    for (const spec of pageSpecs) {
      const seconds = spec.page.seconds ?? 10;
      const before = await rendererIds(browser);
      const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
      const page = await context.newPage();
      await page.goto(`${server.url}#${linkFor(spec)}`);
      // A scenario above the page's memory estimate asks before it opens: the bench agrees.
      await page.waitForSelector('body[data-ready="true"], #large-ask[open]', { timeout: 60000 });
      if (await page.isVisible('#large-ask[open]')) await page.click('#large-ask-open');
      await page.waitForSelector('body[data-ready="true"]', { timeout: 120000 });
      // A shared link opens with its introduction, which would take the click on Play.
      if (await page.isVisible('#intro')) {
        await page.click('#intro button.primary');
        await page.waitForSelector('#intro', { state: 'hidden' });
      }
      const read = () =>
        page.evaluate(() => ({
          steps: Number(document.querySelector('#step-count').textContent.replace(/,/g, '')),
          work: JSON.parse(document.body.dataset.work ?? '{}'),
          t: performance.now(),
        }));
      const renderer = await page.evaluate(() => document.body.dataset.renderer);
      if (!spec.page.orbit) {
        const wasmStepsPerSecond = await browserStepperRate(browser, server, stepper.json(spec), seconds);
        const nodeStepsPerSecond = stepper.node?.(spec);
        await page.$eval('#speed', (s) => {
          s.value = '8';
          s.dispatchEvent(new Event('input'));
        });
        await page.click('#play');
        await page.waitForTimeout(WARM_SECONDS * 1000);
        const a = await read();
        await page.waitForTimeout(seconds * 1000);
        const b = await read();
        const played = rates(a, b);
        runs.push({
          name: spec.name,
          seconds,
          renderer,
          moving: 'playing',
          ...played,
          wasmStepsPerSecond,
          pageOverWasm: played.stepsPerSecond / wasmStepsPerSecond,
          nodeStepsPerSecond,
          pageOverNode: nodeStepsPerSecond ? played.stepsPerSecond / nodeStepsPerSecond : undefined,
          residentMb: await residentMb(browser, before),
          wasmMb: await wasmMb(page),
        });
        // Paused by the keyboard: a click would first wait for the page's own animation frames,
        // which come slowly while the software rasteriser is busy with the view.
        await page.keyboard.press('Space');
        await page.waitForSelector('#play[aria-pressed="false"]');
      }
      // The camera dragged while the run stands still: what the renderer alone keeps up with.
      const box = await page.locator('#view').boundingBox();
      const y = box.y + box.height / 2;
      await page.mouse.move(box.x + box.width * 0.3, y);
      await page.mouse.down();
      let k = 0;
      const drag = async (s) => {
        const until = Date.now() + s * 1000;
        for (; Date.now() < until; k++) {
          await page.mouse.move(box.x + box.width * (0.3 + 0.4 * Math.abs(Math.sin(k / 30))), y);
          await page.waitForTimeout(8);
        }
      };
      const a = await read();
      await drag(seconds);
      const b = await read();
      const traced = spec.page.trace ? await profile(browser, drag) : undefined;
      await page.mouse.up();
      runs.push({ name: spec.name, seconds, renderer, moving: spec.page.orbit ? 'orbiting' : 'panning', ...rates(a, b), profile: traced });
      await context.close();
      await ended(browser, before);
    }
    return { loads, loadMs: median(loads), idle, runs };
  } finally {
    await browser.close();
    await server.close();
  }
}

/** The least the page, playing at full speed and drawing, steps of the wasm stepper's rate in the same browser. */
export const PAGE_OVER_WASM = 0.8;

// Usage: node scripts/bench-page.mjs [tests/bench/a.json ...]   (default: every workload with a
// "page" entry). Plays each workload in the page at full speed after timing its bare stepper in
// the same browser and in wasm under Node, prints each run (JSON, a line each) and the page's rate
// over each stepper's, and fails when a workload plays below PAGE_OVER_WASM of the browser's.
if (process.argv[1] === new URL(import.meta.url).pathname) {
  const { measure, scenarioJson, workloadFiles } = await import('./bench-wasm.mjs');
  const wasm = await import('../web/pkg/kumiki_wasm.js');
  const root = new URL('..', import.meta.url).pathname;
  const files = workloadFiles(process.argv.slice(2));
  const specs = files.map((f) => JSON.parse(readFileSync(`${root}${f}`, 'utf8'))).filter((s) => s.page);
  const page = await benchPage(specs, (s) => wasm.encode_link(scenarioJson(s)), { json: scenarioJson, node: (s) => measure(s).steps_per_second }, 1);
  for (const r of page.runs) {
    console.log(JSON.stringify(r));
    if (r.pageOverWasm === undefined) continue;
    console.log(
      `${r.name}: the page ${r.stepsPerSecond.toPrecision(3)} steps/s drawing ${r.framesPerSecond.toPrecision(3)} frames/s, ` +
        `the wasm stepper ${r.wasmStepsPerSecond.toPrecision(3)} in this browser: page/wasm ${r.pageOverWasm.toFixed(2)} (at least ${PAGE_OVER_WASM}); ` +
        `the stepper in Node ${r.nodeStepsPerSecond.toPrecision(3)}: page/Node ${r.pageOverNode.toFixed(2)}`,
    );
    if (r.pageOverWasm < PAGE_OVER_WASM) process.exitCode = 1;
  }
}
