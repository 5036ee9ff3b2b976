//! The experiment runner: scenarios × a grid of overrides × seeds, one [`Row`] per run.
//!
//! ```json
//! {
//!   "version": 1,
//!   "name": "amas-fig23",
//!   "title": "Total steps against the number of robots",
//!   "scenarios": ["amas-L", "amas-T"],
//!   "grid": { "robots": [1, 2, 3], "field": ["continuous", "discrete"] },
//!   "set": { "max_steps": 50000 },
//!   "seeds": 10,
//!   "trace": { "every": 10, "metrics": ["built"] },
//!   "plot": { "...": "read by the page only" }
//! }
//! ```
//! `scenarios` holds preset names or whole scenario objects; `grid` keys are dotted scenario paths,
//! combined in every way (keys in sorted order, the last varying fastest); `set` applies to every
//! run; `seeds` is a count (seeds 1..=N) or a list. Jobs are numbered scenario-major, then grid,
//! then seed, and every runner reports rows in that order.
//!
//! A grid value may be a range, `sample` adds parameter points drawn at random or by Latin
//! hypercube, and `stop` ends each run early on a condition: [`crate::design`].

use serde::Serialize;
use serde_json::{Map, Value};

use crate::design::{self, Sample, Stop};
use crate::error::{Error, Result};
use crate::hash;
use crate::limits::Limits;
use crate::plot::{self, PlotSpec};
use crate::presets;
use crate::run::Run;
use crate::scenario::{canonical, Scenario, MAX_SEED};
pub use kumiki_model::row::{Row, Trace, PROGRAM_VERSION};

pub const MAX_JOBS: usize = 1_000_000;

#[derive(Clone, Debug)]
pub struct Experiment {
    pub name: String,
    pub title: String,
    pub description: String,
    pub scenarios: Vec<Scenario>,
    pub grid: Vec<(String, Vec<Value>)>,
    pub set: Vec<(String, Value)>,
    pub seeds: Vec<u64>,
    pub trace: Option<TraceSpec>,
    /// Parameter points drawn from ranges, each run with every grid combination.
    pub sample: Option<Sample>,
    /// A condition that ends a run early, checked after every step.
    pub stop: Option<Stop>,
    /// The plots as written in the file (absent: `null`).
    pub plot: Value,
    /// The plots, read and checked against the experiment's grid, models and traces.
    pub plots: Vec<PlotSpec>,
    /// The experiment as read, for the provenance of its exports.
    pub definition: Value,
}

/// What the page shows of an experiment, and the number of jobs its workers share out.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct ExperimentInfo {
    pub name: String,
    pub title: String,
    pub description: String,
    /// Runs: scenarios × grid combinations × seeds.
    pub jobs: usize,
    /// The runs trace metrics (the traces can be exported in long form).
    pub traced: bool,
}

#[derive(Clone, Debug, PartialEq)]
pub struct TraceSpec {
    pub every: u64,
    pub metrics: Vec<String>,
}

/// One run to do.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Job {
    pub index: usize,
    pub scenario: usize,
    pub params: Vec<(String, Value)>,
    pub seed: u64,
}

impl Experiment {
    /// Reads an experiment whose scenarios keep within the page's limits.
    pub fn from_json(text: &str) -> Result<Experiment> {
        Experiment::from_json_within(text, &Limits::PAGE)
    }

    /// [`Experiment::from_json`] with scenarios (and their grid values) held to `limits`.
    pub fn from_json_within(text: &str, limits: &'static Limits) -> Result<Experiment> {
        let value: Value = serde_json::from_str(text).map_err(|e| Error::json(&e))?;
        Experiment::from_value_within(value, limits)
    }

    /// A built-in experiment by name, or an experiment file's text.
    pub fn named_or_json(name_or_text: &str) -> Result<Experiment> {
        Experiment::named_or_json_within(name_or_text, &Limits::PAGE)
    }

    /// [`Experiment::named_or_json`] with scenarios held to `limits`.
    pub fn named_or_json_within(name_or_text: &str, limits: &'static Limits) -> Result<Experiment> {
        if name_or_text.trim_start().starts_with('{') {
            Experiment::from_json_within(name_or_text, limits)
        } else {
            Experiment::from_json_within(presets::experiment_json(name_or_text)?, limits)
        }
    }

    pub fn from_value(value: Value) -> Result<Experiment> {
        Experiment::from_value_within(value, &Limits::PAGE)
    }

    /// [`Experiment::from_value`] with scenarios (and their grid values) held to `limits`.
    pub fn from_value_within(value: Value, limits: &'static Limits) -> Result<Experiment> {
        let definition = value.clone();
        let Value::Object(mut map) = value else {
            return Err(Error::field("", "an experiment is a JSON object"));
        };
        match map.remove("version") {
            Some(v) if v == 1u64 => {}
            Some(v) => return Err(Error::field("version", format!("expected 1, found {v}"))),
            None => return Err(Error::field("version", "is required")),
        }
        let text = |map: &mut Map<String, Value>, key: &str| -> Result<String> {
            match map.remove(key) {
                None => Ok(String::new()),
                Some(Value::String(s)) => Ok(s),
                Some(_) => Err(Error::field(key, "expected text")),
            }
        };
        let name = text(&mut map, "name")?;
        if name.is_empty() {
            return Err(Error::field("name", "is required"));
        }
        let title = text(&mut map, "title")?;
        let description = text(&mut map, "description")?;

        let scenarios = match map.remove("scenarios") {
            Some(Value::Array(list)) if !list.is_empty() => {
                list.into_iter()
                    .enumerate()
                    .map(|(i, item)| {
                        let path = format!("scenarios[{i}]");
                        match item {
                            Value::String(name) => presets::scenario(&name)
                                .and_then(|s| s.with_limits(limits))
                                .map_err(|e| Error::field(&path, e.to_string())),
                            obj @ Value::Object(_) => Scenario::from_value_within(obj, limits)
                                .map_err(|e| e.within(&path)),
                            _ => Err(Error::field(
                                path,
                                "expected a preset name or a scenario object",
                            )),
                        }
                    })
                    .collect::<Result<Vec<_>>>()?
            }
            _ => return Err(Error::field("scenarios", "expected a non-empty list")),
        };

        let grid = match map.remove("grid") {
            None => Vec::new(),
            Some(Value::Object(g)) => g
                .into_iter()
                .map(|(k, v)| design::grid_values(&k, v).map(|values| (k, values)))
                .collect::<Result<Vec<_>>>()?,
            Some(_) => return Err(Error::field("grid", "expected an object of path: [values]")),
        };
        let sample = map.remove("sample").map(Sample::read).transpose()?;
        let set = match map.remove("set") {
            None => Vec::new(),
            Some(Value::Object(s)) => s.into_iter().collect(),
            Some(_) => return Err(Error::field("set", "expected an object of path: value")),
        };
        let seeds = match map.remove("seeds") {
            None => vec![1],
            Some(Value::Number(n)) => match n.as_u64() {
                Some(k) if (1..=MAX_JOBS as u64).contains(&k) => (1..=k).collect(),
                _ => {
                    return Err(Error::field(
                        "seeds",
                        format!("expected a count from 1 to {MAX_JOBS}"),
                    ))
                }
            },
            Some(Value::Array(list)) if !list.is_empty() => list
                .iter()
                .enumerate()
                .map(|(i, v)| match v.as_u64() {
                    Some(s) if s <= MAX_SEED => Ok(s),
                    _ => Err(Error::field(
                        format!("seeds[{i}]"),
                        "expected a seed (a whole number)",
                    )),
                })
                .collect::<Result<Vec<_>>>()?,
            Some(_) => return Err(Error::field("seeds", "expected a count or a list of seeds")),
        };
        let trace = match map.remove("trace") {
            None => None,
            Some(Value::Object(mut t)) => {
                let every = match t.remove("every") {
                    None => 1,
                    Some(v) => v.as_u64().filter(|&e| e > 0).ok_or_else(|| {
                        Error::field("trace.every", "expected a whole number of at least 1")
                    })?,
                };
                let metrics = match t.remove("metrics") {
                    Some(Value::Array(list)) if !list.is_empty() => list
                        .into_iter()
                        .map(|m| match m {
                            Value::String(s) => Ok(s),
                            _ => Err(Error::field("trace.metrics", "expected metric names")),
                        })
                        .collect::<Result<Vec<_>>>()?,
                    _ => {
                        return Err(Error::field(
                            "trace.metrics",
                            "expected a non-empty list of metric names",
                        ))
                    }
                };
                if let Some(k) = t.keys().next() {
                    return Err(Error::field(
                        format!("trace.{k}"),
                        "unknown field; expected every or metrics",
                    ));
                }
                Some(TraceSpec { every, metrics })
            }
            Some(_) => {
                return Err(Error::field(
                    "trace",
                    "expected {\"every\": N, \"metrics\": [...]}",
                ))
            }
        };
        let plot = map.remove("plot").unwrap_or(Value::Null);
        let stop_value = map.remove("stop");
        if let Some(k) = map.keys().next() {
            return Err(Error::field(
                k.as_str(),
                "unknown field; expected version, name, title, description, scenarios, grid, sample, set, seeds, trace, stop or plot",
            ));
        }
        let models: Vec<&str> = {
            let mut m: Vec<&str> = scenarios.iter().map(Scenario::model).collect();
            m.dedup();
            m
        };
        if let Some(t) = &trace {
            for (i, name) in t.metrics.iter().enumerate() {
                crate::models::check_metric(&models, name, "")
                    .map_err(|e| e.within(&format!("trace.metrics[{i}]")))?;
            }
        }
        let stop = stop_value.map(|v| Stop::read(v, &models)).transpose()?;
        let mut experiment = Experiment {
            name,
            title,
            description,
            scenarios,
            grid,
            set,
            seeds,
            trace,
            sample,
            stop,
            plot: Value::Null,
            plots: Vec::new(),
            definition,
        };
        experiment.check_runs()?;
        // The plots are read once the grid is known to be right, so a misspelt grid key is
        // blamed on the grid, not on a plot that names the key as it should be.
        let plots = PlotSpec::read_all(
            plot.clone(),
            &plot::Context {
                params: experiment.param_keys(),
                models,
                traced: experiment
                    .trace
                    .iter()
                    .flat_map(|t| t.metrics.iter().map(String::as_str))
                    .collect(),
            },
        )?;
        experiment.plots = plots;
        experiment.plot = plot;
        Ok(experiment)
    }

    /// The number of runs, and a valid scenario for every combination; a combination that gives
    /// none is blamed on the grid or sample key whose value the scenario refuses.
    fn check_runs(&self) -> Result<()> {
        if let Some(sample) = &self.sample {
            if let Some((k, _)) = sample
                .ranges
                .iter()
                .find(|(k, _)| self.grid.iter().any(|(g, _)| g == k))
            {
                return Err(Error::field(
                    format!("sample.ranges.{k}"),
                    "is also a grid key; a key is either listed or sampled",
                ));
            }
        }
        let sampled: Vec<&str> = self
            .sample
            .iter()
            .flat_map(|s| s.ranges.iter().map(|(k, _)| k.as_str()))
            .collect();
        let combos = self.combinations();
        if (self.scenarios.len() * combos.len()).saturating_mul(self.seeds.len()) > MAX_JOBS {
            return Err(Error::field("grid", format!("more than {MAX_JOBS} runs")));
        }
        for (s, scenario) in self.scenarios.iter().enumerate() {
            for params in &combos {
                self.scenario_for(s, params)
                    .map_err(|e| blame(&scenario.name, params, e, &sampled))?;
            }
        }
        Ok(())
    }

    /// The keys a row's `params` holds: the grid's, then the sample's.
    pub fn param_keys(&self) -> Vec<&str> {
        let grid = self.grid.iter().map(|(k, _)| k.as_str());
        let sampled = self
            .sample
            .iter()
            .flat_map(|s| s.ranges.iter().map(|(k, _)| k.as_str()));
        grid.chain(sampled).collect()
    }

    /// Scenarios × combinations × seeds.
    pub fn job_count(&self) -> usize {
        self.scenarios.len() * self.combinations().len() * self.seeds.len()
    }

    /// Every combination of grid values, the last key varying fastest, each with every sample
    /// point in turn.
    fn combinations(&self) -> Vec<Vec<(String, Value)>> {
        let grid = self.grid_combinations();
        let Some(sample) = &self.sample else {
            return grid;
        };
        let points = sample.points();
        grid.iter()
            .flat_map(|g| {
                points.iter().map(move |p| {
                    let mut c = g.clone();
                    c.extend(p.iter().cloned());
                    c
                })
            })
            .collect()
    }

    fn grid_combinations(&self) -> Vec<Vec<(String, Value)>> {
        let mut combos: Vec<Vec<(String, Value)>> = vec![Vec::new()];
        for (key, values) in &self.grid {
            combos = combos
                .into_iter()
                .flat_map(|prefix| {
                    values.iter().map(move |v| {
                        let mut c = prefix.clone();
                        c.push((key.clone(), v.clone()));
                        c
                    })
                })
                .collect();
        }
        combos
    }

    /// What the page shows of it, given its jobs.
    pub fn info(&self, jobs: &[Job]) -> ExperimentInfo {
        ExperimentInfo {
            name: self.name.clone(),
            title: self.title.clone(),
            description: self.description.clone(),
            jobs: jobs.len(),
            traced: self.trace.is_some(),
        }
    }

    pub fn jobs(&self) -> Vec<Job> {
        let combos = self.combinations();
        let mut jobs = Vec::with_capacity(self.scenarios.len() * combos.len() * self.seeds.len());
        for s in 0..self.scenarios.len() {
            for params in &combos {
                for &seed in &self.seeds {
                    jobs.push(Job {
                        index: jobs.len(),
                        scenario: s,
                        params: params.clone(),
                        seed,
                    });
                }
            }
        }
        jobs
    }

    fn scenario_for(&self, s: usize, params: &[(String, Value)]) -> Result<Scenario> {
        let mut overrides = self.set.clone();
        overrides.extend(params.iter().cloned());
        self.scenarios[s].with_overrides(&overrides)
    }

    pub fn run_job(&self, job: &Job) -> Result<Row> {
        let mut scenario = self.scenario_for(job.scenario, &job.params)?;
        scenario.seed = job.seed;
        let scenario_hash = hash::hex(scenario.hash_without_seed());
        let doc = match &self.stop {
            Some(_) => scenario.to_value(),
            None => Value::Null,
        };
        let stopped = |run: &Run| self.stop.as_ref().is_some_and(|s| s.met(run, &doc));
        let mut run = Run::new(scenario)?;
        let mut trace = self.trace.as_ref().map(|_| Trace::default());
        loop {
            let stop = stopped(&run);
            if let (Some(t), Some(spec)) = (&mut trace, &self.trace) {
                if run.steps() % spec.every == 0 || stop || run.finished() {
                    t.sample(run.steps(), &run.model().metrics(), &spec.metrics);
                }
            }
            // `step` applies the disturbances due at the last step before it says the run is
            // over, as a run without a stop condition always did.
            if stop || !run.step() {
                break;
            }
        }
        Ok(Row::from_outcome(
            run.outcome(),
            canonical_params(&job.params),
            scenario_hash,
            trace,
        ))
    }
}

/// The error of a combination the scenario refuses, blamed on the key whose value it refuses
/// (`grid.robot: amas-L with robot=1: unknown field 'robot'; did you mean 'robots'?`), else on
/// the grid with the combination spelt out.
fn blame(scenario: &str, params: &[(String, Value)], e: Error, sampled: &[&str]) -> Error {
    if let Error::Field { path, reason } = &e {
        let owns = |k: &str| {
            path == k || path.starts_with(&format!("{k}.")) || path.starts_with(&format!("{k}["))
        };
        if let Some((k, value)) = params.iter().find(|(k, _)| owns(k)) {
            let at = match sampled.contains(&k.as_str()) {
                true => format!("sample.ranges.{k}"),
                false => format!("grid.{k}"),
            };
            // The scenario's own reason, cut as its message would be (a misspelt key gets the
            // nearest name rather than the list of them all).
            let reason = Error::field("", reason.clone()).to_string();
            return Error::field(at, format!("{scenario} with {k}={value}: {reason}"));
        }
    }
    let at: Vec<String> = params.iter().map(|(k, v)| format!("{k}={v}")).collect();
    Error::field("grid", format!("{scenario} with {}: {e}", at.join(", ")))
}

fn canonical_params(params: &[(String, Value)]) -> Map<String, Value> {
    match canonical(Value::Object(params.iter().cloned().collect())) {
        Value::Object(m) => m,
        _ => unreachable!(),
    }
}
