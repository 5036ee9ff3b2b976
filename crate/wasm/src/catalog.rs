//! What the core holds built in: the presets, the lessons (with the `catalog` feature only: the
//! page's first-load module leaves them out, and the page fetches them as JSON that
//! scripts/catalog.mjs writes from the rules module), each model's metric table and its helper calls.

#[cfg(feature = "catalog")]
use kumiki_core::lessons;
use kumiki_core::{json, models, presets};
use serde_json::Value;
use wasm_bindgen::prelude::*;

use crate::{js_err, to_js};

/// A model's metric table: `[{name, unit, about}, ...]` in the model's order (see
/// `kumiki_core::models::MetricInfo`); an unknown model is an error that lists the known ones.
#[wasm_bindgen]
pub fn metric_table(model: &str) -> Result<JsValue, JsError> {
    to_js(models::metric_table(model).map_err(js_err)?)
}

#[cfg(feature = "catalog")]
/// The built-in scenarios: name, model, title, description.
#[wasm_bindgen]
pub fn presets() -> Result<JsValue, JsError> {
    to_js(&presets::list().map_err(js_err)?)
}

#[cfg(feature = "catalog")]
#[wasm_bindgen]
pub fn preset_json(name: &str) -> Result<String, JsError> {
    presets::scenario(name)
        .map(|s| s.to_json_pretty())
        .map_err(js_err)
}

#[cfg(feature = "catalog")]
/// The built-in lessons: name, model, paper, section, exercise title and description.
#[wasm_bindgen]
pub fn lessons() -> Result<JsValue, JsError> {
    to_js(&lessons::list().map_err(js_err)?)
}

#[cfg(feature = "catalog")]
#[wasm_bindgen]
pub fn lesson_json(name: &str) -> Result<String, JsError> {
    lessons::scenario(name)
        .map(|s| s.to_json_pretty())
        .map_err(js_err)
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

/// A number as every figure, table and export shows it: the core's one rule
/// (`kumiki_core::plot::number`), so the page's tables and metric cards round as the figures do.
#[wasm_bindgen]
pub fn format_number(value: f64) -> String {
    kumiki_core::plot::number::format(value)
}

/// How a scenario (its JSON text) differs from the built-in scenario it is named after, each
/// changed field in words (`robots: 5 → 3`), or `null` when no preset has its name or its shapes
/// span more than `check_up_to_cells` cells: what a shared edited scenario says beside the
/// preset's description. The page asks it on its own thread, where a large scenario is never read
/// (reading one of 4096 × 4096 cells takes a second and more; its worker reads it).
#[cfg(feature = "catalog")]
#[wasm_bindgen]
pub fn preset_changes(scenario_json: &str, check_up_to_cells: f64) -> Result<JsValue, JsError> {
    let doc: Value = serde_json::from_str(scenario_json).map_err(js_err)?;
    let named = doc["name"].as_str().unwrap_or("");
    if !presets::names().any(|p| p == named) {
        return to_js(&None::<Vec<String>>);
    }
    match read_unless_large(doc, check_up_to_cells)? {
        Some(s) => to_js(&presets::changes_from_preset(&s)),
        None => to_js(&None::<Vec<String>>),
    }
}

/// How a scenario (its JSON text) differs from `preset_json`, the built-in scenario it is named
/// after (the page holds its text), each changed field in words, as [`preset_changes`] says it;
/// `null` when its shapes span more than `check_up_to_cells` cells (never read on the page's thread).
#[wasm_bindgen]
pub fn scenario_changes(
    preset_json: &str,
    scenario_json: &str,
    check_up_to_cells: f64,
) -> Result<JsValue, JsError> {
    let doc: Value = serde_json::from_str(scenario_json).map_err(js_err)?;
    let Some(scenario) = read_unless_large(doc, check_up_to_cells)? else {
        return to_js(&None::<Vec<String>>);
    };
    let preset = kumiki_core::Scenario::from_json(preset_json).map_err(js_err)?;
    to_js(&Some(presets::changes_between(&preset, &scenario)))
}

/// The scenario `doc` holds, or `None` when its shapes span more than `check_up_to_cells` cells:
/// the page's thread never reads a large one (its worker does).
fn read_unless_large(
    doc: Value,
    check_up_to_cells: f64,
) -> Result<Option<kumiki_core::Scenario>, JsError> {
    if kumiki_core::shape::estimate_cells(&doc) as f64 > check_up_to_cells {
        return Ok(None);
    }
    kumiki_core::Scenario::from_value(doc)
        .map(Some)
        .map_err(js_err)
}

/// Every model's rule slots: `[{model, slot: {name, title, about, input, output, paper, random}}]`
/// (`kumiki_core::rules::SlotDoc`), the paper's rule as each slot's script. In the rules module
/// only, which the page loads to edit or run rules.
#[cfg(feature = "rules")]
#[wasm_bindgen]
pub fn rule_slots() -> Result<JsValue, JsError> {
    to_js(&kumiki_core::rules::slots())
}

/// Checks `source` as the script of `model`'s slot `slot` as a scenario's `rules` would
/// (`kumiki_core::rules::Rules::read`): `null` when it reads, else the reason, which starts with
/// "line L, column C: " when the engine places it. The page's editor marks it as the user types.
/// In the rules module only.
#[cfg(feature = "rules")]
#[wasm_bindgen]
pub fn check_rule(model: &str, slot: &str, source: &str) -> Result<Option<String>, JsError> {
    let entry = models::entry(model).map_err(js_err)?;
    let section = serde_json::json!({ slot: source });
    match kumiki_core::rules::Rules::read(Some(section), entry) {
        Ok(_) => Ok(None),
        Err(kumiki_core::Error::Field { reason, .. }) => Ok(Some(reason)),
        Err(e) => Ok(Some(e.to_string())),
    }
}

/// Whether this module runs rule scripts: false in the page's first-load module, true in its
/// rules module (kumiki_wasm_rules), which the page loads for a scenario that carries `rules`.
#[wasm_bindgen]
pub fn rules_engine() -> bool {
    kumiki_core::rules::ENGINE
}
