// The soak: each model's largest preset for many steps (10^6 by default), natively (`kumiki soak`:
// the counting allocator's live heap bytes, and the resident set size) and in wasm under Node
// (the Sim handle the page's worker uses, with its keyframe timeline, reading a frame at every
// sample; wasm memory, which never shrinks, so its size is the peak the page would hold). A run
// that finishes is followed by the next seed, so the steps count work done.
//
// Flat means: the largest sample of the last tenth of the steps exceeds the largest of the
// warm-up by less than 5 % (or, for wasm memory, by less than 1 MiB: see WASM_GRAIN). The warm-up is the first tenth of the steps, and at least the steps
// the page's timeline takes to fill twice. The wasm Sim keeps up to 256 keyframes of a run
// (fewer for large lattices: about 96 MB of them), 16 steps apart or wider when copies cost more
// than their share of the time; when full it drops every other one and doubles the interval.
// That budget is by design: the first fill takes 256 intervals, the second reuses the freed
// keyframes' memory, which it finds in pieces, and from then on the memory stays put however
// long the run goes. fracta-large in wasm copies 32 steps apart from its start: 65.7 MB at the
// first fill (8192 steps), 69.3 MB at the second (16 384) and still 69.3 MB at 90 000 and at
// 10^6 (2026-11-27). So the warm-up is at least 2 × 256 × 32 steps. The script prints start,
// after warm-up, peak, end and the least-squares slope after warm-up for every series, and exits
// with 1 when one is not flat.
// Usage: node scripts/soak.mjs [--steps N] [--every N] [--model M] [--wasm-steps N]
//        [--native FILE]   (the JSON lines of an earlier `kumiki soak`, instead of running it)
//        [--native-steps 0] (wasm only)
import { execFileSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import * as wasm from '../web/pkg/kumiki_wasm.js';
import { readCatalogue } from './catalog.mjs';

const root = new URL('..', import.meta.url).pathname;
/** The built-in scenarios, as the page fetches them (its module leaves them out). */
const catalog = readCatalogue();
const arg = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const steps = Number(arg('steps', 1_000_000));
const wasmSteps = Number(arg('wasm-steps', steps));
const nativeSteps = Number(arg('native-steps', steps));
const every = Number(arg('every', Math.max(1, Math.floor(steps / 100))));
const only = arg('model');
const GROWTH_LIMIT = 0.05;
/**
 * Wasm memory grows only by the allocator's requests to the engine, in 64 KiB pages and in
 * chunks, and a model of many short runs (cubes-light: 41 in 40 000 steps) reaches the size its
 * allocations settle at over dozens of runs: 3.9 MB after 16 384 steps, 4.69 MB before 40 000 and
 * 4.69 MB still at 10^6 (2026-11-27). So wasm memory that grew by less than this is flat whatever
 * its share; a leak of 100 bytes a step passes it within 10 000 steps.
 */
const WASM_GRAIN = 1 << 20;
/** Steps after which a run's keyframe timeline has filled twice (see above). */
const TIMELINE_FULL = 2 * 256 * 32;

/** Start, after warm-up, peak, end, growth and slope (bytes per 10^6 steps) of one series. */
function summarise(points) {
  const last = points[points.length - 1][0];
  const warmEnd = Math.max(last / 10, TIMELINE_FULL);
  const warm = Math.max(...points.filter(([s]) => s <= warmEnd).map(([, v]) => v));
  const end = Math.max(...points.filter(([s]) => s >= last - last / 10).map(([, v]) => v));
  const after = points.filter(([s]) => s > warmEnd);
  const mx = after.reduce((a, [s]) => a + s, 0) / after.length;
  const my = after.reduce((a, [, v]) => a + v, 0) / after.length;
  const sxx = after.reduce((a, [s]) => a + (s - mx) ** 2, 0);
  const slope = sxx > 0 ? (after.reduce((a, [s, v]) => a + (s - mx) * (v - my), 0) / sxx) * 1e6 : 0;
  return {
    start: points[0][1],
    warm,
    peak: Math.max(...points.map(([, v]) => v)),
    end: points[points.length - 1][1],
    growth: (end - warm) / Math.max(warm, 1),
    grew: end - warm,
    slope,
  };
}

function nativeSoak() {
  const saved = arg('native');
  if (saved) {
    const rows = readFileSync(saved, 'utf8')
      .trim()
      .split('\n')
      .map((line) => JSON.parse(line));
    return rows.filter((r) => !only || r.model === only);
  }
  if (nativeSteps === 0) return [];
  const args = ['soak', '--steps', String(nativeSteps), '--every', String(every)];
  if (only) args.push('--model', only);
  const out = execFileSync(`${root}target/release/kumiki`, args, { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'inherit'] });
  return out
    .trim()
    .split('\n')
    .map((line) => JSON.parse(line));
}

function wasmSoak(model, preset, exports) {
  let seed = JSON.parse(catalog.presetText[preset]).seed;
  const open = () => new wasm.Sim(JSON.stringify({ ...JSON.parse(catalog.presetText[preset]), seed }));
  let sim = open();
  let taken = 0;
  let runs = 1;
  const samples = [];
  const t0 = performance.now();
  const chunk = Math.max(1, Math.floor(wasmSteps / 100));
  while (taken < wasmSteps) {
    taken += sim.advance(Math.min(chunk - (taken % chunk), wasmSteps - taken));
    if (sim.finished()) {
      sim.free();
      seed += 1;
      sim = open();
      runs += 1;
    }
    if (taken % chunk === 0 || taken === wasmSteps) {
      // What the worker reads for a frame.
      sim.cells();
      sim.agents();
      sim.events();
      sim.metrics();
      sim.scene();
      sim.hash();
      samples.push({ step: taken, memory: exports.memory.buffer.byteLength });
    }
  }
  sim.free();
  return { model, preset, steps: taken, runs, seconds: (performance.now() - t0) / 1000, samples };
}

/** Each model's preset with the most lattice cells, the first by name on a tie (as `kumiki soak`). */
function largestPresets() {
  const best = new Map();
  for (const { name, model } of catalog.presets) {
    if (only && model !== only) continue;
    const sim = new wasm.Sim(catalog.presetText[name]);
    const cells = sim.layout().dims.reduce((a, d) => a * Math.max(1, d), 1);
    sim.free();
    if (!best.has(model) || cells > best.get(model).cells) best.set(model, { model, preset: name, cells });
  }
  return [...best.values()];
}

const mb = (b) => `${(b / 2 ** 20).toFixed(2)} MB`;
const kb = (b) => `${(b / 1024).toFixed(1)} KB`;
const rows = [];
let flat = true;
function report(where, model, preset, runs, taken, seconds, series, unit, grain = 0) {
  const s = summarise(series);
  const ok = s.growth < GROWTH_LIMIT || s.grew < grain;
  flat &&= ok;
  rows.push({ where, model, preset, runs, steps: taken, seconds, ...s, ok });
  console.log(
    `${where.padEnd(12)} ${model.padEnd(8)} ${preset.padEnd(15)} ${String(taken).padStart(8)} steps ${String(runs).padStart(5)} runs ${seconds.toFixed(0).padStart(5)} s  ` +
      `start ${unit(s.start)}, after warm-up ${unit(s.warm)}, peak ${unit(s.peak)}, end ${unit(s.end)}; ` +
      `growth ${(100 * s.growth).toFixed(2)} %, slope ${unit(s.slope)} per 10^6 steps  ${ok ? 'flat' : 'GROWS'}`,
  );
}

console.log(`soak: ${nativeSteps} steps natively, ${wasmSteps} in wasm, ${every} steps between native samples`);
const native = nativeSoak();
for (const r of native) {
  report(
    'native heap',
    r.model,
    r.preset,
    r.runs,
    r.steps,
    r.seconds,
    r.samples.map((p) => [p.step, p.live_bytes]),
    kb,
  );
  if (r.samples[0].rss_bytes !== null) {
    // Resident memory is shown, not judged: the allocator may keep pages it was given.
    const s = summarise(r.samples.map((p) => [p.step, p.rss_bytes]));
    console.log(`${'native RSS'.padEnd(12)} ${r.model.padEnd(8)} start ${mb(s.start)}, after warm-up ${mb(s.warm)}, peak ${mb(s.peak)}, end ${mb(s.end)}`);
  }
}
if (wasmSteps > 0) {
  const exports = wasm.initSync({ module: readFileSync(`${root}web/pkg/kumiki_wasm_bg.wasm`) });
  for (const r of native.length ? native : largestPresets()) {
    const w = wasmSoak(r.model, r.preset, exports);
    report(
      'wasm memory',
      w.model,
      w.preset,
      w.runs,
      w.steps,
      w.seconds,
      w.samples.map((p) => [p.step, p.memory]),
      mb,
      WASM_GRAIN,
    );
  }
}
writeFileSync(`${root}target/soak-results.json`, JSON.stringify({ when: new Date().toISOString(), steps, wasmSteps, every, rows }, null, 1));
console.log(flat ? 'memory is flat in every soak' : 'memory GROWS in a soak (see above)');
process.exitCode = flat ? 0 : 1;
