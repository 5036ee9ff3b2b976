//! Goals derived from shapes (section 3.3).

use std::collections::VecDeque;

use super::goal::{Goal, Statement, MAX_PRIORITY, MAX_STATEMENTS};
use super::types::types;
use kumiki_model::lattice::{Hex, Lattice};
use kumiki_model::shape::Grid2;

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
