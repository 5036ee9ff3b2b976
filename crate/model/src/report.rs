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
    /// The runs show the claim as strongly as the text states it.
    Holds,
    /// The runs point the way the text says, but less strongly than it states: a small or
    /// non-significant effect where the text argues for a large one, or the behaviour in only
    /// some of the runs where the text says "always" or "most".
    Partial,
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
            Verdict::Partial => "partial",
            Verdict::Differs => "differs",
            Verdict::NotStated => "not stated",
        }
    }
}

/// How large an effect the text's words claim, for [`Ordering::judge`]: the threshold is on
/// Cohen's d (Cohen's conventions: 0.2 small, 0.5 medium, 0.8 large) and on the rank-biserial
/// correlation (0.1, 0.3, 0.5), and an effect must pass both.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Size {
    /// Any effect in the stated direction that is significant ("better", "fewer").
    Any,
    /// At least medium ("clearly", "much").
    Medium,
    /// At least large: the text argues for a large effect (a bottleneck removed, a structure
    /// that "cannot" do what the other does).
    Large,
}

impl Size {
    fn thresholds(self) -> (f64, f64) {
        match self {
            Size::Any => (0.0, 0.0),
            Size::Medium => (0.5, 0.3),
            Size::Large => (0.8, 0.5),
        }
    }

    fn words(self) -> &'static str {
        match self {
            Size::Any => "a significant effect",
            Size::Medium => "a significant effect of at least medium size (|d| ≥ 0.5, |r| ≥ 0.3)",
            Size::Large => "a significant, large effect (|d| ≥ 0.8, |r| ≥ 0.5)",
        }
    }
}

/// A claim that one condition's values lie below (or above) another's, judged by effect size and
/// significance (the two-sided Mann-Whitney U test at the 5 % level) rather than by the sign of a
/// difference alone.
#[derive(Clone, Debug)]
pub struct Ordering {
    /// The comparison, first condition against second.
    pub comparison: Option<crate::stats::Comparison>,
    /// Whether the text claims the first condition's values are the lower.
    pub first_lower: bool,
    pub size: Size,
}

/// The significance level of every verdict that compares two conditions.
pub const ALPHA: f64 = 0.05;

impl Ordering {
    /// The claim "`first` lies below `second`" (`first_lower`) or above it, of effect `size`.
    pub fn new(first: &[f64], second: &[f64], first_lower: bool, size: Size) -> Ordering {
        Ordering {
            comparison: crate::stats::Comparison::of(first, second),
            first_lower,
            size,
        }
    }

    /// Holds when the effect points the stated way, is significant and is at least the stated
    /// size; partial when it points the stated way but is not significant or smaller than stated;
    /// differs when it points the other way (or there is nothing to compare).
    pub fn verdict(&self) -> Verdict {
        let Some(c) = self.comparison else {
            return Verdict::Differs;
        };
        let sign = if self.first_lower { -1.0 } else { 1.0 };
        let (d, r) = (sign * c.cohens_d, sign * c.rank_biserial);
        let way = match d.is_nan() {
            true => r > 0.0,
            false => d > 0.0 && r > 0.0,
        };
        if !way {
            return Verdict::Differs;
        }
        let (dmin, rmin) = self.size.thresholds();
        let big = (d.is_nan() || d >= dmin) && r >= rmin;
        Verdict::from(c.p < ALPHA && big).or_partial()
    }

    /// "Cohen's d -1.20, rank-biserial -0.64, Mann-Whitney p = 0.004 (n = 10, 10): a significant,
    /// large effect", the words saying what was asked and whether it was met.
    pub fn describe(&self) -> String {
        let Some(c) = self.comparison else {
            return "nothing to compare".into();
        };
        let met = match self.verdict() {
            Verdict::Holds => format!("{} as claimed", self.size.words()),
            Verdict::Partial if c.p >= ALPHA => "the claimed direction, not significant".into(),
            Verdict::Partial => format!("the claimed direction, short of {}", self.size.words()),
            _ => "against the claimed direction".into(),
        };
        format!(
            "Cohen's d {}, rank-biserial {}, Mann-Whitney p = {} ({met})",
            fmt(c.cohens_d, 2),
            fmt(c.rank_biserial, 2),
            p_value(c.p),
        )
    }
}

impl Verdict {
    /// Partial where this is differs: for a claim already known to point the stated way.
    fn or_partial(self) -> Verdict {
        match self {
            Verdict::Differs => Verdict::Partial,
            v => v,
        }
    }

    /// The verdict on a claim that something happens in all runs ("always", "in all cases"):
    /// holds when it happens in every run, partial when in most (more than half), differs
    /// otherwise.
    pub fn of_all(happened: usize, runs: usize) -> Verdict {
        match happened {
            _ if runs == 0 => Verdict::Differs,
            h if h == runs => Verdict::Holds,
            h if 2 * h > runs => Verdict::Partial,
            _ => Verdict::Differs,
        }
    }

    /// The verdict on a claim that something happens in most runs: holds when it happens in more
    /// than half, partial when in some, differs when in none.
    pub fn of_most(happened: usize, runs: usize) -> Verdict {
        match happened {
            h if 2 * h > runs => Verdict::Holds,
            0 => Verdict::Differs,
            _ => Verdict::Partial,
        }
    }
}

/// A p value as the report writes it: three decimals, below 0.001 in scientific form.
pub fn p_value(p: f64) -> String {
    match p {
        p if p.is_nan() => "n/a".into(),
        p if p < 0.001 => format!("{p:.2e}"),
        p => format!("{p:.3}"),
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

#[cfg(test)]
mod tests {
    use super::*;

    fn spread(centre: f64) -> Vec<f64> {
        (0..10).map(|i| centre + i as f64).collect()
    }

    #[test]
    fn an_ordering_holds_only_when_large_and_significant_as_claimed() {
        // Disjoint samples, 20 apart with sd 3: d ≈ -6.6, r = -1, p ≈ 1e-5.
        let low = Ordering::new(&spread(0.0), &spread(20.0), true, Size::Large);
        assert_eq!(low.verdict(), Verdict::Holds, "{}", low.describe());
        // The same numbers claimed the other way round differ.
        let high = Ordering::new(&spread(0.0), &spread(20.0), false, Size::Any);
        assert_eq!(high.verdict(), Verdict::Differs);
        // One apart: the right direction, not significant at n = 10.
        let small = Ordering::new(&spread(0.0), &spread(1.0), true, Size::Any);
        assert_eq!(small.verdict(), Verdict::Partial);
        assert!(
            small.describe().contains("not significant"),
            "{}",
            small.describe()
        );
        // One apart at n = 100 (d ≈ -0.35, rank-biserial ≈ -0.19): significant, so it holds
        // for Any, but short of Medium.
        let many = |c: f64| (0..100).map(|i| c + (i % 10) as f64).collect::<Vec<_>>();
        let medium = Ordering::new(&many(0.0), &many(1.0), true, Size::Medium);
        let c = medium.comparison.unwrap();
        assert!(c.p < ALPHA && c.cohens_d > -0.5, "{c:?}");
        assert_eq!(medium.verdict(), Verdict::Partial);
        assert!(
            medium.describe().contains("short of"),
            "{}",
            medium.describe()
        );
        assert_eq!(
            Ordering::new(&many(0.0), &many(1.0), true, Size::Any).verdict(),
            Verdict::Holds
        );
        // Nothing to compare.
        assert_eq!(
            Ordering::new(&[], &[1.0], true, Size::Any).verdict(),
            Verdict::Differs
        );
    }

    #[test]
    fn all_and_most_are_counted_as_the_words_say() {
        assert_eq!(Verdict::of_all(10, 10), Verdict::Holds);
        assert_eq!(Verdict::of_all(9, 10), Verdict::Partial);
        assert_eq!(Verdict::of_all(5, 10), Verdict::Differs);
        assert_eq!(Verdict::of_all(0, 0), Verdict::Differs);
        assert_eq!(Verdict::of_most(6, 10), Verdict::Holds);
        assert_eq!(Verdict::of_most(5, 10), Verdict::Partial);
        assert_eq!(Verdict::of_most(15, 45), Verdict::Partial);
        assert_eq!(Verdict::of_most(0, 10), Verdict::Differs);
    }

    #[test]
    fn p_values_are_written_in_one_way() {
        assert_eq!(p_value(0.04567), "0.046");
        assert_eq!(p_value(8.09e-34), "8.09e-34");
        assert_eq!(p_value(f64::NAN), "n/a");
    }
}
