//! Grading against a classroom exercise. A hand-in is always judged by the teacher's exercise
//! ([`Teacher`]: given, or the one the class's hand-ins carry), never by its own: its exercise
//! must be the class's, its locked fields at the teacher's values, and its disturbances those the
//! exercise allows ([`rules_broken`]); a hand-in that keeps to them is replayed within the
//! exercise's budget ([`Replay`], [`grade`]) and judged, with its points ([`Grade`]). Beside it:
//! whether an edit in the page may replace the scenario in view ([`locked_problem`]), the page's
//! verdict on the run in view ([`verdict`]), the grade table's rows and CSV ([`table`]) and the
//! words a teacher reads ([`words`]). `kumiki check`, the page's verdict and its Grade view use
//! these, so they agree.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::exercise::{listed, lookup_path, Credit, Exercise, Outcome, Verdict, DISTURBANCES};
use crate::handin::Handin;

mod class;
mod replay;
pub mod table;
mod words;

pub use class::{ClassExercise, Source, Teacher};
pub use replay::{grade, Replay};
pub use words::{change_text, shape_change, shown_name, unknown_name};

/// A graded hand-in: the student's scenario judged by the teacher's exercise, replayed to its end
/// (or to the exercise's budget) when it kept to the exercise's rules.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct Grade {
    pub name: String,
    pub met: bool,
    pub because: String,
    pub completed: bool,
    /// The steps replayed (0 when it was not replayed).
    pub steps: u64,
    /// The state hash at the end of the replay (empty when it was not replayed).
    pub hash: String,
    /// Locked fields the hand-in changed: "robots: 5 → 7".
    pub locked_edited: Vec<String>,
    /// Disturbances the exercise does not allow: "'remove' added at step 25 (the exercise allows
    /// none)", or the teacher's left out.
    pub disturbances: Vec<String>,
    /// Every field that differs from the teacher's scenario, when it is known (the name, which
    /// Hand in sets, left out).
    pub changed: Vec<String>,
    /// The hand-in's exercise section is not the class's (its goal, locks or points differ, or it
    /// has none).
    pub exercise_edited: bool,
    /// The replay was stopped at the exercise's budget before its run ended: not judged.
    pub over_budget: bool,
    /// The points earned; absent when the exercise gives none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub points: Option<u32>,
    /// The most points the exercise gives; absent when it gives none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_points: Option<u32>,
    /// Each part of the exercise's credit, judged.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub credit: Vec<Credit>,
    /// The hand-in's record of itself (its `handin` section): when, how many checks and hints,
    /// the answer. (`record`, as a table's row numbers its hand-ins `handin`.)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub record: Option<Handin>,
    /// The metrics the goal and the credit read, at the end of the replayed run (the page's Grade
    /// view shows them; `kumiki check` writes them into its CSV).
    #[serde(skip)]
    pub goal_metrics: BTreeMap<String, Value>,
}

/// A hand-in as the page's Grade view shows it: its grade with the metrics its goal reads, or why
/// it could not be graded.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(untagged)]
pub enum Graded {
    Graded {
        #[serde(flatten)]
        grade: Box<Grade>,
        /// The metrics the goal reads, at the end of the replayed run.
        goal_metrics: BTreeMap<String, Value>,
    },
    Failed {
        /// Why the hand-in could not be graded (a bad link, a row without one).
        error: String,
    },
}

impl Graded {
    pub fn of(graded: crate::error::Result<Grade>) -> Graded {
        match graded {
            Ok(grade) => Graded::from(grade),
            Err(e) => Graded::Failed {
                error: e.to_string(),
            },
        }
    }

    /// The grade, when there is one.
    pub fn grade(&self) -> Option<&Grade> {
        match self {
            Graded::Graded { grade, .. } => Some(grade),
            Graded::Failed { .. } => None,
        }
    }
}

impl From<Grade> for Graded {
    fn from(mut grade: Grade) -> Graded {
        Graded::Graded {
            goal_metrics: std::mem::take(&mut grade.goal_metrics),
            grade: Box::new(grade),
        }
    }
}

/// The locked fields `doc` changed from the exercise's values, in words.
pub fn locked_edits(exercise: &Exercise, doc: &Value) -> Vec<String> {
    exercise
        .locked_changes(doc)
        .into_iter()
        .map(|(path, want, got)| change_text(&path, &want, &got))
        .collect()
}

/// The rules of `exercise` the scenario `doc` breaks, in words: each locked field it changed,
/// and the disturbances the exercise does not allow. Empty when it keeps to them.
pub fn rules_broken(exercise: &Exercise, doc: &Value) -> Vec<String> {
    let mut out = locked_edits(exercise, doc);
    out.extend(exercise.disturbance_problems(listed(doc)));
    out
}

/// The exercise's verdict on the run as it stands, with its points, for the student's page: a
/// run whose scenario breaks a rule of its exercise (a locked field changed, a disturbance it
/// does not allow) is never "Goal met", and the reason names what. `None` when the scenario is
/// no exercise.
pub fn verdict(run: &crate::Run) -> Option<Verdict> {
    let exercise = run.scenario().exercise.as_ref()?;
    let outcome = run.outcome();
    let doc = run.scenario().to_value();
    Some(
        exercise
            .verdict(
                &Outcome {
                    completed: outcome.completed,
                    steps: outcome.steps,
                    metrics: &outcome.metrics,
                    scenario: &doc,
                },
                &rules_broken(exercise, &doc),
            )
            .with_stop(outcome.stopped.as_deref()),
    )
}

/// Why `next` may not replace `current` by an edit (a form field, an editor, the seed, the JSON
/// text, a file, undo), when `current` is an exercise: its exercise section must stay as it is,
/// every locked field at the teacher's value, and no disturbance added that the exercise does not
/// allow (nor one of the teacher's taken away). `None` when the edit may go ahead.
pub fn locked_problem(current: &Value, next: &Value) -> Option<String> {
    let section = current.get("exercise")?;
    if next.get("exercise") != Some(section) {
        return Some(
            "the exercise itself cannot be changed by an edit: open another exercise from its link or the gallery"
                .into(),
        );
    }
    let exercise: Exercise = serde_json::from_value(section.clone()).ok()?;
    let mut edits: Vec<String> = exercise
        .locked
        .iter()
        .filter(|(path, _)| path.as_str() != DISTURBANCES)
        .filter_map(|(path, want)| {
            let got = lookup_path(next, path).cloned().unwrap_or(Value::Null);
            (!crate::exercise::same(&got, want)).then(|| change_text(path, want, &got))
        })
        .collect();
    // Disturbances the scenario in view already breaks the rule with (a link edited by hand) do
    // not hold back an edit that leaves them as they are.
    let before = exercise.disturbance_problems(listed(current));
    edits.extend(
        exercise
            .disturbance_problems(listed(next))
            .into_iter()
            .filter(|p| !before.contains(p)),
    );
    match edits.is_empty() {
        true => None,
        false => Some(format!(
            "locked by the exercise, which keeps the teacher's value ({})",
            edits.join(", ")
        )),
    }
}

impl Grade {
    /// One line a teacher reads: `Ada: met in 209 steps, 8 of 10 points` or `Grace: not met (steps
    /// is 349, but it must be ≤ 300)`. The name is shown as [`shown_name`] shows it.
    pub fn summary(&self) -> String {
        let who = shown_name(&self.name, 60);
        let points = match (self.points, self.max_points) {
            (Some(p), Some(m)) => format!(", {p} of {m} points"),
            _ => String::new(),
        };
        match self.met {
            true => format!("{who}: met in {} steps{points}", self.steps),
            false => format!("{who}: not met ({}){points}", self.because),
        }
    }
}

#[cfg(test)]
mod tests;
