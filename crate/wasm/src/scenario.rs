//! Scenario text: read, checked, compared, estimated and changed by a dotted path.

use kumiki_core::{json, shape, Scenario};
use serde_json::Value;
use wasm_bindgen::prelude::*;

use crate::js_err;

/// Validates scenario JSON and returns it in canonical, indented form.
#[wasm_bindgen]
pub fn normalize_scenario(json: &str) -> Result<String, JsError> {
    Scenario::from_json(json)
        .map(|s| s.to_json_pretty())
        .map_err(js_err)
}

/// A scenario's comparison (its `compare` section), as `[second, first label, second label]`:
/// the second run's scenario (this one with the one setting changed, canonical and indented) and
/// the two runs' names in words; `undefined` when the scenario compares nothing.
#[wasm_bindgen]
pub fn compare_pair(json: &str) -> Result<Option<Vec<String>>, JsError> {
    let scenario = Scenario::from_json(json).map_err(js_err)?;
    let (Some(compare), Some(second)) = (&scenario.compare, scenario.compared().map_err(js_err)?)
    else {
        return Ok(None);
    };
    let (first_label, second_label) = compare.labels(&scenario.to_value());
    Ok(Some(vec![
        second.to_json_pretty(),
        first_label,
        second_label,
    ]))
}

/// The most cells a shape may span in the page (`Limits::PAGE`): a scenario over it is refused
/// by the worker, so the page does not ask the user about the memory it would need.
#[wasm_bindgen]
pub fn page_shape_cells() -> f64 {
    kumiki_core::Limits::PAGE.shape_cells as f64
}

/// The whole of what is wrong with scenario JSON, or "" when nothing is. The errors the other
/// calls throw are brief (under 200 characters); this is the rest, for whoever asks.
#[wasm_bindgen]
pub fn scenario_problem_in_full(json: &str) -> String {
    Scenario::from_json(json)
        .err()
        .map(|e| format!("{e:#}"))
        .unwrap_or_default()
}

/// The cells of the largest shape a scenario's JSON describes, read from the text without
/// building anything (see `shape::estimate_cells`); 0 when it is not JSON. The page opens a
/// scenario above its threshold in the simulation worker, so the main thread never builds it.
/// Saturates at 2^53 so it stays a JavaScript number.
#[wasm_bindgen]
pub fn estimate_cells(json: &str) -> f64 {
    json::parse(json)
        .map(|doc| shape::estimate_cells(&doc).min(1 << 53) as f64)
        .unwrap_or(0.0)
}

/// Sets one dotted path of scenario JSON without validating the result: the page changes a large
/// scenario this way and leaves its validation to the worker that opens it.
#[wasm_bindgen]
pub fn set_scenario_path(json: &str, path: &str, value_json: &str) -> Result<String, JsError> {
    let value: Value =
        json::parse(value_json).unwrap_or_else(|_| Value::String(value_json.to_string()));
    let mut doc: Value = json::parse(json).map_err(js_err)?;
    kumiki_core::scenario::set_path(&mut doc, path, value).map_err(js_err)?;
    json::pretty(&doc).map_err(js_err)
}

/// A fresh seed from the system's entropy (`crypto.getRandomValues`), 0 to 2^53 − 1: the page's
/// "New seed" writes it into the scenario, so the run replays from its link.
#[wasm_bindgen]
pub fn fresh_seed() -> Result<f64, JsError> {
    kumiki_seed::fresh_seed()
        .map(|seed| seed as f64)
        .map_err(|e| JsError::new(&format!("no fresh seed could be drawn: {e}")))
}

/// Applies one dotted-path override to scenario JSON and returns the validated result.
#[wasm_bindgen]
pub fn override_scenario(json: &str, path: &str, value_json: &str) -> Result<String, JsError> {
    let value: Value =
        json::parse(value_json).unwrap_or_else(|_| Value::String(value_json.to_string()));
    Scenario::from_json(json)
        .and_then(|s| s.with_override(path, value))
        .map(|s| s.to_json_pretty())
        .map_err(js_err)
}
