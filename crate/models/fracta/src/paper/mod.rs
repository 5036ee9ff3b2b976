//! The claims of Yoshida et al.'s section 4 (self-assembly and self-repair of the 10-unit
//! triangle), section 3.3 (the spares) and section 3.2.5 (deadlock and irritation) beside
//! Kumiki's figures, for the reproduction report. Every verdict is computed from the experiment
//! rows and from runs of the model's own rules ([`search`]), for both readings of where the
//! spare sits ([`Spare`]; the report's rows are the default's, the middle of an edge).
//!
//! - `assembly`: the self-assembly from two lines, how it starts, whether it is trapped, and
//!   whether the finished shape stays;
//! - `spares`: the spare's place and three spares;
//! - `repair`: the self-repair at each position and over the ten;
//! - `deadlock`: figure 4's deadlock and its dissolution.

use serde_json::{json, Value};

use super::search::{self, Spare};
use kumiki_model::report::{fmt, value, Finding, Paper, Results, Stats, Verdict};

mod assembly;
mod deadlock;
mod repair;
mod spares;

pub const PAPER: Paper = Paper {
    model: "fracta",
    citation: "E. Yoshida, S. Murata, K. Tomita, H. Kurokawa and S. Kokaji, \
               \"Experiment of Self-repairing Modular Machine\"",
    experiments: &[
        "fracta-assembly",
        "fracta-rings",
        "fracta-start",
        "fracta-spares",
        "fracta-repair",
        "fracta-deadlock",
    ],
    findings,
};

fn findings(r: &Results) -> Vec<Finding> {
    let mut out = assembly::findings(r);
    out.extend(spares::findings(r));
    out.extend(repair::findings(r));
    out.extend(deadlock::findings(r));
    out.push(Finding::new(
        "§5.2, fig. 10",
        "Twelve 3-D units build a box from a ladder by the difference-based algorithm with MRF \
         stochastic relaxation; the paper gives the number of steps.",
        "see cubes3d".into(),
        0,
        Verdict::NotStated,
        "The 3-D box is the cubes3d model's preset and experiment; its figures are in the \
         cubes3d section of this report.",
    ));
    out
}

/// The filter of one scenario's rows.
fn scenario(name: &str) -> [(&'static str, Value); 1] {
    [("scenario", json!(name))]
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

/// How many of the values are positive (runs completed, runs that moved).
fn count(values: &[f64]) -> usize {
    values.iter().filter(|&&v| v > 0.0).count()
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
    let moving: Vec<f64> = failed
        .iter()
        .filter(|row| !value(row, "holes").is_some_and(|h| h > 0.0))
        .filter_map(|row| value(row, "mean_difference"))
        .collect();
    let rest = match moving.first() {
        None => String::new(),
        Some(&d) if moving.iter().all(|&v| v == d) => format!(
            ", and {} were still moving at the step cap, every one of them at a mean \
             difference of {}",
            moving.len(),
            fmt(d, 2)
        ),
        Some(_) => format!(", and {} were still moving at the step cap", moving.len()),
    };
    format!(
        "Of the {} runs that did not reach the goal, {holed} ended with a ring of units round \
         empty cells, which no rule can open{rest}.",
        failed.len()
    )
}

/// The value below which a fraction `q` of the sample lies (linear interpolation).
fn percentile(values: &[f64], q: f64) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    let mut sorted = values.to_vec();
    kumiki_model::sort::sort_by(&mut sorted, f64::total_cmp);
    kumiki_model::report::quantile(&sorted, q)
}

/// Where traced runs spend their steps, in words.
fn trace_text(t: &search::Trace, what: &str) -> String {
    format!(
        "the {} runs that reached {what} took {} steps: {} began with a unit able to lower the \
         summed difference and none of those units activated, {} in a local minimum where no \
         motion lowers it (only a unit whose irritation fired can move then); in {} two or more \
         units rolled at once and the summed difference rose (each roll is chosen against the \
         structure as it was); irritation made {} rolls, which take any change.",
        t.runs, t.steps, t.held, t.stuck, t.together_worse, t.irritated_rolls
    )
}
