//! Built-in scenarios and experiments: one JSON file each in a model crate's `presets/` and
//! `experiments/` (`crate/models/<model>/presets/`, ...), registered by file name (the lessons in
//! its `lessons/` too: see [`crate::lessons`]).

use crate::error::{Error, Result};
use crate::scenario::Scenario;

include!(concat!(env!("OUT_DIR"), "/registry.rs"));

/// Names of the built-in scenarios, sorted.
pub fn names() -> impl Iterator<Item = &'static str> {
    PRESET_FILES.iter().map(|(name, _)| *name)
}

/// What the gallery shows of a built-in scenario.
#[derive(Clone, Debug, PartialEq, serde::Serialize, schemars::JsonSchema)]
pub struct PresetInfo {
    pub name: &'static str,
    pub model: String,
    /// The model's title, as its registry entry gives it.
    pub title: String,
    pub description: String,
}

/// Every built-in scenario, in name order.
pub fn list() -> Result<Vec<PresetInfo>> {
    names()
        .map(|name| {
            let s = scenario(name)?;
            Ok(PresetInfo {
                name,
                title: crate::models::entry(s.model())
                    .map(|m| m.title.to_string())
                    .unwrap_or_default(),
                model: s.model().to_string(),
                description: s.description,
            })
        })
        .collect()
}

/// The JSON text of a preset.
pub fn json(name: &str) -> Result<&'static str> {
    lookup(PRESET_FILES, "preset", name)
}

pub fn scenario(name: &str) -> Result<Scenario> {
    scenario_in(PRESET_FILES, "preset", name)
}

/// How `scenario` differs from the built-in scenario it is named after, each changed field in
/// words (`robots: 10 → 3`, a shape's cells added and removed), the description and the exercise
/// left out; `None` when no preset has its name. A shared edited scenario introduces itself with
/// this rather than with the preset's text alone.
pub fn changes_from_preset(scenario: &Scenario) -> Option<Vec<String>> {
    let preset = scenario_in(PRESET_FILES, "preset", &scenario.name).ok()?;
    Some(changes_between(&preset, scenario))
}

/// How `scenario` differs from `preset` (the built-in scenario it is named after), as
/// [`changes_from_preset`] says it: for a caller that holds the preset's text itself (the page's
/// first-load module, which leaves the built-in scenarios out and fetches them apart).
pub fn changes_between(preset: &Scenario, scenario: &Scenario) -> Vec<String> {
    let (was, now) = (preset.to_value(), scenario.to_value());
    crate::exercise::differences(&was, &now)
        .into_iter()
        .filter(|p| p != "description" && !p.starts_with("exercise"))
        .map(|p| {
            let at = |doc: &serde_json::Value| {
                crate::exercise::lookup_path(doc, &p)
                    .cloned()
                    .unwrap_or(serde_json::Value::Null)
            };
            crate::grading::change_text(&p, &at(&was), &at(&now))
        })
        .collect()
}

/// The scenario `name` of `table` (presets or lessons), its errors naming which `kind` it is.
pub(crate) fn scenario_in(
    table: &'static [(&str, &str)],
    kind: &'static str,
    name: &str,
) -> Result<Scenario> {
    in_file(kind, name, Scenario::from_json(lookup(table, kind, name)?))
}

/// A built-in file's scenario, its errors naming the file: which `kind` it is, and its `name`.
pub(crate) fn in_file(kind: &str, name: &str, read: Result<Scenario>) -> Result<Scenario> {
    read.map_err(|e| match e {
        Error::Field { path, reason } => {
            Error::field(path, format!("{reason} (in {kind} '{name}')"))
        }
        other => other,
    })
}

/// Names of the built-in experiments, sorted.
pub fn experiment_names() -> impl Iterator<Item = &'static str> {
    EXPERIMENT_FILES.iter().map(|(name, _)| *name)
}

pub fn experiment_json(name: &str) -> Result<&'static str> {
    lookup(EXPERIMENT_FILES, "experiment", name)
}

pub(crate) fn lookup(
    table: &'static [(&str, &str)],
    kind: &'static str,
    name: &str,
) -> Result<&'static str> {
    table
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, text)| *text)
        .ok_or_else(|| Error::Unknown {
            kind,
            name: name.to_string(),
            known: table.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", "),
        })
}

#[cfg(test)]
mod tests {
    #[test]
    fn an_edited_preset_says_what_differs_from_it() {
        let mut s = super::scenario("amas-L").unwrap();
        assert_eq!(super::changes_from_preset(&s), Some(vec![]));
        s = s
            .with_overrides(&[
                ("robots".into(), 3.into()),
                ("description".into(), "mine".into()),
            ])
            .unwrap();
        assert_eq!(
            super::changes_from_preset(&s),
            Some(vec!["robots: 5 → 3".to_string()])
        );
        s.name = "mine".into();
        assert_eq!(super::changes_from_preset(&s), None);
    }

    use super::*;
    use crate::models;
    use serde_json::Value;

    #[test]
    fn every_preset_is_valid_and_named_after_its_file() {
        assert!(names().count() > 0);
        for name in names() {
            let s = scenario(name).unwrap_or_else(|e| panic!("preset {name}: {e}"));
            assert_eq!(
                s.name, name,
                "preset file {name}.json must carry \"name\": \"{name}\""
            );
            assert!(
                !s.description.is_empty(),
                "preset {name} needs a description"
            );
            models::entry(s.model()).unwrap();
        }
    }

    #[test]
    fn every_layout_names_a_numeric_chart_metric_and_served_fields() {
        for name in names() {
            let run = crate::Run::new(scenario(name).unwrap()).unwrap();
            let (layout, metrics) = (run.model().layout(), run.model().metrics());
            assert!(
                metrics.get(&layout.chart).is_some_and(|v| v.is_number()),
                "{name}: chart metric '{}' is not a numeric metric",
                layout.chart
            );
            for f in &layout.fields {
                assert!(
                    run.model().field(&f.name).is_some(),
                    "{name}: field {} is not served",
                    f.name
                );
            }
        }
    }

    #[test]
    fn every_experiment_is_valid() {
        for name in experiment_names() {
            let e = crate::experiment::Experiment::from_json(experiment_json(name).unwrap())
                .unwrap_or_else(|e| panic!("experiment {name}: {e}"));
            assert_eq!(e.name, name);
            assert!(!e.jobs().is_empty());
        }
    }

    /// What the scenario reader takes as the envelope is the contract's list, which a model
    /// crate leaves out when it reads one of its own preset files: over the built-in scenarios
    /// (one with disturbances, exercises, a comparison, and a hand-in), and a scenario with rules,
    /// the keys written beside the model's own are exactly [`models::ENVELOPE`].
    #[test]
    fn the_envelope_is_the_contracts_list() {
        let mut beside = std::collections::BTreeSet::new();
        // A hand-in of a lesson carries its record too.
        let handin = crate::lessons::scenario("lesson-amas-robots").and_then(|s| {
            let mut doc = s.to_value();
            doc["handin"] = serde_json::json!({"checks": 1});
            crate::Scenario::from_value(doc)
        });
        let paper = models::entry("chobie").unwrap().slots[0].paper;
        let scripted =
            scenario("chobie-crawl3").and_then(|s| s.with_override("rules.leader", paper.into()));
        for s in names()
            .map(scenario)
            .chain(crate::lessons::names().map(crate::lessons::scenario))
            .chain([handin, scripted])
        {
            let s = s.unwrap();
            let Value::Object(doc) = s.to_value() else {
                unreachable!("a scenario is an object")
            };
            let body = s.body();
            beside.extend(doc.keys().filter(|k| !body.contains_key(*k)).cloned());
            assert!(body.keys().all(|k| models::envelope_role(k).is_none()));
        }
        let mut envelope: Vec<String> =
            models::ENVELOPE.iter().map(|k| k.key.to_string()).collect();
        envelope.sort();
        assert_eq!(beside.into_iter().collect::<Vec<_>>(), envelope);
    }

    #[test]
    fn unknown_preset_lists_the_known_ones() {
        let err = json("no-such").unwrap_err().to_string();
        assert!(err.contains("no-such") && err.contains("known"), "{err}");
    }
}
