//! Section 4's self-assembly from two lines, how it starts, section 3.2.5's "sometimes the
//! self-assembly process is trapped", and whether the finished shape stays.

use super::*;

const EXP: &str = "fracta-assembly";

/// The seeds and the step cap of `fracta-assembly`, which the traces follow too.
const SEEDS: u64 = 1000;
const CAP: u64 = 2000;

/// Steps within which [`start`] looks for the first motion.
const FIRST_MOTION_LIMIT: u64 = 200;

/// Steps each finished assembly runs on, every unit working.
const STILL_AFTER: u64 = 500;

/// The leak of model version 6, which `fracta-start` runs.
const OLD_L: f64 = 0.05;

pub(super) fn findings(r: &Results) -> Vec<Finding> {
    let traces = [
        search::trace_assemblies(Spare::Edge, &[], 1..=SEEDS, CAP),
        search::trace_assemblies(Spare::Corner, &[("L", json!(OLD_L))], 1..=SEEDS, CAP),
    ];
    vec![
        success(r),
        convergence(r),
        start(r),
        trapped(&traces),
        stays(),
    ]
}

fn success(r: &Results) -> Finding {
    let [edge, corner] = Spare::BOTH.map(|s| r.values(EXP, &scenario(s.assembly()), "completed"));
    let rings = r.values("fracta-rings", &[], "completed");
    Finding::new(
        "§4, fig. 6",
        "11 units starting from a two-line configuration form the 10-unit triangle with one spare \
         unit; the paper ran 1000 simulations of this self-assembly and reports the success \
         ratio.",
        format!(
            "spare in the middle of an edge: {} runs assembled; beside a corner: {}",
            ratio(&edge),
            ratio(&corner)
        ),
        edge.len() + corner.len(),
        Verdict::NotStated,
        &format!(
            "fracta-triangle10 (the spare in the middle of an edge, the default) and \
             fracta-triangle10-corner (beside a corner), two rows of 6 and 5, seeds 1 to 1000 \
             each, capped at 2000 steps; a run counts when every unit matches a statement \
             exactly, which for 11 units only the triangle with its spare does, under either \
             reading (an enumeration of every 11-cell polyhex, in the tests). Edge: {} Corner: \
             {} The paper states no rule against closing a ring round empty cells; with the \
             `no_holes` rule of earlier rounds, which forbids it (fracta-rings, the edge's \
             seeds), {} runs assembled. {}",
            failures(r, EXP, &scenario(Spare::Edge.assembly())),
            failures(r, EXP, &scenario(Spare::Corner.assembly())),
            ratio(&rings),
            failures(r, "fracta-rings", &[])
        ),
    )
}

fn convergence(r: &Results) -> Finding {
    let [edge, corner] = Spare::BOTH
        .map(|s| Stats::of(&r.values(EXP, &scenario(s.assembly()), "convergence_steps")));
    Finding::new(
        "§4",
        "The paper reports the average convergence time of its 1000 simulations.",
        format!(
            "spare in the middle of an edge: {} steps; beside a corner: {} steps",
            edge.describe(1),
            corner.describe(1)
        ),
        edge.n + corner.n,
        Verdict::NotStated,
        "Steps from the two-line start to the goal, completed runs of fracta-assembly; the \
         experiment's histogram shows the distribution.",
    )
}

/// When and how the first motion comes, in words.
fn when(first: &search::FirstMotion) -> String {
    let at = match first.wait {
        0 => "in the first step".to_string(),
        1 => "in the second step".to_string(),
        n => format!("{n} steps in"),
    };
    let by = if first.by_irritation {
        "made by units whose irritation fired"
    } else {
        "by equation 3"
    };
    format!("{at}, {by}")
}

/// How the assembly from two lines begins under one reading and leak, in words (nothing is
/// random before the first motion is planned, so every seed begins the same way).
fn begins(spare: Spare, l: f64) -> String {
    let set = [("L", json!(l))];
    let Some(first) = search::first_motion_of_assembly(spare, &set, FIRST_MOTION_LIMIT) else {
        return format!("no unit moves in the first {FIRST_MOTION_LIMIT} steps");
    };
    let units = first
        .improving
        .iter()
        .zip(&first.differences)
        .map(|(u, d)| format!("{u} ({d})"))
        .collect::<Vec<_>>()
        .join(", ");
    format!(
        "the units with a roll that lowers the summed difference are {units} (unit \
         (difference)), equation 3 {} them, and the first motion comes {}",
        if first.improving_activated {
            "activates"
        } else {
            "activates none of"
        },
        when(&first)
    )
}

/// The shortest assemblies, and how every assembly from two lines begins with the leak now and
/// with model version 6's.
fn start(r: &Results) -> Finding {
    let steps = r.values(EXP, &scenario(Spare::Edge.assembly()), "convergence_steps");
    let s = Stats::of(&steps);
    let v6 = |spare: Spare| {
        let f = scenario(spare.assembly());
        let steps = r.values("fracta-start", &f, "convergence_steps");
        let o = Stats::of(&steps);
        format!(
            "{} assembled, the shortest in {} steps ({} runs), median {}",
            ratio(&r.values("fracta-start", &f, "completed")),
            fmt(o.min, 0),
            steps.iter().filter(|&&v| v == o.min).count(),
            fmt(o.median, 1)
        )
    };
    let corner = Stats::of(&r.values(
        EXP,
        &scenario(Spare::Corner.assembly()),
        "convergence_steps",
    ));
    Finding::new(
        "§4, fig. 6",
        "The shortest self-assemblies (the hardware run of figure 6 is one self-assembly from \
         two lines).",
        format!(
            "spare in the middle of an edge: shortest {} steps, in {} runs; 5th percentile {}, \
             10th percentile {}; beside a corner: shortest {} steps",
            fmt(s.min, 0),
            steps.iter().filter(|&&v| v == s.min).count(),
            fmt(percentile(&steps, 0.05), 1),
            fmt(percentile(&steps, 0.10), 1),
            fmt(corner.min, 0)
        ),
        s.n,
        Verdict::NotStated,
        &format!(
            "Completed runs of fracta-assembly. The line ends are the start's only movable \
             units. Their neighbours' larger differences send a flux into them; with L = 0.3 \
             the leak takes away as much as one unit of difference on each of a movable \
             unit's bonds brings (3.2.5: x \"remains stable ... due to the leak constant L\"), \
             so their x falls below their difference. Spare in the middle of an edge: {}. \
             Beside a corner: {}. With model version 6's leak, L = 0.05 (fracta-start, the same \
             seeds), the flux lifts their x faster than the leak takes it away. Beside a \
             corner, version 6's presets, {}: every seed waited for irritation, {}. In the \
             middle of an edge {}, as two line ends have difference 3 against these \
             statements: {} (crate/models/fracta/README.md, interpretation 18).",
            begins(Spare::Edge, 0.3),
            begins(Spare::Corner, 0.3),
            begins(Spare::Corner, OLD_L),
            v6(Spare::Corner),
            begins(Spare::Edge, OLD_L),
            v6(Spare::Edge)
        ),
    )
}

/// "Sometimes": in some runs, fewer than half; in more than half but not all it is more than
/// sometimes (partial); in every run or none it differs.
fn sometimes(k: u64, n: u64) -> Verdict {
    match k {
        0 => Verdict::Differs,
        k if k == n => Verdict::Differs,
        k if 2 * k > n => Verdict::Partial,
        _ => Verdict::Holds,
    }
}

fn trapped(traces: &[Option<search::Trace>; 2]) -> Finding {
    let [Some(now), Some(old)] = traces else {
        return Finding::new(
            "§3.2.5",
            "Sometimes the self-assembly process is trapped in a deadlock state.",
            "the assemblies could not be traced (preset missing)".into(),
            0,
            Verdict::Differs,
            "",
        );
    };
    let stalls = |t: &search::Trace| {
        let v: Vec<f64> = t.longest_stalls.iter().map(|&s| s as f64).collect();
        Stats::of(&v).describe(1)
    };
    Finding::new(
        "§3.2.5, fig. 4",
        "Sometimes the self-assembly process is trapped in a deadlock state: all the movable \
         units have the difference 0, so equation 3 moves none of them.",
        format!(
            "{} of {} assemblies passed through such a deadlock ({} of their {} steps); under \
             model version 6 (L = 0.05, the spare beside a corner) {} of {} ({} of {} steps)",
            now.deadlocked_runs,
            now.runs,
            now.deadlocked_steps,
            now.steps,
            old.deadlocked_runs,
            old.runs,
            old.deadlocked_steps,
            old.steps
        ),
        now.runs as usize,
        sometimes(now.deadlocked_runs, now.runs),
        &format!(
            "fracta-triangle10's 1000 seeds traced step by step (capped at 2000 steps; \
             fracta-assembly's runs; version 6's, fracta-start's runs of \
             fracta-triangle10-corner). A step is in the text's \
             deadlock when every movable unit matches a statement exactly and the goal is not \
             reached (figure 4's \"all the movable type o units have the difference 0\"). The \
             verdict reads \"sometimes\" as in some runs, fewer than half (more than half is \
             partial; every run or none differs). Each run's longest stretch of steps in which \
             no unit rolled: {} steps; under version 6 {} (the wait before the first motion, \
             which is no deadlock of the text's: the line ends have difference 1, but equation \
             3 activated none of them). Traced step by step, {} Under version 6, {}",
            stalls(now),
            stalls(old),
            trace_text(now, "the goal"),
            trace_text(old, "the goal")
        ),
    )
}

fn stays() -> Finding {
    let [edge, corner] = Spare::BOTH
        .map(|s| search::stillness(s, &[], 1..=SEEDS, CAP, STILL_AFTER).unwrap_or_default());
    Finding::new(
        "§4, fig. 6",
        "This goal shape remains stable as long as all the units are working without faults.",
        format!(
            "{} of {} finished assemblies made no move in the {STILL_AFTER} steps after the \
             goal; beside a corner {} of {}",
            edge.runs - edge.moved,
            edge.runs,
            corner.runs - corner.moved,
            corner.runs
        ),
        (edge.runs + corner.runs) as usize,
        Verdict::of_all((edge.runs - edge.moved) as usize, edge.runs as usize),
        &format!(
            "Each of fracta-assembly's 1000 seeds of fracta-triangle10 (and of \
             fracta-triangle10-corner) run to the goal, then {STILL_AFTER} steps more with \
             every unit working: x and the irritation carry on from the assembly, so a unit \
             whose irritation fired would roll whatever its difference (condition 5). The \
             verdict asks that every finished shape stays (\"remains stable\"). Irritation \
             fired after the goal in {} runs ({} beside a corner), and {} rolls were made in \
             all ({}). With every difference 0, equation 3 activates no unit (G·x < 0 never \
             holds), but irritation carried over from the assembly, and what equation 4 adds \
             while the finished shape's x drains through its movable units, can still pass \
             I_th in a corner or the spare, an o unit, which then rolls whatever its \
             difference (condition 5) and the shape is rebuilt. With model version 6's leak \
             (L = 0.05) every finished assembly moved again (crate/models/fracta/README.md, \
             \"Beside the paper\").",
            edge.irritated, corner.irritated, edge.moves, corner.moves
        ),
    )
}
