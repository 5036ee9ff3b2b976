//! The cubic lattice in 3-D: what a frame shows ([`model`]), drawn with WebGL2 ([`gl`]) or
//! Canvas 2D ([`canvas`]).

pub mod canvas;
pub mod gl;
mod mesh;
pub mod model;
mod shaders;

pub use canvas::CubicCanvas;
pub use gl::CubicGl;
pub use model::{lamp_placement, CubicModel, Lamp};
