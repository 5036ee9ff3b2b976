//! What the page asks of the core about a scenario beside its [`Draft`](crate::Draft): the
//! largest shape the page takes, and a fresh seed.

use wasm_bindgen::prelude::*;

/// The most cells a shape may span in the page (`Limits::PAGE`): a scenario over it is refused
/// by the worker, so the page does not ask the user about the memory it would need.
#[wasm_bindgen]
pub fn page_shape_cells() -> f64 {
    kumiki_core::Limits::PAGE.shape_cells as f64
}

/// A fresh seed from the system's entropy (`crypto.getRandomValues`), 0 to 2^53 − 1: the page's
/// "New seed" writes it into the scenario, so the run replays from its link.
#[wasm_bindgen]
pub fn fresh_seed() -> Result<f64, JsError> {
    kumiki_seed::fresh_seed()
        .map(|seed| seed as f64)
        .map_err(|e| JsError::new(&format!("no fresh seed could be drawn: {e}")))
}
