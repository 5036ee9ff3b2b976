//! Type-lists (section 4.1): `C31[C41, C31, C31]` is a unit of type C31 whose neighbours have the
//! types C41, C31 and C31, sorted by decreasing valence. A target is a set of type-lists; the
//! difference of equations 4 to 6 measures how far a unit is from the closest one.

use std::collections::BTreeSet;
use std::fmt;

use super::types::{self, CODES, NAMES, TYPE_OF_MASK, VALENCE};
use kumiki_model::error::{Error, Result};
use kumiki_model::lattice::Cubic;
use kumiki_model::shape::Grid3;

/// The most type-lists one description may hold.
pub const MAX_LISTS: usize = 4096;

/// One type-list. `neighbours` are sorted by decreasing code, so by decreasing valence and, within
/// a valence, type 1 before type 0; their number is the valence of `unit`.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct TypeList {
    pub unit: u8,
    pub neighbours: Vec<u8>,
}

impl TypeList {
    /// A type-list from a unit type and its neighbours' types in any order.
    pub fn new(unit: u8, mut neighbours: Vec<u8>) -> TypeList {
        neighbours.sort_unstable_by(|a, b| b.cmp(a));
        TypeList { unit, neighbours }
    }

    /// The unit type followed by the six neighbour slots, blanks (valence 0) at the end.
    pub fn padded(&self) -> [u8; 7] {
        let mut out = [types::C0; 7];
        out[0] = self.unit;
        for (slot, &n) in out[1..].iter_mut().zip(&self.neighbours) {
            *slot = n;
        }
        out
    }
}

impl fmt::Display for TypeList {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<&str> = self.neighbours.iter().map(|&n| NAMES[n as usize]).collect();
        write!(f, "{}[{}]", NAMES[self.unit as usize], names.join(", "))
    }
}

/// One type-list per line, in the canonical order of [`TypeList`]'s `Ord`.
pub fn to_text(lists: &[TypeList]) -> String {
    let mut out = String::new();
    for l in lists {
        out.push_str(&l.to_string());
        out.push('\n');
    }
    out
}

/// Equation 5 with the Kronecker delta of equation 6, for every pair of codes, the blank
/// (valence 0) included: `table[A][B]`.
pub fn diff_table(a: f64) -> [[f64; CODES]; CODES] {
    let mut t = [[0.0; CODES]; CODES];
    for (x, row) in t.iter_mut().enumerate() {
        for (y, cell) in row.iter_mut().enumerate() {
            let (vx, vy) = (VALENCE[x], VALENCE[y]);
            *cell = if vx == vy {
                if x == y {
                    0.0
                } else {
                    1.0
                }
            } else {
                a * f64::from(vx.abs_diff(vy))
            };
        }
    }
    t
}

struct Cursor {
    line: usize,
    chars: Vec<char>,
    pos: usize,
}

impl Cursor {
    fn err(&self, col: usize, reason: impl fmt::Display) -> Error {
        Error::field(
            "",
            format!("line {}, column {}: {reason}", self.line, col + 1),
        )
    }
    fn peek(&self) -> Option<char> {
        self.chars.get(self.pos).copied()
    }
    fn skip_space(&mut self) {
        while self.peek().is_some_and(char::is_whitespace) {
            self.pos += 1;
        }
    }
    /// A type name: letters and digits.
    fn word(&mut self) -> (usize, String) {
        let start = self.pos;
        while self.peek().is_some_and(|c| c.is_ascii_alphanumeric()) {
            self.pos += 1;
        }
        (start, self.chars[start..self.pos].iter().collect())
    }
    fn type_code(&mut self) -> Result<u8> {
        let (col, name) = self.word();
        if name.is_empty() {
            return Err(match self.peek() {
                None => self.err(col, "a connection type is missing at the end of the line"),
                Some(c) => self.err(
                    col,
                    format!("expected a connection type like C31, found '{c}'"),
                ),
            });
        }
        types::code(&name).ok_or_else(|| {
            self.err(
                col,
                format!(
                    "unknown connection type '{name}'; known: {}",
                    types::known_names()
                ),
            )
        })
    }
}

fn closer(open: char) -> char {
    if open == '[' {
        ']'
    } else {
        '}'
    }
}

/// Parses one type-list starting at the cursor (after leading space).
fn parse_one(cur: &mut Cursor) -> Result<TypeList> {
    let unit = cur.type_code()?;
    let unit_name = NAMES[unit as usize];
    cur.skip_space();
    let open_col = cur.pos;
    let open = match cur.peek() {
        Some(c @ ('[' | '{')) => c,
        None => {
            return Err(cur.err(
                open_col,
                format!("{unit_name} needs its neighbours in brackets, like C31[C41, C31, C31]"),
            ))
        }
        Some(c) => {
            return Err(cur.err(
                open_col,
                format!("expected '[' after {unit_name}, found '{c}'"),
            ))
        }
    };
    cur.pos += 1;
    let mismatch = |cur: &Cursor, c: char| {
        cur.err(
            cur.pos,
            format!(
                "'{c}' does not match the '{open}' at column {}",
                open_col + 1
            ),
        )
    };
    let mut neighbours = Vec::new();
    loop {
        cur.skip_space();
        match cur.peek() {
            None => return Err(cur.err(open_col, format!("'{open}' is never closed on this line"))),
            Some(c @ (']' | '}')) => {
                if c != closer(open) {
                    return Err(mismatch(cur, c));
                }
                if !neighbours.is_empty() {
                    return Err(cur.err(cur.pos, "a neighbour type is missing after ','"));
                }
                cur.pos += 1;
                break;
            }
            Some(c @ ('[' | '{')) => {
                return Err(cur.err(
                    cur.pos,
                    format!(
                        "'{c}' inside the list opened at column {}: type-lists do not nest",
                        open_col + 1
                    ),
                ))
            }
            _ => {}
        }
        neighbours.push(cur.type_code()?);
        cur.skip_space();
        match cur.peek() {
            Some(',') => {
                cur.pos += 1;
            }
            Some(c @ (']' | '}')) => {
                if c != closer(open) {
                    return Err(mismatch(cur, c));
                }
                cur.pos += 1;
                break;
            }
            None => return Err(cur.err(open_col, format!("'{open}' is never closed on this line"))),
            Some(c) => {
                return Err(cur.err(
                    cur.pos,
                    format!(
                        "expected ',' or '{}' between neighbours, found '{c}'",
                        closer(open)
                    ),
                ))
            }
        }
    }
    let valence = usize::from(VALENCE[unit as usize]);
    if neighbours.len() != valence {
        return Err(cur.err(
            open_col,
            format!(
                "{unit_name} has valence {valence}, so it needs {valence} neighbour{}, but the list names {}",
                if valence == 1 { "" } else { "s" },
                neighbours.len()
            ),
        ));
    }
    Ok(TypeList::new(unit, neighbours))
}

/// Parses a target description: type-lists like `C31[C41, C31, C31]`, one or more per line,
/// separated by spaces, commas or semicolons (`{...}` is accepted for `[...]`, as in equation 6
/// of the 12-unit paper). Neighbours may be written in any order. Returns the distinct lists in
/// canonical order. Errors name the line, the column and the problem.
pub fn parse(text: &str) -> Result<Vec<TypeList>> {
    let mut set = BTreeSet::new();
    for (n, line) in text.lines().enumerate() {
        let mut cur = Cursor {
            line: n + 1,
            chars: line.chars().collect(),
            pos: 0,
        };
        loop {
            while cur
                .peek()
                .is_some_and(|c| c.is_whitespace() || c == ',' || c == ';')
            {
                cur.pos += 1;
            }
            match cur.peek() {
                None => break,
                Some(c @ (']' | '}')) => {
                    return Err(cur.err(cur.pos, format!("'{c}' has no matching opening bracket")))
                }
                Some(c @ ('[' | '{')) => {
                    return Err(cur.err(
                        cur.pos,
                        format!("'{c}' needs a connection type before it, like C31[...]"),
                    ))
                }
                _ => {}
            }
            set.insert(parse_one(&mut cur)?);
            if set.len() > MAX_LISTS {
                return Err(Error::field(
                    "",
                    format!("more than {MAX_LISTS} different type-lists"),
                ));
            }
        }
    }
    if set.is_empty() {
        return Err(Error::field(
            "",
            "no type-lists; write at least one, like C31[C31, C31, C31]",
        ));
    }
    Ok(set.into_iter().collect())
}

/// The six face neighbours of `c`, in the lattice's direction order.
fn around((x, y, z): (i32, i32, i32)) -> [(i32, i32, i32); 6] {
    Cubic::DIRS.map(|(dx, dy, dz)| (x + dx, y + dy, z + dz))
}

/// The face set of the unit at `c` among `cells`.
fn mask_in(cells: &BTreeSet<(i32, i32, i32)>, c: (i32, i32, i32)) -> u8 {
    let around = around(c);
    let mut m = 0;
    for (d, n) in around.iter().enumerate() {
        if cells.contains(n) {
            m |= 1 << d;
        }
    }
    m
}

/// The unique description of a shape (section 4.1): the distinct type-lists of its units, in
/// canonical order. Every unit needs a neighbour (a lone unit has no connection type).
pub fn describe(units: &[(i32, i32, i32)]) -> Result<Vec<TypeList>> {
    let cells: BTreeSet<(i32, i32, i32)> = units.iter().copied().collect();
    if cells.is_empty() {
        return Err(Error::field("", "the shape has no units"));
    }
    let mut set = BTreeSet::new();
    for &c in &cells {
        let m = mask_in(&cells, c);
        let unit = TYPE_OF_MASK[m as usize];
        if unit == types::C0 {
            return Err(Error::field(
                "",
                format!(
                    "the unit at x={}, y={}, z={} touches no other unit, so it has no connection type",
                    c.0, c.1, c.2
                ),
            ));
        }
        let around = around(c);
        let neighbours = around
            .iter()
            .filter(|n| cells.contains(n))
            .map(|&n| TYPE_OF_MASK[mask_in(&cells, n) as usize])
            .collect();
        set.insert(TypeList::new(unit, neighbours));
    }
    Ok(set.into_iter().collect())
}

/// The units of a grid shape as (x, y, z).
pub fn grid_units(g: &Grid3) -> Vec<(i32, i32, i32)> {
    let mut out = Vec::new();
    for z in 0..g.d {
        for y in 0..g.h {
            for x in 0..g.w {
                if g.get(x, y, z) {
                    out.push((x as i32, y as i32, z as i32));
                }
            }
        }
    }
    out
}

/// [`describe`] for a shape given as cubic-lattice text layers.
pub fn describe_grid(g: &Grid3) -> Result<Vec<TypeList>> {
    describe(&grid_units(g))
}
