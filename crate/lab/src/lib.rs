//! The page's second wasm module, loaded only when the page needs it: experiments run on a pool
//! of workers ([`ExperimentRunner`]), their figures and exports, a claim of the reproduction
//! report recomputed from their rows, and hand-ins graded. The page's own module (`kumiki-wasm`:
//! the runs, the view, the scenario in view, links, presets and lessons) opens the page without
//! this code. Glue only: the work is the core's.

use std::sync::Mutex;

use serde::Serialize;
use wasm_bindgen::prelude::*;

mod experiment;
mod grading;
pub use experiment::*;
pub use grading::*;

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

fn js_err(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

fn to_js<T: Serialize + ?Sized>(value: &T) -> Result<JsValue, JsError> {
    value
        .serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(js_err)
}
