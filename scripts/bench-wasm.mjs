// Times the workloads of tests/bench/*.json through the wasm build in Node, as `kumiki bench`
// times them natively: fresh runs, warm-up steps, one uncounted repeat first (so V8 has tiered
// the code up), median rate over the repeats (a repeat of a short workload sums several runs).
// Usage: node scripts/bench-wasm.mjs tests/bench/a.json [more.json ...]   (one JSON line each)
import { readdirSync, readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import { fileURLToPath } from 'node:url';
import * as lab from '../web/pkg/kumiki_lab.js';
import { readCatalogue } from './catalog.mjs';
import * as wasm from '../web/pkg/kumiki_wasm.js';
import * as wasmRules from '../web/pkg/kumiki_wasm_rules.js';

const root = new URL('..', import.meta.url);
wasm.initSync({ module: readFileSync(fileURLToPath(new URL('web/pkg/kumiki_wasm_bg.wasm', root))) });
/** The built-in scenarios' texts, as the page fetches them (its module leaves them out). */
const { presetText } = readCatalogue();
// The page's second simulation module, with the rule scripts' engine: the workloads with rules
// run in it, as the page runs a scenario with rules.
wasmRules.initSync({ module: readFileSync(fileURLToPath(new URL('web/pkg/kumiki_wasm_rules_bg.wasm', root))) });
// Experiments run in the lab module, as in the page's experiment workers.
lab.initSync({ module: readFileSync(fileURLToPath(new URL('web/pkg/kumiki_lab_bg.wasm', root))) });

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const n = s.length;
  return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
};

/** The workload files named on the command line (`args`), or else every tests/bench/*.json, sorted. */
export function workloadFiles(args) {
  if (args.length > 0) return args;
  return readdirSync(new URL('../tests/bench/', import.meta.url))
    .filter((f) => f.endsWith('.json'))
    .sort()
    .map((f) => `tests/bench/${f}`);
}

/**
 * The workload's scenario JSON: its preset or its own scenario, with its `set` paths changed the
 * way the page's form changes them (a Draft, which checks the result) and `kumiki bench` does.
 */
export function scenarioJson(spec) {
  const json = typeof spec.scenario === 'string' ? presetText[spec.scenario] : JSON.stringify(spec.scenario);
  const set = { ...spec.set };
  if (spec.rules) {
    // "paper": every slot of the model; a list: the slots it names.
    const model = JSON.parse(json).model;
    const named = (name) => spec.rules === 'paper' || (Array.isArray(spec.rules) && spec.rules.includes(name));
    for (const { slot } of wasmRules.rule_slots().filter((s) => s.model === model && named(s.slot.name))) set[`rules.${slot.name}`] = slot.paper;
  }
  if (Object.keys(set).length === 0) return json;
  const draft = new wasm.Draft(Number.MAX_SAFE_INTEGER);
  try {
    let proposal = draft.open(json, false);
    if (!proposal.problem) proposal = draft.edit_all(JSON.stringify(set));
    if (proposal.problem) throw new Error(`${spec.name}: ${proposal.in_full ?? proposal.problem}`);
    return proposal.text;
  } finally {
    draft.free();
  }
}

/** The least time a repeat of a workload is timed for, bare run and page's Sim together. */
const REPEAT_SECONDS = 0.2;

/**
 * How long each hostile script of a rules fixture takes to be stopped in wasm (reading and
 * building its scenario included), the median of the repeats, in seconds.
 */
function timeStops(spec, repeats) {
  const fixture = JSON.parse(readFileSync(fileURLToPath(new URL(spec.stops, root)), 'utf8'));
  const stops = fixture.stopped.map((c) => {
    const json = scenarioJson({ scenario: c.preset, set: { [`rules.${c.slot}`]: c.source } });
    const times = [];
    let stopped;
    for (let r = 0; r < repeats; r++) {
      const t = performance.now();
      const run = new wasmRules.Sim(json);
      while (run.advance(1000) > 0);
      times.push((performance.now() - t) / 1000);
      stopped = run.stopped();
      run.free();
    }
    return { name: c.name, seconds: median(times), stopped };
  });
  return { name: spec.name, target: 'wasm', stops };
}

export function measure(spec) {
  const repeats = Math.max(1, spec.repeats ?? 5);
  if (spec.stops) return timeStops(spec, repeats);
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
  const module = spec.rules ? wasmRules : wasm;
  // The bare run (wasm.Stepper) is the work `kumiki bench` times natively; the page's Sim also
  // keeps keyframes for rewind and the metrics for the chart. The two are timed in turn, a run of
  // each, the first of the pair alternating, and a repeat takes pairs until it has timed at least
  // REPEAT_SECONDS: on this shared machine a run of a few milliseconds is often preempted, and
  // only runs interleaved this finely share the load alike. So the page's Sim/bare compares the
  // same workload, steps and build under the same load.
  const once = (Handle) => {
    const run = new Handle(json);
    run.advance(spec.warmup ?? 0);
    const t = performance.now();
    const done = run.advance(spec.steps ?? 100);
    const secs = (performance.now() - t) / 1000;
    run.free();
    return { done, secs };
  };
  const bare = [];
  const page = [];
  for (let r = 0; r <= repeats; r++) {
    const sum = { bare: { done: 0, secs: 0 }, page: { done: 0, secs: 0 } };
    const add = (to, { done, secs }) => {
      to.done += done;
      to.secs += secs;
    };
    for (let pair = 0; pair === 0 || sum.bare.secs + sum.page.secs < REPEAT_SECONDS; pair++) {
      if (pair % 2) {
        add(sum.page, once(module.Sim));
        add(sum.bare, once(module.Stepper));
      } else {
        add(sum.bare, once(module.Stepper));
        add(sum.page, once(module.Sim));
      }
    }
    if (r > 0) {
      bare.push(sum.bare.done / Math.max(sum.bare.secs, 1e-9));
      page.push(sum.page.done / Math.max(sum.page.secs, 1e-9));
    }
  }
  const probe = new module.Sim(json);
  const cells = probe.cells().length;
  probe.free();
  const out = {
    name: spec.name,
    target: 'wasm',
    cells,
    steps_per_second: median(bare),
    page_steps_per_second: median(page),
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
