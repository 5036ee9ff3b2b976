//! `kumiki soak`: runs each model's largest preset (the most lattice cells; the first by name on a
//! tie) for many steps, 10^6 by default, and samples the memory the process holds, to show that
//! it stays flat however long a run goes. A run that finishes before is followed by the next seed,
//! so the steps count work done, and memory a finished run leaves behind would show too.
//!
//! Every `every` steps it reads what the page's worker reads for a frame (cells, agents, events,
//! metrics, the hash) and records the live heap bytes of the counting allocator and, on Linux,
//! the resident set size. One JSON object per model: the samples and the run count.

use std::time::Instant;

use kumiki_core::{models, presets, Run, Scenario};
use serde_json::{json, Value};

use crate::bench;

/// The preset of `model` with the most lattice cells.
pub fn largest_preset(model: &str) -> Result<&'static str, String> {
    let mut best: Option<(u64, &'static str)> = None;
    for name in presets::names() {
        let scenario = presets::scenario(name).map_err(|e| e.to_string())?;
        if scenario.model() != model {
            continue;
        }
        let dims = Run::new(scenario)
            .map_err(|e| e.to_string())?
            .model()
            .layout()
            .dims;
        let cells = dims.iter().map(|&d| u64::from(d.max(1))).product::<u64>();
        if best.is_none_or(|(most, _)| cells > most) {
            best = Some((cells, name));
        }
    }
    best.map(|(_, name)| name)
        .ok_or_else(|| format!("the model '{model}' has no preset"))
}

/// The models to soak: the one named, or all of them.
pub fn models(only: Option<&str>) -> Result<Vec<&'static str>, String> {
    match only {
        Some(name) => models::entry(name)
            .map(|e| vec![e.name])
            .map_err(|e| e.to_string()),
        None => Ok(models::MODELS.iter().map(|e| e.name).collect()),
    }
}

/// Resident set size of this process in bytes (Linux's /proc), or None elsewhere.
fn resident_bytes() -> Option<u64> {
    let statm = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: u64 = statm.split_whitespace().nth(1)?.parse().ok()?;
    Some(pages * 4096)
}

/// Soaks one model's largest preset for `steps` steps, sampling every `every` steps.
pub fn soak(model: &str, steps: u64, every: u64) -> Result<Value, String> {
    let preset = largest_preset(model)?;
    let base: Scenario = presets::scenario(preset).map_err(|e| e.to_string())?;
    let start = Instant::now();
    // Room for every sample before counting starts: the samples must not be what grows.
    let mut samples: Vec<(u64, usize, Option<u64>)> =
        Vec::with_capacity((steps / every + 2) as usize);
    let live0 = bench::live_bytes();
    let mut scenario = base.clone();
    let mut run = Run::new(scenario.clone()).map_err(|e| e.to_string())?;
    let (mut taken, mut runs) = (0u64, 1u64);
    let mut sink = 0u64;
    while taken < steps {
        let want = every - taken % every;
        let n = run.advance(want.min(steps - taken));
        taken += n;
        if run.finished() {
            scenario.seed += 1;
            run = Run::new(scenario.clone()).map_err(|e| e.to_string())?;
            runs += 1;
        }
        if taken % every == 0 || taken == steps {
            // What the worker reads for a frame; kept from being optimised away.
            let model = run.model();
            sink = sink.wrapping_add(model.cells().len() as u64);
            sink = sink.wrapping_add(model.agents().len() as u64 + model.events().len() as u64);
            sink = sink.wrapping_add(model.metrics().len() as u64 ^ run.state_hash());
            samples.push((
                taken,
                bench::live_bytes().wrapping_sub(live0),
                resident_bytes(),
            ));
        }
    }
    Ok(json!({
        "model": model,
        "preset": preset,
        "steps": taken,
        "runs": runs,
        "seconds": start.elapsed().as_secs_f64(),
        "samples": samples
            .iter()
            .map(|&(step, live, rss)| json!({"step": step, "live_bytes": live, "rss_bytes": rss}))
            .collect::<Vec<_>>(),
        "checksum": sink,
    }))
}
