//! The page's second wasm module, loaded only when the page needs it: experiments run on a pool
//! of workers ([`ExperimentRunner`]), their figures and exports, a claim of the reproduction
//! report recomputed from their rows, and hand-ins graded. The page's own module (`kumiki-wasm`:
//! the runs, the view, the scenario in view, links, presets and lessons) opens the page without
//! this code. Glue only: the work is the core's.

// The conversions to JavaScript; kumiki-bind also installs the panic hook when the module starts
// and exports `panic_message`, in both modules.
use kumiki_bind::{js_err, to_js};

mod experiment;
mod grading;
pub use experiment::*;
pub use grading::*;
