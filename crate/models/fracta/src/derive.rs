//! Goals derived from shapes (section 3.3), and whether a statement can be realised on the
//! lattice at all.

use std::collections::VecDeque;

use super::goal::{Goal, Statement, MAX_PRIORITY, MAX_STATEMENTS};
use super::types::{types, Types};
use kumiki_model::lattice::{Hex, Lattice};
use kumiki_model::shape::Grid2;

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
    sorted.sort_unstable();
    place(0, &slots, &sorted, &mut used, &fits)
}

/// The statements of a shape: one per distinct (type, neighbour types) found in it.
///
/// Several shapes give a goal with priorities: the first shape's statements get priority 1, the
/// second's those not already present priority 2, and so on (section 3.3).
pub fn derive(shapes: &[Grid2]) -> Result<Goal, String> {
    if shapes.is_empty() {
        return Err("no shape to derive statements from".into());
    }
    if shapes.len() > MAX_PRIORITY as usize {
        return Err(format!(
            "{} shapes given; at most {MAX_PRIORITY} priorities",
            shapes.len()
        ));
    }
    let t = types();
    let mut all: Vec<Statement> = Vec::new();
    for (n, shape) in shapes.iter().enumerate() {
        let at = if shapes.len() > 1 {
            format!("shape {}: ", n + 1)
        } else {
            String::new()
        };
        let (lattice, occ) = shape_cells(shape);
        let cells: Vec<usize> = (0..occ.len()).filter(|&i| occ[i]).collect();
        if cells.is_empty() {
            return Err(format!("{at}the shape has no '#' cells"));
        }
        if !connected(&lattice, &occ, &cells) {
            return Err(format!(
                "{at}the shape falls apart into pieces; fracta units are always connected"
            ));
        }
        let mask = |i: usize| -> u8 {
            (0..6)
                .filter(|&d| lattice.neighbour(i, d).is_some_and(|j| occ[j]))
                .fold(0, |m, d| m | 1 << d)
        };
        for &i in &cells {
            let neighbours: Vec<u8> = (0..6)
                .filter_map(|d| lattice.neighbour(i, d).filter(|&j| occ[j]))
                .map(|j| t.of(mask(j)))
                .collect();
            let s = Statement::new(t.of(mask(i)), neighbours, n as u8 + 1);
            if !all
                .iter()
                .any(|k| k.unit == s.unit && k.neighbours == s.neighbours)
            {
                all.push(s);
            }
        }
        if all.len() > MAX_STATEMENTS {
            return Err(format!(
                "{at}more than {MAX_STATEMENTS} distinct statements"
            ));
        }
    }
    Ok(Goal::new(all))
}

/// A shape on its own lattice: its cells keep their rows, so the odd-row offsets stay as drawn.
fn shape_cells(shape: &Grid2) -> (Hex, Vec<bool>) {
    (Hex::new(shape.w, shape.h), shape.cells.clone())
}

fn connected(lattice: &Hex, occ: &[bool], cells: &[usize]) -> bool {
    let mut seen = vec![false; occ.len()];
    let mut queue = VecDeque::from([cells[0]]);
    seen[cells[0]] = true;
    let mut count = 1;
    while let Some(i) = queue.pop_front() {
        for j in lattice.neighbours(i) {
            if occ[j] && !seen[j] {
                seen[j] = true;
                count += 1;
                queue.push_back(j);
            }
        }
    }
    count == cells.len()
}
