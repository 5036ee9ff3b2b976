//! Classroom exercises: a scenario's `exercise` section (what a teacher asks, the fields students
//! may not change, the disturbances they may add, the goal a run must meet, the points its parts
//! give, a question to answer in words and the budget a hand-in is replayed within). The goal
//! language is in [`goal`], the disturbances' rule in [`allow`], the points in [`credit`]; the
//! grading of a hand-in against an exercise is in [`crate::grading`].

mod allow;
mod credit;
mod goal;

pub use allow::{listed, Allowance, MAX_ALLOWED};
pub use credit::{Credit, Part, Verdict, MAX_PARTS, MAX_POINTS};
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
pub const MAX_QUESTION_CHARS: usize = 1000;

/// The path of the scenario's disturbances. Locked, it keeps the teacher's disturbances (each one
/// as it is); what students may add beside them is the exercise's `disturbances`.
pub const DISTURBANCES: &str = "disturbances";

/// A scenario's `exercise` section: what a teacher asks, which fields students may not change,
/// and the goal a run must meet.
///
/// ```json
/// "exercise": {
///   "title": "Fewer collisions",
///   "instructions": "Change the collision rule so that the L is built with *fewer* collisions.",
///   "locked": { "robots": 10, "target": "...", "disturbances": [] },
///   "disturbances": { "remove": 3 },
///   "goal": "completed and metrics.collisions < 20",
///   "credit": [{ "goal": "completed", "points": 5 }, { "goal": "metrics.collisions < 40", "points": 2 }],
///   "question": "Why does the relay help?",
///   "budget": { "steps": 100000 },
///   "hints": ["Section 4.2 compares three rules."]
/// }
/// ```
/// `locked` maps dotted scenario paths to the teacher's values: the page shows those fields
/// read-only, and `kumiki check` reports a hand-in whose values differ. Every change a student
/// can make is a field or a disturbance: a disturbance (a click of the page's tools, or one
/// written into the scenario) beyond the teacher's is allowed only as `disturbances` says, by
/// kind and count; none when it says nothing.
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
    /// The disturbances students may add beside the teacher's, by the model's action kind
    /// (`remove`, `extend`, `fault`, ...), with how many of each: `{"remove": 3}` allows at most
    /// three "Remove module" clicks and nothing else. Left out or empty, none may be added.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    #[schemars(extend("additionalProperties" = {"type": "integer", "minimum": 0, "maximum": MAX_ALLOWED}))]
    pub disturbances: Allowance,
    /// Points for parts of the outcome, each a goal of its own: a hand-in earns the points of
    /// every part it meets, whether or not it meets the whole goal.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    #[schemars(length(max = MAX_PARTS))]
    pub credit: Vec<Part>,
    /// A question the student answers in words, handed in with the link and shown to the
    /// teacher; it is not graded.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[schemars(length(max = MAX_QUESTION_CHARS))]
    pub question: String,
    /// How long a hand-in may take to replay: a run not ended within it is stopped and marked
    /// "over budget" (`kumiki check` and the page's grading alike).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub budget: Option<Budget>,
}

/// The most a hand-in's replay may take: steps (the same on every machine) or seconds of the
/// grading machine's time, or both (whichever comes first).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Budget {
    /// Steps: a run that has not ended after this many is stopped.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(range(min = 1, max = crate::scenario::MAX_STEPS))]
    pub steps: Option<u64>,
    /// Seconds of replay on the machine that grades (building the run included).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schemars(range(min = 0.001, max = MAX_BUDGET_SECONDS))]
    pub seconds: Option<f64>,
}

/// The longest time budget, in seconds: an hour.
pub const MAX_BUDGET_SECONDS: f64 = 3600.0;

impl Exercise {
    /// Reads and checks an exercise section; `doc` is the whole scenario, in which every locked
    /// path must name a field.
    pub fn from_value(value: Value, doc: &Value) -> Result<Exercise> {
        let mut exercise = Exercise::checked(value)?;
        // The teacher's disturbances are always kept: an exercise that does not lock them keeps
        // those of the scenario it is read with (an exercise made before disturbances could be
        // locked, or one written by hand), and writes them back locked.
        exercise
            .locked
            .entry(DISTURBANCES.to_string())
            .or_insert_with(|| Value::Array(allow::listed(doc).to_vec()));
        for path in exercise.locked.keys() {
            if path != DISTURBANCES && lookup_path(doc, path).is_none() {
                return Err(Error::field(
                    format!("locked.{path}"),
                    "no such field in this scenario",
                ));
            }
        }
        Ok(exercise)
    }

    /// Reads and checks an exercise section on its own: its texts, goal, credit, budget and what
    /// it allows and locks, but not whether its locked paths name fields of a scenario.
    pub fn checked(value: Value) -> Result<Exercise> {
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
        long("question", &exercise.question, MAX_QUESTION_CHARS)?;
        Goal::parse(&exercise.goal).map_err(|e| e.within("goal"))?;
        allow::check(&exercise.disturbances)?;
        credit::check(&exercise.credit)?;
        if let Some(budget) = &exercise.budget {
            check_budget(budget).map_err(|e| e.within("budget"))?;
        }
        if exercise
            .locked
            .get(DISTURBANCES)
            .is_some_and(|v| !v.is_array())
        {
            return Err(Error::field(
                format!("locked.{DISTURBANCES}"),
                "the teacher's disturbances are a list, as the scenario's `disturbances`",
            ));
        }
        for path in exercise.locked.keys() {
            if path == "exercise" || path.starts_with("exercise.") {
                return Err(Error::field(
                    format!("locked.{path}"),
                    "the exercise itself cannot be locked; it is never editable by students",
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
    /// The locked disturbances are not among them: they are kept by [`Exercise::disturbance_problems`],
    /// with what students may add beside them.
    pub fn locked_changes(&self, doc: &Value) -> Vec<(String, Value, Value)> {
        self.locked
            .iter()
            .filter(|(path, _)| path.as_str() != DISTURBANCES)
            .filter_map(|(path, want)| {
                let got = lookup_path(doc, path).cloned().unwrap_or(Value::Null);
                (!same(&got, want)).then(|| (path.clone(), want.clone(), got))
            })
            .collect()
    }
}

/// A budget with at least one bound, each within its range.
fn check_budget(budget: &Budget) -> Result<()> {
    match (budget.steps, budget.seconds) {
        (None, None) => Err(Error::field(
            "",
            "give 'steps', 'seconds' or both: the most a hand-in's replay may take",
        )),
        (Some(0), _) => Err(Error::field("steps", "must be at least 1")),
        (Some(n), _) if n > crate::scenario::MAX_STEPS => Err(Error::field(
            "steps",
            format!(
                "{n} is larger than the limit {}",
                crate::scenario::MAX_STEPS
            ),
        )),
        (_, Some(s)) if !(s.is_finite() && (0.001..=MAX_BUDGET_SECONDS).contains(&s)) => {
            Err(Error::field(
                "seconds",
                format!("must be a number of seconds from 0.001 to {MAX_BUDGET_SECONDS}"),
            ))
        }
        _ => Ok(()),
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
