//! Classroom exercises: a scenario's `exercise` section (what a teacher asks, the fields students
//! may not change, the goal a run must meet). The goal language is in [`goal`]; the grading of a
//! hand-in against an exercise is in [`crate::grading`].

mod goal;

pub use goal::{Check, Goal, Outcome, MAX_GOAL_CHARS};

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::error::{Error, Result};

/// Length limits of an exercise's texts, in characters.
pub const MAX_TITLE_CHARS: usize = 100;
pub const MAX_INSTRUCTIONS_CHARS: usize = 10_000;
pub const MAX_HINTS: usize = 10;
pub const MAX_HINT_CHARS: usize = 1000;

/// A scenario's `exercise` section: what a teacher asks, which fields students may not change,
/// and the goal a run must meet.
///
/// ```json
/// "exercise": {
///   "title": "Fewer collisions",
///   "instructions": "Change the collision rule so that the L is built with *fewer* collisions.",
///   "locked": { "robots": 10, "target": "..." },
///   "goal": "completed and metrics.collisions < 20",
///   "hints": ["Section 4.2 compares three rules."]
/// }
/// ```
/// `locked` maps dotted scenario paths to the teacher's values: the page shows those fields
/// read-only, and `kumiki check` reports a hand-in whose values differ.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Exercise {
    /// The exercise's title.
    #[schemars(length(max = MAX_TITLE_CHARS))]
    pub title: String,
    /// What the student is asked to do.
    #[serde(default)]
    #[schemars(length(max = MAX_INSTRUCTIONS_CHARS))]
    pub instructions: String,
    /// Dotted scenario paths and the teacher's values: fields students may not change.
    #[serde(default)]
    pub locked: BTreeMap<String, Value>,
    /// A condition on the run's outcome, such as `completed and steps <= 800`.
    #[schemars(length(max = MAX_GOAL_CHARS))]
    pub goal: String,
    /// Hints shown one at a time.
    #[serde(default)]
    #[schemars(length(max = MAX_HINTS), inner(length(max = MAX_HINT_CHARS)))]
    pub hints: Vec<String>,
}

impl Exercise {
    /// Reads and checks an exercise section; `doc` is the whole scenario, in which every locked
    /// path must name a field.
    pub fn from_value(value: Value, doc: &Value) -> Result<Exercise> {
        let exercise: Exercise = crate::error::from_value(value)?;
        let long = |path: &str, text: &str, max: usize| {
            let n = text.chars().count();
            match n > max {
                true => Err(Error::field(
                    path,
                    format!("{n} characters is too long; at most {max}"),
                )),
                false => Ok(()),
            }
        };
        long("title", &exercise.title, MAX_TITLE_CHARS)?;
        long(
            "instructions",
            &exercise.instructions,
            MAX_INSTRUCTIONS_CHARS,
        )?;
        if exercise.hints.len() > MAX_HINTS {
            return Err(Error::field(
                "hints",
                format!(
                    "{} hints are too many; at most {MAX_HINTS}",
                    exercise.hints.len()
                ),
            ));
        }
        for (i, hint) in exercise.hints.iter().enumerate() {
            long(&format!("hints[{i}]"), hint, MAX_HINT_CHARS)?;
        }
        Goal::parse(&exercise.goal).map_err(|e| e.within("goal"))?;
        for path in exercise.locked.keys() {
            if path == "exercise" || path.starts_with("exercise.") {
                return Err(Error::field(
                    format!("locked.{path}"),
                    "the exercise itself cannot be locked; it is never editable by students",
                ));
            }
            if lookup_path(doc, path).is_none() {
                return Err(Error::field(
                    format!("locked.{path}"),
                    "no such field in this scenario",
                ));
            }
        }
        Ok(exercise)
    }

    /// The goal, parsed (it was checked when the exercise was read).
    pub fn goal(&self) -> Goal {
        Goal::parse(&self.goal).expect("the goal was checked when the exercise was read")
    }

    /// The locked fields whose value in `doc` is not the teacher's: (path, teacher's, found).
    pub fn locked_changes(&self, doc: &Value) -> Vec<(String, Value, Value)> {
        self.locked
            .iter()
            .filter_map(|(path, want)| {
                let got = lookup_path(doc, path).cloned().unwrap_or(Value::Null);
                (!same(&got, want)).then(|| (path.clone(), want.clone(), got))
            })
            .collect()
    }
}

/// Equal JSON values, numbers by their value: 10 and 10.0 are one number (the page's JavaScript
/// writes a teacher's 10.0 as 10, and the core writes a float field back as 10.0).
pub(crate) fn same(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => x == y || x.as_f64() == y.as_f64(),
        (Value::Array(x), Value::Array(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|(a, b)| same(a, b))
        }
        (Value::Object(x), Value::Object(y)) => {
            x.len() == y.len() && x.iter().all(|(k, v)| y.get(k).is_some_and(|w| same(v, w)))
        }
        _ => a == b,
    }
}

/// The value at a dotted path (`stages.0.robots`) of a JSON document.
pub fn lookup_path<'a>(doc: &'a Value, path: &str) -> Option<&'a Value> {
    path.split('.').try_fold(doc, |here, seg| match here {
        Value::Object(map) => map.get(seg),
        Value::Array(items) => seg.parse::<usize>().ok().and_then(|i| items.get(i)),
        _ => None,
    })
}

/// The dotted paths at which two documents differ, down to the values that differ (lists of
/// different lengths count as one difference).
pub fn differences(a: &Value, b: &Value) -> Vec<String> {
    fn walk(a: &Value, b: &Value, at: &str, out: &mut Vec<String>) {
        let join = |k: &str| {
            if at.is_empty() {
                k.to_string()
            } else {
                format!("{at}.{k}")
            }
        };
        match (a, b) {
            (Value::Object(x), Value::Object(y)) => {
                let mut keys: Vec<&String> = x.keys().chain(y.keys()).collect();
                kumiki_model::sort::sort(&mut keys);
                keys.dedup();
                for k in keys {
                    match (x.get(k), y.get(k)) {
                        (Some(p), Some(q)) => walk(p, q, &join(k), out),
                        _ => out.push(join(k)),
                    }
                }
            }
            (Value::Array(x), Value::Array(y)) if x.len() == y.len() => {
                for (i, (p, q)) in x.iter().zip(y).enumerate() {
                    walk(p, q, &join(&i.to_string()), out);
                }
            }
            (p, q) if p != q => out.push(at.to_string()),
            _ => {}
        }
    }
    let mut out = Vec::new();
    walk(a, b, "", &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn exercise_doc(exercise: Value) -> Value {
        let mut doc = crate::presets::scenario("amas-L").unwrap().to_value();
        doc["exercise"] = exercise;
        doc
    }

    #[test]
    fn an_exercise_travels_in_the_scenario_and_its_link() {
        let doc = exercise_doc(json!({
            "title": "Fewer collisions",
            "instructions": "Change *one* thing.",
            "locked": {"robots": 5, "field": "continuous"},
            "goal": "completed and metrics.collisions < 20",
            "hints": ["Section 4.2."]
        }));
        let s = crate::Scenario::from_value(doc).unwrap();
        let e = s.exercise.clone().unwrap();
        assert_eq!(e.title, "Fewer collisions");
        assert_eq!(e.goal().names(), vec!["completed", "metrics.collisions"]);
        let back = crate::link::decode(&crate::link::encode(&s)).unwrap();
        assert_eq!(back, s);
        assert!(e.locked_changes(&s.to_value()).is_empty());
        let edited = s.with_override("robots", json!(7)).unwrap();
        assert_eq!(
            e.locked_changes(&edited.to_value()),
            vec![("robots".to_string(), json!(5), json!(7))]
        );
        assert_eq!(
            differences(&s.to_value(), &edited.to_value()),
            vec!["robots"]
        );
    }

    #[test]
    fn bad_exercises_name_the_field() {
        let err = |exercise: Value| {
            crate::Scenario::from_value(exercise_doc(exercise))
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            err(json!({"title": "t", "goal": "steps = 3"})),
            "exercise.goal: column 7: '=' alone is not a comparison; write '=='"
        );
        assert_eq!(
            err(json!({"title": "t", "goal": "completed", "locked": {"robot": 5}})),
            "exercise.locked.robot: no such field in this scenario"
        );
        assert_eq!(
            err(json!({"title": "t", "goal": "completed", "locked": {"exercise.goal": 1}})),
            "exercise.locked.exercise.goal: the exercise itself cannot be locked; it is never editable by students"
        );
        assert!(err(json!({"goal": "completed"})).starts_with("exercise: 'title' is required"));
        assert!(err(json!({"title": "t", "goal": "completed", "extra": 1}))
            .contains("unknown field 'extra'"));
        assert!(
            err(json!({"title": "t", "goal": "completed", "hints": vec!["h"; 11]}))
                .contains("at most 10")
        );
    }

    #[test]
    fn a_locked_number_is_compared_by_value_as_the_page_writes_it() {
        // The page's JavaScript reads a teacher's 200.0 as 200; the core writes the field as 200.0.
        let doc =
            exercise_doc(json!({"title": "t", "goal": "completed", "locked": {"robots": 5.0}}));
        let s = crate::Scenario::from_value(doc).unwrap();
        let e = s.exercise.clone().unwrap();
        assert!(e.locked_changes(&s.to_value()).is_empty());
        assert!(same(&json!({"a": [10, 0.5]}), &json!({"a": [10.0, 0.5]})));
        assert!(!same(&json!([10]), &json!([10.5])));
        assert!(!same(&json!({"a": 1}), &json!({"a": 1, "b": 2})));
        let edited = s.with_override("robots", json!(6)).unwrap();
        assert_eq!(e.locked_changes(&edited.to_value()).len(), 1);
    }
}
