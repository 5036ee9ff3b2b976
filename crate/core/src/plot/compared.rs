//! Conditions compared in a summary: every pair (first minus second), with three or more the
//! Kruskal-Wallis test and Holm's correction, and the summary records `kumiki sweep --summary`
//! prints and the Python package returns.

use super::figure::{ComparisonRow, Figure, FigureKind, OmnibusRow, DIRECTION};
use super::labels::condition_words;
use super::stats::{holm, Comparison, KruskalWallis};
use super::values::num_at;
use crate::experiment::Row;

pub(super) type Condition<'a> = (Vec<String>, Vec<&'a Row>);

/// Two or more conditions compared on each value: every pair (first minus second, in the
/// conditions' order), and with three or more the Kruskal-Wallis test and Holm's correction of
/// the pairs' p.
pub(super) fn compare_conditions(
    f: &mut Figure,
    group: &[String],
    values: &[String],
    conditions: &[Condition],
) {
    if conditions.len() < 2 {
        return;
    }
    let names: Vec<String> = conditions
        .iter()
        .map(|(k, _)| condition_words(group, k))
        .collect();
    for v in values {
        let xs: Vec<Vec<f64>> = conditions
            .iter()
            .map(|(_, rows)| rows.iter().map(|r| num_at(r, v)).collect())
            .collect();
        let mut pairs = Vec::new();
        for i in 0..xs.len() {
            for j in i + 1..xs.len() {
                if let Some(c) = Comparison::of(&xs[i], &xs[j]) {
                    pairs.push(ComparisonRow {
                        value: v.clone(),
                        conditions: [names[i].clone(), names[j].clone()],
                        comparison: c,
                        p_holm: None,
                    });
                }
            }
        }
        if conditions.len() > 2 {
            let adjusted = holm(&pairs.iter().map(|c| c.comparison.p).collect::<Vec<_>>());
            for (c, p) in pairs.iter_mut().zip(adjusted) {
                c.p_holm = Some(p);
            }
            if let Some(test) = KruskalWallis::of(&xs) {
                f.omnibus.push(OmnibusRow {
                    value: v.clone(),
                    conditions: names.clone(),
                    test,
                });
            }
        }
        f.comparisons.extend(pairs);
    }
    if !f.comparisons.is_empty() {
        f.direction = DIRECTION.to_string();
    }
}

/// The summaries of `figures` as `kumiki sweep --summary` prints them, one JSON object a line:
/// each condition's statistics, then each Kruskal-Wallis test, then each pair compared, every
/// comparison line saying its direction ("first minus second"). The Python package gives the same
/// records.
pub fn summary_lines(figures: &[Figure]) -> Vec<serde_json::Value> {
    use serde_json::json;
    let mut out = Vec::new();
    for f in figures.iter().filter(|f| f.kind == FigureKind::Summary) {
        for r in &f.table {
            out.push(json!({"figure": f.title, "condition": r.condition, "runs": r.runs, "completed": r.completed, "value": r.value, "unit": r.unit, "stats": r.stats}));
        }
        for o in &f.omnibus {
            out.push(json!({"figure": f.title, "value": o.value, "conditions": o.conditions, "kruskal_wallis": o.test}));
        }
        for c in &f.comparisons {
            out.push(json!({"figure": f.title, "value": c.value, "conditions": c.conditions, "direction": "first minus second", "comparison": c.comparison, "p_holm": c.p_holm}));
        }
        if let Some(p) = f.partial {
            out.push(json!({"figure": f.title, "partial": p}));
        }
    }
    out
}
