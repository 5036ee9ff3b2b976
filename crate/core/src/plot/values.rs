//! A row's values as a figure reads them: by path, as numbers and in words, grouped, and a traced
//! metric sampled at given steps.

use serde_json::Value;

use crate::experiment::Row;

/// A value of a row by path: `steps`, `params.robots`, `metrics.total_steps`.
pub fn value_at<'a>(row: &'a Row, path: &str) -> Option<std::borrow::Cow<'a, Value>> {
    use std::borrow::Cow;
    if let Some(k) = path.strip_prefix("params.") {
        return row.params.get(k).map(Cow::Borrowed);
    }
    if let Some(k) = path.strip_prefix("metrics.") {
        return row.metrics.get(k).map(Cow::Borrowed);
    }
    Some(Cow::Owned(match path {
        "scenario" => row.scenario.clone().into(),
        "seed" => row.seed.into(),
        "completed" => row.completed.into(),
        "steps" => row.steps.into(),
        "hash" => row.hash.clone().into(),
        _ => return None,
    }))
}

/// The number a value plots as: a flag as 0 or 1, anything else not a number as NaN.
pub fn number(v: Option<&Value>) -> f64 {
    match v {
        Some(Value::Number(n)) => n.as_f64().unwrap_or(f64::NAN),
        Some(Value::Bool(b)) => f64::from(u8::from(*b)),
        _ => f64::NAN,
    }
}

pub(super) fn num_at(row: &Row, path: &str) -> f64 {
    number(value_at(row, path).as_deref())
}

/// A value in words: a flag as on/off, text as itself, a number as written.
pub fn words(v: Option<&Value>) -> String {
    match v {
        None | Some(Value::Null) => "none".into(),
        Some(Value::Bool(true)) => "on".into(),
        Some(Value::Bool(false)) => "off".into(),
        Some(Value::String(s)) => s.clone(),
        Some(other) => other.to_string(),
    }
}

pub(super) fn group_by<'a>(rows: &[&'a Row], path: Option<&str>) -> Vec<(String, Vec<&'a Row>)> {
    let Some(path) = path else {
        return vec![(String::new(), rows.to_vec())];
    };
    let mut order: Vec<(String, Vec<&Row>)> = Vec::new();
    for r in rows {
        let k = words(value_at(r, path).as_deref());
        match order.iter_mut().find(|(key, _)| *key == k) {
            Some((_, list)) => list.push(r),
            None => order.push((k, vec![r])),
        }
    }
    order
}

/// A run's traced value at each of `steps`: its last sample at or before the step; after its
/// last sample, that sample with `carry`, else NaN.
pub(super) fn sampled(row: &Row, metric: &str, steps: &[u64], carry: bool) -> Vec<f64> {
    let t = row.trace.as_ref().expect("traced rows only");
    let values = t.values.get(metric).and_then(Value::as_array);
    let mut out = Vec::with_capacity(steps.len());
    let mut j = 0;
    for &step in steps {
        while j + 1 < t.step.len() && t.step[j + 1] <= step {
            j += 1;
        }
        let beyond = t.step.last().is_some_and(|&l| step > l);
        let v = match (t.step.get(j), values) {
            (Some(&at), Some(vs)) if at <= step && (carry || !beyond) => number(vs.get(j)),
            _ => f64::NAN,
        };
        out.push(v);
    }
    out
}
