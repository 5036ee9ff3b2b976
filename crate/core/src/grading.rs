//! Grading against a classroom exercise: a hand-in replayed and judged by its exercise
//! ([`grade`]), and what an exercise holds a scenario to, in words a teacher reads: a locked field
//! a scenario changed (a shape as the cells removed and added, not as two texts), whether an edit
//! in the page may replace the scenario in force, the goal's names checked against a model, and
//! the one-line summary of a grade. `kumiki check`, the page's verdict and its Grade view use
//! these, so they agree.

use std::collections::BTreeMap;

use serde::Serialize;
use serde_json::Value;

use crate::error::{Error, Result};
use crate::exercise::{differences, lookup_path, Check, Exercise, Goal, Outcome};

/// The most cell coordinates a shape change lists before "…".
const MAX_CELLS_LISTED: usize = 5;

/// A locked field changed from the teacher's value, in words: `robots: 5 → 7`, or for a shape
/// `target: 4 cells removed at (3, 5), (4, 5), …`.
pub fn change_text(path: &str, want: &Value, got: &Value) -> String {
    match (want, got) {
        (Value::String(a), Value::String(b)) if a.contains('\n') || b.contains('\n') => {
            format!("{path}: {}", shape_change(a, b))
        }
        (want, Value::Null) => format!("{path}: {want} → left out"),
        _ => format!("{path}: {want} → {got}"),
    }
}

/// The cells of a shape's text by position: (column, row, layer), counted from 0 at the text's
/// top left (layers, separated by `---`, from the ground up), and the character there. Hex rows
/// separate their cells with spaces, so a column is a cell's place in its row, not a character's.
fn cells(text: &str) -> Vec<((usize, usize, usize), char)> {
    let mut out = Vec::new();
    for (layer, block) in text.split("\n---").enumerate() {
        let rows = block.lines().filter(|l| l.trim() != "---");
        for (row, line) in rows.filter(|l| !l.trim().is_empty()).enumerate() {
            let line = line.trim_end();
            let marks: Vec<char> = match line.contains(' ') {
                true => line
                    .split_whitespace()
                    .filter_map(|t| t.chars().next())
                    .collect(),
                false => line.chars().collect(),
            };
            for (column, c) in marks.into_iter().enumerate() {
                out.push(((column, row, layer), c));
            }
        }
    }
    out
}

/// How shape `b` differs from shape `a`: cells removed, added, and changed in kind.
pub fn shape_change(a: &str, b: &str) -> String {
    use std::collections::BTreeMap;
    let layered = a.contains("\n---") || b.contains("\n---");
    let (a, b): (BTreeMap<_, _>, BTreeMap<_, _>) = (
        cells(a).into_iter().collect(),
        cells(b).into_iter().collect(),
    );
    let filled =
        |m: &BTreeMap<(usize, usize, usize), char>, at| m.get(at).is_some_and(|&c| c != '.');
    let mut places: Vec<&(usize, usize, usize)> = a.keys().chain(b.keys()).collect();
    // Reading order: layer, row, column.
    kumiki_model::sort::sort_by_key(&mut places, |&&(c, r, l)| (l, r, c));
    places.dedup();
    let (mut removed, mut added, mut changed) = (Vec::new(), Vec::new(), Vec::new());
    for at in places {
        match (filled(&a, at), filled(&b, at)) {
            (true, false) => removed.push(*at),
            (false, true) => added.push(*at),
            (true, true) if a.get(at) != b.get(at) => changed.push(*at),
            _ => {}
        }
    }
    let list = |what: &str, at: &[(usize, usize, usize)]| {
        let shown: Vec<String> = at
            .iter()
            .take(MAX_CELLS_LISTED)
            .map(|&(c, r, l)| match layered {
                true => format!("({c}, {r}, {l})"),
                false => format!("({c}, {r})"),
            })
            .collect();
        let more = if at.len() > MAX_CELLS_LISTED {
            ", …"
        } else {
            ""
        };
        let cells = if at.len() == 1 { "cell" } else { "cells" };
        format!("{} {cells} {what} at {}{more}", at.len(), shown.join(", "))
    };
    let parts: Vec<String> = [
        ("removed", &removed),
        ("added", &added),
        ("changed", &changed),
    ]
    .into_iter()
    .filter(|(_, at)| !at.is_empty())
    .map(|(what, at)| list(what, at))
    .collect();
    match parts.is_empty() {
        true => "the same cells, written differently".into(),
        false => parts.join("; "),
    }
}

/// A graded hand-in: the student's scenario replayed to its end and judged by its exercise.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Grade {
    pub name: String,
    pub met: bool,
    pub because: String,
    pub completed: bool,
    pub steps: u64,
    pub hash: String,
    /// Locked fields the hand-in changed: "robots: 5 → 7".
    pub locked_edited: Vec<String>,
    /// Every field that differs from the teacher's exercise, when it is known (the name, which
    /// Hand in sets, left out).
    pub changed: Vec<String>,
    /// The hand-in's exercise section is not the teacher's (its goal or locks were edited).
    pub exercise_edited: bool,
    /// The metrics the goal reads, at the end of the replayed run (the page's Grade view shows
    /// them; `kumiki check` leaves them out).
    #[serde(skip)]
    pub goal_metrics: BTreeMap<String, Value>,
}

/// A hand-in as the page's Grade view shows it: its grade with the metrics its goal reads, or why
/// it could not be graded.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
#[serde(untagged)]
pub enum Graded {
    Graded {
        #[serde(flatten)]
        grade: Grade,
        /// The metrics the goal reads, at the end of the replayed run.
        goal_metrics: BTreeMap<String, Value>,
    },
    Failed {
        /// Why the hand-in could not be graded (a bad link, no exercise).
        error: String,
    },
}

impl Graded {
    pub fn of(graded: Result<Grade>) -> Graded {
        match graded {
            Ok(mut grade) => Graded::Graded {
                goal_metrics: std::mem::take(&mut grade.goal_metrics),
                grade,
            },
            Err(e) => Graded::Failed {
                error: e.to_string(),
            },
        }
    }
}

/// Replays a hand-in and judges it by the exercise it carries, or by `original`'s when the
/// teacher's exercise is given: the hand-in then may not have edited the exercise itself, and
/// every field that differs from the original is listed. A hand-in with no exercise is an error.
pub fn grade(handin: &crate::Scenario, original: Option<&crate::Scenario>) -> Result<Grade> {
    let exercise = match original {
        Some(o) => o.exercise.as_ref().ok_or_else(|| {
            Error::field("exercise", "the teacher's scenario has no exercise section")
        })?,
        None => handin
            .exercise
            .as_ref()
            .ok_or_else(|| Error::field("exercise", "this scenario is not an exercise hand-in"))?,
    };
    let mut run = crate::Run::new(handin.clone())?;
    run.run_to_end();
    let outcome = run.outcome();
    let doc = handin.to_value();
    let check = exercise.goal().check(&Outcome {
        completed: outcome.completed,
        steps: outcome.steps,
        metrics: &outcome.metrics,
        scenario: &doc,
    });
    let check = with_stop(check, outcome.stopped.as_deref());
    let locked_edited = locked_edits(exercise, &doc);
    let (changed, exercise_edited) = match original {
        // The name is left out: Hand in writes the student's name into it.
        Some(o) => (
            differences(&o.to_value(), &doc)
                .into_iter()
                .filter(|p| !p.starts_with("exercise") && p != "name")
                .collect(),
            handin.exercise.as_ref() != Some(exercise),
        ),
        None => (Vec::new(), false),
    };
    let mut because = check.because;
    if !locked_edited.is_empty() {
        because = format!(
            "the hand-in changed locked fields ({}); {because}",
            locked_edited.join(", ")
        );
    }
    if exercise_edited {
        because = format!("the hand-in edited the exercise itself; {because}");
    }
    let goal_metrics = exercise
        .goal()
        .names()
        .iter()
        .filter_map(|n| n.strip_prefix("metrics."))
        .filter_map(|m| Some((m.to_string(), outcome.metrics.get(m)?.clone())))
        .collect();
    Ok(Grade {
        goal_metrics,
        name: handin.name.clone(),
        met: check.met && !exercise_edited && locked_edited.is_empty(),
        because,
        completed: outcome.completed,
        steps: outcome.steps,
        hash: outcome.hash,
        locked_edited,
        changed,
        exercise_edited,
    })
}

/// The locked fields `doc` changed from the exercise's values, in words.
pub fn locked_edits(exercise: &Exercise, doc: &Value) -> Vec<String> {
    exercise
        .locked_changes(doc)
        .into_iter()
        .map(|(path, want, got)| change_text(&path, &want, &got))
        .collect()
}

/// A goal's verdict with the exercise's locks folded in: a scenario that changed a locked field
/// never meets the goal, and the reason names the field with the teacher's value.
pub fn with_locks(check: Check, exercise: &Exercise, doc: &Value) -> Check {
    let edits = locked_edits(exercise, doc);
    match edits.is_empty() {
        true => check,
        false => Check {
            met: false,
            because: format!(
                "locked fields differ from the exercise's values ({}); {}",
                edits.join(", "),
                check.because
            ),
        },
    }
}

/// A goal's verdict on a run that a rule's script stopped (it went past a cap or failed): never
/// met, whatever the goal, and the stop is the reason.
pub fn with_stop(check: Check, stopped: Option<&str>) -> Check {
    match stopped {
        None => check,
        Some(why) => Check {
            met: false,
            because: format!("a rule's script stopped the run: {why}"),
        },
    }
}

/// Why `next` may not replace `current` by an edit (a form field, an editor, the seed, the JSON
/// text, a file, undo), when `current` is an exercise: its exercise section must stay as it is,
/// and every locked field at the teacher's value. `None` when the edit may go ahead.
pub fn locked_problem(current: &Value, next: &Value) -> Option<String> {
    let section = current.get("exercise")?;
    if next.get("exercise") != Some(section) {
        return Some(
            "the exercise itself cannot be changed by an edit: open another exercise from its link or the gallery, or use Make an exercise…"
                .into(),
        );
    }
    let locked = section.get("locked")?.as_object()?;
    let edits: Vec<String> = locked
        .iter()
        .filter_map(|(path, want)| {
            let got = lookup_path(next, path).cloned().unwrap_or(Value::Null);
            (!crate::exercise::same(&got, want)).then(|| change_text(path, want, &got))
        })
        .collect();
    match edits.is_empty() {
        true => None,
        false => Some(format!(
            "locked by the exercise, which keeps the teacher's value ({})",
            edits.join(", ")
        )),
    }
}

/// The first name in `goal` that `metrics` (the model's metric names) or `doc` (the scenario)
/// does not have, with the nearest known name when one is close: the teacher's editor says so as
/// they type.
pub fn unknown_name(goal: &Goal, metrics: &[String], doc: &Value) -> Option<String> {
    for name in goal.names() {
        if let Some(metric) = name.strip_prefix("metrics.") {
            if !metrics.iter().any(|m| m == metric) {
                let near = nearest(metric, metrics.iter().map(String::as_str));
                return Some(format!(
                    "this model has no metric '{metric}'{}",
                    suggestion("metrics.", near)
                ));
            }
        } else if let Some(path) = name.strip_prefix("scenario.") {
            match lookup_path(doc, path) {
                Some(Value::Number(_) | Value::Bool(_)) => {}
                Some(_) => {
                    return Some(format!(
                        "the scenario's '{path}' is neither a number nor true/false"
                    ))
                }
                None => {
                    let keys = doc
                        .as_object()
                        .map(|m| m.keys().map(String::as_str).collect::<Vec<_>>())
                        .unwrap_or_default();
                    let near = nearest(path, keys.into_iter());
                    return Some(format!(
                        "the scenario has no field '{path}'{}",
                        suggestion("scenario.", near)
                    ));
                }
            }
        }
    }
    None
}

fn suggestion(prefix: &str, near: Option<&str>) -> String {
    near.map(|n| format!("; did you mean '{prefix}{n}'?"))
        .unwrap_or_else(|| match prefix {
            "metrics." => "; the metrics are listed under the view".into(),
            _ => String::new(),
        })
}

/// The candidate closest to `word` by edit distance, when it is within a third of its length
/// (at least 1, at most 3 edits).
fn nearest<'a>(word: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    crate::error::nearest_within(word, candidates, (word.chars().count() / 3).clamp(1, 3))
}

impl Grade {
    /// One line a teacher reads: `Ada: met in 209 steps` or `Grace: not met (steps is 349, but it
    /// must be ≤ 300)`.
    pub fn summary(&self) -> String {
        let who = match self.name.trim() {
            "" => "(no name)",
            n => n,
        };
        match self.met {
            true => format!("{who}: met in {} steps", self.steps),
            false => format!("{who}: not met ({})", self.because),
        }
    }
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
    fn grading_replays_the_hand_in_and_reports_what_changed() {
        let doc = exercise_doc(json!({
            "title": "Build it",
            "locked": {"robots": 5},
            "goal": "completed and steps <= 100000"
        }));
        let teacher = crate::Scenario::from_value(doc).unwrap();
        let fair = teacher.with_override("collision", json!("relay")).unwrap();
        let g = grade(&fair, Some(&teacher)).unwrap();
        assert!(g.met, "{}", g.because);
        assert!(g.completed && g.steps > 0 && g.hash.len() == 16);
        assert_eq!(g.changed, vec!["collision"]);
        assert!(g.locked_edited.is_empty() && !g.exercise_edited);
        // The same run as replaying the link by hand.
        let mut run = crate::Run::new(fair.clone()).unwrap();
        run.run_to_end();
        assert_eq!(g.hash, run.outcome().hash);

        let tampered = teacher.with_override("robots", json!(9)).unwrap();
        let g = grade(&tampered, None).unwrap();
        assert_eq!(g.locked_edited, vec!["robots: 5 → 9"]);
        assert!(!g.met);
        assert!(
            g.because
                .starts_with("the hand-in changed locked fields (robots: 5 → 9); "),
            "{}",
            g.because
        );

        let mut cheat = fair.clone();
        cheat.exercise.as_mut().unwrap().goal = "true".into();
        let g = grade(&cheat, Some(&teacher)).unwrap();
        assert!(g.exercise_edited && !g.met);
        assert!(g
            .because
            .starts_with("the hand-in edited the exercise itself"));

        let plain = crate::presets::scenario("amas-L").unwrap();
        assert!(grade(&plain, None)
            .unwrap_err()
            .to_string()
            .contains("not an exercise"));
    }

    #[test]
    fn a_shape_change_lists_the_cells_removed_and_added_capped() {
        let a = "####....\n####....\n########\n";
        let b = "####....\n##......\n#####...\n";
        assert_eq!(
            shape_change(a, b),
            "5 cells removed at (2, 1), (3, 1), (5, 2), (6, 2), (7, 2)"
        );
        let c = "########\n####....\n########\n";
        assert_eq!(
            shape_change(a, c),
            "4 cells added at (4, 0), (5, 0), (6, 0), (7, 0)"
        );
        let many = "........\n........\n........\n";
        assert_eq!(
            shape_change(a, many),
            "16 cells removed at (0, 0), (1, 0), (2, 0), (3, 0), (0, 1), …"
        );
        assert_eq!(shape_change(a, a), "the same cells, written differently");
    }

    #[test]
    fn hex_rows_count_cells_and_layers_count_from_the_ground() {
        let hex = "# # #\n # # #\n";
        let hex2 = "# . #\n # # #\n";
        assert_eq!(shape_change(hex, hex2), "1 cell removed at (1, 0)");
        let cube = "##\n##\n---\n##\n##\n";
        let cube2 = "##\n##\n---\n##\n#.\n";
        assert_eq!(shape_change(cube, cube2), "1 cell removed at (1, 1, 1)");
    }

    #[test]
    fn change_texts_name_the_field_and_the_teachers_value_first() {
        assert_eq!(change_text("robots", &json!(5), &json!(7)), "robots: 5 → 7");
        assert_eq!(
            change_text("target", &json!("##\n"), &json!("#.\n")),
            "target: 1 cell removed at (1, 0)"
        );
        assert_eq!(
            change_text("seed", &json!(1), &Value::Null),
            "seed: 1 → left out"
        );
    }

    #[test]
    fn an_edit_may_not_change_a_locked_field_or_the_exercise() {
        let current = json!({"seed": 1, "robots": 5, "target": "##\n",
            "exercise": {"title": "t", "goal": "completed", "locked": {"seed": 1, "target": "##\n"}}});
        let mut next = current.clone();
        next["robots"] = json!(6);
        assert_eq!(locked_problem(&current, &next), None);
        next["seed"] = json!(9);
        next["target"] = json!("#.\n");
        assert_eq!(
            locked_problem(&current, &next).unwrap(),
            "locked by the exercise, which keeps the teacher's value (seed: 1 → 9, target: 1 cell removed at (1, 0))"
        );
        // A whole float the page wrote as an integer is the same value.
        let float = json!({"tip_load": 200.0, "exercise": {"title": "t", "goal": "completed", "locked": {"tip_load": 200}}});
        assert_eq!(locked_problem(&float, &float), None);
        let mut unlocked = current.clone();
        unlocked["exercise"]["locked"] = json!({});
        assert!(locked_problem(&current, &unlocked)
            .unwrap()
            .starts_with("the exercise itself cannot be changed"));
        assert_eq!(
            locked_problem(&json!({"seed": 1}), &json!({"seed": 2})),
            None
        );
    }

    #[test]
    fn misspelt_names_are_found_with_a_suggestion() {
        let metrics = vec!["collisions".to_string(), "placed".to_string()];
        let doc = json!({"robots": 5, "field": "continuous"});
        let goal = |t: &str| Goal::parse(t).unwrap();
        assert_eq!(
            unknown_name(
                &goal("completed and metrics.collisions < 40"),
                &metrics,
                &doc
            ),
            None
        );
        assert_eq!(
            unknown_name(&goal("metrics.colisions < 40"), &metrics, &doc).unwrap(),
            "this model has no metric 'colisions'; did you mean 'metrics.collisions'?"
        );
        assert_eq!(
            unknown_name(&goal("metrics.speed < 4"), &metrics, &doc).unwrap(),
            "this model has no metric 'speed'; the metrics are listed under the view"
        );
        assert_eq!(
            unknown_name(&goal("scenario.robot <= 6"), &metrics, &doc).unwrap(),
            "the scenario has no field 'robot'; did you mean 'scenario.robots'?"
        );
        assert_eq!(
            unknown_name(&goal("scenario.field == 1"), &metrics, &doc).unwrap(),
            "the scenario's 'field' is neither a number nor true/false"
        );
    }
}
