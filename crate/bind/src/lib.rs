//! What Kumiki's two wasm modules share: the page's (`kumiki-wasm`) and the lab's
//! (`kumiki-lab`). Each module that links this crate starts by installing the panic hook and
//! exports [`panic_message`]; both convert results and errors to JavaScript the same way.

use std::sync::Mutex;

use serde::Serialize;
use wasm_bindgen::prelude::*;

static PANIC: Mutex<Option<String>> = Mutex::new(None);

/// Installs the panic hook when the module starts: the message goes to the console and is kept
/// for [`panic_message`], so the worker can show it in the page after the trap.
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

/// An error for JavaScript, with the error's message.
pub fn js_err(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

/// A record for JavaScript, as JSON would give it (maps as plain objects, 64-bit integers as
/// numbers).
pub fn to_js<T: Serialize + ?Sized>(value: &T) -> Result<JsValue, JsError> {
    value
        .serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(js_err)
}
