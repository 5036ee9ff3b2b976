//! Partial credit: an exercise's `credit` gives points for parts of the outcome, each part a goal
//! of its own (`completed` 5, `steps < 300` 3, `metrics.collisions < 40` 2), and the verdict on an
//! outcome ([`Verdict`]): the goal, the rules the scenario broke, and the points. The student's
//! page and the grading of a hand-in judge with the same [`Exercise::verdict`].

use serde::{Deserialize, Serialize};

use super::{Exercise, Goal, Outcome, MAX_GOAL_CHARS};
use crate::error::{Error, Result};

/// The most parts an exercise's credit has.
pub const MAX_PARTS: usize = 20;
/// The most points one part gives.
pub const MAX_POINTS: u32 = 1000;

/// A part of the outcome and the points it gives.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Part {
    /// The part, a goal in the goal language: `steps < 300`.
    #[schemars(length(max = MAX_GOAL_CHARS))]
    pub goal: String,
    /// The points it gives when it is met.
    #[schemars(range(max = MAX_POINTS))]
    pub points: u32,
}

/// A part as judged: its points, those earned, and why.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct Credit {
    pub goal: String,
    pub points: u32,
    pub earned: u32,
    pub because: String,
}

/// An exercise's verdict on a run: whether it meets the goal (never when it broke a rule of the
/// exercise: a locked field, a disturbance), why, and the points its parts earn.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Verdict {
    pub met: bool,
    pub because: String,
    /// The points earned; absent when the exercise gives none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub points: Option<u32>,
    /// The most points the exercise gives; absent when it gives none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_points: Option<u32>,
    /// Each part, judged.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub credit: Vec<Credit>,
}

impl Verdict {
    /// This verdict on a run that a rule's script stopped (it went past a cap or failed), when
    /// `stopped` says why: never met and no points, whatever the goal, and the stop is the reason.
    pub fn with_stop(mut self, stopped: Option<&str>) -> Verdict {
        if let Some(why) = stopped {
            self.met = false;
            self.because = format!("a rule's script stopped the run: {why}");
            self.points = self.points.map(|_| 0);
            for part in &mut self.credit {
                part.earned = 0;
            }
        }
        self
    }
}

/// Parts whose goals parse and whose points are within [`MAX_POINTS`].
pub(super) fn check(parts: &[Part]) -> Result<()> {
    if parts.len() > MAX_PARTS {
        return Err(Error::field(
            "credit",
            format!("{} parts are too many; at most {MAX_PARTS}", parts.len()),
        ));
    }
    for (i, part) in parts.iter().enumerate() {
        let path = format!("credit[{i}]");
        Goal::parse(&part.goal).map_err(|e| e.within(&format!("{path}.goal")))?;
        if part.points > MAX_POINTS {
            return Err(Error::field(
                format!("{path}.points"),
                format!(
                    "{} is more than the {MAX_POINTS} a part may give",
                    part.points
                ),
            ));
        }
    }
    Ok(())
}

impl Exercise {
    /// The most points the exercise gives; `None` when it gives none.
    pub fn max_points(&self) -> Option<u32> {
        (!self.credit.is_empty()).then(|| self.credit.iter().map(|p| p.points).sum())
    }

    /// The metrics the goal and the credit's parts read, by name, sorted.
    pub fn metric_names(&self) -> Vec<String> {
        let mut names: Vec<String> = std::iter::once(self.goal())
            .chain(self.credit.iter().filter_map(|p| Goal::parse(&p.goal).ok()))
            .flat_map(|g| g.names())
            .filter_map(|n| n.strip_prefix("metrics.").map(str::to_string))
            .collect();
        kumiki_model::sort::sort(&mut names);
        names.dedup();
        names
    }

    /// The verdict on `outcome` when the scenario broke `broken` (the rules of the exercise it
    /// broke, in words): broken, it meets nothing and earns nothing, and the reason names them.
    pub fn verdict(&self, outcome: &Outcome, broken: &[String]) -> Verdict {
        let check = self.goal().check(outcome);
        let fair = broken.is_empty();
        let credit: Vec<Credit> = self
            .credit
            .iter()
            .map(|part| {
                let c = Goal::parse(&part.goal)
                    .expect("a part's goal was checked when the exercise was read")
                    .check(outcome);
                Credit {
                    goal: part.goal.clone(),
                    points: part.points,
                    earned: if c.met && fair { part.points } else { 0 },
                    because: c.because,
                }
            })
            .collect();
        let because = match fair {
            true => check.because,
            false => format!(
                "the exercise does not allow what this scenario changed ({}); {}",
                broken.join("; "),
                check.because
            ),
        };
        Verdict {
            met: check.met && fair,
            because,
            points: self
                .max_points()
                .map(|_| credit.iter().map(|c| c.earned).sum()),
            max_points: self.max_points(),
            credit,
        }
    }

    /// A verdict with nothing judged: the run was not replayed or not to its end, for `why`.
    pub fn unjudged(&self, why: String) -> Verdict {
        Verdict {
            met: false,
            because: why,
            points: self.max_points().map(|_| 0),
            max_points: self.max_points(),
            credit: Vec::new(),
        }
    }
}

impl Verdict {
    /// The points in words: "7 of 10 points"; empty when the exercise gives none.
    pub fn points_text(&self) -> String {
        match (self.points, self.max_points) {
            (Some(p), Some(m)) => format!("{p} of {m} points"),
            _ => String::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::{json, Map, Value};

    #[test]
    fn each_part_met_earns_its_points_and_a_broken_rule_earns_none() {
        let e: Exercise = serde_json::from_value(json!({
            "title": "t", "goal": "completed and steps <= 200",
            "credit": [
                {"goal": "completed", "points": 5},
                {"goal": "steps < 300", "points": 3},
                {"goal": "metrics.collisions < 40", "points": 2}
            ]
        }))
        .unwrap();
        let metrics: Map<String, Value> = [("collisions".to_string(), json!(55))]
            .into_iter()
            .collect();
        let doc = json!({});
        let outcome = Outcome {
            completed: true,
            steps: 250,
            metrics: &metrics,
            scenario: &doc,
        };
        let v = e.verdict(&outcome, &[]);
        assert!(!v.met, "250 steps miss the goal");
        assert_eq!((v.points, v.max_points), (Some(8), Some(10)));
        assert_eq!(v.points_text(), "8 of 10 points");
        assert_eq!(
            v.credit.iter().map(|c| c.earned).collect::<Vec<_>>(),
            vec![5, 3, 0]
        );
        assert_eq!(
            v.credit[2].because,
            "metrics.collisions is 55, but it must be < 40"
        );
        let broken = e.verdict(&outcome, &["seed: 1 → 2".into()]);
        assert_eq!(broken.points, Some(0));
        assert!(broken
            .because
            .starts_with("the exercise does not allow what this scenario changed (seed: 1 → 2); "));
    }

    #[test]
    fn bad_parts_name_the_field() {
        let err = |credit: Value| {
            let mut doc = crate::presets::scenario("amas-L").unwrap().to_value();
            doc["exercise"] = json!({"title": "t", "goal": "completed", "credit": credit});
            crate::Scenario::from_value(doc).unwrap_err().to_string()
        };
        assert_eq!(
            err(json!([{"goal": "steps = 3", "points": 1}])),
            "exercise.credit[0].goal: column 7: '=' alone is not a comparison; write '=='"
        );
        assert_eq!(
            err(json!([{"goal": "completed", "points": 1001}])),
            "exercise.credit[0].points: 1001 is more than the 1000 a part may give"
        );
    }
}
