//! Kumiki's simulation core. Pure Rust: no browser, no clock, no thread-local randomness.
//!
//! - [`lattice`]: square, hex and cubic lattices behind one neighbourhood API;
//! - [`models`]: the models and their registry;
//! - [`scenario`]: the versioned JSON document that determines a run, and [`shape`] for the text
//!   shapes inside it;
//! - [`link`]: the share-link codec;
//! - [`run`] and [`experiment`]: driving one run, and grids of runs; [`reproduce`]: the papers'
//!   claims beside the figures of those runs;
//! - [`rng`], [`math`], [`hash`]: the portable randomness, maths and state hash every model uses.

pub mod error;
pub mod exercise;
pub mod experiment;
pub mod hash;
pub mod lattice;
pub mod link;
pub mod math;
pub mod models;
pub mod presets;
pub mod reproduce;
pub mod rng;
pub mod run;
pub mod scenario;
pub mod shape;
pub mod timeline;

pub use error::{Error, Result};
pub use experiment::{Experiment, Row};
pub use run::{Outcome, Run};
pub use scenario::Scenario;
