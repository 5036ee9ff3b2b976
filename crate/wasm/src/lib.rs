//! The page's window into the core: one simulation handle ([`Sim`]), one view handle
//! ([`Viewer`], which draws a `Sim` from its buffers in place), one handle on the scenario the page
//! edits ([`Draft`]), one experiment handle ([`ExperimentRunner`]) and a few free functions. Small records go through serde-wasm-bindgen.
//! No simulation logic lives here.

use std::sync::Mutex;

use js_sys::{Float32Array, Float64Array, Uint32Array, Uint8Array};
use kumiki_core::exercise::Goal;
use kumiki_core::experiment::{Experiment, Job, PROGRAM_VERSION};
use kumiki_core::models::Scene;
use kumiki_core::playback::Playback;
use kumiki_core::{grading, hash, json, lessons, link, models, presets, shape, Run, Scenario};
use serde::Serialize;
use serde_json::Value;
use wasm_bindgen::prelude::*;

mod draft;
mod viewer;
pub use draft::Draft;
pub use viewer::{LatticeGeometry, Viewer};

static PANIC: Mutex<Option<String>> = Mutex::new(None);

/// Installs the panic hook: the message goes to the console and is kept for [`panic_message`],
/// so the worker can show it in the page after the trap.
#[wasm_bindgen(start)]
pub fn start() {
    std::panic::set_hook(Box::new(|info| {
        if let Ok(mut slot) = PANIC.lock() {
            *slot = Some(info.to_string());
        }
        console_error_panic_hook::hook(info);
    }));
}

/// The message of the panic that stopped this instance, if one did.
#[wasm_bindgen]
pub fn panic_message() -> Option<String> {
    PANIC.lock().ok().and_then(|slot| slot.clone())
}

/// Panics on purpose. The page's end-to-end test uses it to check that a panic is shown and the
/// page recovers.
#[wasm_bindgen]
pub fn simulate_panic() {
    panic!("simulated panic (diagnostics)");
}

fn js_err(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

fn to_js<T: Serialize + ?Sized>(value: &T) -> Result<JsValue, JsError> {
    value
        .serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(js_err)
}

#[wasm_bindgen]
pub fn version() -> String {
    PROGRAM_VERSION.to_string()
}

/// A model's metric table: `[{name, unit, about}, ...]` in the model's order (see
/// `kumiki_core::models::MetricInfo`); an unknown model is an error that lists the known ones.
#[wasm_bindgen]
pub fn metric_table(model: &str) -> Result<JsValue, JsError> {
    to_js(models::metric_table(model).map_err(js_err)?)
}

/// The built-in scenarios: name, model, title, description.
#[wasm_bindgen]
pub fn presets() -> Result<JsValue, JsError> {
    to_js(&presets::list().map_err(js_err)?)
}

#[wasm_bindgen]
pub fn preset_json(name: &str) -> Result<String, JsError> {
    presets::scenario(name)
        .map(|s| s.to_json_pretty())
        .map_err(js_err)
}

/// The built-in lessons: name, model, paper, section, exercise title and description.
#[wasm_bindgen]
pub fn lessons() -> Result<JsValue, JsError> {
    to_js(&lessons::list().map_err(js_err)?)
}

#[wasm_bindgen]
pub fn lesson_json(name: &str) -> Result<String, JsError> {
    lessons::scenario(name)
        .map(|s| s.to_json_pretty())
        .map_err(js_err)
}

/// The most cells a shape may span in the page (`Limits::PAGE`): a scenario over it is refused
/// by the worker, so the page does not ask the user about the memory it would need.
#[wasm_bindgen]
pub fn page_shape_cells() -> f64 {
    kumiki_core::Limits::PAGE.shape_cells as f64
}

/// The share-link payload (the part after `#`) for scenario JSON.
#[wasm_bindgen]
pub fn encode_link(json: &str) -> Result<String, JsError> {
    Scenario::from_json(json)
        .map(|s| link::encode(&s))
        .map_err(js_err)
}

/// The scenario JSON inside a link, validated and indented.
#[wasm_bindgen]
pub fn decode_link(link_text: &str) -> Result<String, JsError> {
    link::decode(link_text)
        .map(|s| s.to_json_pretty())
        .map_err(js_err)
}

/// The behaviour version of its model that made a link, and this program's: `Versions`. The
/// page warns when they differ.
#[wasm_bindgen]
pub fn link_model_versions(link_text: &str) -> Result<JsValue, JsError> {
    to_js(&link::open(link_text).map_err(js_err)?.versions())
}

/// A link's scenario JSON, not yet checked, with the behaviour version of its model that made
/// it and this program's: `Unpacked`. Nothing is built, so a large scenario's link can be read on
/// the main thread and opened in the worker.
#[wasm_bindgen]
pub fn unpack_link(link_text: &str) -> Result<JsValue, JsError> {
    to_js(&link::unpacked(link_text).map_err(js_err)?)
}

/// A fresh seed from the system's entropy (`crypto.getRandomValues`), 0 to 2^53 − 1: the page's
/// "New seed" writes it into the scenario, so the run replays from its link.
#[wasm_bindgen]
pub fn fresh_seed() -> Result<f64, JsError> {
    kumiki_seed::fresh_seed()
        .map(|seed| seed as f64)
        .map_err(|e| JsError::new(&format!("no fresh seed could be drawn: {e}")))
}

/// A text shape read by the core's rules, as `Cells`: `{w, h, d, cells}` with one 0/1 byte per
/// cell (row-major, layers from the ground up). `lattice` is `square`, `hex` or `cubic`.
#[wasm_bindgen]
pub fn shape_parse(lattice: &str, text: &str) -> Result<JsValue, JsError> {
    to_js(&shape::cells_of(lattice, text).map_err(js_err)?)
}

/// The text form of a shape (the inverse of [`shape_parse`]).
#[wasm_bindgen]
pub fn shape_format(
    lattice: &str,
    w: u32,
    h: u32,
    d: u32,
    cells: &[u8],
) -> Result<String, JsError> {
    let cells = shape::Cells {
        w,
        h,
        d,
        cells: cells.to_vec(),
    };
    shape::text_of(lattice, &cells).map_err(js_err)
}

/// `performance.now()` of the page or worker, in milliseconds; `None` where there is none.
fn clock() -> Option<js_sys::Function> {
    let performance = js_sys::Reflect::get(&js_sys::global(), &"performance".into()).ok()?;
    let now = js_sys::Reflect::get(&performance, &"now".into()).ok()?;
    Some(now.dyn_into::<js_sys::Function>().ok()?.bind0(&performance))
}

/// One running simulation, with the keyframes that let it go back: a
/// [`Playback`](kumiki_core::playback::Playback), which keeps the run, its keyframes and its
/// chart record, read by the page's clock.
#[wasm_bindgen]
pub struct Sim {
    playback: Playback,
    clock: Option<js_sys::Function>,
    /// The scene [`Sim::scene_if_changed`] last gave, so a frame carries it only when it changed.
    last_scene: Option<Scene>,
}

impl Sim {
    pub(crate) fn run(&self) -> &Run {
        self.playback.run()
    }
}

#[wasm_bindgen]
impl Sim {
    #[wasm_bindgen(constructor)]
    pub fn new(scenario_json: &str) -> Result<Sim, JsError> {
        let scenario = Scenario::from_json(scenario_json).map_err(js_err)?;
        Ok(Sim {
            playback: Playback::new(Run::new(scenario).map_err(js_err)?),
            clock: clock(),
            last_scene: None,
        })
    }

    /// Takes up to `n` steps, keeping keyframes and every step's metrics; returns how many were
    /// taken.
    pub fn advance(&mut self, n: u32) -> u32 {
        let clock = &self.clock;
        let mut now = || {
            clock
                .as_ref()
                .and_then(|f| f.call0(&JsValue::NULL).ok())
                .and_then(|v| v.as_f64())
                .unwrap_or(0.0)
        };
        self.playback.advance(u64::from(n), &mut now) as u32
    }

    /// Goes to `step` (at most the furthest step reached) by replaying from the keyframe before
    /// it: the state is bit-identical to the one passed through.
    pub fn seek(&mut self, step: f64) {
        self.playback.seek(step.max(0.0) as u64);
    }

    /// A metric's every-step record for the chart, merged into at most `points` points:
    /// `[steps…, least…, greatest…]`, three runs of the same length.
    pub fn chart(&self, metric: &str, points: u32) -> Float64Array {
        let band = self.playback.series().decimate(metric, points as usize);
        let flat: Vec<f64> = [band.steps, band.min, band.max].concat();
        Float64Array::from(flat.as_slice())
    }

    /// Steps per recorded bucket of the chart's series (1 until the record is full, then doubling).
    pub fn chart_span(&self) -> f64 {
        self.playback.series().span() as f64
    }

    /// The furthest step reached, where the timeline ends.
    pub fn furthest(&self) -> f64 {
        self.playback.furthest() as f64
    }

    /// Keyframes kept and the steps between them, for the page's memory note.
    pub fn keyframes(&self) -> Vec<f64> {
        let (n, every) = self.playback.keyframes();
        vec![n as f64, every as f64]
    }

    pub fn steps(&self) -> f64 {
        self.run().steps() as f64
    }

    pub fn finished(&self) -> bool {
        self.run().finished()
    }

    pub fn completed(&self) -> bool {
        self.run().model().completed()
    }

    /// The 64-bit state hash in hex.
    pub fn hash(&self) -> String {
        hash::hex(self.run().state_hash())
    }

    /// Lattice, legends, fields and tools: see `kumiki_core::models::Layout`.
    pub fn layout(&self) -> Result<JsValue, JsError> {
        to_js(&self.run().model().layout())
    }

    pub fn metrics(&self) -> Result<JsValue, JsError> {
        to_js(&self.run().model().metrics())
    }

    /// One code per cell (a copy, for tests and tools: the page's view reads the model in place,
    /// see [`Viewer`]).
    pub fn cells(&self) -> Uint8Array {
        Uint8Array::from(self.run().model().cells().as_ref())
    }

    /// One value per cell (a copy), NaN where undefined; undefined for an unknown field.
    pub fn field(&self, name: &str) -> Option<Float32Array> {
        self.run()
            .model()
            .field(name)
            .map(|values| Float32Array::from(values.as_ref()))
    }

    /// Agents as `[cell, kind, cell, kind, ...]`.
    pub fn agents(&self) -> Uint32Array {
        let flat: Vec<u32> = self
            .run()
            .model()
            .agents()
            .iter()
            .flat_map(|a| [a.cell, u32::from(a.kind)])
            .collect();
        Uint32Array::from(flat.as_slice())
    }

    /// Events of the last step as `[cell, kind, ...]`.
    pub fn events(&self) -> Uint32Array {
        let flat: Vec<u32> = self
            .run()
            .model()
            .events()
            .iter()
            .flat_map(|e| [e.cell, u32::from(e.kind)])
            .collect();
        Uint32Array::from(flat.as_slice())
    }

    /// The code of one cell (0: empty or off the lattice).
    pub fn cell_code(&self, cell: u32) -> u8 {
        self.run()
            .model()
            .cells()
            .get(cell as usize)
            .copied()
            .unwrap_or(0)
    }

    /// The middle occupied cell in memory order (where a keyboard cursor starts), or -1.
    pub fn middle_occupied(&self) -> f64 {
        let cells = self.run().model().cells();
        let occupied = cells.iter().filter(|&&c| c != 0).count();
        let nth = cells
            .iter()
            .enumerate()
            .filter(|(_, &c)| c != 0)
            .nth(occupied / 2);
        nth.map_or(-1.0, |(i, _)| i as f64)
    }

    /// Applies an action now (a click tool) and records it in the scenario; a click in the past
    /// forks the run (see `kumiki_core::playback::Playback::apply`).
    pub fn apply(&mut self, action_json: &str) -> Result<(), JsError> {
        let action: Value = json::parse(action_json).map_err(js_err)?;
        let Value::Object(action) = action else {
            return Err(JsError::new("an action is a JSON object"));
        };
        self.playback.apply(action).map_err(js_err)
    }

    /// Bonds as one bit mask per cell (bit d: bonded to the neighbour in lattice direction d);
    /// empty for models without bonds. See `kumiki_core::models::Model::bonds`.
    pub fn bonds(&self) -> Uint8Array {
        Uint8Array::from(self.run().model().bonds().as_ref())
    }

    pub fn inspect(&self, cell: u32) -> Result<JsValue, JsError> {
        to_js(&self.run().model().inspect(cell as usize))
    }

    /// Ghost cells, light direction, ground plane and bonds for 3-D views (see
    /// `kumiki_core::models::Scene`); empty for models without them. Read it again after stepping:
    /// the ghost follows the current target.
    pub fn scene(&self) -> Result<JsValue, JsError> {
        to_js(&self.run().model().scene())
    }

    /// [`Sim::scene`] when it differs from what this call last returned (always on the first
    /// call), else null: the worker's frames carry the scene only when it changed, without
    /// serialising it every frame to find out.
    pub fn scene_if_changed(&mut self) -> Result<JsValue, JsError> {
        let scene = self.run().model().scene();
        if self.last_scene.as_ref() == Some(&scene) {
            return Ok(JsValue::NULL);
        }
        let value = to_js(&scene)?;
        self.last_scene = Some(scene);
        Ok(value)
    }

    /// The step limit of the scenario.
    pub fn max_steps(&self) -> f64 {
        self.run().scenario().max_steps as f64
    }

    /// The scenario as it now stands, with clicked disturbances recorded.
    pub fn scenario_json(&self) -> String {
        self.run().scenario().to_json_pretty()
    }

    /// The exercise's goal judged on the run as it stands: `{met, because}`, or undefined when
    /// the scenario is no exercise.
    pub fn check_goal(&self) -> Result<JsValue, JsError> {
        let Some(exercise) = &self.run().scenario().exercise else {
            return Ok(JsValue::UNDEFINED);
        };
        let outcome = self.run().outcome();
        let doc = self.run().scenario().to_value();
        let check = exercise.goal().check(&kumiki_core::exercise::Outcome {
            completed: outcome.completed,
            steps: outcome.steps,
            metrics: &outcome.metrics,
            scenario: &doc,
        });
        // A locked field away from the teacher's value is never "Goal met".
        to_js(&grading::with_locks(check, exercise, &doc))
    }
}

/// A goal in words for students ("Completed, and collisions below 40."), or undefined when it
/// does not parse.
#[wasm_bindgen]
pub fn goal_words(text: &str) -> Option<String> {
    Goal::parse(text).ok().map(|g| g.words())
}

/// The teacher's exercise for grading: a link, or a lesson's name, as `kumiki check --exercise`
/// takes them; a scenario with no exercise section is refused.
fn teacher_exercise(text: &str) -> Result<Scenario, JsError> {
    let text = text.trim();
    let scenario = match lessons::names().any(|n| n == text) {
        true => lessons::scenario(text).map_err(js_err)?,
        false => {
            link::open_within(text, &kumiki_core::Limits::PAGE)
                .map_err(js_err)?
                .scenario
        }
    };
    match scenario.exercise {
        Some(_) => Ok(scenario),
        None => Err(JsError::new(
            "exercise: this scenario has no exercise section",
        )),
    }
}

/// Checks the teacher's exercise for the Grade view: its title, or an error that says why it
/// cannot grade.
#[wasm_bindgen]
pub fn exercise_title(text: &str) -> Result<String, JsError> {
    let scenario = teacher_exercise(text)?;
    Ok(scenario.exercise.map(|e| e.title).unwrap_or_default())
}

/// Grades one hand-in as `kumiki check` does (page limits): the link replayed to its end and
/// judged by the teacher's exercise (`exercise`: a link or a lesson's name) when given, else by
/// its own. Its `Graded` row.
#[wasm_bindgen]
pub fn grade_handin(handin: &str, exercise: Option<String>) -> Result<JsValue, JsError> {
    let original = exercise.map(|e| teacher_exercise(&e)).transpose()?;
    let graded = link::open_within(handin.trim(), &kumiki_core::Limits::PAGE)
        .and_then(|o| kumiki_core::exercise::grade(&o.scenario, original.as_ref()));
    to_js(&kumiki_core::exercise::Graded::of(graded))
}

/// A model's helper call that needs no run (see `kumiki_core::models::query`), for instance
/// `model_query("cubes3d", "derive", '{"shape": "##\n##\n"}')`. Arguments and answer are JSON
/// text; a bad argument is an error that names it.
#[wasm_bindgen]
pub fn model_query(model: &str, name: &str, args_json: &str) -> Result<String, JsError> {
    let args: Value = json::parse(args_json).map_err(js_err)?;
    models::query(model, name, &args)
        .map(|v| v.to_string())
        .map_err(js_err)
}

/// A bare run, without the keyframes and chart record a [`Sim`] keeps: the work `kumiki bench`
/// times natively, so `npm run bench` compares like with like.
#[wasm_bindgen]
pub struct Stepper {
    run: Run,
}

#[wasm_bindgen]
impl Stepper {
    #[wasm_bindgen(constructor)]
    pub fn new(scenario_json: &str) -> Result<Stepper, JsError> {
        let scenario = Scenario::from_json(scenario_json).map_err(js_err)?;
        Ok(Stepper {
            run: Run::new(scenario).map_err(js_err)?,
        })
    }

    /// Takes up to `n` steps; returns how many were taken.
    pub fn advance(&mut self, n: u32) -> u32 {
        self.run.advance(u64::from(n)) as u32
    }
}

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
/// svg` draws it.
#[wasm_bindgen]
pub fn experiment_figures(experiment_json: &str, rows_json: &str) -> Result<JsValue, JsError> {
    let e = Experiment::named_or_json(experiment_json).map_err(js_err)?;
    let rows = json::parse_rows(rows_json).map_err(js_err)?;
    let models: Vec<&str> = e.scenarios.iter().map(Scenario::model).collect();
    let drawn: Vec<Drawn> = kumiki_core::plot::figure::figures(&e.plots, &rows, &models)
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
/// metrics in long form, as `--traces`); `time` is when the sweep ran (RFC 3339).
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
    let p = export::Provenance::of(&e, time);
    match format {
        "csv" => Ok(export::csv(&p, &rows)),
        "json" => Ok(export::json_lines(&p, &rows)),
        "traces" => Ok(export::trace_csv(&p, &rows)),
        other => Err(JsError::new(&format!(
            "'{other}' is not an export format; expected csv, json or traces"
        ))),
    }
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
