//! `kumiki bench`: times the real core on the workloads in `tests/bench/*.json`. The Node script
//! `scripts/bench-wasm.mjs` times the same workloads through the wasm build, so the two can be
//! compared in one run.
//!
//! A workload file:
//! ```json
//! { "name": "amas-square28", "scenario": "amas-square28", "set": {"max_steps": 100000000},
//!   "warmup": 20, "steps": 200, "repeats": 5, "work_per_step": 784, "work_unit": "cell-updates" }
//! ```
//! Each repeat builds a fresh run, warms it up and times `steps` steps (fewer if the run ends);
//! then the same through the [`Playback`] the page's Sim plays (every step's metrics kept for the
//! chart, keyframes for rewind), so `playback_over_bare` (the median of the repeats' ratios) is
//! the page's own share of a step, natively.
//! One more repeat runs first and is not counted, so caches (and in wasm, the engine's optimising
//! compiler) are warm. The median rate over the repeats is reported, with the bytes the run holds
//! per lattice cell.
//!
//! `"rules": "paper"` puts every slot's paper rule, as a script, in the scenario's model, and a
//! list of slot names puts only theirs (`"against"` names the workload of the built-in rules, which the bench prints it beside), and
//! `"stops"` names a file of hostile scripts (`tests/fixtures/rules.json`) to time how long each
//! takes to be stopped instead of stepping one run.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Instant;

use kumiki_core::experiment::Experiment;

use kumiki_core::playback::Playback;
use kumiki_core::{models, presets, Run, Scenario};
use serde_json::{json, Map, Value};

/// Counts live heap bytes, so the benchmark can report the memory a run holds.
///
/// A global allocator is chosen when the program is linked, not per command, so every command
/// has it. It counts only after [`start_counting`], which only `kumiki bench` and `soak` call: the other
/// commands pay one relaxed load of a flag that never changes under them. Measured on
/// `kumiki sweep amas-fig23` (CPU seconds over five runs, two threads): the system allocator
/// alone 1.95-2.00, this one not counting 1.94-2.07, counting 1.94-2.15; no difference shows.
pub struct Counting;

static COUNTING: AtomicBool = AtomicBool::new(false);
/// Bytes allocated minus bytes freed since counting started; it wraps when blocks allocated
/// before are freed, and differences of it stay right.
static LIVE: AtomicUsize = AtomicUsize::new(0);

/// Heap bytes allocated and not yet freed since [`start_counting`] (wrapping; compare two
/// readings).
pub fn live_bytes() -> usize {
    LIVE.load(Ordering::Relaxed)
}

/// Makes [`Counting`] count from now on.
pub fn start_counting() {
    COUNTING.store(true, Ordering::Relaxed);
}

fn add(bytes: usize) {
    if COUNTING.load(Ordering::Relaxed) {
        LIVE.fetch_add(bytes, Ordering::Relaxed);
    }
}

fn sub(bytes: usize) {
    if COUNTING.load(Ordering::Relaxed) {
        LIVE.fetch_sub(bytes, Ordering::Relaxed);
    }
}

// SAFETY: defers to the system allocator and only counts sizes.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        add(layout.size());
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        sub(layout.size());
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        add(layout.size());
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        add(new_size);
        sub(layout.size());
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

/// A workload as read from its file.
pub struct Workload {
    pub name: String,
    pub scenario: Scenario,
    pub warmup: u64,
    pub steps: u64,
    pub repeats: usize,
    pub work_per_step: Option<f64>,
    pub work_unit: String,
    /// Instead of stepping one run: the wall time of a whole built-in experiment.
    pub experiment: Option<String>,
    /// Instead of stepping one run: hostile scripts' scenarios, each timed until it is stopped.
    pub stops: Vec<(String, Scenario)>,
}

pub fn load(path: &std::path::Path) -> Result<Workload, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let v: Value = serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    let err = |m: &str| format!("{}: {m}", path.display());
    let name = v["name"]
        .as_str()
        .ok_or_else(|| err("name is required"))?
        .to_string();
    let experiment = v["experiment"].as_str().map(str::to_string);
    let stops = match v["stops"].as_str() {
        None => Vec::new(),
        Some(file) => hostile(file).map_err(|e| err(&e))?,
    };
    let scenario = match (&v["scenario"], &experiment) {
        (Value::String(preset), _) => presets::scenario(preset).map_err(|e| err(&e.to_string()))?,
        (obj @ Value::Object(_), _) => {
            Scenario::from_value(obj.clone()).map_err(|e| err(&e.to_string()))?
        }
        (Value::Null, Some(exp)) => {
            let e = Experiment::named_or_json(exp).map_err(|e| err(&e.to_string()))?;
            e.scenarios[0].clone()
        }
        (Value::Null, None) if !stops.is_empty() => stops[0].1.clone(),
        _ => {
            return Err(err(
                "scenario (a preset name or object) or experiment is required",
            ))
        }
    };
    let mut overrides = Vec::new();
    if let Some(set) = v["set"].as_object() {
        for (k, val) in set {
            overrides.push((k.clone(), val.clone()));
        }
    }
    let slots = models::entry(scenario.model())
        .map_err(|e| err(&e.to_string()))?
        .slots;
    for slot in slots.iter().filter(|s| scripted(&v["rules"], s.name)) {
        overrides.push((format!("rules.{}", slot.name), slot.paper.into()));
    }
    let scenario = scenario
        .with_overrides(&overrides)
        .map_err(|e| err(&e.to_string()))?;
    let num = |k: &str, d: u64| v[k].as_u64().unwrap_or(d);
    Ok(Workload {
        name,
        scenario,
        warmup: num("warmup", 0),
        steps: num("steps", 100),
        repeats: num("repeats", 5).max(1) as usize,
        work_per_step: v["work_per_step"].as_f64(),
        work_unit: v["work_unit"].as_str().unwrap_or("").to_string(),
        experiment,
        stops,
    })
}

/// Whether a workload's `rules` (`"paper"`: every slot; a list: the slots named) puts the
/// paper's script in slot `name`.
fn scripted(rules: &Value, name: &str) -> bool {
    match rules {
        Value::String(all) => all == "paper",
        Value::Array(names) => names.iter().any(|n| n == name),
        _ => false,
    }
}

/// The hostile scripts of a rules fixture (`stopped`: name, preset, slot, source), each as its
/// scenario.
fn hostile(file: &str) -> Result<Vec<(String, Scenario)>, String> {
    let text = std::fs::read_to_string(file).map_err(|e| format!("{file}: {e}"))?;
    let fixture: Value = serde_json::from_str(&text).map_err(|e| format!("{file}: {e}"))?;
    let cases = fixture["stopped"]
        .as_array()
        .ok_or(format!("{file}: no stopped scripts"))?;
    cases
        .iter()
        .map(|case| {
            let field = |k: &str| case[k].as_str().unwrap_or_default();
            let scenario = presets::scenario(field("preset"))
                .and_then(|s| {
                    s.with_override(&format!("rules.{}", field("slot")), field("source").into())
                })
                .map_err(|e| format!("{file}: {e}"))?;
            Ok((field("name").to_string(), scenario))
        })
        .collect()
}

/// How long each hostile script's run takes to be stopped (reading and building it included),
/// the median of the repeats, in seconds.
fn time_stops(w: &Workload) -> Value {
    let stops: Vec<Value> = w
        .stops
        .iter()
        .map(|(name, scenario)| {
            let mut times = Vec::new();
            let mut stopped = None;
            for _ in 0..w.repeats {
                let t = Instant::now();
                let mut run = Run::new(scenario.clone()).expect("checked at load");
                run.run_to_end();
                times.push(t.elapsed().as_secs_f64());
                stopped = run.stopped().map(str::to_string);
            }
            json!({"name": name, "seconds": median(times), "stopped": stopped})
        })
        .collect();
    json!({"name": w.name, "target": "native", "stops": stops})
}

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    let n = xs.len();
    if n % 2 == 1 {
        xs[n / 2]
    } else {
        (xs[n / 2 - 1] + xs[n / 2]) / 2.0
    }
}

/// Runs one workload and returns its figures as a JSON object.
pub fn measure(w: &Workload, threads: usize) -> Value {
    if !w.stops.is_empty() {
        return time_stops(w);
    }
    if let Some(name) = &w.experiment {
        let exp = Experiment::named_or_json(name).expect("checked at load");
        let jobs = exp.jobs();
        let mut times = Vec::new();
        for _ in 0..w.repeats {
            let t = Instant::now();
            crate::pool::run_ordered(
                jobs.len(),
                threads,
                |i| exp.run_job(&jobs[i]).map(|_| ()),
                |_, r| r,
            )
            .expect("experiment jobs run");
            times.push(t.elapsed().as_secs_f64());
        }
        return json!({
            "name": w.name, "target": "native", "experiment": name, "runs": jobs.len(),
            "threads": threads, "median_seconds": median(times),
        });
    }
    let mut rates = Vec::new();
    let mut playback_rates = Vec::new();
    let mut ratios = Vec::new();
    let mut keyframes = (0, 0);
    let mut bytes_per_cell = 0.0;
    let mut cells = 0usize;
    for repeat in 0..=w.repeats {
        let before = LIVE.load(Ordering::Relaxed);
        let mut run = Run::new(w.scenario.clone()).expect("checked at load");
        let held = LIVE.load(Ordering::Relaxed).wrapping_sub(before);
        cells = run.model().cells().len();
        bytes_per_cell = held as f64 / cells.max(1) as f64;
        run.advance(w.warmup);
        let t = Instant::now();
        let done = run.advance(w.steps);
        let bare = done as f64 / t.elapsed().as_secs_f64().max(1e-9);
        // The same steps as the page's Sim plays them, right after: the Playback that keeps
        // every step's metrics and the keyframes for rewind, with a real clock. Its set-up (the
        // first keyframe and metrics) is not timed, as the bare run's is not.
        let mut run = Run::new(w.scenario.clone()).expect("checked at load");
        run.advance(w.warmup);
        let mut playback = Playback::new(run);
        let clock = Instant::now();
        let mut now = || clock.elapsed().as_secs_f64() * 1e3;
        let t = Instant::now();
        let done = playback.advance(w.steps, &mut now);
        let played = done as f64 / t.elapsed().as_secs_f64().max(1e-9);
        keyframes = playback.keyframes();
        if repeat > 0 {
            rates.push(bare);
            playback_rates.push(played);
            ratios.push(played / bare);
        }
    }
    let steps_per_second = median(rates);
    let mut out = Map::new();
    out.insert("name".into(), w.name.clone().into());
    out.insert("target".into(), "native".into());
    out.insert("cells".into(), cells.into());
    out.insert("steps_per_second".into(), json!(steps_per_second));
    out.insert("bytes_per_cell".into(), json!(bytes_per_cell));
    out.insert(
        "playback_steps_per_second".into(),
        json!(median(playback_rates)),
    );
    out.insert("playback_over_bare".into(), json!(median(ratios)));
    out.insert(
        "keyframes".into(),
        json!({"kept": keyframes.0, "every": keyframes.1}),
    );
    if let Some(work) = w.work_per_step {
        out.insert("work_unit".into(), w.work_unit.clone().into());
        out.insert("work_per_second".into(), json!(work * steps_per_second));
    }
    Value::Object(out)
}
