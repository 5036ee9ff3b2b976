//! How an experiment chooses its runs beyond a grid of listed values, BehaviorSpace's three
//! additions: a grid value written as a range, a sample of parameter points drawn at random or by
//! Latin hypercube from a seed, and a stop condition in the goal language.
//!
//! ```json
//! "grid": { "robots": { "start": 2, "step": 2, "end": 10 } },
//! "sample": { "method": "latin", "count": 20, "seed": 7,
//!             "ranges": { "tip_load": { "min": 0, "max": 4, "integer": true } } },
//! "stop": "metrics.built >= 0.5 or steps >= 2000"
//! ```
//!
//! Everything is computed here, once, from the file: the CLI, the Python package and the page's
//! lab module read the same experiment into the same jobs, so they run the same rows.

use serde_json::{Map, Value};

use crate::error::{Error, Result};
use crate::exercise::{Goal, Outcome};
use crate::rng::Rng;
use crate::run::Run;

/// The most values one range or one sample may give.
pub const MAX_POINTS: usize = 100_000;

/// A grid key's values: a list as written, or a range `{"start", "step", "end"}` (`end`
/// included when a whole number of steps reaches it), read as its list.
pub fn grid_values(key: &str, value: Value) -> Result<Vec<Value>> {
    let at = format!("grid.{key}");
    match value {
        Value::Array(values) if !values.is_empty() => Ok(values),
        Value::Object(map) => range(map).map_err(|e| e.within(&at)),
        _ => Err(Error::field(
            at,
            "expected a non-empty list of values or a range {\"start\", \"step\", \"end\"}",
        )),
    }
}

fn number(map: &Map<String, Value>, key: &str) -> Result<Option<f64>> {
    match map.get(key) {
        None => Ok(None),
        Some(v) => match v.as_f64() {
            Some(x) if x.is_finite() => Ok(Some(x)),
            _ => Err(Error::field(key, "expected a number")),
        },
    }
}

fn unknown_keys(map: &Map<String, Value>, allowed: &[&str]) -> Result<()> {
    match map.keys().find(|k| !allowed.contains(&k.as_str())) {
        None => Ok(()),
        Some(k) => {
            let near = kumiki_model::error::nearest_within(k, allowed.iter().copied(), 2);
            Err(Error::field(
                k.as_str(),
                match near {
                    Some(n) => format!("unknown field '{k}'; did you mean '{n}'?"),
                    None => format!("unknown field '{k}'; expected {}", allowed.join(", ")),
                },
            ))
        }
    }
}

/// The values of a range, from `start` by `step` up to `end`. Whole-number ranges give whole
/// numbers; others are rounded to the decimals `start` and `step` are written with, so 0.1 steps
/// give 0.3 and not 0.30000000000000004.
fn range(map: Map<String, Value>) -> Result<Vec<Value>> {
    unknown_keys(&map, &["start", "step", "end"])?;
    let need = |key: &str| number(&map, key)?.ok_or_else(|| Error::field(key, "is required"));
    let (start, step, end) = (need("start")?, need("step")?, need("end")?);
    if step <= 0.0 {
        return Err(Error::field("step", "expected a number above 0"));
    }
    if end < start {
        return Err(Error::field("end", "is below start"));
    }
    let count = ((end - start) / step * (1.0 + 1e-12) + 1e-9).floor() + 1.0;
    if count > MAX_POINTS as f64 {
        return Err(Error::field(
            "step",
            format!("the range has more than {MAX_POINTS} values"),
        ));
    }
    let whole = [&map["start"], &map["step"]]
        .iter()
        .all(|v| v.is_i64() || v.is_u64());
    let decimals = decimals_of(&map["start"]).max(decimals_of(&map["step"]));
    Ok((0..count as usize)
        .map(|i| {
            let x = start + i as f64 * step;
            match whole {
                true => Value::from(x as i64),
                false => Value::from(round_to(x, decimals)),
            }
        })
        .collect())
}

/// The decimals a number is written with in JSON (0 for a whole number).
fn decimals_of(v: &Value) -> i32 {
    let text = v.to_string();
    let (mantissa, exponent) = match text.split_once(['e', 'E']) {
        Some((m, e)) => (m.to_string(), e.parse::<i32>().unwrap_or(0)),
        None => (text, 0),
    };
    let fraction = mantissa.split_once('.').map_or(0, |(_, f)| f.len() as i32);
    (fraction - exponent).max(0)
}

fn round_to(x: f64, decimals: i32) -> f64 {
    let text = format!("{x:.*}", decimals.clamp(0, 17) as usize);
    text.parse().unwrap_or(x)
}

/// How a sample's points are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Each value uniform in its range, independently.
    Random,
    /// A Latin hypercube: each range cut into `count` equal strata, every stratum used once,
    /// strata paired at random across keys, a uniform point in each.
    Latin,
}

/// A key's range in a sample: `min` to `max`; `integer` draws whole numbers from `min` to `max`
/// inclusive.
#[derive(Clone, Debug, PartialEq)]
pub struct Bounds {
    pub min: f64,
    pub max: f64,
    pub integer: bool,
}

/// `"sample"`: `count` parameter points drawn from `ranges` by `method` with `seed`.
#[derive(Clone, Debug, PartialEq)]
pub struct Sample {
    pub method: Method,
    pub count: usize,
    pub seed: u64,
    pub ranges: Vec<(String, Bounds)>,
}

impl Sample {
    pub fn read(value: Value) -> Result<Sample> {
        Sample::read_map(value).map_err(|e| e.within("sample"))
    }

    fn read_map(value: Value) -> Result<Sample> {
        let Value::Object(map) = value else {
            return Err(Error::field(
                "",
                "expected {\"method\", \"count\", \"seed\", \"ranges\"}",
            ));
        };
        unknown_keys(&map, &["method", "count", "seed", "ranges"])?;
        let method = match map.get("method").and_then(Value::as_str) {
            None | Some("latin") => Method::Latin,
            Some("random") => Method::Random,
            Some(other) => {
                return Err(Error::field(
                    "method",
                    format!("'{other}' is not a method; expected 'latin' or 'random'"),
                ))
            }
        };
        let count = match map.get("count").and_then(Value::as_u64) {
            Some(n) if (1..=MAX_POINTS as u64).contains(&n) => n as usize,
            _ => {
                return Err(Error::field(
                    "count",
                    format!("expected a whole number from 1 to {MAX_POINTS}"),
                ))
            }
        };
        let seed = match map.get("seed") {
            None => 1,
            Some(v) => v
                .as_u64()
                .ok_or_else(|| Error::field("seed", "expected a whole number"))?,
        };
        let ranges = match map.get("ranges") {
            Some(Value::Object(r)) if !r.is_empty() => r
                .iter()
                .map(|(k, v)| {
                    bounds(v)
                        .map(|b| (k.clone(), b))
                        .map_err(|e| e.within(&format!("ranges.{k}")))
                })
                .collect::<Result<Vec<_>>>()?,
            _ => {
                return Err(Error::field(
                    "ranges",
                    "expected an object of path: {\"min\", \"max\"}",
                ))
            }
        };
        Ok(Sample {
            method,
            count,
            seed,
            ranges,
        })
    }

    /// The sample's points, each a value per range key in the ranges' order. The same file
    /// gives the same points everywhere: the draws come from the core's seeded generator.
    pub fn points(&self) -> Vec<Vec<(String, Value)>> {
        let mut rng = Rng::new(self.seed);
        let n = self.count;
        // Column by column: each key's `count` positions in [0, 1).
        let columns: Vec<Vec<f64>> = self
            .ranges
            .iter()
            .map(|_| match self.method {
                Method::Random => (0..n).map(|_| rng.unit()).collect(),
                Method::Latin => {
                    let mut strata: Vec<usize> = (0..n).collect();
                    rng.shuffle(&mut strata);
                    strata
                        .into_iter()
                        .map(|s| (s as f64 + rng.unit()) / n as f64)
                        .collect()
                }
            })
            .collect();
        (0..n)
            .map(|i| {
                self.ranges
                    .iter()
                    .zip(&columns)
                    .map(|((key, b), col)| (key.clone(), b.at(col[i])))
                    .collect()
            })
            .collect()
    }
}

fn bounds(v: &Value) -> Result<Bounds> {
    let Value::Object(map) = v else {
        return Err(Error::field("", "expected {\"min\", \"max\"}"));
    };
    unknown_keys(map, &["min", "max", "integer"])?;
    let min = number(map, "min")?.ok_or_else(|| Error::field("min", "is required"))?;
    let max = number(map, "max")?.ok_or_else(|| Error::field("max", "is required"))?;
    if max < min {
        return Err(Error::field("max", "is below min"));
    }
    let integer = match map.get("integer") {
        None => false,
        Some(Value::Bool(b)) => *b,
        Some(_) => return Err(Error::field("integer", "expected true or false")),
    };
    if integer && (min.fract() != 0.0 || max.fract() != 0.0) {
        return Err(Error::field(
            "integer",
            "whole-number draws need whole-number min and max",
        ));
    }
    Ok(Bounds { min, max, integer })
}

impl Bounds {
    /// The value at position `u` in [0, 1): a whole number from min to max inclusive, or a
    /// number from min to max kept to 6 significant digits (a file's reader sees 1.23457, not
    /// 1.2345678901234).
    fn at(&self, u: f64) -> Value {
        match self.integer {
            true => {
                let span = self.max - self.min + 1.0;
                Value::from((self.min + (u * span).floor()).min(self.max) as i64)
            }
            false => Value::from(significant(self.min + u * (self.max - self.min), 6)),
        }
    }
}

fn significant(x: f64, digits: usize) -> f64 {
    match x {
        0.0 => 0.0,
        _ => format!("{x:.*e}", digits - 1).parse().unwrap_or(x),
    }
}

/// `"stop"`: a condition in the goal language, checked after every step; a run stops at the first
/// step where it holds (and at its own end, as without one).
#[derive(Clone, Debug, PartialEq)]
pub struct Stop {
    goal: Goal,
}

impl Stop {
    /// Reads the condition; every metric it names must be one of `models`' (a misspelt one gets
    /// the nearest name).
    pub fn read(value: Value, models: &[&str]) -> Result<Stop> {
        let Value::String(text) = value else {
            return Err(Error::field(
                "stop",
                "expected a condition, as in 'steps >= 500'",
            ));
        };
        let goal = Goal::parse(&text).map_err(|e| e.within("stop"))?;
        for name in goal.names() {
            if let Some(metric) = name.strip_prefix("metrics.") {
                crate::models::check_metric(models, metric, "metrics.")
                    .map_err(|e| e.within("stop"))?;
            }
        }
        Ok(Stop { goal })
    }

    pub fn text(&self) -> &str {
        self.goal.text()
    }

    /// Whether the run has met the condition at its current step.
    pub fn met(&self, run: &Run, scenario: &Value) -> bool {
        let metrics = run.model().metrics();
        self.goal
            .check(&Outcome {
                completed: run.finished(),
                steps: run.steps(),
                metrics: &metrics,
                scenario,
            })
            .met
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn ranges_include_their_end_and_keep_their_decimals() {
        let r = |v: Value| grid_values("k", v).unwrap();
        assert_eq!(
            r(json!({"start": 2, "step": 2, "end": 10})),
            vec![json!(2), json!(4), json!(6), json!(8), json!(10)]
        );
        assert_eq!(
            r(json!({"start": 0, "step": 0.1, "end": 0.3})),
            vec![json!(0.0), json!(0.1), json!(0.2), json!(0.3)]
        );
        assert_eq!(
            r(json!({"start": 1, "step": 3, "end": 8})),
            vec![json!(1), json!(4), json!(7)]
        );
        assert_eq!(r(json!([1, "a"])), vec![json!(1), json!("a")]);
        let err = |v: Value| grid_values("k", v).unwrap_err().to_string();
        assert_eq!(
            err(json!({"start": 1, "stp": 1, "end": 2})),
            "grid.k.stp: unknown field 'stp'; did you mean 'step'?"
        );
        assert_eq!(
            err(json!({"start": 1, "step": 0, "end": 2})),
            "grid.k.step: expected a number above 0"
        );
        assert_eq!(
            err(json!({"start": 3, "step": 1, "end": 2})),
            "grid.k.end: is below start"
        );
        assert!(err(json!({"start": 0, "step": 1e-9, "end": 1})).contains("more than"));
    }

    #[test]
    fn a_latin_hypercube_uses_every_stratum_once_and_replays_from_its_seed() {
        let s = Sample::read(json!({"method": "latin", "count": 10, "seed": 3,
            "ranges": {"a": {"min": 0, "max": 1}, "b": {"min": 1, "max": 10, "integer": true}}}))
        .unwrap();
        let points = s.points();
        assert_eq!(points, s.points());
        assert_eq!(points.len(), 10);
        let mut strata: Vec<usize> = points
            .iter()
            .map(|p| (p[0].1.as_f64().unwrap() * 10.0) as usize)
            .collect();
        strata.sort();
        assert_eq!(strata, (0..10).collect::<Vec<_>>());
        let mut whole: Vec<i64> = points.iter().map(|p| p[1].1.as_i64().unwrap()).collect();
        whole.sort();
        assert_eq!(
            whole,
            (1..=10).collect::<Vec<_>>(),
            "ten strata of ten whole numbers: each once"
        );
        let other = Sample {
            seed: 4,
            ..s.clone()
        };
        assert_ne!(other.points(), points);
        let random = Sample {
            method: Method::Random,
            ..s
        };
        assert!(random
            .points()
            .iter()
            .all(|p| (0.0..1.0).contains(&p[0].1.as_f64().unwrap())));
    }

    fn experiment(extra: Value) -> crate::Result<crate::Experiment> {
        let mut doc = json!({"version": 1, "name": "t", "scenarios": ["amas-L"], "seeds": 2});
        doc.as_object_mut()
            .unwrap()
            .extend(extra.as_object().unwrap().clone());
        crate::Experiment::from_value(doc)
    }

    #[test]
    fn a_misspelt_key_or_metric_is_blamed_by_name_with_the_nearest() {
        let err = |extra: Value| experiment(extra).unwrap_err().to_string();
        // The plot names the key as it should be; the grid is where the mistake is.
        assert_eq!(
            err(
                json!({"grid": {"robot": [1, 2]}, "plot": {"kind": "lines", "x": "params.robots", "y": "steps", "series": "params.robots"}})
            ),
            "grid.robot: amas-L with robot=1: unknown field 'robot'; did you mean 'robots'?"
        );
        assert_eq!(
            err(
                json!({"sample": {"count": 2, "ranges": {"robots": {"min": 0, "max": 3, "integer": true}}}})
            ),
            "sample.ranges.robots: amas-L with robots=0: at least one robot is needed"
        );
        assert_eq!(
            err(json!({"stop": "metrics.placd >= 20"})),
            "stop: 'metrics.placd' is not a metric of amas; did you mean 'metrics.placed'?"
        );
        assert_eq!(
            err(json!({"trace": {"metrics": ["colisions"]}})),
            "trace.metrics[0]: 'colisions' is not a metric of amas; did you mean 'collisions'?"
        );
        assert!(err(json!({"stop": "steps"})).starts_with("stop: the goal is a number"));
        assert_eq!(
            err(
                json!({"grid": {"robots": [1]}, "sample": {"count": 1, "ranges": {"robots": {"min": 1, "max": 2}}}})
            ),
            "sample.ranges.robots: is also a grid key; a key is either listed or sampled"
        );
    }

    #[test]
    fn a_sampled_sweep_with_a_stop_condition_runs_each_point_until_it_holds() {
        let e = experiment(json!({
            "grid": {"field": ["continuous", "discrete"]},
            "sample": {"count": 3, "seed": 5, "ranges": {"robots": {"min": 2, "max": 6, "integer": true}}},
            "stop": "metrics.placed >= 10",
        }))
        .unwrap();
        let jobs = e.jobs();
        assert_eq!(
            (jobs.len(), e.job_count()),
            (12, 12),
            "2 fields × 3 points × 2 seeds"
        );
        assert_eq!(e.param_keys(), vec!["field", "robots"]);
        for job in jobs.iter().step_by(5) {
            let row = e.run_job(job).unwrap();
            assert!(
                row.metrics["placed"].as_u64().unwrap() >= 10,
                "{:?}",
                job.params
            );
            assert!(!row.completed);
            assert_eq!(e.run_job(job).unwrap(), row, "a run replays");
        }
        // Without the stop condition the same job runs on to its end.
        let mut whole = e.clone();
        whole.stop = None;
        let row = whole.run_job(&jobs[0]).unwrap();
        assert!(row.completed && row.steps > e.run_job(&jobs[0]).unwrap().steps);
    }

    #[test]
    fn a_sample_names_what_is_wrong() {
        let err = |v: Value| Sample::read(v).unwrap_err().to_string();
        assert_eq!(
            err(json!({"method": "sobol", "count": 2, "ranges": {"a": {"min": 0, "max": 1}}})),
            "sample.method: 'sobol' is not a method; expected 'latin' or 'random'"
        );
        assert_eq!(
            err(json!({"count": 2, "ranges": {"a": {"min": 0, "mx": 1}}})),
            "sample.ranges.a.mx: unknown field 'mx'; did you mean 'max'?"
        );
        assert_eq!(
            err(json!({"count": 0, "ranges": {"a": {"min": 0, "max": 1}}})),
            "sample.count: expected a whole number from 1 to 100000"
        );
        assert_eq!(
            err(json!({"count": 2, "ranges": {"a": {"min": 0.5, "max": 1, "integer": true}}})),
            "sample.ranges.a.integer: whole-number draws need whole-number min and max"
        );
    }
}
