//! The page's window into the core: one simulation handle ([`Sim`]), one view handle
//! ([`Viewer`], which draws a `Sim` from its buffers in place), one handle on the scenario the
//! page edits ([`Draft`]) and a few free functions: what the page needs to open. Experiments,
//! the report's claims and grading are the lab module's (`kumiki-lab`), loaded when the page
//! needs them. Small records go through serde-wasm-bindgen. No simulation logic lives here.

use std::sync::Mutex;

use kumiki_core::experiment::PROGRAM_VERSION;
use serde::Serialize;
use wasm_bindgen::prelude::*;

mod catalog;
mod draft;
mod exercise;
mod scenario;
mod shapes;
mod share;
mod sim;
mod viewer;
pub use catalog::*;
pub use draft::Draft;
pub use exercise::*;
pub use scenario::*;
pub use shapes::*;
pub use share::*;
pub use sim::*;
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
