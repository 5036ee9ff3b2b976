//! The claims of Yoshida et al.'s section 4 (self-assembly and self-repair of the 10-unit
//! triangle) and section 3.2.5 (figure 4's deadlock) beside Kumiki's figures, for the
//! reproduction report. Every verdict is computed from the experiment rows.

use serde_json::{json, Value};

use super::search;
use kumiki_model::report::{fmt, value, Finding, Paper, Results, Stats, Verdict};

pub const PAPER: Paper = Paper {
    model: "fracta",
    citation: "E. Yoshida, S. Murata, K. Tomita, H. Kurokawa and S. Kokaji, \
               \"Experiment of Self-repairing Modular Machine\"",
    experiments: &[
        "fracta-assembly",
        "fracta-rings",
        "fracta-start",
        "fracta-repair",
        "fracta-deadlock",
    ],
    findings,
};

/// The units of `fracta-repair` a fault is given to (all but the centre `s`, unit 5), with the
/// place each holds in the triangle with its spare.
const FAULTS: [(u64, &str); 10] = [
    (0, "the spare"),
    (1, "the apex, beside the spare"),
    (2, "the edge unit the spare leans on"),
    (3, "the edge unit beside the apex, away from the spare"),
    (4, "the edge unit at the left of the third row"),
    (6, "the edge unit at the right of the third row"),
    (7, "the bottom-left corner"),
    (8, "a bottom edge unit"),
    (9, "a bottom edge unit"),
    (10, "the bottom-right corner"),
];

fn findings(r: &Results) -> Vec<Finding> {
    let mut out = assembly(r);
    out.extend(repair(r));
    out.extend(deadlock(r));
    out.push(Finding {
        section: "§5.2, fig. 10".into(),
        claim: "Twelve 3-D units build a box from a ladder by the difference-based algorithm \
                with MRF stochastic relaxation; the paper gives the number of steps."
            .into(),
        kumiki: "see cubes3d".into(),
        runs: 0,
        verdict: Verdict::NotStated,
        note: "The 3-D box is the cubes3d model's preset and experiment; its figures are in \
               the cubes3d section of this report."
            .into(),
    });
    out
}

/// The depth the breadth-first search of the fewest repair motions goes to.
const SEARCH_LIMIT: usize = 6;

/// Steps after a cut-off within which a traced repair must finish: the cap of `fracta-repair`.
const TRACE_LIMIT: u64 = 5000;

/// The seeds `fracta-repair` runs for each position, which the traces follow too.
const REPAIR_SEEDS: u64 = 100;

/// Steps after a cut-off within which [`start`] looks for the first motion.
const FIRST_MOTION_LIMIT: u64 = 200;

/// How a repair begins, as far as the report tells positions apart.
enum Begins {
    /// Equation 3 activates a unit that can lower the summed difference.
    Prompt,
    /// Units could lower it, but equation 3 activates none of them: irritation moves first,
    /// after this many steps.
    HeldBack(u64),
    /// No unit can lower it: irritation moves first, after this many steps.
    NoBetterMotion(u64),
}

/// How the repair of a fault on `unit` begins, in words and as a [`Begins`].
fn start(unit: u64) -> (String, Begins) {
    if search::fewest_repair_motions(unit, 0) == Some(0) {
        return (
            "The cut-off leaves the triangle: no unit needs to move.".into(),
            Begins::Prompt,
        );
    }
    let Some(first) = search::first_motion_after_fault(unit, FIRST_MOTION_LIMIT) else {
        return (
            format!("No unit moves within {FIRST_MOTION_LIMIT} steps of the cut-off."),
            Begins::Prompt,
        );
    };
    let units = first
        .improving
        .iter()
        .map(u32::to_string)
        .collect::<Vec<_>>()
        .join(", ");
    let (who, them) = match first.improving.len() {
        0 => ("no unit has a motion".to_string(), ""),
        1 => (format!("only unit {units} has a motion"), "it"),
        _ => (
            format!("units {units} have a motion"),
            "at least one of them",
        ),
    };
    let activated = match (first.improving.is_empty(), first.improving_activated) {
        (true, _) => String::new(),
        (false, true) => format!("; equation 3 activates {them}"),
        (false, false) if them == "it" => "; equation 3 does not activate it".into(),
        (false, false) => "; equation 3 activates none of them".into(),
    };
    let when = match first.wait {
        0 => "in the cut-off's own step".to_string(),
        1 => "1 step after the cut-off".to_string(),
        n => format!("{n} steps after the cut-off"),
    };
    let how = if first.by_irritation {
        ", made by units whose irritation fired"
    } else {
        ""
    };
    let begins = match (first.improving.is_empty(), first.improving_activated) {
        (true, _) => Begins::NoBetterMotion(first.wait),
        (false, false) => Begins::HeldBack(first.wait),
        (false, true) => Begins::Prompt,
    };
    (
        format!(
            "Right after the cut-off {who} that lowers the summed difference{activated}; the \
             first motion comes {when}{how}."
        ),
        begins,
    )
}

/// The activation threshold of `fracta-start`: just below 1, so that equation 2's initial
/// state, x = diff, passes equation 3 for every unit with a difference.
const START_G: f64 = 0.99;

/// How every assembly from two lines begins (nothing is random before the first motion), and
/// how it begins when equation 3 holds at the initial state (`fracta-start`).
fn assembly_start(r: &Results) -> String {
    let Some(first) = search::first_motion_of_assembly(1.0, FIRST_MOTION_LIMIT) else {
        return format!("No unit moves in the first {FIRST_MOTION_LIMIT} steps.");
    };
    let units = first
        .improving
        .iter()
        .zip(&first.differences)
        .map(|(u, d)| format!("{u} ({d})"))
        .collect::<Vec<_>>()
        .join(", ");
    let activated = if first.improving_activated {
        "equation 3 activates one of them"
    } else {
        "equation 3 activates none of them: equation 2's initial state, x(i, 0) = diff(i, 0), \
         makes it read G·diff < diff in the first step, which no unit passes with G = 1, and \
         afterwards x, the estimate of the difference around them, rises above their own, fed \
         by their neighbours' larger differences (\"this makes units having relatively large \
         difference move\", section 3.2.4, and theirs are the smallest)"
    };
    let how = if first.by_irritation {
        ", made by units whose irritation fired (section 3.2.5's way out of a deadlock)"
    } else {
        ""
    };
    let mut text = format!(
        "At the start the units with a roll that lowers the summed difference are {units} \
         (unit (difference); the structure's mean is {}); {activated}. The first motion comes \
         {} steps in{how}, the same in every seed, so the shortest assembly is that wait plus \
         the motions.",
        fmt(first.mean_difference, 2),
        first.wait
    );
    let steps = r.values("fracta-start", &[], "convergence_steps");
    if let Some(lowered) = search::first_motion_of_assembly(START_G, FIRST_MOTION_LIMIT) {
        let s = Stats::of(&steps);
        let here = Stats::of(&r.values("fracta-assembly", &[], "convergence_steps"));
        text.push_str(&format!(
            " With G = {START_G} (fracta-start, the same seeds), the initial state passes \
             equation 3 for every unit with a difference, and the first motion comes {}{}: \
             {} runs assembled, the shortest in {} steps ({} runs), median {} against {} \
             with G = 1. The text gives no value of G (nor of K, L or I_th), so whether the \
             paper's units began at once or waited for irritation cannot be recovered from it; \
             G stays 1 (crate/models/fracta/README.md, interpretation 18).",
            match lowered.wait {
                0 => "in the first step".to_string(),
                n => format!("{n} steps in"),
            },
            if lowered.by_irritation {
                ", by irritation"
            } else {
                ", by equation 3"
            },
            ratio(&r.values("fracta-start", &[], "completed")),
            fmt(s.min, 0),
            steps.iter().filter(|&&v| v == s.min).count(),
            fmt(s.median, 1),
            fmt(here.median, 1)
        ));
    }
    text
}

/// "k of n (p %)".
fn ratio(done: &[f64]) -> String {
    let k = done.iter().filter(|&&v| v > 0.0).count();
    let n = done.len();
    let pct = if n == 0 {
        f64::NAN
    } else {
        100.0 * k as f64 / n as f64
    };
    format!("{k} of {n} ({} %)", fmt(pct, 1))
}

/// What the runs that did not reach the goal ended in: how many with an enclosed hole (a ring
/// of units round an empty cell, which no rule can open; the paper states no rule against
/// closing one, so `no_holes` is off by default), the others at the step cap.
fn failures(r: &Results, experiment: &str, filter: &[(&str, Value)]) -> String {
    let failed: Vec<_> = r
        .select(experiment, filter)
        .into_iter()
        .filter(|row| !row.completed)
        .collect();
    if failed.is_empty() {
        return "Every run reached the goal.".into();
    }
    let holed = failed
        .iter()
        .filter(|row| value(row, "holes").is_some_and(|h| h > 0.0))
        .count();
    let moving = failed.len() - holed;
    let rest = if moving > 0 {
        format!(", and {moving} were still moving at the step cap")
    } else {
        String::new()
    };
    format!(
        "Of the {} runs that did not reach the goal, {holed} ended with a ring of units round \
         empty cells, which no rule can open{rest}.",
        failed.len()
    )
}

/// The value below which a fraction `q` of the sorted sample lies (linear interpolation).
fn percentile(values: &[f64], q: f64) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    let mut sorted = values.to_vec();
    kumiki_model::sort::sort_by(&mut sorted, f64::total_cmp);
    let pos = q * (sorted.len() - 1) as f64;
    let (lo, hi) = (pos.floor() as usize, pos.ceil() as usize);
    sorted[lo] + (sorted[hi] - sorted[lo]) * (pos - lo as f64)
}

fn assembly(r: &Results) -> Vec<Finding> {
    const EXP: &str = "fracta-assembly";
    let done = r.values(EXP, &[], "completed");
    let rings = r.values("fracta-rings", &[], "completed");
    let steps = r.values(EXP, &[], "convergence_steps");
    let s = Stats::of(&steps);
    vec![
        Finding {
            section: "§4, fig. 6".into(),
            claim: "11 units starting from a two-line configuration form the 10-unit triangle \
                    with one spare unit; the paper ran 1000 simulations of this self-assembly \
                    and reports the success ratio."
                .into(),
            kumiki: format!("{} runs assembled", ratio(&done)),
            runs: done.len(),
            verdict: Verdict::NotStated,
            note: format!(
                "fracta-triangle10 (two rows of 6 and 5), seeds 1 to 1000, capped at 2000 \
                 steps; a run counts when every unit matches a statement exactly, which for 11 \
                 units only the triangle with its spare beside a corner does (checked over 300 \
                 seeds in the tests). {} The paper states no rule against closing a ring \
                 round empty cells; with the `no_holes` rule of earlier rounds, which forbids \
                 it (fracta-rings, the same seeds), {} runs assembled. {}",
                failures(r, EXP, &[]),
                ratio(&rings),
                failures(r, "fracta-rings", &[])
            ),
        },
        Finding {
            section: "§4".into(),
            claim: "The paper reports the average convergence time of its 1000 simulations.".into(),
            kumiki: format!("{} steps", s.describe(1)),
            runs: s.n,
            verdict: Verdict::NotStated,
            note: "Steps from the two-line start to the goal, completed runs of \
                   fracta-assembly; the experiment's histogram shows the distribution."
                .into(),
        },
        Finding {
            section: "§4, fig. 6".into(),
            claim: "The shortest self-assemblies (the hardware run of figure 6 is one \
                    self-assembly from two lines)."
                .into(),
            kumiki: format!(
                "shortest {} steps, in {} runs; 5th percentile {}, 10th percentile {}",
                fmt(s.min, 0),
                steps.iter().filter(|&&v| v == s.min).count(),
                fmt(percentile(&steps, 0.05), 1),
                fmt(percentile(&steps, 0.10), 1)
            ),
            runs: s.n,
            verdict: Verdict::NotStated,
            note: format!("Completed runs of fracta-assembly. {}", assembly_start(r)),
        },
    ]
}

/// Where traced repairs spend their steps, in words.
fn trace_text(t: &search::RepairTrace) -> String {
    format!(
        "the {} runs that rebuilt the triangle took {} steps: {} began with a unit able to \
         lower the summed difference and none of those units activated, {} in a local minimum \
         where no motion lowers it (only a unit whose irritation fired can move then); in {} \
         two or more units rolled at once and the summed difference rose (each roll is chosen \
         against the structure as it was); irritation made {} rolls, which take any change.",
        t.runs, t.steps, t.held, t.stuck, t.together_worse, t.irritated_rolls
    )
}

fn repair(r: &Results) -> Vec<Finding> {
    const EXP: &str = "fracta-repair";
    // Per position: the fewest motions that repair it and how its repair begins. Both run the
    // model (a search, a simulation), so each is worked out once for the rows and the summary.
    let analysed: Vec<(Option<usize>, (String, Begins))> = FAULTS
        .iter()
        .map(|&(unit, _)| {
            (
                search::fewest_repair_motions(unit, SEARCH_LIMIT),
                start(unit),
            )
        })
        .collect();
    let traces: Vec<Option<search::RepairTrace>> = FAULTS
        .iter()
        .map(|&(unit, _)| search::trace_repairs(unit, 1..=REPAIR_SEEDS, TRACE_LIMIT))
        .collect();
    let held_text = |t: &Option<search::RepairTrace>| match t {
        Some(t) => format!("Traced step by step (the same seeds), {}", trace_text(t)),
        None => "The repair could not be traced (preset missing).".into(),
    };
    let mut out = Vec::new();
    for (((unit, role), (fewest, (begins, _))), held) in
        FAULTS.into_iter().zip(&analysed).zip(&traces)
    {
        let filter: [(&str, Value); 1] = [("disturbances.0.unit", json!(unit))];
        let done = r.values(EXP, &filter, "completed");
        let s = r.stats(EXP, &filter, "repair_steps");
        let moves = r.stats(EXP, &filter, "moves");
        let all = !done.is_empty() && done.iter().all(|&v| v > 0.0);
        out.push(Finding {
            section: "§4, fig. 6".into(),
            claim: format!(
                "A fault cut into unit {unit} ({role}) of the triangle with its spare is \
                 repaired: the other 10 units rebuild the triangle."
            ),
            kumiki: format!(
                "{} repaired; repair {} steps; mean {} motions, at least {} needed",
                ratio(&done),
                s.describe(1),
                fmt(moves.mean, 1),
                fewest.map_or(format!("more than {SEARCH_LIMIT}"), |n| n.to_string())
            ),
            runs: done.len(),
            verdict: Verdict::from(all),
            note: format!(
                "fracta-repair: the fault at step 10, 100 seeds, capped at 5000 steps; repair \
                 time from the fault to the triangle (its detection and cut-off take the first \
                 step), after which the units measure themselves against the first priority, \
                 the triangle (section 3.3). The fewest motions are a breadth-first search \
                 over the model's own motions, one unit at a time, from the 10 units the \
                 cut-off leaves. {begins} {} {}",
                held_text(held),
                failures(r, EXP, &filter)
            ),
        });
    }
    let s = r.stats(EXP, &[], "repair_steps");
    let moves = r.stats(EXP, &[], "moves");
    let done = r.values(EXP, &[], "completed");
    let needed: Vec<f64> = analysed
        .iter()
        .filter_map(|(fewest, _)| fewest.map(|n| n as f64))
        .collect();
    let (mut held, mut none) = (Vec::new(), Vec::new());
    for (&(unit, _), (_, (_, begins))) in FAULTS.iter().zip(&analysed) {
        match *begins {
            Begins::HeldBack(wait) => held.push(format!("a fault on unit {unit} ({wait} steps)")),
            Begins::NoBetterMotion(wait) => {
                none.push(format!("a fault on unit {unit} ({wait} steps)"))
            }
            Begins::Prompt => {}
        }
    }
    let mut waits = Vec::new();
    if !held.is_empty() {
        waits.push(format!(
            "Where units could lower the summed difference but equation 3 activates none of \
             them, the first motion waits for irritation: {}. Which units equation 3 \
             activates is where these repairs lose their time (crate/models/fracta/README.md, \
             \"Beside the paper\").",
            held.join(", ")
        ));
    }
    if !none.is_empty() {
        waits.push(format!(
            "Where no single motion lowers it, irritation makes the first motion too, as the \
             paper's condition 5 is meant to: {}.",
            none.join(", ")
        ));
    }
    let prompt = analysed
        .iter()
        .filter(|(fewest, (_, begins))| {
            matches!(begins, Begins::Prompt) && fewest.is_some_and(|n| n > 0)
        })
        .count();
    let moving = analysed
        .iter()
        .filter(|(fewest, _)| fewest.is_some_and(|n| n > 0))
        .count();
    waits.push(format!(
        "At {prompt} of the {moving} positions where a unit must move, equation 3 activates a \
         unit that can lower the summed difference in the cut-off's own step: the cut-off \
         leaves x where the finished structure had it (0, as every difference was 0) and \
         raises the differences of the units around the hole above it, so they pass equation \
         3 first (crate/models/fracta/README.md, interpretation 8)."
    ));
    let fastest: Vec<f64> = FAULTS
        .iter()
        .map(|&(unit, _)| {
            r.stats(EXP, &[("disturbances.0.unit", json!(unit))], "repair_steps")
                .min
        })
        .collect();
    if fastest.iter().all(|v| v.is_finite()) {
        waits.push(format!(
            "The fastest run at each position takes {} steps, a mean of {}.",
            fastest
                .iter()
                .map(|&v| fmt(v, 0))
                .collect::<Vec<_>>()
                .join(", "),
            fmt(fastest.iter().sum::<f64>() / fastest.len() as f64, 1)
        ));
    }
    let total = search::RepairTrace::total(traces.iter().flatten());
    waits.push(format!(
        "Traced step by step over all positions, {}",
        trace_text(&total)
    ));
    let held = waits.join(" ");
    let every = FAULTS.iter().all(|&(unit, _)| {
        let v = r.values(EXP, &[("disturbances.0.unit", json!(unit))], "completed");
        !v.is_empty() && v.iter().all(|&c| c > 0.0)
    });
    out.push(Finding::new(
        "§4",
        "The self-repair succeeds with the fault given to each of the 10 units other than the \
         centre s unit; the paper reports the success and the average self-repair time.",
        format!(
            "{} repaired; repair {} steps; mean {} motions, against a mean of {} over the 10 \
             positions for the fewest that repair them",
            ratio(&done),
            s.describe(1),
            fmt(moves.mean, 1),
            if needed.len() == FAULTS.len() {
                fmt(needed.iter().sum::<f64>() / needed.len() as f64, 1)
            } else {
                "n/a".into()
            }
        ),
        done.len(),
        Verdict::from(every),
        format!(
            "All 10 positions of fracta-repair together; the verdict asks that every run at \
             every position rebuilt the triangle. The speed is not judged: the paper's average \
             is a figure of its own runs, and the rows above give Kumiki's per position. {held}"
        )
        .as_str(),
    ));
    out
}

fn deadlock(r: &Results) -> Vec<Finding> {
    const EXP: &str = "fracta-deadlock";
    let off: [(&str, Value); 1] = [("I_th", json!(1_000_000_000))];
    let on: [(&str, Value); 1] = [("I_th", json!(10))];
    let still = r.values(EXP, &off, "moves");
    let stuck = !still.is_empty() && still.iter().all(|&m| m == 0.0);
    let moved = r.values(EXP, &on, "moves");
    let dissolved = !moved.is_empty() && moved.iter().all(|&m| m > 0.0);
    let done = r.values(EXP, &on, "completed");
    let s = r.stats(EXP, &on, "convergence_steps");
    vec![
        Finding {
            section: "§3.2.5, fig. 4".into(),
            claim: "A configuration whose movable units are all type o with neighbours {K, K} \
                    (difference 0) is in deadlock."
                .into(),
            kumiki: format!(
                "{} of {} runs made no move in 5000 steps without irritation",
                still.iter().filter(|&&m| m == 0.0).count(),
                still.len()
            ),
            runs: still.len(),
            verdict: Verdict::from(stuck),
            note: "fracta-deadlock (two triangles of six sharing a corner unit, goal the \
                   triangle with its spare) with I_th = 10^9, so that condition 5 never fires."
                .into(),
        },
        Finding {
            section: "§3.2.5".into(),
            claim: "Irritation (equations 4 and 5) dissolves the deadlock locally.".into(),
            kumiki: format!(
                "{} runs left the deadlock; {} reached the goal, in {} steps",
                ratio(&moved),
                ratio(&done),
                s.describe(1)
            ),
            runs: moved.len(),
            verdict: Verdict::from(dissolved),
            note: format!(
                "fracta-deadlock with I_th = 10: the o units' irritation fires and they roll; \
                 the verdict asks that every run leaves the deadlock. {}",
                failures(r, EXP, &on)
            ),
        },
    ]
}
