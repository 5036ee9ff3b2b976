//! The fewest motions a repair needs: a breadth-first search over the model's own motions,
//! for the reproduction report to put beside the repair times.

use std::collections::BTreeSet;

use super::*;
use kumiki_model::entry::ENVELOPE;
use kumiki_model::limits::Limits;

/// The presets the search starts from, read from this crate's files.
const REPAIR: &str = include_str!("../presets/fracta-repair.json");
const TRIANGLE10: &str = include_str!("../presets/fracta-triangle10.json");

impl Fracta {
    /// The model of one of this crate's preset files, built the way a run builds it (within the
    /// page's limits): the file's own keys, its envelope left out, with its seed.
    fn of_preset(text: &str) -> Option<Fracta> {
        let Ok(Value::Object(mut doc)) = serde_json::from_str::<Value>(text) else {
            return None;
        };
        let seed = doc.get("seed")?.as_u64()?;
        doc.retain(|key, _| !ENVELOPE.contains(&key.as_str()));
        let spec: Spec = kumiki_model::error::from_value(Value::Object(doc)).ok()?;
        let checked = model::Spec::validate(&spec, &Limits::PAGE).ok()?;
        Some(Fracta::from_checked(checked, seed))
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

/// The `fracta-repair` preset's model with the fault on `unit` applied and cut off.
fn after_cut_off(unit: u64) -> Option<Fracta> {
    let Value::Object(fault) = json!({"kind": "fault", "unit": unit}) else {
        return None;
    };
    let mut m = Fracta::of_preset(REPAIR)?;
    m.apply(&fault).ok()?;
    m.cut_off_faulty();
    Some(m)
}

/// What a repair waits for before its first motion.
#[derive(Clone, Debug, PartialEq)]
pub struct FirstMotion {
    /// The working units that, right after the cut-off, have a motion lowering the summed
    /// difference.
    pub improving: Vec<u32>,
    /// Their differences at that moment.
    pub differences: Vec<u32>,
    /// The mean difference of the working units at that moment.
    pub mean_difference: f64,
    /// Whether equation 3 activated one of them before or at the first motion.
    pub improving_activated: bool,
    /// Steps from the cut-off to the step of the first motion.
    pub wait: u64,
    /// Whether every unit that made the first motion had fired by irritation.
    pub by_irritation: bool,
}

/// The units with a motion that lowers the summed difference around them.
fn improving_units(m: &Fracta) -> Vec<u32> {
    let t = types();
    let mut probe = m.clone();
    let mut out = Vec::new();
    for &u in &m.working {
        if !t.info[m.class[u as usize] as usize].movable {
            continue;
        }
        let cell = m.units[u as usize].cell;
        let improves = (0..6).any(|pivot| {
            Turn::BOTH.into_iter().any(|turn| {
                m.legal(cell, m.mask[u as usize], pivot, turn)
                    .is_some_and(|to| probe.change_after(u, cell, to) < 0)
            })
        });
        if improves {
            out.push(u);
        }
    }
    out
}

/// How the repair of a fault on `unit` of `fracta-repair` begins, run with the preset's seed for
/// at most `limit` steps after the cut-off; `None` when no unit moved by then.
pub fn first_motion_after_fault(unit: u64, limit: u64) -> Option<FirstMotion> {
    first_motion(after_cut_off(unit)?, limit)
}

/// How the self-assembly of `fracta-triangle10` from two lines begins, within `limit` steps.
/// Nothing is drawn at random before the first motion, so every seed begins the same way.
pub fn first_motion_of_assembly(limit: u64) -> Option<FirstMotion> {
    first_motion(Fracta::of_preset(TRIANGLE10)?, limit)
}

/// The units of `m` with a motion that lowers the summed difference, with their differences
/// and the structure's mean, and when and how the first motion comes.
fn first_motion(mut m: Fracta, limit: u64) -> Option<FirstMotion> {
    let improving = improving_units(&m);
    let differences = improving.iter().map(|&u| m.diff[u as usize]).collect();
    let mean_difference = m.mean_difference();
    let mut improving_activated = false;
    for wait in 0..limit {
        m.decide();
        improving_activated |= m
            .active
            .iter()
            .any(|&(u, irritated)| !irritated && improving.contains(&u));
        if !m.plans.is_empty() {
            let by_irritation = m.plans.iter().all(|p| {
                m.active
                    .iter()
                    .any(|&(u, irritated)| u == p.unit && irritated)
            });
            return Some(FirstMotion {
                improving,
                differences,
                mean_difference,
                improving_activated,
                wait,
                by_irritation,
            });
        }
        m.act();
    }
    None
}

/// Over the repair of a fault on `unit` (the preset's seed, at most `limit` steps after the
/// cut-off): the steps it took, and of them the steps in which some unit had a motion that
/// lowers the summed difference but no such unit was activated (by equation 3 or by
/// irritation). `None` if the preset is missing or the repair did not finish.
pub fn held_back_steps(unit: u64, limit: u64) -> Option<(u64, u64)> {
    let mut m = after_cut_off(unit)?;
    let mut held = 0;
    for step in 0..limit {
        if m.completed() {
            return Some((step, held));
        }
        let improving = improving_units(&m);
        m.decide();
        if !improving.is_empty() && !m.active.iter().any(|a| improving.contains(&a.0)) {
            held += 1;
        }
        m.act();
    }
    None
}

/// The fewest motions (one unit's motion at a time, every rule of the model applied) that take
/// the 10 units left after a fault on `unit` of the `fracta-repair` preset to the triangle,
/// searched breadth first up to `limit` motions; `None` if more are needed or the preset is
/// missing.
pub fn fewest_repair_motions(unit: u64, limit: usize) -> Option<usize> {
    let m = after_cut_off(unit)?;
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
