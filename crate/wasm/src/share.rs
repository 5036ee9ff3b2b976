//! Share links: a scenario packed into the part of a link after `#`, and unpacked again.

use kumiki_core::{json, link, models, Scenario};
use serde::Serialize;
use serde_json::Value;
use wasm_bindgen::prelude::*;

use crate::{js_err, to_js};

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

/// The behaviour version of its model that made a link, and this program's:
/// `{made_with, current}`. The page warns when they differ.
#[wasm_bindgen]
pub fn link_model_versions(link_text: &str) -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    struct Versions {
        made_with: u32,
        current: u32,
    }
    let opened = link::open(link_text).map_err(js_err)?;
    to_js(&Versions {
        made_with: opened.made_with,
        current: opened.current,
    })
}

/// A link's scenario JSON, not yet validated, with the behaviour version of its model that made
/// it and this program's: `{scenario, made_with, current}`. Nothing is built, so a large
/// scenario's link can be read on the main thread and opened in the worker.
#[wasm_bindgen]
pub fn unpack_link(link_text: &str) -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    struct Unpacked {
        scenario: String,
        made_with: u32,
        current: u32,
    }
    let (doc, made_with) = link::unpack(link_text).map_err(js_err)?;
    let model = doc.get("model").and_then(Value::as_str).unwrap_or_default();
    let current = models::entry(model).map_or(made_with, |e| e.model_version);
    to_js(&Unpacked {
        scenario: json::pretty(&doc).map_err(js_err)?,
        made_with,
        current,
    })
}

/// The share-link payload for scenario JSON that was validated before (the page's own scenario),
/// without building its model again.
#[wasm_bindgen]
pub fn pack_link(json: &str) -> Result<String, JsError> {
    json::parse(json).map(link::pack).map_err(js_err)
}
