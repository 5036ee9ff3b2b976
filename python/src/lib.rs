//! The kumiki Python package's native module (`kumiki._kumiki`): glue only, like the wasm
//! modules. Every record crosses as the JSON text the CLI writes (a row as `kumiki run` and
//! `kumiki sweep` print it, the provenance as their exports carry it), so the package and the CLI
//! give the same bytes; `kumiki/__init__.py` turns them into pandas DataFrames.

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

use kumiki_core::experiment::{Experiment, Row, Trace};
use kumiki_core::export::{self, Provenance};
use kumiki_core::plot::{figure, number, pdf, svg};
use kumiki_core::{grading, hash, json, lessons, link, models, presets, Limits, Run, Scenario};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use serde_json::{json, Map, Value};

fn err(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

fn limits(large: bool) -> &'static Limits {
    match large {
        true => &Limits::LARGE,
        false => &Limits::PAGE,
    }
}

/// A scenario from JSON text, a file, a share link, a preset or a lesson name, as the CLI opens
/// one; returned as its JSON (a link made with another behaviour version says so in `note`).
#[pyfunction]
#[pyo3(signature = (source, allow_large = false))]
fn open_scenario(source: &str, allow_large: bool) -> PyResult<(String, Option<String>)> {
    let (scenario, note) = open_source(source, limits(allow_large)).map_err(err)?;
    Ok((scenario.to_value().to_string(), note))
}

fn open_source(
    source: &str,
    limits: &'static Limits,
) -> Result<(Scenario, Option<String>), String> {
    let text = |e: kumiki_core::Error| e.to_string();
    if source.trim_start().starts_with('{') {
        return Ok((
            Scenario::from_json_within(source, limits).map_err(text)?,
            None,
        ));
    }
    if Path::new(source).is_file() {
        let json = std::fs::read_to_string(source).map_err(|e| e.to_string())?;
        let s = Scenario::from_json_within(&json, limits).map_err(|e| format!("{source}: {e}"))?;
        return Ok((s, None));
    }
    if source.contains('#') || source.starts_with(link::PREFIX) {
        let opened = link::open_within(source, limits).map_err(text)?;
        let note = opened.version_differs().then(|| {
            format!(
                "this link was made with {} behaviour version {}, and this Kumiki runs {}; results may differ",
                opened.scenario.model(),
                opened.made_with,
                opened.current
            )
        });
        return Ok((opened.scenario, note));
    }
    let named = if presets::names().any(|n| n == source) {
        presets::scenario(source)
    } else if lessons::names().any(|n| n == source) {
        lessons::scenario(source)
    } else {
        return Err(format!(
            "'{source}' is not JSON, a file, a share link, a preset or a lesson (see kumiki.presets() and kumiki.lessons())"
        ));
    };
    Ok((
        named.and_then(|s| s.with_limits(limits)).map_err(text)?,
        None,
    ))
}

fn scenario_of(text: &str, allow_large: bool) -> PyResult<Scenario> {
    Scenario::from_json_within(text, limits(allow_large)).map_err(err)
}

/// The overrides as `kumiki run --set` takes them: each value read as JSON when it parses.
fn overrides(sets: Vec<(String, String)>) -> PyResult<Vec<(String, Value)>> {
    sets.into_iter()
        .map(|(path, value)| {
            let v = serde_json::from_str(&value).unwrap_or(Value::String(value));
            Ok((path, v))
        })
        .collect()
}

/// Runs `count` jobs on `threads` threads; the results in job order.
fn pooled<T: Send>(count: usize, threads: usize, work: impl Fn(usize) -> T + Sync) -> Vec<T> {
    let next = AtomicUsize::new(0);
    let done: Mutex<BTreeMap<usize, T>> = Mutex::new(BTreeMap::new());
    std::thread::scope(|scope| {
        for _ in 0..threads.clamp(1, count.max(1)) {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                if i >= count {
                    break;
                }
                let result = work(i);
                done.lock().expect("no worker panicked").insert(i, result);
            });
        }
    });
    done.into_inner()
        .expect("no worker panicked")
        .into_values()
        .collect()
}

fn threads(jobs: Option<usize>) -> usize {
    jobs.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
}

/// The rows of `kumiki run SCENARIO --seed S... [--set PATH=VALUE]... [--max-steps M]`, each
/// as the JSON line it prints, in the same order (each seed's run, then its compared run).
#[pyfunction]
#[pyo3(signature = (scenario, seeds, sets, max_steps = None, jobs = None, allow_large = false))]
fn run_rows(
    py: Python<'_>,
    scenario: &str,
    seeds: Vec<u64>,
    sets: Vec<(String, String)>,
    max_steps: Option<u64>,
    jobs: Option<usize>,
    allow_large: bool,
) -> PyResult<Vec<String>> {
    let mut scenario = scenario_of(scenario, allow_large)?;
    let sets = overrides(sets)?;
    let mut params = Map::new();
    if !sets.is_empty() {
        scenario = scenario.with_overrides(&sets).map_err(err)?;
        params.extend(sets);
    }
    if let Some(m) = max_steps {
        scenario = scenario.with_override("max_steps", m.into()).map_err(err)?;
    }
    let mut runs = vec![(scenario.clone(), params.clone())];
    if let (Some(compare), Some(mut second)) =
        (&scenario.compare, scenario.compared().map_err(err)?)
    {
        let (_, label) = compare.labels(&scenario.to_value());
        second.name = format!("{} ({label})", second.name);
        let mut params = params.clone();
        params.insert(compare.path.clone(), compare.value.clone());
        runs.push((second, params));
    }
    let runs: Vec<(Scenario, Map<String, Value>, String)> = runs
        .into_iter()
        .map(|(s, p)| {
            let h = hash::hex(s.hash_without_seed());
            (s, p, h)
        })
        .collect();
    let total = seeds.len() * runs.len();
    let rows = py.detach(|| {
        pooled(total, threads(jobs), |i| {
            let (scenario, params, scenario_hash) = &runs[i % runs.len()];
            let mut s = scenario.clone();
            s.seed = seeds[i / runs.len()];
            let mut run = Run::new(s).map_err(|e| e.to_string())?;
            run.run_to_end();
            let row = Row::from_outcome(run.outcome(), params.clone(), scenario_hash.clone(), None);
            serde_json::to_string(&row).map_err(|e| e.to_string())
        })
    });
    rows.into_iter().map(|r| r.map_err(err)).collect()
}

/// One run's metrics at every `every`-th step and at its end: the steps and each metric's
/// values (JSON: `{"step": [...], "values": {name: [...]}}`), all metrics when `metrics` is
/// empty.
#[pyfunction]
#[pyo3(signature = (scenario, seed, metrics, every = 1, allow_large = false))]
fn trace(
    py: Python<'_>,
    scenario: &str,
    seed: Option<u64>,
    metrics: Vec<String>,
    every: u64,
    allow_large: bool,
) -> PyResult<String> {
    let mut scenario = scenario_of(scenario, allow_large)?;
    if let Some(s) = seed {
        scenario.seed = s;
    }
    let model = scenario.model().to_string();
    let names: Vec<String> = match metrics.is_empty() {
        true => models::metric_table(&model)
            .map_err(err)?
            .iter()
            .map(|m| m.name.to_string())
            .collect(),
        false => {
            for m in &metrics {
                models::check_metric(&[&model], m, "").map_err(err)?;
            }
            metrics
        }
    };
    let every = every.max(1);
    let t = py.detach(|| -> Result<Trace, String> {
        let mut run = Run::new(scenario).map_err(|e| e.to_string())?;
        let mut t = Trace::default();
        loop {
            if run.steps() % every == 0 || run.finished() {
                t.sample(run.steps(), &run.model().metrics(), &names);
            }
            if !run.step() {
                break;
            }
        }
        Ok(t)
    });
    serde_json::to_string(&t.map_err(err)?).map_err(err)
}

/// The agents of one run (the robots on their modules, where the model has them) at every
/// `every`-th step and at its end: JSON records of step, agent (its place in the model's list),
/// cell, x, y, z and kind (its code and name in the model's legend).
#[pyfunction]
#[pyo3(signature = (scenario, seed, every = 1, allow_large = false))]
fn agents(
    py: Python<'_>,
    scenario: &str,
    seed: Option<u64>,
    every: u64,
    allow_large: bool,
) -> PyResult<String> {
    let mut scenario = scenario_of(scenario, allow_large)?;
    if let Some(s) = seed {
        scenario.seed = s;
    }
    let every = every.max(1);
    let records = py.detach(|| -> Result<Vec<Value>, String> {
        let mut run = Run::new(scenario).map_err(|e| e.to_string())?;
        let layout = run.model().layout();
        let [w, h, _] = layout.dims;
        let kinds: BTreeMap<u8, String> =
            layout.agents.iter().map(|e| (e.code, e.name.clone())).collect();
        let mut out = Vec::new();
        loop {
            if run.steps() % every == 0 || run.finished() {
                for (i, a) in run.model().agents().iter().enumerate() {
                    let (x, y, z) = (a.cell % w, a.cell / w % h.max(1), a.cell / (w * h).max(1));
                    out.push(json!({
                        "step": run.steps(), "agent": i, "cell": a.cell, "x": x, "y": y, "z": z,
                        "kind": a.kind, "kind_name": kinds.get(&a.kind).cloned().unwrap_or_default(),
                    }));
                }
            }
            if !run.step() {
                break;
            }
        }
        Ok(out)
    });
    Ok(Value::Array(records.map_err(err)?).to_string())
}

fn experiment_of(source: &str, allow_large: bool) -> PyResult<Experiment> {
    let limits = limits(allow_large);
    if !source.trim_start().starts_with('{') && Path::new(source).is_file() {
        let text = std::fs::read_to_string(source).map_err(err)?;
        return Experiment::from_json_within(&text, limits)
            .map_err(|e| err(format!("{source}: {e}")));
    }
    if source.starts_with(link::EXPERIMENT_PREFIX) || source.contains("#x") {
        let json = link::unpack_experiment(source).map_err(err)?;
        return Experiment::from_json_within(&json, limits).map_err(err);
    }
    Experiment::named_or_json_within(source, limits).map_err(err)
}

/// The experiment as read (its definition's JSON) and its number of runs.
#[pyfunction]
#[pyo3(signature = (experiment, allow_large = false))]
fn open_experiment(experiment: &str, allow_large: bool) -> PyResult<(String, usize)> {
    let e = experiment_of(experiment, allow_large)?;
    Ok((e.definition.to_string(), e.job_count()))
}

/// `kumiki sweep EXPERIMENT`: the provenance (JSON, as the exports carry it; `time` as given)
/// and every row's JSON line, in job order.
#[pyfunction]
#[pyo3(signature = (experiment, time, jobs = None, allow_large = false))]
fn sweep(
    py: Python<'_>,
    experiment: &str,
    time: &str,
    jobs: Option<usize>,
    allow_large: bool,
) -> PyResult<(String, Vec<String>)> {
    let e = experiment_of(experiment, allow_large)?;
    let list = e.jobs();
    let provenance = serde_json::to_string(&Provenance::of(&e, time)).map_err(err)?;
    let rows = py.detach(|| {
        pooled(list.len(), threads(jobs), |i| {
            e.run_job(&list[i])
                .map_err(|e| e.to_string())
                .and_then(|r| serde_json::to_string(&r).map_err(|e| e.to_string()))
        })
    });
    Ok((
        provenance,
        rows.into_iter()
            .map(|r| r.map_err(err))
            .collect::<PyResult<_>>()?,
    ))
}

fn rows_of(rows: &str) -> PyResult<Vec<Row>> {
    json::parse_rows(rows).map_err(err)
}

/// The figures of the experiment's plots from rows (a JSON array): each figure's record (JSON)
/// and its SVG, marked partial when the rows are fewer than the runs.
#[pyfunction]
fn figures(experiment: &str, rows: &str) -> PyResult<Vec<(String, String)>> {
    let e = experiment_of(experiment, true)?;
    let rows = rows_of(rows)?;
    figure::figures_of(&e, &rows)
        .iter()
        .map(|f| Ok((serde_json::to_string(f).map_err(err)?, svg::svg(f))))
        .collect()
}

/// Figure `index` as a one-page PDF.
#[pyfunction]
fn figure_pdf<'py>(
    py: Python<'py>,
    experiment: &str,
    rows: &str,
    index: usize,
) -> PyResult<Bound<'py, PyBytes>> {
    let e = experiment_of(experiment, true)?;
    let figs = figure::figures_of(&e, &rows_of(rows)?);
    let f = figs
        .get(index)
        .ok_or_else(|| err(format!("the experiment has {} figures", figs.len())))?;
    Ok(PyBytes::new(py, &pdf::pdf(&svg::layout(f))))
}

/// `kumiki sweep --summary`'s JSON lines from rows (a JSON array).
#[pyfunction]
fn summary(experiment: &str, rows: &str) -> PyResult<Vec<String>> {
    let e = experiment_of(experiment, true)?;
    let figs = figure::figures_of(&e, &rows_of(rows)?);
    Ok(figure::summary_lines(&figs)
        .iter()
        .map(Value::to_string)
        .collect())
}

/// The rows exported as the CLI and the page write them: `csv`, `json` or `traces`, with their
/// provenance (partial when the rows are fewer than the runs).
#[pyfunction]
fn export_rows(experiment: &str, rows: &str, format: &str, time: &str) -> PyResult<String> {
    let e = experiment_of(experiment, true)?;
    let rows = rows_of(rows)?;
    let p = Provenance::of_rows(&e, time, &rows);
    match format {
        "csv" => Ok(export::csv(&p, &rows)),
        "json" => Ok(export::json_lines(&p, &rows)),
        "traces" => Ok(export::trace_csv(&p, &rows)),
        other => Err(err(format!(
            "'{other}' is not an export format; expected csv, json or traces"
        ))),
    }
}

/// Hand-ins graded, as `kumiki check --format json` writes each (the graded record's JSON), by
/// their own exercise or by the teacher's (`exercise`, any scenario source).
#[pyfunction]
#[pyo3(signature = (handins, exercise = None, jobs = None))]
fn check(
    py: Python<'_>,
    handins: Vec<String>,
    exercise: Option<String>,
    jobs: Option<usize>,
) -> PyResult<Vec<String>> {
    let opened: Vec<Result<Scenario, String>> = handins
        .iter()
        .map(|h| open_source(h, &Limits::PAGE).map(|(s, _)| s))
        .collect();
    let teacher = match exercise {
        Some(e) => grading::Teacher::given(&open_source(&e, &Limits::PAGE).map_err(err)?.0),
        None => grading::Teacher::from_handins(
            opened
                .iter()
                .filter_map(|s| s.as_ref().ok())
                .map(Scenario::to_value),
        ),
    }
    .map_err(|e| err(format!("exercise: {e}")))?;
    let graded = py.detach(|| {
        pooled(opened.len(), threads(jobs), |i| {
            let started = std::time::Instant::now();
            let mut clock = || started.elapsed().as_secs_f64();
            let g = match &opened[i] {
                Ok(s) => grading::Graded::of(grading::grade(s.clone(), &teacher, &mut clock)),
                Err(e) => grading::Graded::Failed { error: e.clone() },
            };
            serde_json::to_string(&g).unwrap_or_default()
        })
    });
    Ok(graded)
}

/// A share link of a scenario (JSON), the page's `#k1.` part.
#[pyfunction]
fn share_link(scenario: &str) -> PyResult<String> {
    Ok(link::encode(&scenario_of(scenario, true)?))
}

/// A number as every figure and table shows it.
#[pyfunction]
fn format_number(value: f64) -> String {
    number::format(value)
}

/// The built-in scenarios, experiments and lessons, by name.
#[pyfunction]
fn names(kind: &str) -> PyResult<Vec<String>> {
    Ok(match kind {
        "presets" => presets::names().map(str::to_string).collect(),
        "experiments" => presets::experiment_names().map(str::to_string).collect(),
        "lessons" => lessons::names().map(str::to_string).collect(),
        other => return Err(err(format!("no list of {other}"))),
    })
}

/// Every metric of every model (or of one): model, name, unit and meaning, as JSON.
#[pyfunction]
#[pyo3(signature = (model = None))]
fn metrics(model: Option<&str>) -> PyResult<String> {
    let mut out = Vec::new();
    for m in models::MODELS
        .iter()
        .filter(|m| model.is_none_or(|x| x == m.name))
    {
        for i in m.metrics {
            out.push(json!({"model": m.name, "name": i.name, "unit": i.unit, "about": i.about}));
        }
    }
    if out.is_empty() {
        return Err(err(format!("no model is named '{}'", model.unwrap_or(""))));
    }
    Ok(Value::Array(out).to_string())
}

/// The program's version, as every row carries it, and the commit it was built from.
#[pyfunction]
fn version() -> (String, String) {
    (
        kumiki_core::experiment::PROGRAM_VERSION.to_string(),
        export::COMMIT.to_string(),
    )
}

#[pymodule]
fn _kumiki(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(open_scenario, m)?)?;
    m.add_function(wrap_pyfunction!(run_rows, m)?)?;
    m.add_function(wrap_pyfunction!(trace, m)?)?;
    m.add_function(wrap_pyfunction!(agents, m)?)?;
    m.add_function(wrap_pyfunction!(open_experiment, m)?)?;
    m.add_function(wrap_pyfunction!(sweep, m)?)?;
    m.add_function(wrap_pyfunction!(figures, m)?)?;
    m.add_function(wrap_pyfunction!(figure_pdf, m)?)?;
    m.add_function(wrap_pyfunction!(summary, m)?)?;
    m.add_function(wrap_pyfunction!(export_rows, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(share_link, m)?)?;
    m.add_function(wrap_pyfunction!(format_number, m)?)?;
    m.add_function(wrap_pyfunction!(names, m)?)?;
    m.add_function(wrap_pyfunction!(metrics, m)?)?;
    m.add_function(wrap_pyfunction!(version, m)?)?;
    Ok(())
}
