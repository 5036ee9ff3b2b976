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

fn build(rows: Vec<Vec<bool>>) -> Result<Grid2> {
    if rows.is_empty() {
        return Err(Error::field(
            "",
            "the shape is empty; draw it with '#' and '.'",
        ));
    }
    let w = rows.iter().map(Vec::len).max().unwrap_or(0);
    let h = rows.len();
    let mut cells = Vec::with_capacity(w * h);
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

/// Parses a square-lattice shape (`.##.` rows).
pub fn parse_square(text: &str) -> Result<Grid2> {
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
    build(rows)
}

/// Parses a hex-lattice shape (space-separated cells, odd rows indented).
pub fn parse_hex(text: &str) -> Result<Grid2> {
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
    build(rows)
}

/// Parses a cubic-lattice shape: square-lattice layers from the ground up, separated by `---`.
pub fn parse_cubic(text: &str) -> Result<Grid3> {
    let mut layers: Vec<Grid2> = Vec::new();
    for (n, block) in text.split("---").enumerate() {
        let layer = parse_square(block).map_err(|e| match e {
            Error::Field { reason, .. } => Error::field("", format!("layer {}: {reason}", n + 1)),
            other => other,
        })?;
        layers.push(layer);
    }
    let w = layers.iter().map(|l| l.w).max().unwrap_or(0);
    let h = layers.iter().map(|l| l.h).max().unwrap_or(0);
    let d = layers.len() as u32;
    let mut cells = vec![false; (w * h * d) as usize];
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
