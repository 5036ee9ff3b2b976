//! The models Kumiki knows, in gallery order: the one list of models. A model is registered by
//! its [`ModelEntry`] here; the scenario reader, the schemas, the metrics table, the helper calls,
//! the reproduction report and the gallery's titles all find it through this list.

use super::ModelEntry;

pub const MODELS: &[ModelEntry] = &[
    kumiki_amas::ENTRY,
    kumiki_chobie::ENTRY,
    kumiki_cubes3d::ENTRY,
    kumiki_fracta::ENTRY,
];
