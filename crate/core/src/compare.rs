//! Two runs side by side: a scenario's optional `compare` section names the one setting in which
//! a second run differs from it.
//!
//! ```json
//! "compare": { "path": "field", "value": "discrete",
//!              "label": "discrete field", "base_label": "continuous field" }
//! ```
//!
//! The scenario itself is the first run (`base_label`); the second is the same scenario with
//! `path` set to `value` (`label`), without the `compare` and `exercise` sections. Both are read
//! and checked when the scenario is: a section whose second run would be invalid, or the same as
//! the first, is refused by name. The section changes nothing of the first run, so a scenario
//! without it reads, writes and hashes as before; the link that holds the scenario holds both runs.

use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::error::{Error, Result};
use kumiki_model::entry::{envelope_role, Role};

/// The longest label, in characters.
pub const MAX_LABEL_CHARS: usize = 60;

/// A scenario's `compare` section: the one setting the second run changes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Compare {
    /// The dotted path of the setting the second run changes (`field`, `adaptation`,
    /// `stages.0.robots`, `seed`).
    pub path: String,
    /// The setting's value in the second run.
    pub value: Value,
    /// The second run's name in words ("adaptation off"); by default PATH VALUE.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[schemars(length(max = MAX_LABEL_CHARS))]
    pub label: String,
    /// The first run's (the scenario's own) name in words ("adaptation on"); by default PATH and
    /// the scenario's value.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[schemars(length(max = MAX_LABEL_CHARS))]
    pub base_label: String,
}

impl Compare {
    /// Reads a `compare` section against the scenario document `doc` (the scenario without it):
    /// the path must name a setting of the run, the value must differ from it, and the labels
    /// must tell the runs apart.
    pub fn from_value(section: Value, doc: &Value) -> Result<Compare> {
        let compare: Compare =
            serde_json::from_value(section).map_err(|e| Error::field("", e.to_string()))?;
        let head = compare.path.split('.').next().unwrap_or_default();
        // The envelope's other keys name or describe the scenario, or are sections themselves:
        // varying them would not change the run.
        let fixed = envelope_role(head).is_some_and(|role| role != Role::Setting);
        if compare.path.is_empty() || fixed {
            return Err(Error::field(
                "path",
                format!(
                    "'{}' is not a setting a second run can change",
                    compare.path
                ),
            ));
        }
        let base = lookup(doc, &compare.path)
            .ok_or_else(|| Error::field("path", format!("no setting '{}'", compare.path)))?;
        // A number is the same number however it is written: the page writes a float 2.0 as 2.
        let same = match (base.as_f64(), compare.value.as_f64()) {
            (Some(a), Some(b)) => a == b,
            _ => *base == compare.value,
        };
        if same {
            return Err(Error::field(
                "value",
                "is the scenario's own value; the second run would be the same",
            ));
        }
        for (key, text) in [
            ("label", &compare.label),
            ("base_label", &compare.base_label),
        ] {
            let chars = text.chars().count();
            if chars > MAX_LABEL_CHARS {
                return Err(Error::field(
                    key,
                    format!("{chars} characters is too long; at most {MAX_LABEL_CHARS}"),
                ));
            }
        }
        let (first, second) = compare.labels(doc);
        if first == second {
            return Err(Error::field(
                "label",
                "is the first run's label too; the chart could not tell them apart",
            ));
        }
        Ok(compare)
    }

    /// The two runs' names in words, the first run's (the scenario `doc`'s own) first. A label
    /// left empty is the setting's path and value, read from `doc` as it stands, so it follows
    /// edits of the first run's setting.
    pub fn labels(&self, doc: &Value) -> (String, String) {
        let words = |v: Option<&Value>| match v {
            Some(Value::String(s)) => s.clone(),
            Some(other) => other.to_string(),
            None => "?".into(),
        };
        let named = |label: &str, value: Option<&Value>| match label {
            "" => format!("{} {}", self.path, words(value)),
            own => own.to_string(),
        };
        (
            named(&self.base_label, lookup(doc, &self.path)),
            named(&self.label, Some(&self.value)),
        )
    }
}

/// The value at a dotted path of a JSON document (numeric segments index lists).
/// A slot without a script runs the paper's rule, which a scenario writes as no key: null.
fn lookup<'a>(doc: &'a Value, path: &str) -> Option<&'a Value> {
    let found = path.split('.').try_fold(doc, |here, seg| match here {
        Value::Object(map) => map.get(seg),
        Value::Array(items) => items.get(seg.parse::<usize>().ok()?),
        _ => None,
    });
    let rule = path.split('.').count() == 2 && path.starts_with("rules.");
    found.or(rule.then_some(&Value::Null))
}

#[cfg(test)]
mod tests {
    use serde_json::{json, Value};

    use crate::presets;
    use crate::run::Run;
    use crate::scenario::Scenario;

    fn with_compare(section: Value) -> crate::error::Result<Scenario> {
        let mut doc = presets::scenario("amas-L").unwrap().to_value();
        doc["compare"] = section;
        Scenario::from_value(doc)
    }

    #[test]
    fn a_scenario_without_a_comparison_writes_as_before() {
        let plain = presets::scenario("amas-L").unwrap();
        assert!(plain.compare.is_none());
        assert!(!plain.to_json().contains("compare"));
        assert!(plain.compared().unwrap().is_none());
    }

    #[test]
    fn the_second_run_is_the_scenario_with_the_one_setting_changed() {
        let s = with_compare(json!({"path": "field", "value": "discrete"})).unwrap();
        let c = s.compare.as_ref().unwrap();
        assert_eq!(
            c.labels(&s.to_value()),
            ("field continuous".into(), "field discrete".into())
        );
        let second = s.compared().unwrap().unwrap();
        let expected = presets::scenario("amas-L")
            .unwrap()
            .with_override("field", json!("discrete"))
            .unwrap();
        assert_eq!(second.to_json(), expected.to_json());
        // The section changes nothing of the first run, and it survives writing and reading.
        let again = Scenario::from_json(&s.to_json()).unwrap();
        assert_eq!(again, s);
        let mut first = Run::new(s.clone()).unwrap();
        let mut plain = Run::new(presets::scenario("amas-L").unwrap()).unwrap();
        first.run_to_end();
        plain.run_to_end();
        assert_eq!(first.state_hash(), plain.state_hash());
    }

    #[test]
    fn a_comparison_that_changes_nothing_or_breaks_the_run_is_refused_by_name() {
        let err = |section: Value| with_compare(section).unwrap_err().to_string();
        assert_eq!(
            err(json!({"path": "field", "value": "continuous"})),
            "compare.value: is the scenario's own value; the second run would be the same"
        );
        // The same number written as an integer: the page's JavaScript writes 2.0 as 2.
        let mut fracta = presets::scenario("fracta-deadlock").unwrap().to_value();
        assert_eq!(fracta["irritation_gain"], json!(2.0));
        fracta["compare"] = json!({"path": "irritation_gain", "value": 2});
        assert_eq!(
            Scenario::from_value(fracta).unwrap_err().to_string(),
            "compare.value: is the scenario's own value; the second run would be the same"
        );
        assert_eq!(
            err(json!({"path": "name", "value": "x"})),
            "compare.path: 'name' is not a setting a second run can change"
        );
        assert_eq!(
            err(json!({"path": "robotz", "value": 3})),
            "compare.path: no setting 'robotz'"
        );
        assert!(err(json!({"path": "robots", "value": 0})).starts_with("compare.robots:"));
        assert!(err(json!({"path": "field", "value": "wavy"})).starts_with("compare.field:"));
        assert!(
            err(json!({"path": "field", "value": "discrete", "colour": 1})).starts_with("compare:")
        );
        assert!(err(
            json!({"path": "field", "value": "discrete", "label": "a", "base_label": "a"})
        )
        .starts_with("compare.label:"));
    }
}
