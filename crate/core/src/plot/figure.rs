//! What a plot draws, computed from the rows: panels of series of points (the statistic, its
//! spread and n at each x), axis labels with units, legends in words, and the statistic and
//! spread named in words from the spec (the rows' values are read by `values.rs`, the words
//! come from `labels.rs`). The SVG ([`super::svg`]) draws exactly this, and the tests check that
//! each point is the statistic the figure names.

use std::collections::BTreeMap;

use schemars::JsonSchema;
use serde::Serialize;

use super::compared;
pub use super::compared::summary_lines;
use super::labels::{axis_label, facet_title, name_of, spread_words, statistic_words, unit_of};
use super::stats::{Comparison, KruskalWallis, Stats};
use super::values::{group_by, num_at, sampled, value_at, words};
use super::{statistic_of, Carry, PlotSpec, Spread, Statistic, Where};
use crate::experiment::Row;

/// What kind of plot a figure is (its spec's `kind`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum FigureKind {
    Lines,
    Trace,
    Histogram,
    Bars,
    Summary,
}

/// What a plot draws, as the page's table and the SVG read it.
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct Figure {
    pub kind: FigureKind,
    /// The spec's title.
    pub title: String,
    /// What is drawn, in words, from the spec and the rows: "median and interquartile range of
    /// 10 runs per point".
    pub described: String,
    pub statistic: Option<Statistic>,
    pub spread: Option<Spread>,
    pub x_label: String,
    pub y_label: String,
    pub log_y: bool,
    pub panels: Vec<Panel>,
    /// For `summary`: one row per condition and value.
    pub table: Vec<SummaryRow>,
    /// For `summary` with two or more conditions: every pair of conditions compared, value by
    /// value, the first condition minus the second (as `direction` says).
    pub comparisons: Vec<ComparisonRow>,
    /// For `summary` with three or more conditions: the Kruskal-Wallis test of each value.
    pub omnibus: Vec<OmnibusRow>,
    /// How every signed figure of the comparisons reads, stated once (the words of `DIRECTION`), or empty
    /// without comparisons.
    pub direction: String,
    /// Set when the figure draws only some of the experiment's runs (a cancelled sweep).
    pub partial: Option<Partial>,
}

/// The direction of every comparison, in words.
pub const DIRECTION: &str = "each comparison is the first condition minus the second: a positive difference, Cohen's d or rank-biserial correlation means the first condition's values tend to be larger";

/// Runs drawn of the runs the experiment has.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, serde::Deserialize, JsonSchema)]
pub struct Partial {
    pub runs: usize,
    pub of: usize,
}

impl Partial {
    /// "partial: 120 of 600 runs".
    pub fn words(&self) -> String {
        format!("partial: {} of {} runs", self.runs, self.of)
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct Panel {
    /// The facet, in words ("tip load: 0"); empty without facets.
    pub title: String,
    /// Category names of a bar chart (x is the category's index).
    pub categories: Vec<String>,
    /// Width of a histogram's bins.
    pub bin_width: Option<f64>,
    pub series: Vec<Series>,
}

#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct Series {
    /// In words: "collision: token", "adaptation: on".
    pub label: String,
    pub points: Vec<Point>,
}

#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct Point {
    pub x: f64,
    pub y: f64,
    /// The spread's ends, when one is drawn.
    pub band: Option<[f64; 2]>,
    /// Runs behind the point.
    pub n: usize,
}

#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct SummaryRow {
    /// The condition: one value per group path, in words.
    pub condition: Vec<String>,
    pub runs: usize,
    pub completed: usize,
    pub value: String,
    pub unit: String,
    pub stats: Option<Stats>,
}

#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct ComparisonRow {
    pub value: String,
    /// The two conditions, first and second: every signed figure is the first minus the second.
    pub conditions: [String; 2],
    pub comparison: Comparison,
    /// With three or more conditions: the Mann-Whitney p corrected by Holm's method for the
    /// number of pairs compared on this value.
    pub p_holm: Option<f64>,
}

/// The Kruskal-Wallis test of one value across three or more conditions.
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct OmnibusRow {
    pub value: String,
    /// The conditions tested, in words.
    pub conditions: Vec<String>,
    pub test: KruskalWallis,
}

/// The statistic and band of `values` as the figure draws them.
pub fn point_of(
    values: &[f64],
    statistic: Statistic,
    spread: Spread,
) -> Option<(f64, Option<[f64; 2]>, usize)> {
    let s = Stats::of(values)?;
    let y = match statistic {
        Statistic::Mean => s.mean,
        Statistic::Median => s.median,
    };
    let band = match spread {
        Spread::None => None,
        Spread::Minmax => Some([s.min, s.max]),
        Spread::Sd => Some([(s.mean - s.sd).max(s.min), (s.mean + s.sd).min(s.max)]),
        Spread::Ci95 => Some(s.ci95),
        Spread::Iqr => Some([s.q1, s.q3]),
    };
    Some((y, band, s.n))
}

/// "3 runs", "3 to 10 runs", from the points' n.
fn runs_words(panels: &[Panel]) -> String {
    let ns: Vec<usize> = panels
        .iter()
        .flat_map(|p| p.series.iter().flat_map(|s| s.points.iter().map(|p| p.n)))
        .collect();
    match (ns.iter().min(), ns.iter().max()) {
        (Some(a), Some(b)) if a == b => format!("n = {a} {}", if *a == 1 { "run" } else { "runs" }),
        (Some(a), Some(b)) => format!("n = {a} to {b} runs"),
        _ => "no runs".into(),
    }
}

/// Every figure of an experiment's plots, from its rows.
pub fn figures(specs: &[PlotSpec], rows: &[Row], models: &[&str]) -> Vec<Figure> {
    specs.iter().map(|s| figure(s, rows, models)).collect()
}

pub fn figure(spec: &PlotSpec, rows: &[Row], models: &[&str]) -> Figure {
    let all: Vec<&Row> = rows.iter().collect();
    let mut f = Figure {
        kind: match spec {
            PlotSpec::Lines(_) => FigureKind::Lines,
            PlotSpec::Trace(_) => FigureKind::Trace,
            PlotSpec::Histogram(_) => FigureKind::Histogram,
            PlotSpec::Bars(_) => FigureKind::Bars,
            PlotSpec::Summary(_) => FigureKind::Summary,
        },
        title: spec.title().to_string(),
        described: String::new(),
        statistic: None,
        spread: None,
        x_label: String::new(),
        y_label: String::new(),
        log_y: false,
        panels: Vec::new(),
        table: Vec::new(),
        comparisons: Vec::new(),
        omnibus: Vec::new(),
        direction: String::new(),
        partial: None,
    };
    match spec {
        PlotSpec::Lines(s) => {
            let spread = s.spread.unwrap_or(Spread::Minmax);
            let statistic = statistic_of(s.statistic, spread);
            let ys = s.y.list();
            f.x_label = axis_label(s.x_label.as_deref(), &s.x, models);
            f.y_label = match ys.as_slice() {
                [one] => axis_label(s.y_label.as_deref(), one, models),
                _ => s.y_label.clone().unwrap_or_else(|| "value".into()),
            };
            f.log_y = s.log_y;
            for (facet, part) in group_by(&all, s.facet.as_deref()) {
                let mut series = Vec::new();
                for y in &ys {
                    let first = series.len();
                    for (value, rows) in group_by(&part, s.series.as_deref()) {
                        let label = [
                            if ys.len() > 1 {
                                name_of(y)
                            } else {
                                String::new()
                            },
                            s.series
                                .as_deref()
                                .map_or(String::new(), |p| format!("{}: {value}", name_of(p))),
                        ]
                        .into_iter()
                        .filter(|t| !t.is_empty())
                        .collect::<Vec<_>>()
                        .join(", ");
                        let mut by_x: BTreeMap<OrdF64, Vec<f64>> = BTreeMap::new();
                        for r in &rows {
                            let x = num_at(r, &s.x);
                            if x.is_finite() {
                                by_x.entry(OrdF64(x)).or_default().push(num_at(r, y));
                            }
                        }
                        let points = by_x
                            .into_iter()
                            .filter_map(|(x, v)| {
                                point_of(&v, statistic, spread).map(|(y, band, n)| Point {
                                    x: x.0,
                                    y,
                                    band,
                                    n,
                                })
                            })
                            .collect();
                        series.push(Series {
                            label: if label.is_empty() { name_of(y) } else { label },
                            points,
                        });
                    }
                    // A quantity the series do not change (a bound) is one line, not several on
                    // top of each other.
                    let mine = &series[first..];
                    if mine.len() > 1 && mine.iter().all(|m| m.points == mine[0].points) {
                        let mut one = series[first].clone();
                        one.label = name_of(y);
                        series.truncate(first);
                        series.push(one);
                    }
                }
                f.panels.push(Panel {
                    title: facet_title(s.facet.as_deref(), &facet),
                    categories: Vec::new(),
                    bin_width: None,
                    series,
                });
            }
            f.statistic = Some(statistic);
            f.spread = Some(spread);
            f.described = described(statistic, spread, &f.panels, "point");
        }
        PlotSpec::Trace(s) => {
            let spread = s.spread.unwrap_or(Spread::Sd);
            let statistic = statistic_of(s.statistic, spread);
            let carry = s.carry.unwrap_or(Carry::Last) == Carry::Last;
            f.x_label = s.x_label.clone().unwrap_or_else(|| "step".into());
            f.y_label = axis_label(s.y_label.as_deref(), &format!("metrics.{}", s.y), models);
            let traced: Vec<&Row> = all
                .iter()
                .copied()
                .filter(|r| {
                    r.trace
                        .as_ref()
                        .is_some_and(|t| t.values.contains_key(&s.y))
                })
                .collect();
            let mut steps: Vec<u64> = traced
                .iter()
                .flat_map(|r| r.trace.as_ref().unwrap().step.iter().copied())
                .collect();
            kumiki_model::sort::sort(&mut steps);
            steps.dedup();
            if steps.len() > 1500 {
                let every = steps.len().div_ceil(1500);
                let last = steps.len() - 1;
                steps = steps
                    .into_iter()
                    .enumerate()
                    .filter(|(i, _)| i % every == 0 || *i == last)
                    .map(|(_, s)| s)
                    .collect();
            }
            for (facet, part) in group_by(&traced, s.facet.as_deref()) {
                let mut series = Vec::new();
                for (value, rows) in group_by(&part, s.series.as_deref()) {
                    let cols: Vec<Vec<f64>> = rows
                        .iter()
                        .map(|r| sampled(r, &s.y, &steps, carry))
                        .collect();
                    let points = steps
                        .iter()
                        .enumerate()
                        .filter_map(|(k, &step)| {
                            let v: Vec<f64> = cols.iter().map(|c| c[k]).collect();
                            point_of(&v, statistic, spread).map(|(y, band, n)| Point {
                                x: step as f64,
                                y,
                                band,
                                n,
                            })
                        })
                        .collect();
                    series.push(Series {
                        label: s
                            .series
                            .as_deref()
                            .map_or_else(|| name_of(&s.y), |p| format!("{}: {value}", name_of(p))),
                        points,
                    });
                }
                f.panels.push(Panel {
                    title: facet_title(s.facet.as_deref(), &facet),
                    categories: Vec::new(),
                    bin_width: None,
                    series,
                });
            }
            f.statistic = Some(statistic);
            f.spread = Some(spread);
            f.described = described(statistic, spread, &f.panels, "step");
        }
        PlotSpec::Histogram(s) => {
            let bins = s.bins.unwrap_or(20) as usize;
            let use_rows: Vec<&Row> = all
                .iter()
                .copied()
                .filter(|r| s.only != Some(Where::Completed) || r.completed)
                .collect();
            f.x_label = axis_label(s.x_label.as_deref(), &s.value, models);
            f.y_label = "runs".into();
            let mut total = 0;
            for (value, rows) in group_by(&use_rows, s.series.as_deref()) {
                let values: Vec<f64> = rows
                    .iter()
                    .map(|r| num_at(r, &s.value))
                    .filter(|v| v.is_finite())
                    .collect();
                total += values.len();
                let (lo, hi) = values
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
                        (a.min(v), b.max(v))
                    });
                let width = if hi > lo {
                    (hi - lo) / bins as f64
                } else {
                    1.0
                };
                let mut counts = vec![0usize; bins];
                for v in &values {
                    counts[(((v - lo) / width) as usize).min(bins - 1)] += 1;
                }
                let points = match values.is_empty() {
                    true => Vec::new(),
                    false => counts
                        .iter()
                        .enumerate()
                        .map(|(i, &c)| Point {
                            x: lo + (i as f64 + 0.5) * width,
                            y: c as f64,
                            band: None,
                            n: c,
                        })
                        .collect(),
                };
                f.panels.push(Panel {
                    title: facet_title(s.series.as_deref(), &value),
                    categories: Vec::new(),
                    bin_width: Some(width),
                    series: vec![Series {
                        label: "runs".into(),
                        points,
                    }],
                });
            }
            f.described = format!(
                "runs per bin, {bins} bins; n = {total} runs{}",
                if s.only == Some(Where::Completed) {
                    " that completed"
                } else {
                    ""
                }
            );
        }
        PlotSpec::Bars(s) => {
            let spread = s.spread.unwrap_or(Spread::Minmax);
            let statistic = statistic_of(s.statistic, spread);
            f.x_label = s.x_label.clone().unwrap_or_else(|| name_of(&s.x));
            f.y_label = axis_label(s.y_label.as_deref(), &s.y, models);
            let cats: Vec<String> = group_by(&all, Some(&s.x))
                .into_iter()
                .map(|(k, _)| k)
                .collect();
            let mut series = Vec::new();
            for (value, rows) in group_by(&all, s.series.as_deref()) {
                let by_cat = group_by(&rows, Some(&s.x));
                let points = cats
                    .iter()
                    .enumerate()
                    .filter_map(|(i, c)| {
                        let part = &by_cat.iter().find(|(k, _)| k == c)?.1;
                        let v: Vec<f64> = part.iter().map(|r| num_at(r, &s.y)).collect();
                        point_of(&v, statistic, spread).map(|(y, band, n)| Point {
                            x: i as f64,
                            y,
                            band,
                            n,
                        })
                    })
                    .collect();
                series.push(Series {
                    label: s
                        .series
                        .as_deref()
                        .map_or_else(|| name_of(&s.y), |p| format!("{}: {value}", name_of(p))),
                    points,
                });
            }
            f.panels.push(Panel {
                title: String::new(),
                categories: cats,
                bin_width: None,
                series,
            });
            f.statistic = Some(statistic);
            f.spread = Some(spread);
            f.described = described(statistic, spread, &f.panels, "bar");
        }
        PlotSpec::Summary(s) => {
            let group: Vec<String> = s.group.clone().unwrap_or_else(|| vec!["scenario".into()]);
            let values: Vec<String> = s.values.clone().unwrap_or_else(|| vec!["steps".into()]);
            let mut conditions: Vec<(Vec<String>, Vec<&Row>)> = Vec::new();
            for r in &all {
                let key: Vec<String> = group
                    .iter()
                    .map(|g| words(value_at(r, g).as_deref()))
                    .collect();
                match conditions.iter_mut().find(|(k, _)| *k == key) {
                    Some((_, list)) => list.push(r),
                    None => conditions.push((key, vec![r])),
                }
            }
            for (key, part) in &conditions {
                for v in &values {
                    let xs: Vec<f64> = part.iter().map(|r| num_at(r, v)).collect();
                    f.table.push(SummaryRow {
                        condition: key.clone(),
                        runs: part.len(),
                        completed: part.iter().filter(|r| r.completed).count(),
                        value: v.clone(),
                        unit: unit_of(v, models).unwrap_or("").to_string(),
                        stats: Stats::of(&xs),
                    });
                }
            }
            compared::compare_conditions(&mut f, &group, &values, &conditions);
            f.x_label = group
                .iter()
                .map(|g| name_of(g))
                .collect::<Vec<_>>()
                .join(", ");
            f.described = format!(
                "per condition: n, mean, sd, median, interquartile range and 95% confidence interval of the mean{}",
                match (f.comparisons.is_empty(), f.omnibus.is_empty()) {
                    (true, _) => "",
                    (false, true) => "; the two conditions compared by the difference of means, Cohen's d, the rank-biserial correlation and the Mann-Whitney U test",
                    (false, false) => "; the conditions tested together by the Kruskal-Wallis H test, then each pair compared by the difference of means, Cohen's d, the rank-biserial correlation and the Mann-Whitney U test, its p corrected for the pairs by Holm's method",
                }
            );
        }
    }
    f
}

/// Every figure of an experiment's plots from its rows, marked partial when the rows are fewer
/// than the experiment's runs (a cancelled sweep).
pub fn figures_of(e: &crate::experiment::Experiment, rows: &[Row]) -> Vec<Figure> {
    let models: Vec<&str> = e.scenarios.iter().map(|s| s.model()).collect();
    let mut figs = figures(&e.plots, rows, &models);
    let of = e.job_count();
    if rows.len() < of {
        for f in &mut figs {
            f.partial = Some(Partial {
                runs: rows.len(),
                of,
            });
        }
    }
    figs
}

fn described(statistic: Statistic, spread: Spread, panels: &[Panel], per: &str) -> String {
    let spread = match spread {
        Spread::None => String::new(),
        s => format!(", {}", spread_words(s)),
    };
    format!(
        "{}{spread}; {} per {per}",
        statistic_words(statistic),
        runs_words(panels)
    )
}

/// An f64 key in x order (NaN never enters).
#[derive(Clone, Copy, Debug, PartialEq)]
struct OrdF64(f64);

impl Eq for OrdF64 {}

impl PartialOrd for OrdF64 {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for OrdF64 {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0)
    }
}
