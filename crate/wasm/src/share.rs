//! Share links: a scenario packed into the part of a link after `#`, and unpacked again.

use kumiki_core::{link, Scenario};
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
