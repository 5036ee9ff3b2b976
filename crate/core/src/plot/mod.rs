//! Plot specifications, part of the experiment contract: typed and checked when an experiment is
//! read, like scenarios. A plot names the rows' values by path (`steps`, `params.robots`,
//! `metrics.total_steps`), the statistic drawn (`mean` or `median`) and the spread around it;
//! [`figure`] computes what is drawn and how it is described, [`svg`] lays it out ([`draw`]) and
//! writes it as SVG or, by [`pdf`], as PDF, in one font ([`text`]) with one rule for numbers
//! ([`number`]), and [`stats`] holds the statistics the summaries report. The page and `kumiki sweep --plot svg` draw the
//! same figures from the same code.

#[cfg(test)]
mod clip_tests;
mod compared;
pub mod draw;
pub mod figure;
mod labels;
pub mod number;
pub mod pdf;
pub mod stats;
pub mod svg;
mod table;
#[cfg(test)]
mod tests;
pub mod text;
mod values;

use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

use crate::error::{from_value, Error, Result};

/// What a line or bar stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Statistic {
    Mean,
    Median,
}

/// The band or whisker around the statistic.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Spread {
    None,
    /// The runs' smallest to largest value.
    Minmax,
    /// One sample standard deviation either side of the mean, clipped to the runs' range.
    Sd,
    /// The 95% confidence interval of the mean (Student's t).
    Ci95,
    /// The interquartile range, first to third quartile (`quartiles` is read as `iqr`).
    #[serde(alias = "quartiles")]
    Iqr,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Carry {
    /// A run that ended early keeps its final value.
    Last,
    /// A run that ended early drops out.
    None,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Where {
    Completed,
}

/// A path or a list of paths.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Paths {
    One(String),
    Many(Vec<String>),
}

impl Paths {
    pub fn list(&self) -> Vec<&str> {
        match self {
            Paths::One(p) => vec![p.as_str()],
            Paths::Many(ps) => ps.iter().map(String::as_str).collect(),
        }
    }
}

/// y against x, one line per series value, the statistic over seeds with a spread.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Lines {
    #[serde(default)]
    pub title: String,
    pub x: String,
    pub y: Paths,
    pub series: Option<String>,
    pub facet: Option<String>,
    pub statistic: Option<Statistic>,
    pub spread: Option<Spread>,
    pub x_label: Option<String>,
    pub y_label: Option<String>,
    #[serde(default)]
    pub log_y: bool,
}

/// A traced metric against step.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Trace {
    #[serde(default)]
    pub title: String,
    pub y: String,
    pub series: Option<String>,
    pub facet: Option<String>,
    pub statistic: Option<Statistic>,
    pub spread: Option<Spread>,
    pub carry: Option<Carry>,
    pub x_label: Option<String>,
    pub y_label: Option<String>,
}

/// The distribution of a value.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Histogram {
    #[serde(default)]
    pub title: String,
    pub value: String,
    pub series: Option<String>,
    pub bins: Option<u32>,
    #[serde(rename = "where")]
    pub only: Option<Where>,
    pub x_label: Option<String>,
}

/// The statistic of a value per category.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Bars {
    #[serde(default)]
    pub title: String,
    pub x: String,
    pub y: String,
    pub series: Option<String>,
    pub statistic: Option<Statistic>,
    pub spread: Option<Spread>,
    pub x_label: Option<String>,
    pub y_label: Option<String>,
}

/// A table of n, mean, sd, median, IQR and 95% interval per group, and a comparison when there
/// are two groups.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Summary {
    #[serde(default)]
    pub title: String,
    pub group: Option<Vec<String>>,
    pub values: Option<Vec<String>>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum PlotSpec {
    Lines(Lines),
    Trace(Trace),
    Histogram(Histogram),
    Bars(Bars),
    Summary(Summary),
}

pub const KINDS: &str = "lines, trace, histogram, bars or summary";

/// What the plot paths of an experiment may name.
pub struct Context<'a> {
    /// The grid's keys (`params.<key>`).
    pub params: Vec<&'a str>,
    /// The models the experiment runs (their metrics are `metrics.<name>`).
    pub models: Vec<&'a str>,
    /// The traced metrics.
    pub traced: Vec<&'a str>,
}

const ROW_FIELDS: &[&str] = &["scenario", "seed", "completed", "steps", "hash"];

impl PlotSpec {
    /// The `plot` of an experiment: absent (a summary by scenario), one spec or a list, each
    /// checked against what the experiment's rows hold.
    pub fn read_all(value: Value, ctx: &Context) -> Result<Vec<PlotSpec>> {
        match value {
            Value::Null => Ok(vec![PlotSpec::Summary(Summary {
                title: String::new(),
                group: None,
                values: None,
            })]),
            Value::Array(list) => list
                .into_iter()
                .enumerate()
                .map(|(i, v)| PlotSpec::read(v, ctx).map_err(|e| e.within(&format!("plot[{i}]"))))
                .collect(),
            one => Ok(vec![PlotSpec::read(one, ctx).map_err(|e| e.within("plot"))?]),
        }
    }

    pub fn read(value: Value, ctx: &Context) -> Result<PlotSpec> {
        let Value::Object(mut map) = value else {
            return Err(Error::field("", "a plot is an object with a kind"));
        };
        let kind = match map.remove("kind") {
            Some(Value::String(k)) => k,
            _ => return Err(Error::field("kind", format!("is required: {KINDS}"))),
        };
        let body = Value::Object(map);
        let spec = match kind.as_str() {
            "lines" => PlotSpec::Lines(from_value(body)?),
            "trace" => PlotSpec::Trace(from_value(body)?),
            "histogram" => PlotSpec::Histogram(from_value(body)?),
            "bars" => PlotSpec::Bars(from_value(body)?),
            "summary" => PlotSpec::Summary(from_value(body)?),
            other => {
                return Err(Error::field(
                    "kind",
                    format!("'{other}' is not a plot kind; expected {KINDS}"),
                ))
            }
        };
        spec.check(ctx)?;
        Ok(spec)
    }

    /// The spec as JSON, `kind` first, as it is written in an experiment file.
    pub fn to_value(&self) -> Value {
        let (kind, body) = match self {
            PlotSpec::Lines(s) => ("lines", serde_json::to_value(s)),
            PlotSpec::Trace(s) => ("trace", serde_json::to_value(s)),
            PlotSpec::Histogram(s) => ("histogram", serde_json::to_value(s)),
            PlotSpec::Bars(s) => ("bars", serde_json::to_value(s)),
            PlotSpec::Summary(s) => ("summary", serde_json::to_value(s)),
        };
        let mut out = Map::new();
        out.insert("kind".into(), kind.into());
        if let Ok(Value::Object(m)) = body {
            out.extend(m.into_iter().filter(|(_, v)| !v.is_null()));
        }
        Value::Object(out)
    }

    pub fn title(&self) -> &str {
        match self {
            PlotSpec::Lines(s) => &s.title,
            PlotSpec::Trace(s) => &s.title,
            PlotSpec::Histogram(s) => &s.title,
            PlotSpec::Bars(s) => &s.title,
            PlotSpec::Summary(s) => &s.title,
        }
    }

    fn check(&self, ctx: &Context) -> Result<()> {
        let path = |field: &str, p: &str| check_path(p, ctx).map_err(|e| e.within(field));
        let opt = |field: &str, p: &Option<String>| p.as_deref().map_or(Ok(()), |p| path(field, p));
        match self {
            PlotSpec::Lines(s) => {
                path("x", &s.x)?;
                for (i, y) in s.y.list().into_iter().enumerate() {
                    path(&format!("y[{i}]"), y)?;
                }
                opt("series", &s.series)?;
                opt("facet", &s.facet)?;
                statistic_and_spread(s.statistic, s.spread)?;
            }
            PlotSpec::Trace(s) => {
                if !ctx.traced.contains(&s.y.as_str()) {
                    return Err(Error::field(
                        "y",
                        match ctx.traced.is_empty() {
                            true => format!("'{}' is not traced: the experiment has no trace", s.y),
                            false => format!(
                                "'{}' is not traced; traced: {}",
                                s.y,
                                ctx.traced.join(", ")
                            ),
                        },
                    ));
                }
                opt("series", &s.series)?;
                opt("facet", &s.facet)?;
                statistic_and_spread(s.statistic, s.spread)?;
            }
            PlotSpec::Histogram(s) => {
                path("value", &s.value)?;
                opt("series", &s.series)?;
                if let Some(b) = s.bins {
                    if !(2..=200).contains(&b) {
                        return Err(Error::field("bins", "expected 2 to 200 bins"));
                    }
                }
            }
            PlotSpec::Bars(s) => {
                path("x", &s.x)?;
                path("y", &s.y)?;
                opt("series", &s.series)?;
                statistic_and_spread(s.statistic, s.spread)?;
            }
            PlotSpec::Summary(s) => {
                for (i, g) in s.group.iter().flatten().enumerate() {
                    path(&format!("group[{i}]"), g)?;
                }
                for (i, v) in s.values.iter().flatten().enumerate() {
                    path(&format!("values[{i}]"), v)?;
                }
            }
        }
        Ok(())
    }
}

/// The statistic a spread goes with when the spec names none: the median with `iqr`, the mean
/// otherwise.
pub fn statistic_of(statistic: Option<Statistic>, spread: Spread) -> Statistic {
    statistic.unwrap_or(match spread {
        Spread::Iqr => Statistic::Median,
        _ => Statistic::Mean,
    })
}

/// A spread is drawn around the statistic it belongs to: sd and the 95% interval around a mean,
/// the IQR around a median; min to max around either.
fn statistic_and_spread(statistic: Option<Statistic>, spread: Option<Spread>) -> Result<()> {
    match (statistic, spread) {
        (Some(Statistic::Median), Some(s @ (Spread::Sd | Spread::Ci95))) => Err(Error::field(
            "spread",
            format!(
                "{} belongs to a mean, not a median; with a median use iqr, minmax or none",
                spread_word(s)
            ),
        )),
        (Some(Statistic::Mean), Some(Spread::Iqr)) => Err(Error::field(
            "spread",
            "iqr belongs to a median, not a mean; with a mean use sd, ci95, minmax or none",
        )),
        _ => Ok(()),
    }
}

fn spread_word(s: Spread) -> &'static str {
    match s {
        Spread::None => "none",
        Spread::Minmax => "minmax",
        Spread::Sd => "sd",
        Spread::Ci95 => "ci95",
        Spread::Iqr => "iqr",
    }
}

fn check_path(p: &str, ctx: &Context) -> Result<()> {
    if ROW_FIELDS.contains(&p) {
        return Ok(());
    }
    if let Some(key) = p.strip_prefix("params.") {
        return match ctx.params.contains(&key) {
            true => Ok(()),
            false => Err(Error::field(
                "",
                match ctx.params.is_empty() {
                    true => format!("'{p}' names no grid key: the experiment has no grid"),
                    false => format!(
                        "'{p}' names no grid key; the grid has {}",
                        ctx.params
                            .iter()
                            .map(|k| format!("params.{k}"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                },
            )),
        };
    }
    if let Some(name) = p.strip_prefix("metrics.") {
        return crate::models::check_metric(&ctx.models, name, "metrics.");
    }
    Err(Error::field(
        "",
        format!(
            "'{p}' is not a value of a row; expected {}, params.<grid key> or metrics.<metric>",
            ROW_FIELDS.join(", ")
        ),
    ))
}
