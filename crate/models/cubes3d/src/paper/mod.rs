//! The claims of Yoshida et al. (and of section 5.2 of the self-repair paper) that the
//! reproduction report checks, read from the built-in experiments: the selection rules of
//! figures 8 and 9 (`rules`), the motion toward the light of section 6 (`light`) and the sizes of
//! section 7 (`scale`).

use serde_json::{json, Value};

use kumiki_model::report::{self, Finding, Ordering, Paper, Results, Stats, Verdict};
use kumiki_model::row::Row;

mod light;
mod rules;
mod scale;

pub const PAPER: Paper = Paper {
    model: "cubes3d",
    citation: "E. Yoshida, S. Murata, H. Kurokawa, K. Tomita and S. Kokaji, \"A Distributed Reconfiguration Method for 3-D Homogeneous Structure\"; and section 5.2 of E. Yoshida, S. Murata, K. Tomita, H. Kurokawa and S. Kokaji, \"Experiment of Self-repairing Modular Machine\"",
    experiments: &[
        "cubes-fig8",
        "cubes-fig9",
        "cubes-fig14",
        "cubes-light-readings",
        "cubes-scale",
    ],
    findings,
};

/// A traced metric of a run at `step`; a run that ended earlier keeps its last value (a
/// completed run keeps D = 0).
fn at(row: &Row, metric: &str, step: u64) -> Option<f64> {
    let trace = row.trace.as_ref()?;
    let values = trace.values.get(metric)?.as_array()?;
    let k = trace.step.iter().rposition(|&s| s <= step)?;
    values.get(k)?.as_f64()
}

/// A traced metric of each selected run at `step`.
fn traced_values(
    results: &Results,
    exp: &str,
    filter: &[(&str, Value)],
    metric: &str,
    step: u64,
) -> Vec<f64> {
    results
        .select(exp, filter)
        .into_iter()
        .filter_map(|r| at(r, metric, step))
        .collect()
}

fn traced(
    results: &Results,
    exp: &str,
    filter: &[(&str, Value)],
    metric: &str,
    step: u64,
) -> Stats {
    Stats::of(&traced_values(results, exp, filter, metric, step))
}

/// The figures of a comparison without its verdict's words: "Cohen's d 0.41, rank-biserial
/// 0.18, Mann-Whitney p = 0.026", for a test beside a claim rather than the claim itself.
fn figures(o: &Ordering) -> String {
    match o.comparison {
        None => "nothing to compare".into(),
        Some(c) => format!(
            "Cohen's d {}, rank-biserial {}, Mann-Whitney p = {}",
            report::fmt(c.cohens_d, 2),
            report::fmt(c.rank_biserial, 2),
            report::p_value(c.p)
        ),
    }
}

/// The weakest of several verdicts on the parts of one claim: differs when one part differs,
/// partial when one is partial, holds when all hold.
fn weakest(verdicts: &[Verdict]) -> Verdict {
    let rank = |v: &Verdict| match v {
        Verdict::Differs => 0,
        Verdict::Partial => 1,
        Verdict::Holds => 2,
        Verdict::NotStated => 3,
    };
    verdicts
        .iter()
        .copied()
        .min_by_key(rank)
        .unwrap_or(Verdict::Differs)
}

fn findings(results: &Results) -> Vec<Finding> {
    let mut out = rules::rules(results, "cubes-fig8", "fig. 8 (8 units)", "zigzag", 1000);
    out.extend(rules::rules(
        results,
        "cubes-fig9",
        "fig. 9 (12 units)",
        "ladder",
        2000,
    ));
    let box_steps = results.stats("cubes-fig9", &[("selection", json!("mrf"))], "reached");
    out.push(Finding {
        section: "Self-repair paper §5.2, fig. 10".into(),
        claim: "Twelve units build a box from a ladder with the goal C31{C31, C31, C41} C41{C31, C31, C41, C41} (equation 6), movable types C1, C21 and C31; the paper reports the steps of one run.".into(),
        kumiki: format!("steps to complete: {}", box_steps.describe(0)),
        runs: box_steps.n,
        verdict: Verdict::NotStated,
        note: "The runs of cubes-fig9 with the MRF rule that reached the goal (the first step at it); the preset's goal and movable types are equation 6's (a test checks it). The paper's figure is one run it picked.".into(),
    });
    out.extend(light::findings(results));
    out.extend(scale::findings(results));
    out.push(Finding::new(
        "§7, figs. 15–17",
        "Larger structures are described hierarchically: basic structures fix the geometry between nodes, each node holds a sub-structure described recursively, and assembly proceeds from the top level down.",
        "not built".into(),
        0,
        Verdict::NotStated,
        "The text gives the idea and defers the method (\"the details of this method are to be reported in future work\"); figures 15 to 17 are not in the text. Missing: the primitive types of figure 15 and the node geometry each fixes, how a sub-structure attaches to a node and how that is written, how a unit learns its node and level, what a unit's difference is against a recursive description, and when a level counts as assembled so the next begins. See crate/models/cubes3d/README.md, interpretation 21.",
    ));
    out
}
