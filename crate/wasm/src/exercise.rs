//! Exercises: goals checked as a teacher types them, edits held to an exercise's locks, and
//! hand-ins graded as `kumiki check` grades them.

use kumiki_core::exercise::Goal;
use kumiki_core::{grading, lessons, link, Scenario};
use serde::Serialize;
use serde_json::Value;
use wasm_bindgen::prelude::*;

use crate::{js_err, to_js};

/// What is wrong with an exercise goal (see `kumiki_core::exercise`), or undefined when it
/// reads well: the teacher's editor validates as they type. `metrics` are the model's metric
/// names and `scenario_json` the scenario, against which the goal's names are checked.
#[wasm_bindgen]
pub fn goal_problem(text: &str, metrics: Vec<String>, scenario_json: &str) -> Option<String> {
    match Goal::parse(text) {
        Err(e) => Some(e.to_string()),
        Ok(goal) => {
            let doc: Value = serde_json::from_str(scenario_json).unwrap_or(Value::Null);
            grading::unknown_name(&goal, &metrics, &doc)
        }
    }
}

/// A goal in words for students ("Completed, and collisions below 40."), or undefined when it
/// does not parse.
#[wasm_bindgen]
pub fn goal_words(text: &str) -> Option<String> {
    Goal::parse(text).ok().map(|g| g.words())
}

/// Why the scenario `next_json` may not replace `current_json` by an edit, when the current one
/// is an exercise (a locked field away from the teacher's value, or the exercise itself changed);
/// undefined when it may.
#[wasm_bindgen]
pub fn exercise_guard(current_json: &str, next_json: &str) -> Option<String> {
    let current: Value = serde_json::from_str(current_json).ok()?;
    let next: Value = serde_json::from_str(next_json).ok()?;
    grading::locked_problem(&current, &next)
}

/// The teacher's exercise for grading: a link, or a lesson's name, as `kumiki check --exercise`
/// takes them; a scenario with no exercise section is refused.
fn teacher_exercise(text: &str) -> Result<Scenario, JsError> {
    let text = text.trim();
    let scenario = match lessons::names().any(|n| n == text) {
        true => lessons::scenario(text).map_err(js_err)?,
        false => {
            link::open_within(text, &kumiki_core::Limits::PAGE)
                .map_err(js_err)?
                .scenario
        }
    };
    match scenario.exercise {
        Some(_) => Ok(scenario),
        None => Err(JsError::new(
            "exercise: this scenario has no exercise section",
        )),
    }
}

/// Checks the teacher's exercise for the Grade view: its title, or an error that says why it
/// cannot grade.
#[wasm_bindgen]
pub fn exercise_title(text: &str) -> Result<String, JsError> {
    let scenario = teacher_exercise(text)?;
    Ok(scenario.exercise.map(|e| e.title).unwrap_or_default())
}

/// Grades one hand-in as `kumiki check` does (page limits): the link replayed to its end and
/// judged by the teacher's exercise (`exercise`: a link or a lesson's name) when given, else by
/// its own. A graded row (`{name, met, because, completed, steps, hash, locked_edited, changed,
/// exercise_edited, goal_metrics}`) or `{error}`.
#[wasm_bindgen]
pub fn grade_handin(handin: &str, exercise: Option<String>) -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    struct Graded {
        #[serde(flatten)]
        grade: kumiki_core::grading::Grade,
        goal_metrics: std::collections::BTreeMap<String, Value>,
    }
    #[derive(Serialize)]
    struct Failed {
        error: String,
    }
    let original = exercise.map(|e| teacher_exercise(&e)).transpose()?;
    let graded = link::open_within(handin.trim(), &kumiki_core::Limits::PAGE)
        .and_then(|o| kumiki_core::grading::grade(&o.scenario, original.as_ref()));
    match graded {
        Ok(mut grade) => to_js(&Graded {
            goal_metrics: std::mem::take(&mut grade.goal_metrics),
            grade,
        }),
        Err(e) => to_js(&Failed {
            error: e.to_string(),
        }),
    }
}
