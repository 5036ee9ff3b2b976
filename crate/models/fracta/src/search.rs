//! What the report measures beside the runs, on the model's own rules: the fewest motions a
//! repair needs (a breadth-first search), how a run begins, where its steps go (a step-by-step
//! trace), and whether a finished shape stays still; each for both readings of where the spare
//! sits ([`Spare`]).

use std::collections::BTreeSet;

use super::*;
use kumiki_model::entry::envelope_role;
use kumiki_model::limits::Limits;

/// Where figure 5's spare sits (interpretation 15): the readings the report runs, each with the
/// presets that hold it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Spare {
    /// In the middle of an edge, bonded to its two edge units (the default).
    Edge,
    /// Beside a corner, bonded to the corner and the next edge unit.
    Corner,
}

impl Spare {
    pub const BOTH: [Spare; 2] = [Spare::Edge, Spare::Corner];

    /// The self-assembly from two lines.
    pub fn assembly(self) -> &'static str {
        match self {
            Spare::Edge => "fracta-triangle10",
            Spare::Corner => "fracta-triangle10-corner",
        }
    }

    /// The finished triangle with its spare and a fault.
    pub fn repair(self) -> &'static str {
        match self {
            Spare::Edge => "fracta-repair",
            Spare::Corner => "fracta-repair-corner",
        }
    }

    /// Figure 4's deadlock.
    pub fn deadlock(self) -> &'static str {
        match self {
            Spare::Edge => "fracta-deadlock",
            Spare::Corner => "fracta-deadlock-corner",
        }
    }

    /// "in the middle of an edge", "beside a corner".
    pub fn words(self) -> &'static str {
        match self {
            Spare::Edge => "in the middle of an edge",
            Spare::Corner => "beside a corner",
        }
    }

    fn assembly_text(self) -> &'static str {
        match self {
            Spare::Edge => include_str!("../presets/fracta-triangle10.json"),
            Spare::Corner => include_str!("../presets/fracta-triangle10-corner.json"),
        }
    }

    fn repair_text(self) -> &'static str {
        match self {
            Spare::Edge => include_str!("../presets/fracta-repair.json"),
            Spare::Corner => include_str!("../presets/fracta-repair-corner.json"),
        }
    }
}

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

/// The repair preset's model of `spare` (run with `seed`) with the fault on `unit` applied and
/// cut off. The finished triangle makes no draw before the fault, so this is the state the
/// preset's run with that seed reaches in the step that cuts the unit off.
fn after_cut_off(spare: Spare, unit: u64, seed: u64) -> Option<Fracta> {
    let Value::Object(fault) = json!({"kind": "fault", "unit": unit}) else {
        return None;
    };
    let mut m = Fracta::of_preset(spare.repair_text(), |doc| {
        doc.insert("seed".into(), json!(seed));
    })?;
    m.apply(&fault).ok()?;
    m.cut_off_faulty();
    Some(m)
}

/// The assembly preset's model of `spare` run with `seed`, its keys changed by `set`.
fn assembly(spare: Spare, seed: u64, set: &[(&str, Value)]) -> Option<Fracta> {
    Fracta::of_preset(spare.assembly_text(), |doc| {
        doc.insert("seed".into(), json!(seed));
        for (key, value) in set {
            doc.insert(key.to_string(), value.clone());
        }
    })
}

/// What a run waits for before its first motion.
#[derive(Clone, Debug, PartialEq)]
pub struct FirstMotion {
    /// The working units that, at the start, have a motion lowering the summed difference.
    pub improving: Vec<u32>,
    /// Their differences at that moment.
    pub differences: Vec<u32>,
    /// The mean difference of the working units at that moment.
    pub mean_difference: f64,
    /// Whether equation 3 activated one of them before or at the first motion.
    pub improving_activated: bool,
    /// Steps from the start to the step of the first motion.
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

/// How the repair of a fault on `unit` begins, run with the repair preset's seed for at most
/// `limit` steps after the cut-off; `None` when no unit moved by then.
pub fn first_motion_after_fault(spare: Spare, unit: u64, limit: u64) -> Option<FirstMotion> {
    let seed = serde_json::from_str::<Value>(spare.repair_text())
        .ok()?
        .get("seed")?
        .as_u64()?;
    first_motion(after_cut_off(spare, unit, seed)?, limit)
}

/// How the self-assembly from two lines begins, within `limit` steps, with the preset's keys
/// changed by `set`. Nothing is drawn at random before the first motion is planned, so every
/// seed begins the same way.
pub fn first_motion_of_assembly(
    spare: Spare,
    set: &[(&str, Value)],
    limit: u64,
) -> Option<FirstMotion> {
    first_motion(assembly(spare, 1, set)?, limit)
}

/// The units of `m` with a motion that lowers the summed difference, with their differences
/// and the structure's mean, and when and how the first motion comes.
fn first_motion(mut m: Fracta, limit: u64) -> Option<FirstMotion> {
    let improving = improving_units(&m);
    let differences = improving.iter().map(|&u| m.diff[u as usize]).collect();
    let mean_difference = m.mean_difference();
    let mut improving_activated = false;
    for wait in 0..limit {
        // A script in a rule slot that stops ends the search where it stopped.
        m.decide().ok()?;
        improving_activated |= m
            .active
            .iter()
            .any(|&(u, irritated)| !irritated && improving.contains(&u));
        if !m.plans.is_empty() {
            let by_irritation = m.plans.iter().all(|p| m.irritated(p.unit));
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

impl Fracta {
    /// Whether unit `u` is active this step because its irritation fired.
    fn irritated(&self, u: u32) -> bool {
        self.active.iter().any(|&(a, fired)| a == u && fired)
    }
}

/// Where runs spend their steps, summed over the runs that reached the goal.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Trace {
    /// Runs that reached the goal within the limit, and runs that did not (not counted below).
    pub runs: u64,
    pub unfinished: u64,
    /// Steps to the goal.
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
    /// Runs that passed through the text's deadlock (section 3.2.5, figure 4): every movable
    /// unit matches a statement (difference 0), so equation 3 activates none, and the goal is
    /// not reached.
    pub deadlocked_runs: u64,
    /// The steps that began in such a deadlock.
    pub deadlocked_steps: u64,
    /// Each run's longest stretch of steps in which no unit rolled.
    pub longest_stalls: Vec<u64>,
}

impl Trace {
    fn add(&mut self, t: &Trace) {
        self.runs += t.runs;
        self.unfinished += t.unfinished;
        self.steps += t.steps;
        self.held += t.held;
        self.stuck += t.stuck;
        self.together_worse += t.together_worse;
        self.irritated_rolls += t.irritated_rolls;
        self.deadlocked_runs += t.deadlocked_runs;
        self.deadlocked_steps += t.deadlocked_steps;
        self.longest_stalls.extend(&t.longest_stalls);
    }

    /// The sum of several traces.
    pub fn total<'a>(traces: impl IntoIterator<Item = &'a Trace>) -> Trace {
        let mut out = Trace::default();
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

/// Whether `m` is in the text's deadlock: not at its goal, and every working movable unit
/// matches a statement.
fn deadlocked(m: &Fracta) -> bool {
    let t = types();
    !m.completed()
        && m.working
            .iter()
            .all(|&u| m.diff[u as usize] == 0 || !t.info[m.class[u as usize] as usize].movable)
}

/// Runs `m` to its goal, step by step, for at most `limit` steps, and says where the steps
/// went (a [`Trace`] of one run, `unfinished` when it did not get there).
fn trace_run(mut m: Fracta, limit: u64) -> Trace {
    let mut run = Trace {
        runs: 1,
        ..Trace::default()
    };
    let (mut stall, mut longest) = (0, 0);
    while !m.completed() && run.steps < limit {
        let improving = improving_units(&m);
        let before = summed_difference(&m);
        if deadlocked(&m) {
            run.deadlocked_steps += 1;
        }
        if m.decide().is_err() {
            break;
        }
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
        stall = if m.moves == moves { stall + 1 } else { 0 };
        longest = longest.max(stall);
        if m.moves >= moves + 2 && summed_difference(&m) > before {
            run.together_worse += 1;
        }
        run.irritated_rolls += fired
            .iter()
            .filter(|&&(u, cell)| m.units[u as usize].cell != cell)
            .count() as u64;
    }
    run.deadlocked_runs = u64::from(run.deadlocked_steps > 0);
    run.longest_stalls = vec![longest];
    if m.completed() {
        run
    } else {
        Trace {
            unfinished: 1,
            ..Trace::default()
        }
    }
}

/// Traces the repair of a fault on `unit` of the repair preset, step by step, for each of
/// `seeds` (at most `limit` steps after the cut-off each).
pub fn trace_repairs(
    spare: Spare,
    unit: u64,
    seeds: impl IntoIterator<Item = u64>,
    limit: u64,
) -> Option<Trace> {
    let mut out = Trace::default();
    for seed in seeds {
        out.add(&trace_run(after_cut_off(spare, unit, seed)?, limit));
    }
    Some(out)
}

/// Traces the self-assembly from two lines, step by step, for each of `seeds` (at most
/// `limit` steps each), with the preset's keys changed by `set`.
pub fn trace_assemblies(
    spare: Spare,
    set: &[(&str, Value)],
    seeds: impl IntoIterator<Item = u64>,
    limit: u64,
) -> Option<Trace> {
    let mut out = Trace::default();
    for seed in seeds {
        out.add(&trace_run(assembly(spare, seed, set)?, limit));
    }
    Some(out)
}

/// What finished shapes do while every unit works: the self-assemblies of `seeds` that reached
/// the goal within `limit` steps, each run on for `after` more steps.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stillness {
    /// Assemblies that reached the goal.
    pub runs: u64,
    /// Of them, those in which a unit moved after the goal was reached.
    pub moved: u64,
    /// Rolls made after the goal, over all runs.
    pub moves: u64,
    /// Runs whose irritation fired after the goal.
    pub irritated: u64,
}

/// Runs the self-assembly of `spare` (its keys changed by `set`) for each of `seeds` until it
/// reaches the goal (within `limit` steps), then `after` steps more with every unit working.
pub fn stillness(
    spare: Spare,
    set: &[(&str, Value)],
    seeds: impl IntoIterator<Item = u64>,
    limit: u64,
    after: u64,
) -> Option<Stillness> {
    let mut out = Stillness::default();
    for seed in seeds {
        let mut m = assembly(spare, seed, set)?;
        while !m.completed() && m.steps < limit {
            m.step();
        }
        if !m.completed() {
            continue;
        }
        let (moves, irritations) = (m.moves, m.irritations);
        for _ in 0..after {
            m.step();
        }
        out.runs += 1;
        out.moved += u64::from(m.moves > moves);
        out.moves += m.moves - moves;
        out.irritated += u64::from(m.irritations > irritations);
    }
    Some(out)
}

/// The fewest motions (one unit's motion at a time, every rule of the model applied) that take
/// the 10 units left after a fault on `unit` of the repair preset to the triangle, searched
/// breadth first up to `limit` motions; `None` if more are needed or the preset is missing.
pub fn fewest_repair_motions(spare: Spare, unit: u64, limit: usize) -> Option<usize> {
    let m = after_cut_off(spare, unit, 1)?;
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
