//! Goal descriptions (sections 3.2.1 and 3.3): statements such as `K{o, K, K, s}`, read from
//! text (each checked to be one that can occur on the lattice), written back, derived from a
//! shape (`derive.rs`), and the difference of a unit to the closest one (section 3.2.2).
//!
//! The text form, one or more statements per line:
//! ```text
//! # the 10-unit triangle
//! o{K, K}  K{o, K, K, s}  s{K, K, K, K, K, K}
//! 2: o{ε, c}  ε{o, K, c}
//! ```
//! A line may start with a priority `N:` (1 to 9, default 1) that applies to its statements.
//! `#` starts a comment. Type names are the display names (`ε`) or their ASCII spellings
//! (`eps`, `lambda`, `psi`; Latin letters in either case). The neighbour list may be written in
//! any order; it is kept sorted by bond count, as in the paper.

use super::types::{types, Types, CLASSES, NONE};

/// The largest number of statements a goal may hold.
pub const MAX_STATEMENTS: usize = 512;
/// The largest goal text accepted, in bytes.
pub const MAX_GOAL_TEXT: usize = 64 * 1024;
/// Priorities run from 1 (first) to this.
pub const MAX_PRIORITY: u8 = 9;

/// One statement: a unit of type `unit` whose neighbours have the types `neighbours`.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Statement {
    pub priority: u8,
    pub unit: u8,
    /// Sorted: by bond count, then class order.
    pub neighbours: Vec<u8>,
}

impl Statement {
    pub fn new(unit: u8, mut neighbours: Vec<u8>, priority: u8) -> Statement {
        neighbours.sort_unstable();
        Statement {
            priority,
            unit,
            neighbours,
        }
    }

    /// `K{o, K, K, s}`.
    pub fn text(&self) -> String {
        let t = types();
        let names: Vec<&str> = self.neighbours.iter().map(|&c| t.name(c)).collect();
        format!("{}{{{}}}", t.name(self.unit), names.join(", "))
    }
}

/// How statements of lower priority take part in the difference. See the documentation of
/// [`Goal::difference`].
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, serde::Deserialize, serde::Serialize, schemars::JsonSchema,
)]
#[serde(rename_all = "lowercase")]
pub enum Priorities {
    /// Every statement counts alike; priority only breaks ties between equally close ones.
    Pooled,
    /// A unit that matches a statement of any priority exactly has difference 0; otherwise its
    /// difference is measured against the first-priority statements only.
    Guided,
    /// A statement of priority p counts p − 1 farther than it is, unless matched exactly.
    Penalty,
}

/// A statement as [`Goal::difference`] reads it: its neighbour types right-aligned in six
/// places, the places before them `none`. Two lists padded at the front to one length pair
/// place by place as padded to six: the extra places pair `none` with `none`, distance 0.
#[derive(Clone, Copy, Debug)]
struct Packed {
    unit: u8,
    nb: [u8; 6],
    priority: u8,
}

/// Sorted neighbour types right-aligned in six places, `none` before them.
fn right_aligned(neighbours: &[u8]) -> [u8; 6] {
    let mut out = [NONE; 6];
    out[6 - neighbours.len()..].copy_from_slice(neighbours);
    out
}

/// A goal: its statements, sorted by priority, then type, then neighbours, without repeats.
#[derive(Clone, Debug)]
pub struct Goal {
    statements: Vec<Statement>,
    packed: Vec<Packed>,
    /// The first (smallest) priority present.
    top: u8,
}

/// The difference of a unit and the statement it was measured against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Closest {
    pub difference: u32,
    /// Index into [`Goal::statements`].
    pub statement: u16,
}

impl Goal {
    /// A goal from statements; repeats keep their first priority.
    pub fn new(mut statements: Vec<Statement>) -> Goal {
        kumiki_model::sort::sort(&mut statements);
        let mut kept: Vec<Statement> = Vec::with_capacity(statements.len());
        for s in statements {
            if !kept
                .iter()
                .any(|k| k.unit == s.unit && k.neighbours == s.neighbours)
            {
                kept.push(s);
            }
        }
        let packed = kept
            .iter()
            .map(|s| Packed {
                unit: s.unit,
                nb: right_aligned(&s.neighbours),
                priority: s.priority,
            })
            .collect();
        let top = kept.iter().map(|s| s.priority).min().unwrap_or(1);
        Goal {
            statements: kept,
            packed,
            top,
        }
    }

    pub fn statements(&self) -> &[Statement] {
        &self.statements
    }

    /// The goal as text, one priority per line, in the form [`Goal::parse`] reads.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let mut p = 1;
        while p <= MAX_PRIORITY {
            let line: Vec<String> = self
                .statements
                .iter()
                .filter(|s| s.priority == p)
                .map(Statement::text)
                .collect();
            if !line.is_empty() {
                if p > 1 {
                    out.push_str(&format!("{p}: "));
                }
                out.push_str(&line.join("  "));
                out.push('\n');
            }
            p += 1;
        }
        out
    }

    /// The goal without its `levels` last priority levels, keeping at least the first level
    /// present: the description the units repair towards once `levels` units are lost
    /// (section 3.3: the first priority is the original shape, each later one adds a spare).
    pub fn without_last_levels(&self, levels: usize) -> Goal {
        let mut present: Vec<u8> = self.statements.iter().map(|s| s.priority).collect();
        present.dedup();
        let keep = present.len().saturating_sub(levels).max(1);
        let last = present[keep - 1];
        Goal::new(
            self.statements
                .iter()
                .filter(|s| s.priority <= last)
                .cloned()
                .collect(),
        )
    }

    /// Reads a goal. Errors name the line and the problem.
    pub fn parse(text: &str) -> Result<Goal, String> {
        if text.len() > MAX_GOAL_TEXT {
            return Err(format!(
                "the goal text is {} bytes; the limit is {MAX_GOAL_TEXT}",
                text.len()
            ));
        }
        let t = types();
        let mut statements = Vec::new();
        for (i, raw) in text.lines().enumerate() {
            let line = i + 1;
            let content = raw.split('#').next().unwrap_or("");
            let parsed = parse_line(t, content).map_err(|e| format!("line {line}: {e}"))?;
            statements.extend(parsed);
            if statements.len() > MAX_STATEMENTS {
                return Err(format!(
                    "line {line}: more than {MAX_STATEMENTS} statements"
                ));
            }
        }
        if statements.is_empty() {
            return Err("the goal has no statements; write one like K{o, K, K, s}".into());
        }
        Ok(Goal::new(statements))
    }

    /// The difference of a unit of class `own` whose neighbours have the classes `neighbours`
    /// (sorted ascending) to the closest statement (section 3.2.2).
    ///
    /// The distance to one statement is the distance between the unit's type and the
    /// statement's, plus the distances between the neighbour types paired in sorted order (the
    /// paper sorts both lists by bond count); a shorter list is padded at its front with `none`,
    /// the class with no bonds, which sorts first.
    pub fn difference(
        &self,
        dist: &[[u8; CLASSES]; CLASSES],
        own: u8,
        neighbours: &[u8],
        mode: Priorities,
    ) -> Closest {
        let mut best = Closest {
            difference: u32::MAX,
            statement: 0,
        };
        let mut exact: Option<u16> = None;
        let cur = right_aligned(neighbours);
        for (k, s) in self.packed.iter().enumerate() {
            // What the statement's score adds to its distance. A statement whose distance
            // reaches the best score less that cannot score better, and one whose distance
            // reaches 1 is no exact match, so its sum stops at the larger of the two.
            let offset = match mode {
                Priorities::Pooled | Priorities::Guided => 0,
                Priorities::Penalty => u32::from(s.priority - self.top),
            };
            let bound = best.difference.saturating_sub(offset).max(1);
            let Some(d) = distance(dist, own, &cur, s, bound) else {
                continue;
            };
            if d == 0 {
                exact = Some(k as u16);
                break;
            }
            let scored = match mode {
                Priorities::Guided if s.priority != self.top => continue,
                _ => d + offset,
            };
            if scored < best.difference {
                best = Closest {
                    difference: scored,
                    statement: k as u16,
                };
            }
        }
        match exact {
            Some(k) => Closest {
                difference: 0,
                statement: k,
            },
            None => best,
        }
    }
}

/// The distance of a unit (type `own`, neighbour types `cur` right-aligned) to statement `s`,
/// or `None` once it reaches `bound`.
#[inline]
fn distance(
    dist: &[[u8; CLASSES]; CLASSES],
    own: u8,
    cur: &[u8; 6],
    s: &Packed,
    bound: u32,
) -> Option<u32> {
    let mut c = u32::from(dist[own as usize][s.unit as usize]);
    for i in 0..6 {
        if c >= bound {
            return None;
        }
        c += u32::from(dist[cur[i] as usize][s.nb[i] as usize]);
    }
    (c < bound).then_some(c)
}

fn parse_line(t: &Types, content: &str) -> Result<Vec<Statement>, String> {
    let mut rest = content.trim();
    let mut priority = 1u8;
    if rest.starts_with(|c: char| c.is_ascii_digit()) {
        let digits: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
        let after = rest[digits.len()..].trim_start();
        match after.strip_prefix(':') {
            Some(tail) => {
                priority = match digits.parse::<u8>() {
                    Ok(p) if (1..=MAX_PRIORITY).contains(&p) => p,
                    _ => {
                        return Err(format!(
                            "priority '{digits}' must be a whole number from 1 to {MAX_PRIORITY}"
                        ))
                    }
                };
                rest = tail.trim();
            }
            None => {
                return Err(format!(
                    "expected a priority like '2:' or a statement like K{{o, K, K, s}}, found '{}'",
                    clip(rest)
                ))
            }
        }
        if rest.is_empty() {
            return Err(format!("priority {priority} is followed by no statement"));
        }
    }
    let mut out = Vec::new();
    loop {
        rest = rest.trim_start_matches(|c: char| c.is_whitespace() || c == ';' || c == ',');
        if rest.is_empty() {
            break;
        }
        let Some(open) = rest.find('{') else {
            return Err(format!(
                "expected a statement like K{{o, K, K, s}}, found '{}'",
                clip(rest)
            ));
        };
        let head = rest[..open].trim();
        if head.is_empty() {
            return Err(format!(
                "a statement starts with its unit's type, as in K{{o, K, K, s}}; found '{}'",
                clip(rest)
            ));
        }
        if head.contains(|c: char| c.is_whitespace() || c == '}') {
            return Err(format!(
                "expected a statement like K{{o, K, K, s}}, found '{}'",
                clip(head)
            ));
        }
        let Some(close) = rest[open..].find('}').map(|c| c + open) else {
            return Err(format!("missing '}}' after '{}'", clip(rest)));
        };
        let inner = &rest[open + 1..close];
        if inner.contains('{') {
            return Err(format!("missing '}}' after '{}'", clip(&rest[..=open])));
        }
        let unit = class_of_word(t, head)?;
        let names: Vec<&str> = inner.split(',').map(str::trim).collect();
        if names.iter().all(|n| n.is_empty()) {
            return Err(format!(
                "{head}{{}} lists no neighbours; a {} unit has {} of them",
                t.name(unit),
                t.info[unit as usize].bonds
            ));
        }
        let mut neighbours = Vec::with_capacity(names.len());
        for n in names {
            if n.is_empty() {
                return Err(format!("an empty name in '{}'", clip(&rest[..=close])));
            }
            neighbours.push(class_of_word(t, n)?);
        }
        let bonds = t.info[unit as usize].bonds as usize;
        if neighbours.len() != bonds {
            return Err(format!(
                "a {} unit has {bonds} bonds, so {} needs {bonds} neighbour types, not {}",
                t.name(unit),
                clip(&rest[..=close]),
                neighbours.len()
            ));
        }
        let statement = Statement::new(unit, neighbours, priority);
        if !realisable(t, statement.unit, &statement.neighbours) {
            return Err(format!(
                "{} cannot occur: neighbours of a unit that are next to each other are bonded to \
                 each other too, and no arrangement of these types around a {} unit allows that",
                statement.text(),
                t.name(unit)
            ));
        }
        out.push(statement);
        rest = &rest[close + 1..];
    }
    Ok(out)
}

/// Whether some arrangement of `neighbours` around a unit of class `unit` is consistent on the
/// lattice: a neighbour in slot k is bonded to the unit and, since the cells of slots k − 1 and
/// k + 1 touch it, to whichever of those are occupied, and to none that are empty.
pub fn realisable(t: &Types, unit: u8, neighbours: &[u8]) -> bool {
    let own = t.info[unit as usize].canonical;
    let slots: Vec<usize> = (0..6).filter(|d| own & (1 << d) != 0).collect();
    if slots.len() != neighbours.len() {
        return false;
    }
    let occupied = |d: usize| own & (1 << (d % 6)) != 0;
    // What a neighbour of class c in slot k needs: bit k+3 (towards the unit) set, bits k+2 and
    // k+4 equal to the occupancy of the unit's slots k+1 and k-1.
    let fits = |c: u8, k: usize| -> bool {
        (0..64u8).filter(|&m| t.of(m) == c).any(|m| {
            let bit = |d: usize| m & (1 << (d % 6)) != 0;
            bit(k + 3) && bit(k + 2) == occupied(k + 1) && bit(k + 4) == occupied(k + 5)
        })
    };
    let mut used = vec![false; neighbours.len()];
    fn place(
        i: usize,
        slots: &[usize],
        neighbours: &[u8],
        used: &mut [bool],
        fits: &dyn Fn(u8, usize) -> bool,
    ) -> bool {
        if i == slots.len() {
            return true;
        }
        for j in 0..neighbours.len() {
            if used[j] || (j > 0 && neighbours[j] == neighbours[j - 1] && !used[j - 1]) {
                continue;
            }
            if fits(neighbours[j], slots[i]) {
                used[j] = true;
                if place(i + 1, slots, neighbours, used, fits) {
                    return true;
                }
                used[j] = false;
            }
        }
        false
    }
    let mut sorted = neighbours.to_vec();
    kumiki_model::sort::sort(&mut sorted);
    place(0, &slots, &sorted, &mut used, &fits)
}

fn class_of_word(t: &Types, word: &str) -> Result<u8, String> {
    if let Some(c) = t.parse(word) {
        return Ok(c);
    }
    let hint = if word == "0" {
        " (the letter o, not zero?)"
    } else {
        ""
    };
    Err(format!(
        "'{}' is not a connection type{hint}; known: {}",
        clip(word),
        t.known()
    ))
}

fn clip(s: &str) -> String {
    let s = s.trim();
    if s.chars().count() > 40 {
        format!("{}…", s.chars().take(40).collect::<String>())
    } else {
        s.to_string()
    }
}
