//! What the paper claims and what Kumiki measures. The paper reports behaviours, not numbers;
//! each finding below reads the built-in experiments' rows and decides its verdict from them,
//! as strongly as the text states the claim: "in all cases" in every run, "most" in more than
//! half, and an ordering of two conditions by its effect size and significance
//! ([`Ordering`]).
//!
//! - `crawl`: the crawl of section 3.3 and the initial forms, methods and leaders of section
//!   IV;
//! - `bridge`: the bridge and its load adaptation (section 3.4) and the stress model.

use serde_json::{json, Value};

use kumiki_model::report::{Finding, Ordering, Paper, Results, Size, Stats, Verdict};
use kumiki_model::row::Row;

mod bridge;
mod crawl;

pub const PAPER: Paper = Paper {
    model: "chobie",
    citation: "Y. Suzuki, N. Inou, H. Kimura and M. Koseki, \"Reconfigurable group robots adaptively transforming a mechanical structure – Crawl motion and adaptive transformation with new algorithms\"",
    experiments: &[
        "chobie-crawl",
        "chobie-forms",
        "chobie-leaders",
        "chobie-bridge",
        "chobie-load",
        "chobie-mechanics",
    ],
    findings,
};

fn findings(r: &Results) -> Vec<Finding> {
    let mut out = Vec::new();
    crawl::crawl(r, &mut out);
    crawl::forms(r, &mut out);
    crawl::leaders(r, &mut out);
    bridge::bridge(r, &mut out);
    out
}

/// A traced metric of a row, one value per cycle.
fn traced(row: &Row, metric: &str) -> Vec<f64> {
    row.trace
        .as_ref()
        .and_then(|t| t.values.get(metric))
        .and_then(Value::as_array)
        .map(|a| a.iter().filter_map(Value::as_f64).collect())
        .unwrap_or_default()
}

/// A cumulative traced metric as the amount added in each traced cycle (the first sample, at
/// the run's start, has none before it).
fn per_cycle_of(row: &Row, metric: &str) -> Vec<f64> {
    traced(row, metric)
        .windows(2)
        .map(|w| w[1] - w[0])
        .collect()
}
