//! Exercises: a goal in words (a goal being typed and an edit against an exercise's locks are
//! checked by the [`Draft`](crate::Draft); grading hand-ins is the lab module's, `kumiki-lab`).

use kumiki_core::exercise::Goal;
use wasm_bindgen::prelude::*;

/// A goal in words for students ("Completed, and collisions below 40."), or undefined when it
/// does not parse.
#[wasm_bindgen]
pub fn goal_words(text: &str) -> Option<String> {
    Goal::parse(text).ok().map(|g| g.words())
}
