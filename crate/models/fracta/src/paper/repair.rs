//! Section 4's self-repair: a fault at each of the ten units other than the centre, one row a
//! position, and the ten together as the paper ran them, one experiment a position.

use super::*;

const EXP: &str = "fracta-repair";

/// The units a fault is given to (all but the centre `s`, unit 5 in both presets).
const UNITS: [u64; 10] = [0, 1, 2, 3, 4, 6, 7, 8, 9, 10];

/// The place each unit holds in the triangle with its spare, by reading.
fn role(spare: Spare, unit: u64) -> &'static str {
    match (spare, unit) {
        (Spare::Edge, 0) => "the apex",
        (Spare::Edge, 1) => "the edge unit beside the apex, away from the spare",
        (Spare::Edge, 2) => "the edge unit above the spare",
        (Spare::Edge, 3) => "the spare",
        (Spare::Edge, 4) => "the edge unit below unit 1, away from the spare",
        (Spare::Edge, 6) => "the edge unit below the spare",
        (Spare::Edge, 7) => "the corner opposite the spare's edge",
        (Spare::Edge, 8 | 9) => "a bottom edge unit",
        (Spare::Edge, 10) => "the corner below the spare",
        (Spare::Corner, 0) => "the spare",
        (Spare::Corner, 1) => "the apex, beside the spare",
        (Spare::Corner, 2) => "the edge unit the spare leans on",
        (Spare::Corner, 3) => "the edge unit beside the apex, away from the spare",
        (Spare::Corner, 4) => "the edge unit at the left of the third row",
        (Spare::Corner, 6) => "the edge unit at the right of the third row",
        (Spare::Corner, 7) => "the bottom-left corner",
        (Spare::Corner, 8 | 9) => "a bottom edge unit",
        (Spare::Corner, 10) => "the bottom-right corner",
        _ => "the centre",
    }
}

/// The depth the breadth-first search of the fewest repair motions goes to.
const SEARCH_LIMIT: usize = 6;

/// Steps after a cut-off within which a traced repair must finish: the cap of `fracta-repair`.
const TRACE_LIMIT: u64 = 5000;

/// The seeds `fracta-repair` runs for each position, which the traces follow too.
const SEEDS: u64 = 100;

/// Steps after a cut-off within which [`begins`] looks for the first motion.
const FIRST_MOTION_LIMIT: u64 = 200;

/// The filter of one reading's runs at one position.
fn at(spare: Spare, unit: u64) -> [(&'static str, Value); 2] {
    [
        ("scenario", json!(spare.repair())),
        ("disturbances.0.unit", json!(unit)),
    ]
}

/// How the repair of a fault on `unit` begins, in words.
fn begins(spare: Spare, unit: u64) -> String {
    if search::fewest_repair_motions(spare, unit, 0) == Some(0) {
        return "The cut-off leaves the triangle: no unit needs to move.".into();
    }
    let Some(first) = search::first_motion_after_fault(spare, unit, FIRST_MOTION_LIMIT) else {
        return format!("No unit moves within {FIRST_MOTION_LIMIT} steps of the cut-off.");
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
    format!(
        "Right after the cut-off {who} that lowers the summed difference{activated}; the first \
         motion comes {when}{how}."
    )
}

pub(super) fn findings(r: &Results) -> Vec<Finding> {
    let spare = Spare::Edge;
    let traces: Vec<Option<search::Trace>> = UNITS
        .iter()
        .map(|&unit| search::trace_repairs(spare, unit, 1..=SEEDS, TRACE_LIMIT))
        .collect();
    let fewest: Vec<Option<usize>> = UNITS
        .iter()
        .map(|&unit| search::fewest_repair_motions(spare, unit, SEARCH_LIMIT))
        .collect();
    let mut out: Vec<Finding> = UNITS
        .iter()
        .zip(&traces)
        .zip(&fewest)
        .map(|((&unit, trace), &fewest)| position(r, spare, unit, trace, fewest))
        .collect();
    out.push(together(r, &traces, &fewest));
    out
}

fn position(
    r: &Results,
    spare: Spare,
    unit: u64,
    trace: &Option<search::Trace>,
    fewest: Option<usize>,
) -> Finding {
    let filter = at(spare, unit);
    let done = r.values(EXP, &filter, "completed");
    let s = r.stats(EXP, &filter, "repair_steps");
    let moves = r.stats(EXP, &filter, "moves");
    let traced = match trace {
        Some(t) => format!(
            "Traced step by step (the same seeds), {}",
            trace_text(t, "the triangle")
        ),
        None => "The repair could not be traced (preset missing).".into(),
    };
    Finding::new(
        "§4, fig. 6",
        &format!(
            "A fault cut into unit {unit} ({}) of the triangle with its spare is repaired: the \
             other 10 units rebuild the triangle.",
            role(spare, unit)
        ),
        format!(
            "{} repaired; repair {} steps; mean {} motions, at least {} needed",
            ratio(&done),
            s.describe(1),
            fmt(moves.mean, 1),
            fewest.map_or(format!("more than {SEARCH_LIMIT}"), |n| n.to_string())
        ),
        done.len(),
        Verdict::of_most(count(&done), done.len()),
        &format!(
            "fracta-repair (the spare in the middle of an edge): the fault at step 10, 100 \
             seeds, capped at 5000 steps; repair time from the fault to the triangle (its \
             detection and cut-off take the first step), after which the units measure \
             themselves against the first priority, the triangle (section 3.3). The paper ran \
             one experiment at this position, so the verdict asks whether one run is more \
             likely to repair it than not (most of Kumiki's runs), and the count says how \
             often. The fewest motions are a breadth-first search over the model's own \
             motions, one unit at a time, from the 10 units the cut-off leaves. {} {traced} {}",
            begins(spare, unit),
            failures(r, EXP, &filter)
        ),
    )
}

/// The paper's experiment: one run at each of the ten positions. Kumiki's runs at seed k, one
/// a position, make the k-th such experiment; each gives whether all ten repaired and their
/// mean repair time.
struct Experiments {
    /// Experiments in which all ten runs repaired.
    all: usize,
    /// Experiments made (the seeds every position has).
    made: usize,
    /// The mean repair steps of each experiment in which all ten repaired.
    means: Vec<f64>,
}

fn one_run_per_position(r: &Results, spare: Spare) -> Experiments {
    let rows: Vec<Vec<_>> = UNITS
        .iter()
        .map(|&unit| r.select(EXP, &at(spare, unit)))
        .collect();
    let seeds: Vec<u64> = rows
        .first()
        .map(|p| p.iter().map(|row| row.seed).collect())
        .unwrap_or_default();
    let mut out = Experiments {
        all: 0,
        made: 0,
        means: Vec::new(),
    };
    for seed in seeds {
        let runs: Vec<_> = rows
            .iter()
            .filter_map(|p| p.iter().find(|row| row.seed == seed))
            .collect();
        if runs.len() < UNITS.len() {
            continue;
        }
        out.made += 1;
        if runs.iter().all(|row| row.completed) {
            out.all += 1;
            let steps: Vec<f64> = runs
                .iter()
                .filter_map(|row| value(row, "repair_steps"))
                .collect();
            out.means
                .push(steps.iter().sum::<f64>() / steps.len().max(1) as f64);
        }
    }
    out
}

fn together(r: &Results, traces: &[Option<search::Trace>], fewest: &[Option<usize>]) -> Finding {
    let [edge, corner] = Spare::BOTH.map(|s| one_run_per_position(r, s));
    let line = |e: &Experiments| {
        format!(
            "{} of {} one-run-per-position experiments repaired all 10; their mean repair time {} \
             steps",
            e.all,
            e.made,
            Stats::of(&e.means).describe(1)
        )
    };
    let filter = scenario(Spare::Edge.repair());
    let done = r.values(EXP, &filter, "completed");
    let s = r.stats(EXP, &filter, "repair_steps");
    let needed: Vec<f64> = fewest.iter().flatten().map(|&n| n as f64).collect();
    let fastest: Vec<f64> = UNITS
        .iter()
        .map(|&unit| r.stats(EXP, &at(Spare::Edge, unit), "repair_steps").min)
        .collect();
    let total = search::Trace::total(traces.iter().flatten());
    Finding::new(
        "§4",
        "The self-repair succeeds with the fault given to each of the 10 units other than the \
         centre s unit, one experiment a position; the paper reports the success and the \
         average self-repair time.",
        format!(
            "{}; beside a corner, {}. Over all 1000 runs (middle of an edge): {} repaired, repair \
             {} steps",
            line(&edge),
            line(&corner),
            ratio(&done),
            s.describe(1)
        ),
        done.len(),
        Verdict::of_most(edge.all, edge.made),
        &format!(
            "Like with like: the paper gave the fault to each of the 10 units once, so its \
             success is a statement about ten runs and its average a mean over ten. Kumiki's \
             runs with seed k at the ten positions of fracta-repair make the k-th such \
             experiment (100 in all); the verdict asks whether most of them repaired all ten, \
             as the paper's one did, and the spread of their means is what one experiment's \
             average could have been. The speed is not judged: the paper's average is a figure \
             of its own runs. The fewest motions that repair the ten positions average {} (a \
             breadth-first search); the fastest run at each position takes {} steps. Traced \
             step by step over all positions, {}",
            if needed.len() == UNITS.len() {
                fmt(needed.iter().sum::<f64>() / needed.len() as f64, 1)
            } else {
                "n/a".into()
            },
            fastest
                .iter()
                .map(|&v| fmt(v, 0))
                .collect::<Vec<_>>()
                .join(", "),
            trace_text(&total, "the triangle")
        ),
    )
}
