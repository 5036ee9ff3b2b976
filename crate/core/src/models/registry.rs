//! The models Kumiki knows, in gallery order: the one list of models. A model is registered by
//! its crate's name here, one line a model; the scenario reader, the schemas, the metrics table,
//! the helper calls, the reproduction report and the gallery's titles all find it through the
//! two tables that line fills: its [`ModelEntry`] and its paper.

use super::ModelEntry;
use kumiki_model::report::Paper;

/// Fills [`MODELS`] with each named crate's `ENTRY` and [`PAPERS`] with its `paper::PAPER`, in
/// the order given.
macro_rules! register {
    ($($model:ident),* $(,)?) => {
        /// Every model's entry, in gallery order.
        pub const MODELS: &[ModelEntry] = &[$($model::ENTRY),*];
        /// Every model's paper for the reproduction report, in the same order. A table apart
        /// from the entries: a build that never reads it (the page's own wasm module) does not
        /// link the findings' code.
        pub const PAPERS: &[Paper] = &[$($model::paper::PAPER),*];
    };
}

register! {
    kumiki_amas,
    kumiki_chobie,
    kumiki_cubes3d,
    kumiki_fracta,
}
