//! The square and hex lattices, drawn with WebGL2 ([`gl`]) or Canvas 2D ([`canvas`]).

pub mod canvas;
pub mod gl;
