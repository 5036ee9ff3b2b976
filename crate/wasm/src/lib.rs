//! The page's window into the core: one simulation handle ([`Sim`]), one view handle
//! ([`Viewer`], which draws a `Sim` from its buffers in place), one handle on the scenario the
//! page edits ([`Draft`]) and a few free functions: what the page needs to open. Experiments,
//! the report's claims and grading are the lab module's (`kumiki-lab`), loaded when the page
//! needs them. Small records go through serde-wasm-bindgen. No simulation logic lives here.

use kumiki_core::experiment::PROGRAM_VERSION;
use wasm_bindgen::prelude::*;

// The conversions to JavaScript; kumiki-bind also installs the panic hook when the module starts
// and exports `panic_message`, in both modules.
use kumiki_bind::{js_err, to_js};

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

/// Panics on purpose. The page's end-to-end test uses it to check that a panic is shown and the
/// page recovers.
#[wasm_bindgen]
pub fn simulate_panic() {
    panic!("simulated panic (diagnostics)");
}

#[wasm_bindgen]
pub fn version() -> String {
    PROGRAM_VERSION.to_string()
}
