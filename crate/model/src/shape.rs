//! Shapes as text a teacher can type.
//!
//! - Square and hex lattices: one line per row, top row first. `#` marks a cell of the shape, `.`
//!   an empty one. On the square lattice characters are adjacent (`.##.`). On the hex lattice the
//!   cells are separated by spaces and odd rows (the second, fourth, ...) sit half a cell to the
//!   right, so a teacher indents them by one space; indentation is otherwise ignored:
//!   ```text
//!   . # # .
//!    # # # .
//!   . # # .
//!   ```
//! - Cubic lattice: layers from the ground up, each a square-lattice block, separated by a line
//!   holding `---`.
//!
//! Blank lines before the first row and after the last are ignored; rows shorter than the widest
//! are padded with empty cells.

use crate::error::{Error, Result};
use crate::limits::Limits;

/// The cell count of a `dims` box, checked against `max` (the most cells a shape's text may
/// describe, [`Limits::shape_cells`]) without overflowing. Rows are padded to the widest, so a
/// short text can describe a huge rectangle: the size is computed from the text in 64 bits and
/// checked before anything is allocated. Each model then applies its own, smaller limits to the
/// shapes it accepts.
fn checked_cells(dims: &[u64], max: u64) -> Result<usize> {
    let total = dims
        .iter()
        .try_fold(1u64, |acc, &d| acc.checked_mul(d))
        .filter(|&n| n <= max);
    match total {
        Some(n) => Ok(n as usize),
        None => Err(Error::field(
            "",
            format!(
                "the shape spans {} cells, more than the {max} a shape may have",
                dims.iter()
                    .map(u64::to_string)
                    .collect::<Vec<_>>()
                    .join(" × ")
            ),
        )),
    }
}

/// A planar shape: `cells[y * w + x]` is true where the shape has a cell.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Grid2 {
    pub w: u32,
    pub h: u32,
    pub cells: Vec<bool>,
}

/// A 3-D shape: `cells[(z * h + y) * w + x]`, z = 0 is the ground layer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Grid3 {
    pub w: u32,
    pub h: u32,
    pub d: u32,
    pub cells: Vec<bool>,
}

impl Grid2 {
    pub fn get(&self, x: u32, y: u32) -> bool {
        x < self.w && y < self.h && self.cells[(y * self.w + x) as usize]
    }
    pub fn count(&self) -> usize {
        self.cells.iter().filter(|&&c| c).count()
    }
}

impl Grid3 {
    pub fn get(&self, x: u32, y: u32, z: u32) -> bool {
        x < self.w
            && y < self.h
            && z < self.d
            && self.cells[((z * self.h + y) * self.w + x) as usize]
    }
    pub fn count(&self) -> usize {
        self.cells.iter().filter(|&&c| c).count()
    }
}

fn trimmed_lines(text: &str) -> Vec<&str> {
    let lines: Vec<&str> = text.lines().map(|l| l.trim_end()).collect();
    let first = lines.iter().position(|l| !l.is_empty());
    let last = lines.iter().rposition(|l| !l.is_empty());
    match (first, last) {
        (Some(a), Some(b)) => lines[a..=b].to_vec(),
        _ => Vec::new(),
    }
}

fn cell(ch: char, row: usize, col: usize) -> Result<bool> {
    match ch {
        '#' => Ok(true),
        '.' => Ok(false),
        other => Err(Error::field(
            "",
            format!(
                "row {}, column {}: '{other}' is not a cell; use '#' for a cell and '.' for none",
                row + 1,
                col + 1
            ),
        )),
    }
}

fn build(rows: Vec<Vec<bool>>, max: u64) -> Result<Grid2> {
    if rows.is_empty() {
        return Err(Error::field(
            "",
            "the shape is empty; draw it with '#' and '.'",
        ));
    }
    let w = rows.iter().map(Vec::len).max().unwrap_or(0);
    let h = rows.len();
    let mut cells = Vec::with_capacity(checked_cells(&[w as u64, h as u64], max)?);
    for row in rows {
        let n = row.len();
        cells.extend(row);
        cells.extend(std::iter::repeat_n(false, w - n));
    }
    Ok(Grid2 {
        w: w as u32,
        h: h as u32,
        cells,
    })
}

/// Parses a square-lattice shape (`.##.` rows) of at most the page's [`Limits::shape_cells`].
pub fn parse_square(text: &str) -> Result<Grid2> {
    parse_square_within(text, &Limits::PAGE)
}

/// [`parse_square`] within `limits`.
pub fn parse_square_within(text: &str, limits: &Limits) -> Result<Grid2> {
    let rows = trimmed_lines(text)
        .iter()
        .enumerate()
        .map(|(r, line)| {
            line.chars()
                .enumerate()
                .map(|(c, ch)| cell(ch, r, c))
                .collect()
        })
        .collect::<Result<Vec<Vec<bool>>>>()?;
    build(rows, limits.shape_cells)
}

/// Parses a hex-lattice shape (space-separated cells, odd rows indented) of at most the page's
/// [`Limits::shape_cells`].
pub fn parse_hex(text: &str) -> Result<Grid2> {
    parse_hex_within(text, &Limits::PAGE)
}

/// [`parse_hex`] within `limits`.
pub fn parse_hex_within(text: &str, limits: &Limits) -> Result<Grid2> {
    let rows = trimmed_lines(text)
        .iter()
        .enumerate()
        .map(|(r, line)| {
            line.split_whitespace()
                .enumerate()
                .map(|(c, tok)| {
                    let mut chars = tok.chars();
                    match (chars.next(), chars.next()) {
                        (Some(ch), None) => cell(ch, r, c),
                        _ => Err(Error::field(
                            "",
                            format!("row {}, cell {}: '{tok}' is not a cell; separate hex cells with spaces", r + 1, c + 1),
                        )),
                    }
                })
                .collect()
        })
        .collect::<Result<Vec<Vec<bool>>>>()?;
    build(rows, limits.shape_cells)
}

/// Parses a cubic-lattice shape: square-lattice layers from the ground up, separated by `---`,
/// of at most the page's [`Limits::shape_cells`].
pub fn parse_cubic(text: &str) -> Result<Grid3> {
    parse_cubic_within(text, &Limits::PAGE)
}

/// [`parse_cubic`] within `limits`.
pub fn parse_cubic_within(text: &str, limits: &Limits) -> Result<Grid3> {
    let mut layers: Vec<Grid2> = Vec::new();
    for (n, block) in text.split("---").enumerate() {
        let layer = parse_square_within(block, limits).map_err(|e| match e {
            Error::Field { reason, .. } => Error::field("", format!("layer {}: {reason}", n + 1)),
            other => other,
        })?;
        layers.push(layer);
    }
    let w = layers.iter().map(|l| l.w).max().unwrap_or(0);
    let h = layers.iter().map(|l| l.h).max().unwrap_or(0);
    let size = checked_cells(
        &[w as u64, h as u64, layers.len() as u64],
        limits.shape_cells,
    )?;
    let d = layers.len() as u32;
    let mut cells = vec![false; size];
    for (z, layer) in layers.iter().enumerate() {
        for y in 0..layer.h {
            for x in 0..layer.w {
                if layer.get(x, y) {
                    cells[((z as u32 * h + y) * w + x) as usize] = true;
                }
            }
        }
    }
    Ok(Grid3 { w, h, d, cells })
}

/// The cells of the box a shape text describes, counted from the text alone: no parsing, no
/// allocation, saturating instead of overflowing. A row's cells are its `#` and `.` characters,
/// so this holds for square, hex and cubic texts alike (the widest row times the rows, times the
/// `---` layers). The page uses it to tell a large scenario before anything is built.
pub fn text_cells(text: &str) -> u64 {
    let (mut w, mut h, mut layers) = (0u64, 0u64, 0u64);
    for block in text.split("---") {
        layers += 1;
        let rows = block
            .lines()
            .map(|line| line.bytes().filter(|&b| b == b'#' || b == b'.').count() as u64);
        let (mut widest, mut count) = (0u64, 0u64);
        for cells in rows.filter(|&n| n > 0) {
            widest = widest.max(cells);
            count += 1;
        }
        w = w.max(widest);
        h = h.max(count);
    }
    w.saturating_mul(h).saturating_mul(layers)
}

/// The cells of the largest shape a scenario document describes, from its text alone: every
/// string is read as a shape text ([`text_cells`]) and every `{"rect": [w, h]}` as a `w × h`
/// box. An estimate of the lattice a model would build (margins and supply rows are not
/// counted), used to open large scenarios away from the page's main thread.
pub fn estimate_cells(doc: &serde_json::Value) -> u64 {
    use serde_json::Value;
    match doc {
        Value::String(text) => text_cells(text),
        Value::Array(items) => items.iter().map(estimate_cells).max().unwrap_or(0),
        Value::Object(map) => {
            let rect = map.get("rect").and_then(Value::as_array).map(|sides| {
                sides
                    .iter()
                    .map(|v| v.as_u64().unwrap_or(0))
                    .fold(1u64, u64::saturating_mul)
            });
            map.values()
                .map(estimate_cells)
                .chain(rect)
                .max()
                .unwrap_or(0)
        }
        _ => 0,
    }
}

/// A shape as the page's editors hold it: `w × h × d` cells, one byte each (1 filled, 0 empty),
/// row-major and layers from the ground up (`d` is 1 on a planar lattice).
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, schemars::JsonSchema)]
pub struct Cells {
    pub w: u32,
    pub h: u32,
    pub d: u32,
    pub cells: Vec<u8>,
}

/// Reads a text shape of a lattice (`square`, `hex` or `cubic`) into its [`Cells`], with the row
/// and column of a bad character.
pub fn cells_of(lattice: &str, text: &str) -> Result<Cells> {
    let bytes = |cells: Vec<bool>| cells.into_iter().map(u8::from).collect();
    let planar = |g: Grid2| Cells {
        w: g.w,
        h: g.h,
        d: 1,
        cells: bytes(g.cells),
    };
    match lattice {
        "square" => parse_square(text).map(planar),
        "hex" => parse_hex(text).map(planar),
        "cubic" => parse_cubic(text).map(|g| Cells {
            w: g.w,
            h: g.h,
            d: g.d,
            cells: bytes(g.cells),
        }),
        other => Err(unknown_lattice(other)),
    }
}

/// The text of [`Cells`] on a lattice: the inverse of [`cells_of`].
pub fn text_of(lattice: &str, shape: &Cells) -> Result<String> {
    let Cells { w, h, d, cells } = shape;
    let (w, h, d) = (*w, *h, *d);
    let n = (w as usize) * (h as usize) * (d.max(1) as usize);
    if cells.len() != n {
        return Err(Error::field(
            "cells",
            format!("{} cells given for a {w}×{h}×{d} shape", cells.len()),
        ));
    }
    let cells: Vec<bool> = cells.iter().map(|&c| c != 0).collect();
    match lattice {
        "square" => Ok(square_text(&Grid2 { w, h, cells })),
        "hex" => Ok(hex_text(&Grid2 { w, h, cells })),
        "cubic" => Ok(cubic_text(&Grid3 { w, h, d, cells })),
        other => Err(unknown_lattice(other)),
    }
}

fn unknown_lattice(name: &str) -> Error {
    Error::field(
        "lattice",
        format!("unknown lattice '{name}'; known: square, hex, cubic"),
    )
}

/// The text form of a square-lattice shape, the inverse of [`parse_square`].
pub fn square_text(g: &Grid2) -> String {
    let mut out = String::with_capacity(((g.w + 1) * g.h) as usize);
    for y in 0..g.h {
        for x in 0..g.w {
            out.push(if g.get(x, y) { '#' } else { '.' });
        }
        out.push('\n');
    }
    out
}

/// The text form of a hex-lattice shape, the inverse of [`parse_hex`].
pub fn hex_text(g: &Grid2) -> String {
    let mut out = String::new();
    for y in 0..g.h {
        if y % 2 == 1 {
            out.push(' ');
        }
        let row: Vec<&str> = (0..g.w)
            .map(|x| if g.get(x, y) { "#" } else { "." })
            .collect();
        out.push_str(&row.join(" "));
        out.push('\n');
    }
    out
}

/// The text form of a cubic-lattice shape, the inverse of [`parse_cubic`].
pub fn cubic_text(g: &Grid3) -> String {
    let layers: Vec<String> = (0..g.d)
        .map(|z| {
            let layer = Grid2 {
                w: g.w,
                h: g.h,
                cells: (0..g.h)
                    .flat_map(|y| (0..g.w).map(move |x| (x, y)))
                    .map(|(x, y)| g.get(x, y, z))
                    .collect(),
            };
            square_text(&layer)
        })
        .collect();
    layers.join("---\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_cells_counts_the_box_without_parsing() {
        assert_eq!(text_cells(".##.\n####\n#...\n"), 12);
        assert_eq!(
            text_cells("#\n####\n\n"),
            8,
            "short rows are padded to the widest"
        );
        assert_eq!(
            text_cells(". # # .\n # # # .\n"),
            8,
            "hex cells are counted, not spaces"
        );
        assert_eq!(text_cells("##\n##\n---\n#\n"), 8, "two layers of 2×2");
        let wide = "#".repeat(1 << 19);
        let tall = format!("{wide}\n{}", "#\n".repeat(1 << 19));
        assert_eq!(text_cells(&tall), (1u64 << 19) * ((1 << 19) + 1));
    }

    #[test]
    fn estimate_cells_takes_the_largest_shape_or_rect() {
        let doc = serde_json::json!({
            "name": "a",
            "target": {"rect": [2048, 2040]},
            "initial": "###\n###\n",
            "stages": [{"rect": [4, 4]}],
        });
        assert_eq!(estimate_cells(&doc), 2048 * 2040);
        let huge = serde_json::json!({"target": {"rect": [u64::MAX, 3]}});
        assert_eq!(estimate_cells(&huge), u64::MAX);
        assert_eq!(estimate_cells(&serde_json::json!({"robots": 5})), 0);
    }

    #[test]
    fn square_round_trip() {
        let text = ".##.\n####\n#...\n";
        let g = parse_square(text).unwrap();
        assert_eq!((g.w, g.h, g.count()), (4, 3, 7));
        assert_eq!(square_text(&g), text);
    }

    #[test]
    fn short_rows_are_padded_and_blank_edges_dropped() {
        let g = parse_square("\n\n##\n#\n\n").unwrap();
        assert_eq!((g.w, g.h), (2, 2));
        assert!(g.get(0, 1) && !g.get(1, 1));
    }

    #[test]
    fn bad_character_names_row_and_column() {
        let err = parse_square("##\n#x\n").unwrap_err().to_string();
        assert!(err.contains("row 2, column 2"), "{err}");
        assert!(err.contains("'x'"), "{err}");
    }

    #[test]
    fn empty_shape_is_an_error() {
        assert!(parse_square("  \n\n").is_err());
    }

    #[test]
    fn hex_round_trip() {
        let text = ". # # .\n # # # .\n. # # .\n";
        let g = parse_hex(text).unwrap();
        assert_eq!((g.w, g.h, g.count()), (4, 3, 7));
        assert_eq!(hex_text(&g), text);
        assert!(parse_hex("## .").is_err());
    }

    #[test]
    fn huge_shapes_are_refused_before_they_are_allocated() {
        // One long row and many short ones: 4 MB of text that would pad to 10^12 cells.
        let text = format!("{}\n{}", "#".repeat(1 << 20), "#\n".repeat(1 << 20));
        let err = parse_square(&text).unwrap_err().to_string();
        assert!(
            err.contains("1048576 × 1048577") && err.contains("16777216"),
            "{err}"
        );
        let hex = format!("{}\n{}", "# ".repeat(5000), "#\n".repeat(5000));
        assert!(parse_hex(&hex).is_err());
        // Layers that each fit but together do not.
        let layer = format!("{}\n{}", "#".repeat(4096), "#\n".repeat(4095));
        let cubic = [layer.as_str(), "#\n"].join("---\n");
        let err = parse_cubic(&cubic).unwrap_err().to_string();
        assert!(err.contains("4096 × 4096 × 2"), "{err}");
        assert!(parse_square(&"#".repeat(4096)).is_ok());
    }

    #[test]
    fn cubic_round_trip() {
        let text = "##\n##\n---\n#.\n..\n";
        let g = parse_cubic(text).unwrap();
        assert_eq!((g.w, g.h, g.d, g.count()), (2, 2, 2, 5));
        assert!(g.get(0, 0, 1) && !g.get(1, 0, 1));
        assert_eq!(cubic_text(&g), text);
        let err = parse_cubic("##\n---\n#?\n").unwrap_err().to_string();
        assert!(err.contains("layer 2"), "{err}");
    }
}
