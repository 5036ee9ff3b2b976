//! The fewest motions a repair needs: a breadth-first search over the model's own motions,
//! for the reproduction report to put beside the repair times.

use std::collections::BTreeSet;

use super::*;
use kumiki_model::entry::envelope_role;
use kumiki_model::limits::Limits;

/// The presets the search starts from, read from this crate's files.
const REPAIR: &str = include_str!("../presets/fracta-repair.json");
const TRIANGLE10: &str = include_str!("../presets/fracta-triangle10.json");

impl Fracta {
    /// The model of one of this crate's preset files, built the way a run builds it (within the
    /// page's limits): the file's own keys after `edit` changed them, its envelope left out, with
    /// its seed.
    fn of_preset(text: &str, edit: impl FnOnce(&mut Map<String, Value>)) -> Option<Fracta> {
        let Ok(Value::Object(mut doc)) = serde_json::from_str::<Value>(text) else {
            return None;
        };
        edit(&mut doc);
        let seed = doc.get("seed")?.as_u64()?;
        doc.retain(|key, _| envelope_role(key).is_none());
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

/// The `fracta-repair` preset's model (run with `seed`) with the fault on `unit` applied and
/// cut off. The finished triangle makes no draw before the fault, so this is the state the
/// preset's run with that seed reaches in the step that cuts the unit off.
fn after_cut_off(unit: u64, seed: u64) -> Option<Fracta> {
    let Value::Object(fault) = json!({"kind": "fault", "unit": unit}) else {
        return None;
    };
    let mut m = Fracta::of_preset(REPAIR, |doc| {
        doc.insert("seed".into(), json!(seed));
    })?;
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
pub(super) fn improving_units(m: &Fracta) -> Vec<u32> {
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
    let seed = serde_json::from_str::<Value>(REPAIR)
        .ok()?
        .get("seed")?
        .as_u64()?;
    first_motion(after_cut_off(unit, seed)?, limit)
}

/// How the self-assembly of `fracta-triangle10` from two lines begins, within `limit` steps,
/// with the activation threshold `g` (equation 3). Nothing is drawn at random before the first
/// motion, so every seed begins the same way.
pub fn first_motion_of_assembly(g: f64, limit: u64) -> Option<FirstMotion> {
    first_motion(
        Fracta::of_preset(TRIANGLE10, |doc| {
            doc.insert("G".into(), json!(g));
        })?,
        limit,
    )
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

/// Where the repairs of a fault on one unit spend their steps, summed over the runs that
/// reached the triangle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RepairTrace {
    /// Runs that reached the triangle within the limit, and runs that did not (not counted
    /// below).
    pub runs: u64,
    pub unfinished: u64,
    /// Steps from the fault to the triangle.
    pub steps: u64,
    /// Steps that began with some unit able to lower the summed difference and none of those
    /// units activated (by equation 3 or by irritation).
    pub held: u64,
    /// Steps that began in a local minimum: no unit had a motion that lowers the summed
    /// difference, so only a unit whose irritation fired could move.
    pub stuck: u64,
    /// Steps in which two or more units rolled and the summed difference rose: rolls chosen
    /// each against the structure as it was, made together.
    pub together_worse: u64,
    /// Rolls made by units whose irritation fired (condition 5), which take any change.
    pub irritated_rolls: u64,
}

impl RepairTrace {
    fn add(&mut self, t: &RepairTrace) {
        self.runs += t.runs;
        self.unfinished += t.unfinished;
        self.steps += t.steps;
        self.held += t.held;
        self.stuck += t.stuck;
        self.together_worse += t.together_worse;
        self.irritated_rolls += t.irritated_rolls;
    }

    /// The sum of several traces.
    pub fn total<'a>(traces: impl IntoIterator<Item = &'a RepairTrace>) -> RepairTrace {
        let mut out = RepairTrace::default();
        for t in traces {
            out.add(t);
        }
        out
    }
}

/// The summed difference of the working units.
fn summed_difference(m: &Fracta) -> u64 {
    m.working
        .iter()
        .map(|&u| u64::from(m.diff[u as usize]))
        .sum()
}

/// Traces the repair of a fault on `unit` of `fracta-repair`, step by step, for each of
/// `seeds` (at most `limit` steps after the cut-off each): where the runs that reach the
/// triangle spend their steps (see [`RepairTrace`]).
pub fn trace_repairs(
    unit: u64,
    seeds: impl IntoIterator<Item = u64>,
    limit: u64,
) -> Option<RepairTrace> {
    let mut out = RepairTrace::default();
    for seed in seeds {
        let mut m = after_cut_off(unit, seed)?;
        let mut run = RepairTrace {
            runs: 1,
            ..RepairTrace::default()
        };
        while !m.completed() && run.steps < limit {
            let improving = improving_units(&m);
            let before = summed_difference(&m);
            m.decide();
            if improving.is_empty() {
                run.stuck += 1;
            } else if !m.active.iter().any(|a| improving.contains(&a.0)) {
                run.held += 1;
            }
            let fired: Vec<(u32, u32)> = m
                .active
                .iter()
                .filter(|a| a.1)
                .map(|a| (a.0, m.units[a.0 as usize].cell))
                .collect();
            let moves = m.moves;
            m.act();
            run.steps += 1;
            if m.moves >= moves + 2 && summed_difference(&m) > before {
                run.together_worse += 1;
            }
            run.irritated_rolls += fired
                .iter()
                .filter(|&&(u, cell)| m.units[u as usize].cell != cell)
                .count() as u64;
        }
        if m.completed() {
            out.add(&run);
        } else {
            out.unfinished += 1;
        }
    }
    Some(out)
}

/// The fewest motions (one unit's motion at a time, every rule of the model applied) that take
/// the 10 units left after a fault on `unit` of the `fracta-repair` preset to the triangle,
/// searched breadth first up to `limit` motions; `None` if more are needed or the preset is
/// missing.
pub fn fewest_repair_motions(unit: u64, limit: usize) -> Option<usize> {
    let m = after_cut_off(unit, 1)?;
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
