//! Experiments: one handle whose jobs a pool of workers shares out ([`ExperimentRunner`]), the
//! built-in experiment files, their links, figures and exports, and a claim of the reproduction
//! report recomputed from their rows.

use kumiki_core::experiment::{Experiment, Job};
use kumiki_core::{json, link, presets};
use serde::Serialize;
use wasm_bindgen::prelude::*;

use crate::{js_err, to_js};

/// An experiment parsed once, whose jobs a pool of workers shares out.
#[wasm_bindgen]
pub struct ExperimentRunner {
    experiment: Experiment,
    jobs: Vec<Job>,
}

#[wasm_bindgen]
impl ExperimentRunner {
    /// From a built-in experiment name or an experiment's JSON text.
    #[wasm_bindgen(constructor)]
    pub fn new(name_or_json: &str) -> Result<ExperimentRunner, JsError> {
        let experiment = Experiment::named_or_json(name_or_json).map_err(js_err)?;
        let jobs = experiment.jobs();
        Ok(ExperimentRunner { experiment, jobs })
    }

    /// The experiment's `ExperimentInfo`.
    pub fn info(&self) -> Result<JsValue, JsError> {
        to_js(&self.experiment.info(&self.jobs))
    }

    pub fn job_count(&self) -> u32 {
        self.jobs.len() as u32
    }

    /// Runs job `index` and returns its row as JSON text, exactly as `kumiki sweep` writes it:
    /// kept as text, a real 1.0 stays 1.0 in the page's exports.
    pub fn run(&self, index: u32) -> Result<String, JsError> {
        let job = self
            .jobs
            .get(index as usize)
            .ok_or_else(|| JsError::new("no such job"))?;
        let row = self.experiment.run_job(job).map_err(js_err)?;
        serde_json::to_string(&row).map_err(js_err)
    }
}

/// The built-in experiments, each's `ExperimentInfo`.
#[wasm_bindgen]
pub fn experiments() -> Result<JsValue, JsError> {
    let infos: Vec<_> = presets::experiment_names()
        .map(|name| {
            let runner = ExperimentRunner::new(name)?;
            Ok(runner.experiment.info(&runner.jobs))
        })
        .collect::<Result<_, JsError>>()?;
    to_js(&infos)
}

/// The text of a built-in experiment file, for the page's editor.
#[wasm_bindgen]
pub fn experiment_json(name: &str) -> Result<String, JsError> {
    presets::experiment_json(name)
        .map(str::to_string)
        .map_err(js_err)
}

/// An experiment's link payload (`x1.…`, without the `#`), after checking the experiment.
#[wasm_bindgen]
pub fn pack_experiment(experiment_json: &str) -> Result<String, JsError> {
    let e = Experiment::from_json(experiment_json).map_err(js_err)?;
    Ok(link::pack_experiment(&e.definition))
}

/// The experiment JSON (pretty) inside an experiment link; checked, so a bad one is an error.
#[wasm_bindgen]
pub fn unpack_experiment(link_text: &str) -> Result<String, JsError> {
    let json = link::unpack_experiment(link_text).map_err(js_err)?;
    let e = Experiment::from_json(&json).map_err(js_err)?;
    serde_json::to_string_pretty(&e.definition).map_err(js_err)
}

#[derive(Serialize)]
struct Drawn {
    figure: kumiki_core::plot::figure::Figure,
    svg: String,
}

/// The figures of an experiment's plots from its rows (a JSON array of rows as
/// `ExperimentRunner::run` gives them): each figure's data and its SVG, as `kumiki sweep --plot
/// svg` draws it. Rows fewer than the experiment's runs (a cancelled sweep) give figures marked
/// "partial: N of M runs".
#[wasm_bindgen]
pub fn experiment_figures(experiment_json: &str, rows_json: &str) -> Result<JsValue, JsError> {
    let e = Experiment::named_or_json(experiment_json).map_err(js_err)?;
    let rows = json::parse_rows(rows_json).map_err(js_err)?;
    let drawn: Vec<Drawn> = kumiki_core::plot::figure::figures_of(&e, &rows)
        .into_iter()
        .map(|figure| Drawn {
            svg: kumiki_core::plot::svg::svg(&figure),
            figure,
        })
        .collect();
    to_js(&drawn)
}

/// An experiment's rows (a JSON array of row texts) exported with their provenance, the bytes
/// `kumiki sweep` writes: `format` is `csv`, `json` (JSON lines) or `traces` (the traced
/// metrics in long form, as `--traces`); `time` is when the sweep ran (RFC 3339). Rows fewer than
/// the experiment's runs (a cancelled sweep) are marked "partial: N of M runs", with only their
/// seeds.
#[wasm_bindgen]
pub fn experiment_export(
    experiment_json: &str,
    rows_json: &str,
    format: &str,
    time: &str,
) -> Result<String, JsError> {
    use kumiki_core::export;
    let e = Experiment::named_or_json(experiment_json).map_err(js_err)?;
    let rows = json::parse_rows(rows_json).map_err(js_err)?;
    let p = export::Provenance::of_rows(&e, time, &rows);
    match format {
        "csv" => Ok(export::csv(&p, &rows)),
        "json" => Ok(export::json_lines(&p, &rows)),
        "traces" => Ok(export::trace_csv(&p, &rows)),
        other => Err(JsError::new(&format!(
            "'{other}' is not an export format; expected csv, json or traces"
        ))),
    }
}

/// Figure `index` of an experiment's plots from its rows, as a one-page PDF (the SVG's layout,
/// set in Helvetica), marked partial as [`experiment_figures`] marks it.
#[wasm_bindgen]
pub fn experiment_figure_pdf(
    experiment_json: &str,
    rows_json: &str,
    index: u32,
) -> Result<Vec<u8>, JsError> {
    let e = Experiment::named_or_json(experiment_json).map_err(js_err)?;
    let rows = json::parse_rows(rows_json).map_err(js_err)?;
    let figures = kumiki_core::plot::figure::figures_of(&e, &rows);
    let f = figures
        .get(index as usize)
        .ok_or_else(|| JsError::new(&format!("the experiment has {} figures", figures.len())))?;
    Ok(kumiki_core::plot::pdf::pdf(
        &kumiki_core::plot::svg::layout(f),
    ))
}

/// A claim of the reproduction report (`id`, as in `docs/reproduction.json`) recomputed from the
/// rows of its experiments, by the function `kumiki reproduce` writes the report with:
/// `rows_json` is an object from experiment name to its rows (each as `ExperimentRunner::run`
/// gives it, in job order). Gives the finding: section, claim, figure, runs, verdict, note.
#[wasm_bindgen]
pub fn reproduce_claim(model: &str, id: &str, rows_json: &str) -> Result<JsValue, JsError> {
    use kumiki_core::reproduce;
    let paper = reproduce::paper(model)
        .ok_or_else(|| JsError::new(&format!("no paper is registered for model '{model}'")))?;
    let given: std::collections::BTreeMap<String, Vec<kumiki_core::experiment::Row>> =
        serde_json::from_str(rows_json).map_err(js_err)?;
    let mut results = reproduce::Results::for_paper(paper);
    for (name, rows) in given {
        results.insert(&name, rows);
    }
    let finding = reproduce::recompute(paper, id, &results)
        .ok_or_else(|| JsError::new(&format!("the report has no claim '{id}' for {model}")))?;
    to_js(&finding)
}

/// The reproduction report as `kumiki reproduce` last wrote it (`docs/reproduction.json`, built
/// into this module): each model's section, by model name. The page's About tab shows it.
#[wasm_bindgen]
pub fn reproduction_report() -> Result<JsValue, JsError> {
    let report: serde_json::Value =
        json::parse(include_str!("../../../docs/reproduction.json")).map_err(js_err)?;
    to_js(&report["models"])
}
