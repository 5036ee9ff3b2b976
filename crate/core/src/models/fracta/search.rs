//! The fewest motions a repair needs: a breadth-first search over the model's own motions,
//! for the reproduction report to put beside the repair times.

use std::collections::BTreeSet;

use super::*;
use crate::scenario::Scenario;

impl Fracta {
    /// The model of a scenario, built the way a run builds it.
    pub(super) fn of_scenario(s: &Scenario) -> Result<Fracta> {
        let models::ModelSpec::Fracta(spec) = &s.spec else {
            return Err(Error::field("model", "not a fracta scenario"));
        };
        Ok(Fracta::from_checked(
            models::Spec::validate(spec, s.limits)?,
            s.seed,
        ))
    }

    /// The occupied cells of the working units, sorted: a configuration up to which unit is
    /// where.
    fn configuration(&self) -> Vec<u32> {
        let mut cells: Vec<u32> = self
            .working
            .iter()
            .map(|&u| self.units[u as usize].cell)
            .collect();
        cells.sort_unstable();
        cells
    }
}

/// The fewest motions (one unit's motion at a time, every rule of the model applied) that take
/// the 10 units left after a fault on `unit` of the `fracta-repair` preset to the triangle,
/// searched breadth first up to `limit` motions; `None` if more are needed or the preset is
/// missing.
pub fn fewest_repair_motions(unit: u64, limit: usize) -> Option<usize> {
    let mut s = crate::presets::scenario("fracta-repair").ok()?;
    let fault = s.disturbances.first_mut()?;
    fault.action.insert("unit".into(), json!(unit));
    let action = fault.action.clone();
    let mut m = Fracta::of_scenario(&s).ok()?;
    m.apply(&action).ok()?;
    m.cut_off_faulty();
    let mut seen = BTreeSet::from([m.configuration()]);
    let mut layer = vec![m];
    for depth in 0..=limit {
        if layer.iter().any(Fracta::completed) {
            return Some(depth);
        }
        let mut next = Vec::new();
        for m in &layer {
            for &u in &m.working {
                let cell = m.units[u as usize].cell;
                for pivot in 0..6 {
                    for turn in Turn::BOTH {
                        let Some(to) = m.legal(cell, m.mask[u as usize], pivot, turn) else {
                            continue;
                        };
                        let mut n = m.clone();
                        n.occ[cell as usize] = NO_UNIT;
                        n.occ[to as usize] = u;
                        n.units[u as usize].cell = to;
                        n.refresh();
                        if seen.insert(n.configuration()) {
                            next.push(n);
                        }
                    }
                }
            }
        }
        layer = next;
    }
    None
}
