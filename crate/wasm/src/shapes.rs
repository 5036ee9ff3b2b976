//! Text shapes for the page's editors, parsed and written by the core's rules.

use kumiki_core::shape;
use wasm_bindgen::prelude::*;

use crate::{js_err, to_js};

/// A text shape read by the core's rules, as `Cells`: `{w, h, d, cells}` with one 0/1 byte per
/// cell (row-major, layers from the ground up). `lattice` is `square`, `hex` or `cubic`.
#[wasm_bindgen]
pub fn shape_parse(lattice: &str, text: &str) -> Result<JsValue, JsError> {
    to_js(&shape::cells_of(lattice, text).map_err(js_err)?)
}

/// The text form of a shape (the inverse of [`shape_parse`]).
#[wasm_bindgen]
pub fn shape_format(
    lattice: &str,
    w: u32,
    h: u32,
    d: u32,
    cells: &[u8],
) -> Result<String, JsError> {
    let cells = shape::Cells {
        w,
        h,
        d,
        cells: cells.to_vec(),
    };
    shape::text_of(lattice, &cells).map_err(js_err)
}
