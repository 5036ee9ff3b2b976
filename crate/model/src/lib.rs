//! The contract every Kumiki model is written against, and all a model crate depends on. Pure
//! Rust: no browser, no clock, no thread-local randomness.
//!
//! - [`model`]: the [`Model`](model::Model) trait, the typed scenario description
//!   ([`Spec`](model::Spec)), what a renderer reads ([`Layout`](model::Layout),
//!   [`Scene`](model::Scene), ...), metrics and actions; [`entry`]: the
//!   [`ModelEntry`](entry::ModelEntry) that registers a model, with its helper calls and paper;
//! - [`bounds`]: the range of each number a description may take, stated once for its check and
//!   its schema;
//! - [`lattice`] and [`shape`]: square, hex and cubic lattices, and the text shapes scenarios
//!   carry; [`limits`]: every size a scenario may ask for;
//! - [`rng`], [`math`], [`hash`]: the portable randomness, maths and state hash every model uses;
//!   [`error`]: errors that name the field and the rule; [`sort`]: one stable sort for the cold
//!   paths; [`stats`]: two conditions compared (effect sizes, the Mann-Whitney U test);
//!   `typescript` (with the `schema` feature): TypeScript declarations written from JSON Schemas;
//! - [`slot`]: the rule slots, decisions a model lets a user's script take in place of its
//!   paper's rule;
//! - [`row`] and [`report`]: what a run leaves, and the vocabulary a model's paper uses to turn
//!   experiment rows into the reproduction report's findings.

pub mod bounds;
pub mod entry;
pub mod error;
pub mod hash;
pub mod lattice;
pub mod limits;
pub mod math;
pub mod model;
mod read;
pub mod report;
pub mod rng;
pub mod row;
pub mod shape;
pub mod slot;
pub mod sort;
pub mod stats;
#[cfg(feature = "schema")]
pub mod typescript;

pub use error::{Error, Result};
pub use limits::Limits;
