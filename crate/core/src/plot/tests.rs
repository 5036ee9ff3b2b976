//! Drawn equals described: every built-in experiment's figures, from rows made up for its jobs,
//! draw at each point the statistic and spread their description names, over the runs it says.

use serde_json::{json, Map, Value};

use super::figure::{figures, Figure};
use super::labels::name_of;
use super::values::{value_at, words};
use super::{statistic_of, PlotSpec, Spread, Statistic};
use crate::experiment::{Experiment, Row, Trace};
use crate::presets;
use crate::run::Outcome;

/// Rows for every job of `e`, with made-up metric values (a fixed hash of the job, so medians
/// and means differ), so every plot has something to draw.
pub(super) fn made_up_rows(e: &Experiment) -> Vec<Row> {
    let mut state: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % 1000) as f64
    };
    e.jobs()
        .into_iter()
        .map(|job| {
            let scenario = &e.scenarios[job.scenario];
            let mut metrics = Map::new();
            for m in crate::models::metric_table(scenario.model()).unwrap() {
                // Skewed, so the mean and the median differ.
                let v = next();
                metrics.insert(m.name.into(), json!(v * v / 1000.0));
            }
            let trace = e.trace.as_ref().map(|t| {
                let steps: Vec<u64> = (0..=(next() as u64 % 5 + 2)).map(|k| k * t.every).collect();
                let values = t
                    .metrics
                    .iter()
                    .map(|m| {
                        (
                            m.clone(),
                            Value::Array(steps.iter().map(|_| json!(next())).collect()),
                        )
                    })
                    .collect();
                Trace {
                    step: steps,
                    values,
                }
            });
            Row {
                outcome: Outcome {
                    scenario: scenario.name.clone(),
                    seed: job.seed,
                    completed: next() < 700.0,
                    steps: next() as u64,
                    hash: "0".into(),
                    metrics,
                    stopped: None,
                },
                params: job.params.iter().cloned().collect(),
                scenario_hash: "0".into(),
                version: "test".into(),
                trace,
            }
        })
        .collect()
}

/// The statistic and band, computed here the plain way.
fn expected(values: &[f64], statistic: Statistic, spread: Spread) -> (f64, Option<[f64; 2]>) {
    let mut v: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    let mean = v.iter().sum::<f64>() / n as f64;
    let median = match n % 2 {
        1 => v[n / 2],
        _ => (v[n / 2 - 1] + v[n / 2]) / 2.0,
    };
    let sd =
        (v.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / (n.max(2) - 1) as f64).sqrt();
    let q = |p: f64| super::stats::quantile(&v, p);
    let y = if statistic == Statistic::Mean {
        mean
    } else {
        median
    };
    let band = match spread {
        Spread::None => None,
        Spread::Minmax => Some([v[0], v[n - 1]]),
        Spread::Sd => Some([(mean - sd).max(v[0]), (mean + sd).min(v[n - 1])]),
        Spread::Iqr => Some([q(0.25), q(0.75)]),
        Spread::Ci95 => {
            let h = super::stats::t975(n - 1) * sd / (n as f64).sqrt();
            Some([mean - h, mean + h])
        }
    };
    (y, band)
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
}

/// The value after "name: " in a label, for the path's name.
fn part<'a>(label: &'a str, path: &str) -> Option<&'a str> {
    let key = format!("{}: ", name_of(path));
    let at = label.find(&key)? + key.len();
    // The series is the label's last part: the rest is its value, commas and all.
    Some(&label[at..])
}

fn matches(row: &Row, path: Option<&str>, label: &str) -> bool {
    match path.and_then(|p| part(label, p).map(|v| (p, v))) {
        Some((p, v)) => words(value_at(row, p).as_deref()) == v,
        None => true,
    }
}

fn check(e: &Experiment, spec: &PlotSpec, f: &Figure, rows: &[Row]) {
    let at = format!("{} '{}'", e.name, f.title);
    for word in [
        "mean",
        "median",
        "IQR",
        "min/max",
        "quartile",
        "sd",
        "deviation",
    ] {
        assert!(
            !spec
                .title()
                .to_lowercase()
                .split(|c: char| !c.is_alphanumeric() && c != '/')
                .any(|w| w == word.to_lowercase()),
            "{at}: the title names a statistic ('{word}'); the figure writes it from the spec"
        );
    }
    let (statistic, spread, x, ys, series, facet): (
        Statistic,
        Spread,
        &str,
        Vec<&str>,
        Option<&str>,
        Option<&str>,
    ) = match spec {
        PlotSpec::Lines(s) => {
            let sp = s.spread.unwrap_or(Spread::Minmax);
            (
                statistic_of(s.statistic, sp),
                sp,
                s.x.as_str(),
                s.y.list(),
                s.series.as_deref(),
                s.facet.as_deref(),
            )
        }
        PlotSpec::Bars(s) => {
            let sp = s.spread.unwrap_or(Spread::Minmax);
            (
                statistic_of(s.statistic, sp),
                sp,
                s.x.as_str(),
                vec![s.y.as_str()],
                s.series.as_deref(),
                None,
            )
        }
        PlotSpec::Trace(s) => return check_trace(&at, s, f, rows),
        PlotSpec::Histogram(s) => return check_histogram(&at, s, f, rows),
        PlotSpec::Summary(s) => return check_summary(&at, s, f, rows),
    };
    assert_eq!(
        (f.statistic, f.spread),
        (Some(statistic), Some(spread)),
        "{at}"
    );
    let words_of = super::labels::statistic_words(statistic);
    assert!(
        f.described.starts_with(words_of),
        "{at}: '{}' does not start with {words_of}",
        f.described
    );
    assert!(
        f.described.contains(super::labels::spread_words(spread)),
        "{at}: '{}'",
        f.described
    );
    let mut ns = Vec::new();
    let mut drawn = 0;
    for p in &f.panels {
        for s in &p.series {
            let y = match ys.as_slice() {
                [one] => *one,
                many => many
                    .iter()
                    .copied()
                    .find(|y| s.label.starts_with(&name_of(y)))
                    .unwrap(),
            };
            for pt in &s.points {
                let values: Vec<f64> = rows
                    .iter()
                    .filter(|r| {
                        facet.is_none_or(|fp| {
                            format!("{}: {}", name_of(fp), words(value_at(r, fp).as_deref()))
                                == p.title
                        })
                    })
                    .filter(|r| matches(r, series, &s.label))
                    .filter(|r| match spec {
                        PlotSpec::Bars(_) => {
                            words(value_at(r, x).as_deref()) == p.categories[pt.x as usize]
                        }
                        _ => super::values::number(value_at(r, x).as_deref()) == pt.x,
                    })
                    .map(|r| super::values::number(value_at(r, y).as_deref()))
                    .collect();
                let n = values.iter().filter(|v| v.is_finite()).count();
                assert_eq!(pt.n, n, "{at}: n at x = {}", pt.x);
                let (want, band) = expected(&values, statistic, spread);
                assert!(
                    close(pt.y, want),
                    "{at}: {} at x = {} is {} but the {words_of} is {want}",
                    s.label,
                    pt.x,
                    pt.y
                );
                match (pt.band, band) {
                    (Some(a), Some(b)) => assert!(
                        close(a[0], b[0]) && close(a[1], b[1]),
                        "{at}: band {a:?} is not {b:?}"
                    ),
                    (a, b) => assert_eq!(
                        a.is_some(),
                        b.is_some(),
                        "{at}: band drawn {a:?}, described {b:?}"
                    ),
                }
                ns.push(n);
                drawn += 1;
            }
        }
    }
    assert!(drawn > 0, "{at}: nothing drawn");
    let said = runs_said(&ns);
    assert!(
        f.described.contains(&said),
        "{at}: '{}' should say {said}",
        f.described
    );
}

/// "n = 10 runs", "n = 3 to 10 runs": what a figure says of the points' n.
fn runs_said(ns: &[usize]) -> String {
    let (lo, hi) = (ns.iter().min().unwrap(), ns.iter().max().unwrap());
    match lo == hi {
        true => format!("n = {lo} run"),
        false => format!("n = {lo} to {hi} runs"),
    }
}

/// A run's traced value at `step`, worked out plainly: its last sample at or before the step;
/// past its last sample, that sample when the spec carries it, else none.
fn traced_at(row: &Row, metric: &str, step: u64, carry: bool) -> f64 {
    let t = row.trace.as_ref().unwrap();
    let Some(i) = t.step.iter().rposition(|&s| s <= step) else {
        return f64::NAN;
    };
    if !carry && step > *t.step.last().unwrap() {
        return f64::NAN;
    }
    super::values::number(t.values[metric].as_array().unwrap().get(i))
}

/// A trace draws at each step the statistic over the runs' values at that step.
fn check_trace(at: &str, s: &super::Trace, f: &Figure, rows: &[Row]) {
    let spread = s.spread.unwrap_or(Spread::Sd);
    let statistic = statistic_of(s.statistic, spread);
    let carry = s.carry.unwrap_or(super::Carry::Last) == super::Carry::Last;
    assert_eq!(
        (f.statistic, f.spread),
        (Some(statistic), Some(spread)),
        "{at}"
    );
    let words_of = super::labels::statistic_words(statistic);
    assert!(
        f.described.starts_with(words_of)
            && f.described.contains(super::labels::spread_words(spread)),
        "{at}: '{}'",
        f.described
    );
    let mut ns = Vec::new();
    for p in &f.panels {
        for series in &p.series {
            let runs: Vec<&Row> = rows
                .iter()
                .filter(|r| {
                    s.facet.as_deref().is_none_or(|fp| {
                        format!("{}: {}", name_of(fp), words(value_at(r, fp).as_deref())) == p.title
                    })
                })
                .filter(|r| matches(r, s.series.as_deref(), &series.label))
                .collect();
            assert!(
                !series.points.is_empty(),
                "{at}: {} draws nothing",
                series.label
            );
            for pt in &series.points {
                let values: Vec<f64> = runs
                    .iter()
                    .map(|r| traced_at(r, &s.y, pt.x as u64, carry))
                    .collect();
                let n = values.iter().filter(|v| v.is_finite()).count();
                assert_eq!(pt.n, n, "{at}: n at step {}", pt.x);
                let (want, band) = expected(&values, statistic, spread);
                assert!(
                    close(pt.y, want),
                    "{at}: {} at step {} is {} but the {words_of} is {want}",
                    series.label,
                    pt.x,
                    pt.y
                );
                let (a, b) = (pt.band.unwrap(), band.unwrap());
                assert!(
                    close(a[0], b[0]) && close(a[1], b[1]),
                    "{at}: band {a:?} is not {b:?} at step {}",
                    pt.x
                );
                ns.push(n);
            }
        }
    }
    let said = runs_said(&ns);
    assert!(
        f.described.contains(&said),
        "{at}: '{}' should say {said}",
        f.described
    );
}

/// A histogram counts every run it says it counts, each in the bin that holds its value.
fn check_histogram(at: &str, s: &super::Histogram, f: &Figure, rows: &[Row]) {
    let bins = s.bins.unwrap_or(20) as usize;
    let counted: Vec<&Row> = rows
        .iter()
        .filter(|r| s.only != Some(super::Where::Completed) || r.completed)
        .collect();
    let mut total = 0;
    for p in &f.panels {
        let values: Vec<f64> = counted
            .iter()
            .filter(|r| {
                s.series.as_deref().is_none_or(|sp| {
                    format!("{}: {}", name_of(sp), words(value_at(r, sp).as_deref())) == p.title
                })
            })
            .map(|r| super::values::number(value_at(r, &s.value).as_deref()))
            .filter(|v| v.is_finite())
            .collect();
        let points = &p.series[0].points;
        assert_eq!(points.len(), bins, "{at}: {bins} bins");
        let width = p.bin_width.unwrap();
        assert_eq!(
            points.iter().map(|pt| pt.n).sum::<usize>(),
            values.len(),
            "{at}: every run in {} is in a bin",
            p.title
        );
        for (i, pt) in points.iter().enumerate() {
            let (lo, hi) = (pt.x - width / 2.0, pt.x + width / 2.0);
            let last = i + 1 == points.len();
            let inside = values
                .iter()
                .filter(|&&v| {
                    v >= lo - 1e-9 * lo.abs() && (v < hi || last && v <= hi + 1e-9 * hi.abs())
                })
                .count();
            assert_eq!(pt.n, inside, "{at}: the bin at {} counts its runs", pt.x);
            assert_eq!(pt.y, pt.n as f64, "{at}: a bar's height is its count");
        }
        total += values.len();
    }
    assert!(
        f.described
            .contains(&format!("{bins} bins; n = {total} runs")),
        "{at}: '{}' should say {bins} bins and n = {total}",
        f.described
    );
}

/// A summary's row is the statistics of its condition's runs.
fn check_summary(at: &str, s: &super::Summary, f: &Figure, rows: &[Row]) {
    let group = s.group.clone().unwrap_or_else(|| vec!["scenario".into()]);
    let values = s.values.clone().unwrap_or_else(|| vec!["steps".into()]);
    assert!(!f.table.is_empty(), "{at}: an empty table");
    let mut seen = 0;
    for row in &f.table {
        let runs: Vec<&Row> = rows
            .iter()
            .filter(|r| {
                group
                    .iter()
                    .zip(&row.condition)
                    .all(|(g, v)| words(value_at(r, g).as_deref()) == *v)
            })
            .collect();
        assert_eq!(row.runs, runs.len(), "{at}: runs of {:?}", row.condition);
        assert_eq!(
            row.completed,
            runs.iter().filter(|r| r.completed).count(),
            "{at}"
        );
        let xs: Vec<f64> = runs
            .iter()
            .map(|r| super::values::number(value_at(r, &row.value).as_deref()))
            .collect();
        let stats = row.stats.unwrap();
        assert_eq!(stats.n, xs.iter().filter(|v| v.is_finite()).count(), "{at}");
        let (mean, ci) = expected(&xs, Statistic::Mean, Spread::Ci95);
        let (median, iqr) = expected(&xs, Statistic::Median, Spread::Iqr);
        let (ci, iqr) = (ci.unwrap(), iqr.unwrap());
        assert!(
            close(stats.mean, mean) && close(stats.median, median),
            "{at}: {:?} {}",
            row.condition,
            row.value
        );
        if stats.n > 1 {
            assert!(
                close(stats.ci95[0], ci[0]) && close(stats.ci95[1], ci[1]),
                "{at}"
            );
        }
        assert!(close(stats.q1, iqr[0]) && close(stats.q3, iqr[1]), "{at}");
        seen += 1;
    }
    let conditions = seen / values.len();
    assert_eq!(
        seen,
        conditions * values.len(),
        "{at}: each condition gives every value"
    );
    // Every pair of conditions, value by value (made-up values are never all missing); with
    // three or more a Kruskal-Wallis test of each value and Holm's p on every pair.
    assert_eq!(
        f.comparisons.len(),
        conditions * (conditions - 1) / 2 * values.len(),
        "{at}: every pair of conditions is compared, value by value"
    );
    assert_eq!(
        f.omnibus.len(),
        if conditions > 2 { values.len() } else { 0 },
        "{at}"
    );
    assert!(
        f.comparisons
            .iter()
            .all(|c| c.p_holm.is_some() == (conditions > 2)),
        "{at}"
    );
    assert_eq!(f.direction.is_empty(), f.comparisons.is_empty(), "{at}");
}

#[test]
fn every_built_in_figure_draws_what_it_describes() {
    for name in presets::experiment_names() {
        let e = Experiment::named_or_json(name).unwrap();
        let rows = made_up_rows(&e);
        let models: Vec<&str> = e.scenarios.iter().map(|s| s.model()).collect();
        let figs = figures(&e.plots, &rows, &models);
        assert_eq!(figs.len(), e.plots.len());
        for (spec, f) in e.plots.iter().zip(&figs) {
            check(&e, spec, f, &rows);
            let svg = super::svg::svg(f);
            assert!(
                svg.starts_with("<svg") && svg.contains(&super::svg::escape(&f.described)),
                "{name}"
            );
        }
    }
}

#[test]
fn amas_fig27_rules_draws_the_median_and_its_iqr() {
    let e = Experiment::named_or_json("amas-fig27-rules").unwrap();
    let f = figures(&e.plots, &made_up_rows(&e), &["amas"]);
    assert_eq!(f[0].statistic, Some(Statistic::Median));
    assert_eq!(f[0].spread, Some(Spread::Iqr));
    assert!(
        f[0].described
            .starts_with("median, interquartile range; n = 10 runs per point"),
        "{}",
        f[0].described
    );
}

fn experiment_with_plot(plot: Value) -> crate::Result<Experiment> {
    Experiment::from_value(json!({
        "version": 1, "name": "t", "scenarios": ["amas-L"],
        "grid": {"robots": [1, 2]}, "seeds": 2, "plot": plot
    }))
}

#[test]
fn a_plot_that_names_an_unknown_choice_is_refused_with_the_choices() {
    let err = |plot: Value| experiment_with_plot(plot).unwrap_err().to_string();
    assert_eq!(
        err(json!({"kind": "lines", "x": "params.robots", "y": "steps", "spread": "range"})),
        "plot.spread: 'range' is not a choice; expected one of 'none', 'minmax', 'sd', 'ci95', 'iqr', 'quartiles'"
    );
    assert_eq!(
        err(
            json!([{"kind": "summary"}, {"kind": "lines", "x": "params.robots", "y": "steps", "statistic": "mode"}])
        ),
        "plot[1].statistic: 'mode' is not a choice; expected 'mean' or 'median'"
    );
    assert_eq!(
        err(json!({"kind": "pie"})),
        "plot.kind: 'pie' is not a plot kind; expected lines, trace, histogram, bars or summary"
    );
    assert!(
        err(json!({"kind": "lines", "x": "params.robot", "y": "steps"}))
            .starts_with("plot.x: 'params.robot' names no grid key; the grid has params.robots")
    );
    assert!(
        err(json!({"kind": "bars", "x": "scenario", "y": "metrics.totl_steps"}))
            == "plot.y: 'metrics.totl_steps' is not a metric of amas; did you mean 'metrics.total_steps'?"
    );
    assert!(err(json!({"kind": "lines", "x": "params.robots", "y": "steps", "statistic": "median", "spread": "sd"})).contains("sd belongs to a mean"));
    assert!(
        err(json!({"kind": "lines", "x": "params.robots", "y": "steps", "colour": "red"}))
            .starts_with("plot.colour: unknown field")
    );
    assert!(err(json!({"kind": "trace", "y": "built"})).contains("not traced"));
    // `quartiles`, as older files write it, reads as `iqr`.
    let e = experiment_with_plot(
        json!({"kind": "lines", "x": "params.robots", "y": "steps", "spread": "quartiles"}),
    )
    .unwrap();
    assert!(matches!(&e.plots[0], PlotSpec::Lines(l) if l.spread == Some(Spread::Iqr)));
}

#[test]
fn statistics_match_values_worked_by_hand() {
    use super::stats::{t975, Comparison, Stats};
    let a = [1.0, 2.0, 3.0, 4.0, 5.0];
    let b = [6.0, 7.0, 8.0, 9.0, 10.0];
    let s = Stats::of(&a).unwrap();
    assert_eq!((s.n, s.mean, s.median, s.q1, s.q3), (5, 3.0, 3.0, 2.0, 4.0));
    assert!(close(s.sd, 2.5f64.sqrt()));
    // 3 ± t(0.975, 4) · sd / √5, t = 2.776.
    let half = 2.776 * 2.5f64.sqrt() / 5f64.sqrt();
    assert!(close(s.ci95[0], 3.0 - half) && close(s.ci95[1], 3.0 + half));
    // Every value of a below every value of b: U = 0, and the exact two-sided p is 2 / C(10, 5).
    let c = Comparison::of(&a, &b).unwrap();
    assert_eq!((c.u, c.rank_biserial, c.method), (0.0, -1.0, "exact"));
    assert!(close(c.p, 2.0 / 252.0), "{}", c.p);
    // First minus second, as U takes the first's side: every value of a lies below b's.
    assert!(close(c.cohens_d, -5.0 / 2.5f64.sqrt()));
    assert!(close(c.difference, -5.0));
    // Interleaved: U = 12.5 of 25 pairs would be no effect; here U = 10 and p is large.
    let c = Comparison::of(&[1.0, 3.0, 5.0, 7.0, 9.0], &[2.0, 4.0, 6.0, 8.0, 10.0]).unwrap();
    assert_eq!(c.u, 10.0);
    assert!(c.p > 0.5 && c.p <= 1.0);
    // Ties: the normal approximation with tie correction.
    let c = Comparison::of(&[1.0, 1.0, 2.0, 2.0], &[2.0, 3.0, 3.0, 4.0]).unwrap();
    assert_eq!(c.method, "normal");
    assert!(c.p > 0.0 && c.p < 0.1, "{}", c.p);
    assert!((t975(100) - 1.98397).abs() < 1e-4, "{}", t975(100));
    assert!((t975(31) - 2.0395).abs() < 1e-3, "{}", t975(31));
}
