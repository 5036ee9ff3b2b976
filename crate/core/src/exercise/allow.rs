//! The disturbances an exercise lets students add: every click of the page's tools (remove or
//! break a module, mark one to be removed, add a target cell, cut a unit's power, add or hold a
//! 3-D unit, put a load down) and every disturbance written into the scenario is one, so none
//! gets past the locks.
//!
//! A scenario's disturbances are the teacher's (the exercise's locked `disturbances`, filled in
//! from the scenario an exercise is read with when it does not lock them) and those a student
//! added. The teacher's stay as they
//! are; the added ones are counted by kind against the exercise's `disturbances` (`{"remove":
//! 3}`): a kind it does not name may not be added at all. The page asks [`Exercise::click_problem`]
//! before it applies a click, grading asks [`Exercise::disturbance_problems`]: one rule.

use std::collections::BTreeMap;

use serde_json::Value;

use super::{same, Exercise, DISTURBANCES};
use crate::error::{Error, Result};

/// What an exercise lets students add: the most of each kind of disturbance.
pub type Allowance = BTreeMap<String, u32>;

/// The most disturbances of one kind an exercise may allow.
pub const MAX_ALLOWED: u32 = 10_000;
/// The longest kind's name, in characters.
const MAX_KIND_CHARS: usize = 40;
/// The most steps listed for one kind before "…".
const MAX_STEPS_LISTED: usize = 5;

/// An allowance whose kinds are names (lower-case letters, digits, `_` and `-`) and whose counts
/// are within [`MAX_ALLOWED`].
pub(super) fn check(allow: &Allowance) -> Result<()> {
    for (kind, &n) in allow {
        let path = format!("disturbances.{kind}");
        let named = !kind.is_empty()
            && kind.chars().count() <= MAX_KIND_CHARS
            && kind
                .chars()
                .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_' || c == '-');
        if !named {
            return Err(Error::field(
                path,
                "a kind of disturbance is the model's name for it, such as 'remove' (its action's \"kind\")",
            ));
        }
        if n > MAX_ALLOWED {
            return Err(Error::field(
                path,
                format!("{n} is more than the {MAX_ALLOWED} an exercise may allow"),
            ));
        }
    }
    Ok(())
}

/// A scenario document's disturbances, each a JSON object with its step `at`.
pub fn listed(doc: &Value) -> &[Value] {
    doc.get(DISTURBANCES)
        .and_then(Value::as_array)
        .map_or(&[], Vec::as_slice)
}

/// A disturbance's kind, as its action names it.
fn kind(d: &Value) -> &str {
    d.get("kind").and_then(Value::as_str).unwrap_or("(no kind)")
}

/// A disturbance's step, as written.
fn step(d: &Value) -> String {
    d.get("at").map_or_else(|| "?".into(), Value::to_string)
}

/// `list` against the teacher's `base`, each one matched once: the teacher's that `list` lacks
/// (left out or changed), and the ones `list` adds.
fn split<'a>(list: &'a [Value], base: &'a [Value]) -> (Vec<&'a Value>, Vec<&'a Value>) {
    let mut used = vec![false; list.len()];
    let mut missing = Vec::new();
    for want in base {
        match (0..list.len()).find(|&i| !used[i] && same(&list[i], want)) {
            Some(i) => used[i] = true,
            None => missing.push(want),
        }
    }
    let added = list
        .iter()
        .zip(&used)
        .filter(|(_, &u)| !u)
        .map(|(d, _)| d)
        .collect();
    (missing, added)
}

/// The steps of `items` in words: "step 25", "steps 25, 30, …".
fn steps_text(items: &[&Value]) -> String {
    let shown: Vec<String> = items
        .iter()
        .take(MAX_STEPS_LISTED)
        .map(|d| step(d))
        .collect();
    let more = if items.len() > MAX_STEPS_LISTED {
        ", …"
    } else {
        ""
    };
    match items.len() {
        1 => format!("step {}", shown[0]),
        _ => format!("steps {}{more}", shown.join(", ")),
    }
}

/// How many of `kind` the allowance lets a student add, in words.
fn allows(n: u32) -> String {
    match n {
        0 => "the exercise allows none".into(),
        n => format!("the exercise allows at most {n}"),
    }
}

impl Exercise {
    /// The teacher's disturbances the exercise keeps, each as written (its locked
    /// `disturbances`, which reading an exercise fills in from its scenario when it lacks them).
    pub fn kept(&self) -> &[Value] {
        self.locked
            .get(DISTURBANCES)
            .and_then(Value::as_array)
            .map_or(&[], Vec::as_slice)
    }

    /// How many disturbances of `kind` students may add.
    pub fn allowed(&self, kind: &str) -> u32 {
        self.disturbances.get(kind).copied().unwrap_or(0)
    }

    /// What is wrong with a scenario's disturbances `list` beside the teacher's kept ones: the
    /// teacher's left out or changed, and each kind added beyond what the exercise allows, with
    /// its steps, in words. Empty when they are as the exercise allows.
    pub fn disturbance_problems(&self, list: &[Value]) -> Vec<String> {
        let (missing, added) = split(list, self.kept());
        let mut out = Vec::new();
        if !missing.is_empty() {
            let named: Vec<String> = missing
                .iter()
                .take(MAX_STEPS_LISTED)
                .map(|d| format!("{} at step {}", kind(d), step(d)))
                .collect();
            let more = if missing.len() > MAX_STEPS_LISTED {
                ", …"
            } else {
                ""
            };
            out.push(format!(
                "the exercise's own disturbances were left out or changed ({}{more})",
                named.join(", ")
            ));
        }
        let mut by_kind: BTreeMap<&str, Vec<&Value>> = BTreeMap::new();
        for d in added {
            by_kind.entry(kind(d)).or_default().push(d);
        }
        for (k, items) in by_kind {
            let allowed = self.allowed(k);
            if items.len() as u64 > u64::from(allowed) {
                let count = match items.len() {
                    1 => String::new(),
                    n => format!("{n} × "),
                };
                out.push(format!(
                    "{count}'{k}' added at {} ({})",
                    steps_text(&items),
                    allows(allowed)
                ));
            }
        }
        out
    }

    /// How many disturbances of `kind` `list` adds beside the teacher's kept ones.
    pub fn added(&self, kind_of: &str, list: &[Value]) -> u32 {
        let (_, added) = split(list, self.kept());
        added.iter().filter(|d| kind(d) == kind_of).count() as u32
    }

    /// Why one more disturbance of `kind` (a click of the tool `label`) may not be added to a
    /// scenario whose disturbances are `list`; `None` when it may.
    pub fn click_problem(&self, kind: &str, label: &str, list: &[Value]) -> Option<String> {
        let allowed = self.allowed(kind);
        let used = self.added(kind, list);
        (used >= allowed).then(|| match allowed {
            0 => format!("{label} is locked by the exercise: it allows no '{kind}' disturbance"),
            1 => format!(
                "{label} is locked by the exercise: it allows one '{kind}' disturbance, and it is used"
            ),
            n => format!(
                "{label} is locked by the exercise: it allows {n} '{kind}' disturbances, and all {used} are used"
            ),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn exercise(allow: Value, kept: Value) -> Exercise {
        serde_json::from_value(json!({
            "title": "t", "goal": "completed", "disturbances": allow,
            "locked": {"disturbances": kept}
        }))
        .unwrap()
    }

    #[test]
    fn added_disturbances_are_counted_by_kind_beside_the_teachers() {
        let e = exercise(
            json!({"remove": 2}),
            json!([{"at": 10, "kind": "fault", "unit": 3}]),
        );
        let list = [
            json!({"at": 5, "kind": "remove", "cells": [4]}),
            json!({"at": 10, "kind": "fault", "unit": 3}),
            json!({"at": 12, "kind": "remove", "cells": [9]}),
        ];
        assert!(e.disturbance_problems(&list).is_empty());
        assert_eq!(e.added("remove", &list), 2);
        let more = [
            list.as_slice(),
            &[json!({"at": 30, "kind": "remove", "cells": [1]})],
        ]
        .concat();
        assert_eq!(
            e.disturbance_problems(&more),
            vec!["3 × 'remove' added at steps 5, 12, 30 (the exercise allows at most 2)"]
        );
        let other = [json!({"at": 25, "kind": "break", "cells": [7]})];
        assert_eq!(
            e.disturbance_problems(&other),
            vec![
                "the exercise's own disturbances were left out or changed (fault at step 10)",
                "'break' added at step 25 (the exercise allows none)"
            ]
        );
    }

    #[test]
    fn a_click_is_refused_once_its_kind_is_used_up_with_the_reason() {
        let e = exercise(json!({"remove": 1}), json!([]));
        assert_eq!(e.click_problem("remove", "Remove module", &[]), None);
        let one = [json!({"at": 5, "kind": "remove", "cells": [4]})];
        assert_eq!(
            e.click_problem("remove", "Remove module", &one).unwrap(),
            "Remove module is locked by the exercise: it allows one 'remove' disturbance, and it is used"
        );
        assert_eq!(
            e.click_problem("extend", "Add target cell", &one).unwrap(),
            "Add target cell is locked by the exercise: it allows no 'extend' disturbance"
        );
    }

    #[test]
    fn kinds_are_names_and_counts_are_bounded() {
        let bad = |allow: Value| {
            let mut doc = crate::presets::scenario("amas-L").unwrap().to_value();
            doc["exercise"] = json!({"title": "t", "goal": "completed", "disturbances": allow});
            crate::Scenario::from_value(doc).unwrap_err().to_string()
        };
        assert_eq!(
            bad(json!({"Remove module": 1})),
            "exercise.disturbances.Remove module: a kind of disturbance is the model's name for it, such as 'remove' (its action's \"kind\")"
        );
        assert_eq!(
            bad(json!({"remove": 10_001})),
            "exercise.disturbances.remove: 10001 is more than the 10000 an exercise may allow"
        );
    }
}
