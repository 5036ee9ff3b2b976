//! What a figure names in words: a path's name and unit, an axis label, the statistic and the
//! spread, a condition and a facet's title.

use super::{Spread, Statistic};

/// A path's name in words: `params.tip_load` is "tip load", `params.disturbances.0.count`
/// "disturbances 0 count".
pub fn name_of(path: &str) -> String {
    let short = path
        .strip_prefix("params.")
        .or_else(|| path.strip_prefix("metrics."))
        .unwrap_or(path);
    short.replace(['_', '.'], " ")
}

/// The unit of a path, from the models' metric tables (the first model that has the metric).
pub fn unit_of(path: &str, models: &[&str]) -> Option<&'static str> {
    if path == "steps" {
        return Some("steps");
    }
    let name = path.strip_prefix("metrics.")?;
    models
        .iter()
        .find_map(|m| crate::models::metric_info(m, name))
        .map(|i| i.unit)
}

/// An axis label: the spec's, or the path's name; with the unit in brackets unless it says it.
pub(super) fn axis_label(given: Option<&str>, path: &str, models: &[&str]) -> String {
    let label = given.map_or_else(|| name_of(path), str::to_string);
    match unit_of(path, models) {
        Some(unit) if !label.contains(unit) => format!("{label} [{unit}]"),
        _ => label,
    }
}

/// "mean", "median".
pub fn statistic_words(s: Statistic) -> &'static str {
    match s {
        Statistic::Mean => "mean",
        Statistic::Median => "median",
    }
}

/// The spread in words, as the figure names it.
pub fn spread_words(s: Spread) -> &'static str {
    match s {
        Spread::None => "",
        Spread::Minmax => "min to max",
        Spread::Sd => "± one standard deviation (clipped to the runs' range)",
        Spread::Ci95 => "95% confidence interval",
        Spread::Iqr => "interquartile range",
    }
}

/// A condition in words: "adaptation: on, tip load: 2".
pub fn condition_words(group: &[String], key: &[String]) -> String {
    group
        .iter()
        .zip(key)
        .map(|(g, v)| format!("{}: {v}", name_of(g)))
        .collect::<Vec<_>>()
        .join(", ")
}

pub(super) fn facet_title(path: Option<&str>, value: &str) -> String {
    path.map_or(String::new(), |p| format!("{}: {value}", name_of(p)))
}
