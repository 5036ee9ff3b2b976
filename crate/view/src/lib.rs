//! Kumiki's view: it draws the lattices and their fields next to the simulation, reading the
//! model's buffers in place.
//!
//! - [`geometry`], [`camera`] and [`palette`] are pure: where cells are, how the view looks at
//!   them and what colour they are. The page's editors ask them too (through the wasm module).
//! - [`view::View`] owns an OffscreenCanvas (and one for annotations), a camera and a renderer:
//!   WebGL2 ([`planar::gl`], [`cubic::gl`]) or the Canvas 2D fallback ([`planar::canvas`],
//!   [`cubic::canvas`]), with [`annotate`] drawing labels, arrows and marks over either.
//!
//! - [`contract`]: the records that cross to and from the page, whose TypeScript is generated.
//!
//! It reads the model contract (`kumiki-model`) alone; the core never depends on this crate.

pub mod annotate;
pub mod camera;
pub mod contract;
pub mod cubic;
pub mod geometry;
pub mod gl;
pub mod palette;
pub mod planar;
pub mod scene;
pub mod view;
