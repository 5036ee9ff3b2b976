//! The teacher's guide to each lesson, written into docs/teaching.md by `kumiki schema` from the
//! lesson files' `guide` (what the lesson teaches, how long it takes, what students are likely to
//! try, the answer in words) and from the lessons themselves: each try and the solution are
//! replayed and graded as a hand-in would be, so the guide says what each one gives with the
//! models as they are, and `kumiki schema --check` notices when a model's change makes it stale.
//!
//! ```json
//! "guide": {
//!   "teaches": "Why a discrete field sends every robot round the same corner…",
//!   "minutes": 20,
//!   "tries": [{ "what": "A wider stem", "set": { "target": "…" } }],
//!   "answer": "Share the arm out to both sides of the stem…"
//! }
//! ```

use serde::Deserialize;
use serde_json::Value;

use crate::error::{Error, Result};
use crate::grading::{grade, Teacher};
use crate::lessons;

/// The most minutes a lesson may be said to take.
const MAX_MINUTES: u32 = 180;

/// A lesson file's `guide`.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Guide {
    /// What the lesson teaches, in a sentence or two.
    pub teaches: String,
    /// About how long it takes a student, in minutes.
    pub minutes: u32,
    /// What students are likely to try first: each an edit by dotted path, said in words.
    pub tries: Vec<Try>,
    /// The answer in words: why the lesson's solution works.
    pub answer: String,
}

/// An edit students are likely to try.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Try {
    /// The try in words: "The blackboard rule".
    pub what: String,
    /// The edit, by dotted path.
    pub set: serde_json::Map<String, Value>,
}

/// The guide of lesson `name`, checked: its texts given, its minutes within reason, at least one
/// try, and each try an edit of fields the lesson leaves open.
pub fn guide(name: &str) -> Result<Guide> {
    let value = lessons::part(name, "guide")?.ok_or_else(|| {
        Error::field(
            "guide",
            format!("lesson '{name}' has no guide: what it teaches, how long, what students try, the answer"),
        )
    })?;
    let guide: Guide = crate::error::from_value(value).map_err(|e| e.within("guide"))?;
    let empty = |text: &str| text.trim().is_empty();
    if empty(&guide.teaches) || empty(&guide.answer) || guide.tries.is_empty() {
        return Err(Error::field(
            "guide",
            format!(
                "lesson '{name}': 'teaches', 'answer' and at least one of 'tries' are required"
            ),
        ));
    }
    if !(1..=MAX_MINUTES).contains(&guide.minutes) {
        return Err(Error::field(
            "guide.minutes",
            format!("from 1 to {MAX_MINUTES} minutes"),
        ));
    }
    Ok(guide)
}

/// What an edit of lesson `name` gives, graded as a hand-in: "met in 105 steps", or "not met
/// (metrics.collisions is 127, but it must be < 40)".
fn outcome(name: &str, edits: &[(String, Value)]) -> Result<String> {
    let lesson = lessons::scenario(name)?;
    let teacher = Teacher::given(&lesson)?;
    let handin = lesson.with_overrides(edits)?;
    let g = grade(handin, &teacher, &mut || 0.0)?;
    if !g.locked_edited.is_empty() {
        return Err(Error::field(
            "guide.tries",
            format!(
                "lesson '{name}': a try changes a locked field ({})",
                g.locked_edited.join(", ")
            ),
        ));
    }
    Ok(match g.met {
        true => format!("met in {} steps", g.steps),
        false => format!("not met ({})", g.because),
    })
}

/// An edit in Markdown: `collision` = `"relay"` inline, and the shapes it sets as blocks to
/// follow the line (a shape is named "the shape below").
fn edit_text(edits: &[(String, Value)]) -> (String, String) {
    let mut blocks = String::new();
    let inline = edits
        .iter()
        .map(|(path, value)| match value {
            Value::String(s) if s.contains('\n') => {
                blocks.push_str(&format!(
                    "\n  ```text\n  {}\n  ```\n",
                    s.trim_end().replace('\n', "\n  ")
                ));
                format!("`{path}` = the shape below")
            }
            other => format!("`{path}` = `{other}`"),
        })
        .collect::<Vec<_>>()
        .join(", ");
    (inline, blocks)
}

/// The teachers' guide to every lesson, in name order: docs/teaching.md's part between
/// `<!-- guide:begin -->` and `<!-- guide:end -->`.
pub fn markdown() -> Result<String> {
    let mut out = String::new();
    for info in lessons::list()? {
        let name = info.name;
        let g = guide(name)?;
        let exercise = lessons::scenario(name)?
            .exercise
            .expect("a lesson is an exercise");
        out.push_str(&format!(
            "### `{name}`: {}\n\n{} · {} · about {} minutes · goal `{}` ({})\n\n**What it teaches.** {}\n\n**What students are likely to try**, and what it gives:\n\n",
            info.title,
            info.model,
            info.section,
            g.minutes,
            exercise.goal,
            exercise.goal().words(),
            g.teaches.trim()
        ));
        out.push_str(&format!(
            "- The lesson as given: {}.\n",
            outcome(name, &[])?
        ));
        for t in &g.tries {
            let edits: Vec<(String, Value)> = t.set.clone().into_iter().collect();
            let (inline, blocks) = edit_text(&edits);
            out.push_str(&format!(
                "- {} ({inline}): {}.\n{blocks}",
                t.what.trim(),
                outcome(name, &edits)?
            ));
        }
        let solution = lessons::solution(name)?;
        let (inline, blocks) = edit_text(&solution);
        out.push_str(&format!(
            "\n**The answer.** {} The lesson's solution, {inline}: {}.\n{blocks}\n",
            g.answer.trim(),
            outcome(name, &solution)?
        ));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every lesson has a guide that reads; what it says the tries give is replayed by
    /// `kumiki schema` (its check keeps docs/teaching.md current).
    #[test]
    fn every_lesson_has_a_guide() {
        for name in lessons::names() {
            let g = guide(name).unwrap();
            for t in &g.tries {
                let edits: Vec<(String, Value)> = t.set.clone().into_iter().collect();
                lessons::scenario(name)
                    .unwrap()
                    .with_overrides(&edits)
                    .unwrap_or_else(|e| panic!("{name}: try '{}': {e}", t.what));
            }
        }
    }
}
