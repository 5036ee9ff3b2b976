//! Text shapes for the page's editors, parsed and written by the core's rules.

use kumiki_core::shape;
use serde::Serialize;
use wasm_bindgen::prelude::*;

use crate::{js_err, to_js};

/// A text shape parsed by the core's rules: `{w, h, d, cells}` with one 0/1 byte per cell
/// (row-major, layers from the ground up). `lattice` is `square`, `hex` or `cubic`.
#[wasm_bindgen]
pub fn shape_parse(lattice: &str, text: &str) -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    struct Parsed {
        w: u32,
        h: u32,
        d: u32,
        cells: Vec<u8>,
    }
    let bytes = |cells: Vec<bool>| cells.into_iter().map(u8::from).collect();
    let parsed = match lattice {
        "square" | "hex" => {
            let g = if lattice == "square" {
                shape::parse_square(text)
            } else {
                shape::parse_hex(text)
            }
            .map_err(js_err)?;
            Parsed {
                w: g.w,
                h: g.h,
                d: 1,
                cells: bytes(g.cells),
            }
        }
        "cubic" => {
            let g = shape::parse_cubic(text).map_err(js_err)?;
            Parsed {
                w: g.w,
                h: g.h,
                d: g.d,
                cells: bytes(g.cells),
            }
        }
        other => return Err(JsError::new(&format!("unknown lattice '{other}'"))),
    };
    to_js(&parsed)
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
    let n = (w as usize) * (h as usize) * (d.max(1) as usize);
    if cells.len() != n {
        return Err(JsError::new(&format!(
            "{} cells given for a {w}×{h}×{d} shape",
            cells.len()
        )));
    }
    let filled: Vec<bool> = cells.iter().map(|&c| c != 0).collect();
    Ok(match lattice {
        "square" => shape::square_text(&shape::Grid2 {
            w,
            h,
            cells: filled,
        }),
        "hex" => shape::hex_text(&shape::Grid2 {
            w,
            h,
            cells: filled,
        }),
        "cubic" => shape::cubic_text(&shape::Grid3 {
            w,
            h,
            d,
            cells: filled,
        }),
        other => return Err(JsError::new(&format!("unknown lattice '{other}'"))),
    })
}
