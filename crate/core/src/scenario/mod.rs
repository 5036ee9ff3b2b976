//! The scenario: one versioned JSON document that fully determines a run.
//!
//! ```json
//! {
//!   "version": 1,
//!   "model": "amas",
//!   "name": "amas-L",
//!   "description": "The L-shaped benchmark of section 5.",
//!   "seed": 1,
//!   "max_steps": 20000,
//!   "disturbances": [{ "at": 360, "kind": "remove", "count": 10 }],
//!   "rules": { "leader": "fn leader(robot) { ... }" },
//!   "...": "every other key belongs to the model and is checked by it"
//! }
//! ```
//!
//! The envelope keys are read here; the rest is read once into the model's typed description
//! ([`ModelSpec`]), which rejects unknown keys and invalid values by name and is checked, with
//! every scheduled action, without building the model. What the check learns (the shapes laid on
//! the lattice) stays with the description, so the run builds its model without checking it
//! again. A disturbance is applied after `at` steps have run; its other keys are the model's
//! action. `rules` puts scripts in the model's rule slots ([`crate::rules`]).

use serde_json::{Map, Value};

use crate::compare::Compare;
use crate::error::{Error, Result};
use crate::exercise::Exercise;
use crate::handin::Handin;
use crate::limits::Limits;
use crate::models::{self, Action, Model, ModelSpec};
use crate::rules::{self, Rules};
pub use kumiki_model::entry::{envelope_role, EnvelopeKey, Role, ENVELOPE};

mod migrate;
pub use migrate::{migrate, Document, Migration, MIGRATIONS};

/// The scenario format version this build reads and writes.
pub const FORMAT_VERSION: u64 = 1;
/// Seeds travel through JavaScript numbers, so they stay exact integers there.
pub const MAX_SEED: u64 = (1 << 53) - 1;
/// No run may ask for more steps than this.
pub const MAX_STEPS: u64 = 100_000_000;
/// The longest name and description, in characters: a link's title stays a title.
pub const MAX_NAME_CHARS: usize = 100;
pub const MAX_DESCRIPTION_CHARS: usize = 4000;

/// A model action scheduled at a step.
#[derive(Clone, Debug, PartialEq)]
pub struct Disturbance {
    pub at: u64,
    pub action: Action,
}

impl Disturbance {
    /// The disturbance as the scenario writes it: its action with its step `at`.
    pub fn to_value(&self) -> Value {
        let mut m = self.action.clone();
        m.insert("at".into(), self.at.into());
        Value::Object(m)
    }
}

/// A read and validated scenario: the envelope and the model's typed description.
#[derive(Clone, Debug, PartialEq)]
pub struct Scenario {
    pub name: String,
    pub description: String,
    pub seed: u64,
    pub max_steps: u64,
    pub disturbances: Vec<Disturbance>,
    /// A classroom exercise: instructions, locked fields and a goal (see [`crate::exercise`]).
    pub exercise: Option<Exercise>,
    /// A second run to show beside this one, differing in one setting (see [`crate::compare`]).
    pub compare: Option<Compare>,
    /// A hand-in's record of itself: when, how many checks and hints, an answer (see
    /// [`crate::handin`]).
    pub handin: Option<Handin>,
    /// Scripts in the model's rule slots, in place of the paper's rules (see [`crate::rules`]).
    pub rules: Rules,
    /// The model's own keys, read into its typed description.
    pub spec: ModelSpec,
    /// The size limits it was read under; its overrides and its run are held to them too.
    pub limits: &'static Limits,
}

impl Scenario {
    /// Reads and fully validates a scenario from JSON text, within the page's limits.
    pub fn from_json(text: &str) -> Result<Scenario> {
        Scenario::from_json_within(text, &Limits::PAGE)
    }

    /// Reads and fully validates a scenario from a JSON value, within the page's limits.
    pub fn from_value(value: Value) -> Result<Scenario> {
        Scenario::from_value_within(value, &Limits::PAGE)
    }

    /// [`Scenario::from_json`] within `limits`.
    pub fn from_json_within(text: &str, limits: &'static Limits) -> Result<Scenario> {
        #[cfg(test)]
        crate::counts::parse();
        let value: Value = serde_json::from_str(text).map_err(|e| Error::json(&e))?;
        Scenario::from_value_within(value, limits)
    }

    /// [`Scenario::from_value`] within `limits`.
    pub fn from_value_within(value: Value, limits: &'static Limits) -> Result<Scenario> {
        let Value::Object(mut map) = value else {
            return Err(Error::field("", "a scenario is a JSON object"));
        };
        let version = take_u64(&mut map, "version", None, u64::MAX)?;
        let mut map = migrate(version, map)?;
        let model = take_string(&mut map, "model", None)?;
        let entry = models::entry(&model)?;
        let name = take_text(&mut map, "name", MAX_NAME_CHARS)?;
        let description = take_text(&mut map, "description", MAX_DESCRIPTION_CHARS)?;
        let seed = take_u64(&mut map, "seed", Some(1), MAX_SEED)?;
        let max_steps = take_u64(
            &mut map,
            "max_steps",
            Some(entry.default_max_steps),
            MAX_STEPS,
        )?;
        let disturbances = take_disturbances(&mut map)?;
        let rules = Rules::read(map.remove(rules::KEY), entry)?;
        let exercise = map.remove("exercise");
        let compare = map.remove("compare");
        let handin = map
            .remove("handin")
            .map(|v| Handin::from_value(v).map_err(|e| e.within("handin")))
            .transpose()?;
        if max_steps == 0 {
            return Err(Error::field("max_steps", "must be at least 1"));
        }
        let spec = ModelSpec::read(&model, map, limits, disturbances.iter().map(|d| &d.action))?;
        let mut scenario = Scenario {
            name,
            description,
            seed,
            max_steps,
            disturbances,
            exercise: None,
            compare: None,
            handin,
            rules,
            spec,
            limits,
        };
        if let Some(section) = exercise {
            let doc = scenario.to_value();
            scenario.exercise =
                Some(Exercise::from_value(section, &doc).map_err(|e| e.within("exercise"))?);
        }
        if let Some(section) = compare {
            let doc = scenario.to_value();
            scenario.compare =
                Some(Compare::from_value(section, &doc).map_err(|e| e.within("compare"))?);
            scenario.compared().map_err(|e| e.within("compare"))?;
        }
        Ok(scenario)
    }

    /// The same scenario held to other limits (validated again).
    pub fn with_limits(&self, limits: &'static Limits) -> Result<Scenario> {
        Scenario::from_value_within(self.to_value(), limits)
    }

    /// The model's registered name.
    pub fn model(&self) -> &'static str {
        self.spec.model()
    }

    /// The model's keys as JSON, every default written out.
    pub fn body(&self) -> Map<String, Value> {
        self.spec.to_body()
    }

    /// Builds the model at step 0 from what reading the scenario learnt, checking nothing again,
    /// with its rules' scripts in their slots: the one place a scenario becomes a model.
    pub fn build(&self) -> Result<Box<dyn Model>> {
        let mut model = self.spec.build(self.seed, self.limits)?;
        self.install(model.as_mut())?;
        Ok(model)
    }

    /// Puts the scenario's scripts in `model`'s rule slots.
    pub(crate) fn install(&self, model: &mut dyn Model) -> Result<rules::Installed> {
        self.rules.install(model, models::entry(self.model())?)
    }

    /// [`Scenario::build`] for a run that keeps this scenario: what reading it learnt goes into
    /// the model (see [`ModelSpec::build_once`]).
    pub(crate) fn build_once(&mut self) -> Result<Box<dyn Model>> {
        self.spec.build_once(self.seed, self.limits)
    }

    /// The whole scenario as one JSON object, keys sorted.
    pub fn to_value(&self) -> Value {
        let mut map = self.body();
        map.insert("version".into(), FORMAT_VERSION.into());
        map.insert("model".into(), self.model().into());
        map.insert("name".into(), self.name.clone().into());
        map.insert("description".into(), self.description.clone().into());
        map.insert("seed".into(), self.seed.into());
        map.insert("max_steps".into(), self.max_steps.into());
        if !self.disturbances.is_empty() {
            let list = self
                .disturbances
                .iter()
                .map(Disturbance::to_value)
                .collect();
            map.insert("disturbances".into(), Value::Array(list));
        }
        if let Some(exercise) = &self.exercise {
            map.insert(
                "exercise".into(),
                serde_json::to_value(exercise).expect("an exercise serialises"),
            );
        }
        if let Some(compare) = &self.compare {
            map.insert(
                "compare".into(),
                serde_json::to_value(compare).expect("a comparison serialises"),
            );
        }
        if let Some(handin) = &self.handin {
            map.insert(
                "handin".into(),
                serde_json::to_value(handin).expect("a hand-in record serialises"),
            );
        }
        if !self.rules.is_empty() {
            map.insert(rules::KEY.into(), self.rules.to_value());
        }
        canonical(Value::Object(map))
    }

    /// Compact canonical JSON: the form that is hashed and put into links.
    pub fn to_json(&self) -> String {
        self.to_value().to_string()
    }

    /// Indented JSON for files and the page's editor.
    pub fn to_json_pretty(&self) -> String {
        serde_json::to_string_pretty(&self.to_value()).expect("a JSON value always serialises")
    }

    /// Hash of the scenario with the seed left out, so every seed of one configuration shares it.
    pub fn hash_without_seed(&self) -> u64 {
        let mut copy = self.clone();
        copy.seed = 0;
        crate::hash::of_bytes(copy.to_json().as_bytes())
    }

    /// The second run of a comparison: this scenario with the `compare` section's setting
    /// changed, without that section, the exercise and the hand-in's record (both are the first
    /// run's).
    /// `None` when the scenario compares nothing.
    pub fn compared(&self) -> Result<Option<Scenario>> {
        let Some(compare) = &self.compare else {
            return Ok(None);
        };
        let mut doc = self.to_value();
        if let Value::Object(map) = &mut doc {
            map.remove("compare");
            map.remove("exercise");
            map.remove("handin");
        }
        set_path(&mut doc, &compare.path, compare.value.clone())?;
        Scenario::from_value_within(doc, self.limits).map(Some)
    }

    /// A copy with `path` set to `value`, re-validated. Paths are dotted (`stages.0.target`);
    /// numeric segments index arrays.
    pub fn with_override(&self, path: &str, value: Value) -> Result<Scenario> {
        let mut doc = self.to_value();
        set_path(&mut doc, path, value)?;
        Scenario::from_value_within(doc, self.limits)
    }

    /// A copy with several overrides applied at once before validating.
    pub fn with_overrides(&self, overrides: &[(String, Value)]) -> Result<Scenario> {
        let mut doc = self.to_value();
        for (path, value) in overrides {
            set_path(&mut doc, path, value.clone())?;
        }
        Scenario::from_value_within(doc, self.limits)
    }
}

/// Parses the VALUE of `--set PATH=VALUE`: JSON if it parses as JSON, otherwise a string, so
/// `--set field=discrete` and `--set robots=5` both do what they say.
pub fn parse_override(text: &str) -> Result<(String, Value)> {
    let (path, raw) = text
        .split_once('=')
        .ok_or_else(|| Error::field("--set", format!("'{text}' is not PATH=VALUE")))?;
    let path = path.trim();
    if path.is_empty() {
        return Err(Error::field("--set", format!("'{text}' has an empty path")));
    }
    let value = serde_json::from_str(raw).unwrap_or_else(|_| Value::String(raw.to_string()));
    Ok((path.to_string(), value))
}

/// Sets a dotted path in a JSON document, creating the last key if it is missing. A scenario
/// without rules writes no `rules`: a rule set by its path (`rules.leader`) starts the section.
pub fn set_path(doc: &mut Value, path: &str, value: Value) -> Result<()> {
    let segments: Vec<&str> = path.split('.').collect();
    let mut here = doc;
    for (n, seg) in segments.iter().enumerate() {
        let last = n + 1 == segments.len();
        let so_far = segments[..=n].join(".");
        here = match here {
            Value::Object(map) => {
                if last {
                    map.insert((*seg).to_string(), value);
                    return Ok(());
                }
                if n == 0 && *seg == rules::KEY {
                    map.entry(rules::KEY)
                        .or_insert_with(|| Value::Object(Map::new()));
                }
                map.get_mut(*seg)
                    .ok_or_else(|| Error::field(so_far, "no such field"))?
            }
            Value::Array(items) => {
                let len = items.len();
                let i: usize = seg
                    .parse()
                    .map_err(|_| Error::field(&so_far, "this is a list; index it with a number"))?;
                let slot = items.get_mut(i).ok_or_else(|| {
                    Error::field(&so_far, format!("index out of range (the list has {len})"))
                })?;
                if last {
                    *slot = value;
                    return Ok(());
                }
                slot
            }
            _ => {
                return Err(Error::field(
                    segments[..n].join("."),
                    "is not an object or list, so it has no fields",
                ))
            }
        };
    }
    Ok(())
}

/// The same value with object keys sorted at every depth, whatever the map implementation.
pub fn canonical(value: Value) -> Value {
    match value {
        Value::Object(map) => {
            let mut entries: Vec<(String, Value)> = map.into_iter().collect();
            kumiki_model::sort::sort_by(&mut entries, |a, b| a.0.cmp(&b.0));
            Value::Object(
                entries
                    .into_iter()
                    .map(|(k, v)| (k, canonical(v)))
                    .collect(),
            )
        }
        Value::Array(items) => Value::Array(items.into_iter().map(canonical).collect()),
        other => other,
    }
}

fn take_string(map: &mut Map<String, Value>, key: &str, default: Option<&str>) -> Result<String> {
    match map.remove(key) {
        Some(Value::String(s)) => Ok(s),
        Some(other) => Err(Error::field(
            key,
            format!("expected text, found {}", kind(&other)),
        )),
        None => default
            .map(str::to_string)
            .ok_or_else(|| Error::field(key, "is required")),
    }
}

/// Optional text of at most `max` characters.
fn take_text(map: &mut Map<String, Value>, key: &str, max: usize) -> Result<String> {
    let text = take_string(map, key, Some(""))?;
    let chars = text.chars().count();
    match chars <= max {
        true => Ok(text),
        false => Err(Error::field(
            key,
            format!("{chars} characters is too long; at most {max}"),
        )),
    }
}

fn as_u64(key: &str, value: &Value, max: u64) -> Result<u64> {
    match value.as_u64() {
        Some(n) if n <= max => Ok(n),
        Some(n) => Err(Error::field(
            key,
            format!("{n} is larger than the limit {max}"),
        )),
        None => Err(Error::field(
            key,
            format!("expected a whole number of at least 0, found {}", value),
        )),
    }
}

fn take_u64(
    map: &mut Map<String, Value>,
    key: &str,
    default: Option<u64>,
    max: u64,
) -> Result<u64> {
    match map.remove(key) {
        Some(v) => as_u64(key, &v, max),
        None => default.ok_or_else(|| Error::field(key, "is required")),
    }
}

fn take_disturbances(map: &mut Map<String, Value>) -> Result<Vec<Disturbance>> {
    let list = match map.remove("disturbances") {
        None => return Ok(Vec::new()),
        Some(Value::Array(list)) => list,
        Some(other) => {
            return Err(Error::field(
                "disturbances",
                format!("expected a list, found {}", kind(&other)),
            ))
        }
    };
    let mut out = Vec::with_capacity(list.len());
    for (i, item) in list.into_iter().enumerate() {
        let path = format!("disturbances[{i}]");
        let Value::Object(mut action) = item else {
            return Err(Error::field(
                path,
                "expected an object like {\"at\": 10, ...}",
            ));
        };
        let at = match action.remove("at") {
            Some(v) => as_u64(&format!("{path}.at"), &v, MAX_STEPS)?,
            None => return Err(Error::field(format!("{path}.at"), "is required")),
        };
        out.push(Disturbance { at, action });
    }
    // Stable: actions at the same step keep their written order.
    kumiki_model::sort::sort_by_key(&mut out, |d| d.at);
    Ok(out)
}

fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "true/false",
        Value::Number(_) => "a number",
        Value::String(_) => "text",
        Value::Array(_) => "a list",
        Value::Object(_) => "an object",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn set_path_creates_and_indexes() {
        let mut doc = json!({"a": {"b": [1, 2, {"c": 3}]}});
        set_path(&mut doc, "a.b.2.c", json!(9)).unwrap();
        set_path(&mut doc, "a.new", json!("x")).unwrap();
        assert_eq!(doc, json!({"a": {"b": [1, 2, {"c": 9}], "new": "x"}}));
        assert!(set_path(&mut doc, "a.b.7", json!(0))
            .unwrap_err()
            .to_string()
            .contains("a.b.7"));
        assert!(set_path(&mut doc, "a.missing.x", json!(0)).is_err());
        assert!(set_path(&mut doc, "a.b.x", json!(0)).is_err());
    }

    #[test]
    fn override_values_parse_as_json_or_text() {
        assert_eq!(
            parse_override("robots=5").unwrap(),
            ("robots".into(), json!(5))
        );
        assert_eq!(
            parse_override("field=discrete").unwrap(),
            ("field".into(), json!("discrete"))
        );
        assert_eq!(
            parse_override("x=[1,2]").unwrap(),
            ("x".into(), json!([1, 2]))
        );
        assert!(parse_override("robots").is_err());
        assert!(parse_override("=3").is_err());
    }

    #[test]
    fn long_names_and_descriptions_are_refused_by_length() {
        let doc = |name: &str, description: &str| {
            let mut doc = crate::presets::scenario("amas-L").unwrap().to_value();
            doc["name"] = name.into();
            doc["description"] = description.into();
            doc
        };
        assert!(Scenario::from_value(doc(&"n".repeat(MAX_NAME_CHARS), "")).is_ok());
        let err = Scenario::from_value(doc(&"é".repeat(MAX_NAME_CHARS + 1), ""))
            .unwrap_err()
            .to_string();
        assert_eq!(err, "name: 101 characters is too long; at most 100");
        let err = Scenario::from_value(doc("x", &"d".repeat(MAX_DESCRIPTION_CHARS + 1)))
            .unwrap_err()
            .to_string();
        assert!(err.starts_with("description: 4001 characters"), "{err}");
    }

    #[test]
    fn canonical_sorts_keys_at_every_depth() {
        let v = canonical(json!({"b": 1, "a": {"z": 1, "y": [{"q": 1, "p": 2}]}}));
        assert_eq!(v.to_string(), r#"{"a":{"y":[{"p":2,"q":1}],"z":1},"b":1}"#);
    }
}
