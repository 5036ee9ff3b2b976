// Times the workloads of tests/bench/*.json through the wasm build in Node, exactly as
// `kumiki bench` times them natively: fresh run per repeat, warm-up steps, one uncounted repeat
// first (so V8 has tiered the code up), median rate.
// Usage: node scripts/bench-wasm.mjs tests/bench/a.json [more.json ...]   (one JSON line each)
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import { fileURLToPath } from 'node:url';
import * as lab from '../web/pkg/kumiki_lab.js';
import * as wasm from '../web/pkg/kumiki_wasm.js';

const root = new URL('..', import.meta.url);
wasm.initSync({ module: readFileSync(fileURLToPath(new URL('web/pkg/kumiki_wasm_bg.wasm', root))) });
// Experiments run in the lab module, as in the page's experiment workers.
lab.initSync({ module: readFileSync(fileURLToPath(new URL('web/pkg/kumiki_lab_bg.wasm', root))) });

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const n = s.length;
  return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
};

function scenarioJson(spec) {
  let json = typeof spec.scenario === 'string' ? wasm.preset_json(spec.scenario) : JSON.stringify(spec.scenario);
  for (const [path, value] of Object.entries(spec.set ?? {})) {
    json = wasm.override_scenario(json, path, JSON.stringify(value));
  }
  return json;
}

export function measure(spec) {
  const repeats = Math.max(1, spec.repeats ?? 5);
  if (spec.experiment) {
    const runner = new lab.ExperimentRunner(spec.experiment);
    const times = [];
    for (let r = 0; r < repeats; r++) {
      const t = performance.now();
      for (let i = 0; i < runner.job_count(); i++) runner.run(i);
      times.push((performance.now() - t) / 1000);
    }
    return { name: spec.name, target: 'wasm', experiment: spec.experiment, runs: runner.job_count(), threads: 1, median_seconds: median(times) };
  }
  const json = scenarioJson(spec);
  // The bare run (wasm.Stepper) is the work `kumiki bench` times natively; the page's Sim also
  // keeps keyframes for rewind and every step's metrics for the chart, timed apart.
  const rate = (Handle) => {
    const rates = [];
    for (let r = 0; r <= repeats; r++) {
      const run = new Handle(json);
      run.advance(spec.warmup ?? 0);
      const t = performance.now();
      const done = run.advance(spec.steps ?? 100);
      const secs = (performance.now() - t) / 1000;
      if (r > 0) rates.push(done / Math.max(secs, 1e-9));
      run.free();
    }
    return median(rates);
  };
  const probe = new wasm.Sim(json);
  const cells = probe.cells().length;
  probe.free();
  const out = {
    name: spec.name,
    target: 'wasm',
    cells,
    steps_per_second: rate(wasm.Stepper),
    page_steps_per_second: rate(wasm.Sim),
  };
  if (spec.work_per_step) {
    out.work_unit = spec.work_unit ?? '';
    out.work_per_second = spec.work_per_step * out.steps_per_second;
  }
  return out;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  for (const file of process.argv.slice(2)) {
    const spec = JSON.parse(readFileSync(file, 'utf8'));
    console.log(JSON.stringify(measure(spec)));
  }
}
