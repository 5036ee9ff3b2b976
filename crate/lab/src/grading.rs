//! Hand-ins graded as `kumiki check` grades them, for the gallery's Grade view and its workers.

use kumiki_core::{grading, lessons, link, Scenario};
use wasm_bindgen::prelude::*;

use crate::{js_err, to_js};

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
/// its own. Its `Graded` row.
#[wasm_bindgen]
pub fn grade_handin(handin: &str, exercise: Option<String>) -> Result<JsValue, JsError> {
    let original = exercise.map(|e| teacher_exercise(&e)).transpose()?;
    let graded = link::open_within(handin.trim(), &kumiki_core::Limits::PAGE)
        .and_then(|o| grading::grade(&o.scenario, original.as_ref()));
    to_js(&grading::Graded::of(graded))
}
