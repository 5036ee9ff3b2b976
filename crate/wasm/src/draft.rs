//! The scenario the page shows and edits, held in the simulation worker between edits, beside the
//! run built from it: a handle on [`kumiki_core::draft::Draft`]. Answers are `Proposal` and
//! `Comparison` records (web/contract.gen.ts).

use kumiki_core::json;
use serde_json::Value;
use wasm_bindgen::prelude::*;

use crate::{js_err, to_js, Sim};

/// The page's scenario in view, held by the simulation worker. One per worker, made once; `free`
/// is never needed.
#[wasm_bindgen]
pub struct Draft {
    pub(crate) draft: kumiki_core::draft::Draft,
}

#[wasm_bindgen]
impl Draft {
    /// A draft with nothing in view, which checks scenarios whose shapes span up to
    /// `check_up_to_cells` cells at once and proposes larger ones unchecked, for their run to
    /// check once the page has said so.
    #[wasm_bindgen(constructor)]
    pub fn new(check_up_to_cells: f64) -> Draft {
        Draft {
            draft: kumiki_core::draft::Draft::new(check_up_to_cells as u64),
        }
    }

    /// Opens scenario JSON in place of the one in view; `keep_locks` holds it to the exercise in
    /// view (an edit of the JSON text). A `Proposal`.
    pub fn open(&mut self, json: &str, keep_locks: bool) -> Result<JsValue, JsError> {
        to_js(&self.draft.open(json, keep_locks))
    }

    /// Sets several dotted paths at once (`changes_json`: an object from path to value) and
    /// checks the result once. A `Proposal`.
    pub fn edit_all(&mut self, changes_json: &str) -> Result<JsValue, JsError> {
        let Value::Object(changes) = json::parse(changes_json).map_err(js_err)? else {
            return Err(JsError::new("changes are an object from path to value"));
        };
        let changes: Vec<(String, Value)> = changes.into_iter().collect();
        to_js(&self.draft.edit(&changes))
    }

    /// `sim` runs the scenario in view: a large one it checked as it opened, or the one in view
    /// with a click recorded.
    pub fn ran(&mut self, sim: &Sim) {
        self.draft.ran(sim.run().scenario().clone());
    }

    /// The share-link payload of the scenario in view, or of it named `name` (a hand-in).
    pub fn link(&self, name: Option<String>) -> Result<String, JsError> {
        self.draft.link(name.as_deref()).map_err(js_err)
    }

    /// The hand-in link of the scenario in view, named `name`, with its record (`record_json`:
    /// `{"made": "2026-11-28T10:15:00Z", "checks": 3, "hints": 1, "answer": "…"}`, the page's
    /// clock giving the time).
    pub fn handin(&self, name: &str, record_json: &str) -> Result<String, JsError> {
        let record = json::parse(record_json).map_err(js_err)?;
        self.draft.handin(name, record).map_err(js_err)
    }

    /// Why a click of the tool `label` (its action's `kind`) may not be made on the scenario in
    /// view, as the exercise says; undefined when it may.
    pub fn click_problem(&self, kind: &str, label: &str) -> Option<String> {
        self.draft.click_problem(kind, label)
    }

    /// How many more disturbances of `kind` the exercise in view lets a student add; undefined
    /// when no exercise is in view.
    pub fn clicks_left(&self, kind: &str) -> Option<u32> {
        self.draft.clicks_left(kind)
    }

    /// The scenario in view's `Comparison`.
    pub fn comparison(&self) -> Result<JsValue, JsError> {
        to_js(&self.draft.comparison().map_err(js_err)?)
    }

    /// What is wrong with an exercise goal for the scenario in view, whose model reports
    /// `metrics`; undefined when it reads well.
    pub fn goal_problem(&self, goal: &str, metrics: Vec<String>) -> Option<String> {
        self.draft.goal_problem(goal, &metrics)
    }
}
