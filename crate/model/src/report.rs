//! The reproduction report's vocabulary, as a model's paper uses it: the [`Paper`] a model names,
//! the [`Finding`]s its claims become, read from the experiments' rows ([`Results`]) with
//! [`Stats`]. The core runs the experiments and writes the report.

use std::collections::{BTreeMap, BTreeSet};

use serde::Serialize;
use serde_json::Value;

use crate::row::Row;

/// A model's paper and the claims the report checks.
pub struct Paper {
    pub model: &'static str,
    pub citation: &'static str,
    /// Built-in experiments (`experiments/<name>.json` of the model's crate) whose
    /// rows the findings read.
    pub experiments: &'static [&'static str],
    pub findings: fn(&Results) -> Vec<Finding>,
}

/// Whether the paper's claim holds in Kumiki, where the paper states a comparison.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    Holds,
    Differs,
    /// The text states a figure or a behaviour but no comparison to judge.
    NotStated,
}

impl Verdict {
    /// Holds when `ok`, differs otherwise.
    pub fn from(ok: bool) -> Verdict {
        if ok {
            Verdict::Holds
        } else {
            Verdict::Differs
        }
    }

    pub fn label(self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::Differs => "differs",
            Verdict::NotStated => "not stated",
        }
    }
}

/// One claim of the paper beside Kumiki's figure.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Finding {
    /// Where the paper makes the claim: "§5.2, fig. 23".
    pub section: String,
    /// The claim, quoted or closely paraphrased.
    pub claim: String,
    /// Kumiki's figure with its spread.
    pub kumiki: String,
    /// How many runs the figure rests on.
    pub runs: usize,
    pub verdict: Verdict,
    /// How it was measured, and for a difference the evidence of why.
    pub note: String,
}

impl Finding {
    pub fn new(
        section: &str,
        claim: &str,
        kumiki: String,
        runs: usize,
        verdict: Verdict,
        note: &str,
    ) -> Finding {
        Finding {
            section: section.into(),
            claim: claim.into(),
            kumiki,
            runs,
            verdict,
            note: note.into(),
        }
    }
}

/// The rows of every experiment a paper reads, by experiment name, each in job order.
#[derive(Clone, Debug, Default)]
pub struct Results {
    rows: BTreeMap<String, Vec<Row>>,
    /// Experiments known to the report but not run this time: they read as no rows (a claim
    /// recomputed from its own experiments only).
    withheld: BTreeSet<String>,
}

impl Results {
    pub fn new() -> Results {
        Results::default()
    }

    /// Results for `paper` where none of its experiments has run yet: each reads as no rows
    /// until its rows are inserted.
    pub fn for_paper(paper: &Paper) -> Results {
        Results {
            rows: BTreeMap::new(),
            withheld: paper.experiments.iter().map(|e| e.to_string()).collect(),
        }
    }

    pub fn insert(&mut self, experiment: &str, rows: Vec<Row>) {
        self.withheld.remove(experiment);
        self.rows.insert(experiment.to_string(), rows);
    }

    /// These results with the rows of `experiment` withheld.
    pub fn without(&self, experiment: &str) -> Results {
        let mut out = self.clone();
        out.rows.remove(experiment);
        out.withheld.insert(experiment.to_string());
        out
    }

    /// These results with only the rows of `keep`; every other experiment is withheld.
    pub fn only(&self, keep: &[String]) -> Results {
        let mut out = Results::new();
        for (name, rows) in &self.rows {
            match keep.contains(name) {
                true => out.insert(name, rows.clone()),
                false => {
                    out.withheld.insert(name.clone());
                }
            }
        }
        out.withheld.extend(self.withheld.iter().cloned());
        out
    }

    /// The rows of an experiment (none when it is withheld). Panics when the paper did not list
    /// it: that is a programming error in the paper's findings, not bad input.
    pub fn rows(&self, experiment: &str) -> &[Row] {
        match self.rows.get(experiment) {
            Some(rows) => rows,
            None if self.withheld.contains(experiment) => &[],
            None => panic!("experiment '{experiment}' was not run for this report"),
        }
    }

    /// The rows whose scenario name and grid parameters match every `(key, value)` of the
    /// filter; `key` is `"scenario"` or a grid path such as `"robots"`.
    pub fn select(&self, experiment: &str, filter: &[(&str, Value)]) -> Vec<&Row> {
        self.rows(experiment)
            .iter()
            .filter(|row| filter.iter().all(|(k, v)| matches(row, k, v)))
            .collect()
    }

    /// One number per selected row: `"steps"`, `"completed"` (1 or 0), or a metric's name. A row
    /// without the metric, or with a value that is not a number, gives no number.
    pub fn values(&self, experiment: &str, filter: &[(&str, Value)], metric: &str) -> Vec<f64> {
        self.select(experiment, filter)
            .into_iter()
            .filter_map(|row| value(row, metric))
            .collect()
    }

    /// [`Stats`] of [`Results::values`].
    pub fn stats(&self, experiment: &str, filter: &[(&str, Value)], metric: &str) -> Stats {
        Stats::of(&self.values(experiment, filter, metric))
    }
}

fn matches(row: &Row, key: &str, want: &Value) -> bool {
    if key == "scenario" {
        return want.as_str() == Some(row.scenario.as_str());
    }
    match (row.params.get(key), want) {
        (Some(Value::Number(a)), Value::Number(b)) => a.as_f64() == b.as_f64(),
        (Some(got), want) => got == want,
        (None, _) => false,
    }
}

/// A row's value of `"steps"`, `"completed"` or a metric.
pub fn value(row: &Row, metric: &str) -> Option<f64> {
    match metric {
        "steps" => Some(row.steps as f64),
        "completed" => Some(if row.completed { 1.0 } else { 0.0 }),
        name => match row.metrics.get(name)? {
            Value::Number(n) => n.as_f64(),
            Value::Bool(b) => Some(if *b { 1.0 } else { 0.0 }),
            _ => None,
        },
    }
}

/// Summary statistics of a sample. Quartiles are interpolated between order statistics (the
/// "linear" rule of R type 7 and NumPy's default).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Stats {
    pub n: usize,
    pub mean: f64,
    /// Sample standard deviation (n − 1); 0 for fewer than two values.
    pub sd: f64,
    pub median: f64,
    pub q1: f64,
    pub q3: f64,
    pub min: f64,
    pub max: f64,
}

impl Stats {
    /// NaN statistics for an empty sample, so a missing measurement shows rather than hides.
    pub fn of(values: &[f64]) -> Stats {
        let n = values.len();
        if n == 0 {
            return Stats {
                n,
                mean: f64::NAN,
                sd: f64::NAN,
                median: f64::NAN,
                q1: f64::NAN,
                q3: f64::NAN,
                min: f64::NAN,
                max: f64::NAN,
            };
        }
        let mut sorted = values.to_vec();
        crate::sort::sort_by(&mut sorted, f64::total_cmp);
        let mean = sorted.iter().sum::<f64>() / n as f64;
        let sd = if n > 1 {
            (sorted.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n - 1) as f64).sqrt()
        } else {
            0.0
        };
        Stats {
            n,
            mean,
            sd,
            median: quantile(&sorted, 0.5),
            q1: quantile(&sorted, 0.25),
            q3: quantile(&sorted, 0.75),
            min: sorted[0],
            max: sorted[n - 1],
        }
    }

    /// "mean 1187 (sd 95; median 1170, IQR 1100–1250, range 1010–1400; n = 10)", with `digits`
    /// decimals.
    pub fn describe(&self, digits: usize) -> String {
        if self.n == 0 {
            return "no runs".into();
        }
        let f = |v: f64| fmt(v, digits);
        if self.n == 1 {
            return format!("{} (n = 1)", f(self.mean));
        }
        format!(
            "mean {} (sd {}; median {}, IQR {}–{}, range {}–{}; n = {})",
            f(self.mean),
            f(self.sd),
            f(self.median),
            f(self.q1),
            f(self.q3),
            f(self.min),
            f(self.max),
            self.n
        )
    }

    /// "1187 ± 95" (mean ± sd), for compact comparisons.
    pub fn short(&self, digits: usize) -> String {
        format!("{} ± {}", fmt(self.mean, digits), fmt(self.sd, digits))
    }
}

/// Linear interpolation between order statistics of sorted values (Hyndman and Fan's type 7, the
/// default of R and NumPy).
pub fn quantile(sorted: &[f64], q: f64) -> f64 {
    let pos = q * (sorted.len() - 1) as f64;
    let lo = pos.floor() as usize;
    let hi = pos.ceil() as usize;
    sorted[lo] + (sorted[hi] - sorted[lo]) * (pos - lo as f64)
}

/// A number with a fixed count of decimals; `-0` is written `0`.
pub fn fmt(v: f64, digits: usize) -> String {
    if v.is_nan() {
        return "n/a".into();
    }
    let s = format!("{v:.digits$}");
    match s
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        true => s.trim_start_matches('-').to_string(),
        false => s,
    }
}
