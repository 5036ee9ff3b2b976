//! The models Kumiki knows, in gallery order. The one list of models is the core's dependencies on
//! the model crates (`crate/core/Cargo.toml`, one line a model, in gallery order): the build
//! script turns it into the one invocation of `register!` below. The scenario reader, the schemas,
//! the metrics table, the helper calls, the reproduction report and the gallery's titles all find a
//! model through the two tables that line fills: its [`ModelEntry`] and its paper.

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

include!(concat!(env!("OUT_DIR"), "/models.rs"));

#[cfg(test)]
mod tests {
    use super::*;

    /// Every crate under `crate/models/` is registered (a dependency of the core written another
    /// way than `kumiki-<model> = { path = "../models/<model>" }` would not be), each under its
    /// folder's name.
    #[test]
    fn every_model_crate_is_registered_under_its_folders_name() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../models");
        let mut folders: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.join("Cargo.toml").is_file())
            .map(|p| p.file_name().unwrap().to_str().unwrap().to_string())
            .collect();
        folders.sort();
        let mut names: Vec<&str> = MODELS.iter().map(|m| m.name).collect();
        names.sort_unstable();
        assert_eq!(
            names, folders,
            "the registered models are not the crates under crate/models/"
        );
    }
}
