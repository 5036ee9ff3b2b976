//! Kumiki's simulation core. Pure Rust: no browser, no clock, no thread-local randomness.
//!
//! Built on the models' contract, [`kumiki_model`], whose lattices, shapes, limits, randomness,
//! maths, hash and errors it re-exports under the same names.
//!
//! - [`lattice`]: square, hex and cubic lattices behind one neighbourhood API;
//! - [`models`]: the models and their registry;
//! - [`scenario`]: the versioned JSON document that determines a run, and [`shape`] for the text
//!   shapes inside it;
//! - [`limits`]: every size a scenario may ask for, per model and lattice;
//! - [`link`]: the share-link codec;
//! - [`schema`]: the JSON Schemas of scenarios and experiments, derived from the same types;
//! - [`presets`] and [`lessons`]: the built-in scenarios and classroom exercises;
//! - [`rules`]: a scenario's scripts in its model's rule slots (the engine with the `rules`
//!   feature);
//! - [`run`] and [`experiment`]: driving one run, and grids of runs ([`design`]: ranges, samples
//!   and stop conditions); [`playback`]: a run played,
//!   rewound and forked as the page does it, with its keyframes ([`timeline`]) and chart record
//!   ([`series`]); [`reproduce`]: the papers'
//!   claims beside the figures of those runs;
//! - [`rng`], [`math`], [`hash`]: the portable randomness, maths and state hash every model uses;
//! - [`json`]: JSON text in and out for the crates built on this one, one parser in the wasm module.

pub use kumiki_model::{bounds, error, hash, lattice, limits, math, rng, shape, sort};

pub mod compare;
#[cfg(test)]
pub mod counts;
pub mod design;
pub mod draft;
pub mod exercise;
pub mod experiment;
pub mod export;
pub mod grading;
pub mod guide;
pub mod handin;
#[cfg(feature = "sheets")]
pub mod handins;
pub mod json;
pub mod lessons;
#[cfg(test)]
mod limits_tests;
pub mod link;
pub mod models;
pub mod playback;
pub mod plot;
pub mod presets;
pub mod reproduce;
pub mod rules;
pub mod run;
pub mod scenario;
#[cfg(feature = "schema")]
pub mod schema;
pub mod series;
pub mod timeline;

pub use error::{Error, Result};
pub use experiment::{Experiment, Row};
pub use limits::Limits;
pub use run::{Outcome, Run};
pub use scenario::Scenario;
