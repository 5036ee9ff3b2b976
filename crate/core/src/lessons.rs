//! Built-in lessons: classroom exercises tied to the papers, one JSON file each in a model crate's
//! `lessons/`, registered by file name like the presets.
//!
//! A lesson is a scenario with an `exercise` section. Its description starts with
//! `Lesson (SECTION): ` where SECTION names the paper's section and figures it is about, so the
//! gallery and `kumiki lessons` can show it; a test holds every lesson to that form. Beside the
//! scenario, its file holds the edit the lesson is designed to be solved by (`solution`), which a
//! test makes and grades; the scenario, its links and the page leave it out.

use serde::Serialize;
use serde_json::{Map, Value};

use crate::error::{Error, Result};
use crate::models;
use crate::presets::{in_file, lookup, LESSON_FILES};
use crate::scenario::Scenario;

/// The key of a lesson file that holds its solution, beside the scenario's keys.
const SOLUTION: &str = "solution";
/// The keys of a lesson file beside the scenario's: its solution and the teacher's guide to it
/// ([`crate::guide`]).
const BESIDE: [&str; 2] = [SOLUTION, "guide"];

/// Names of the built-in lessons, sorted.
pub fn names() -> impl Iterator<Item = &'static str> {
    LESSON_FILES.iter().map(|(name, _)| *name)
}

/// The JSON text of a lesson.
pub fn json(name: &str) -> Result<&'static str> {
    lookup(LESSON_FILES, "lesson", name)
}

pub fn scenario(name: &str) -> Result<Scenario> {
    let doc = file(name)?;
    in_file("lesson", name, Scenario::from_value(Value::Object(doc)))
}

/// The edit lesson `name` is designed to be solved by, as dotted paths and their values (its
/// file's `solution`): a student who makes it meets the goal.
pub fn solution(name: &str) -> Result<Vec<(String, Value)>> {
    match part(name, SOLUTION)? {
        Some(Value::Object(edits)) if !edits.is_empty() => Ok(edits.into_iter().collect()),
        _ => Err(Error::field(
            SOLUTION,
            format!(
                "lesson '{name}' gives no solution: the edits, by dotted path, that meet its goal"
            ),
        )),
    }
}

/// The part `key` of lesson `name`'s file beside its scenario (its solution, its guide).
pub fn part(name: &str, key: &str) -> Result<Option<Value>> {
    Ok(document(name)?.remove(key))
}

/// A lesson's scenario keys, without what its file holds beside them.
fn file(name: &str) -> Result<Map<String, Value>> {
    let mut doc = document(name)?;
    for key in BESIDE {
        doc.remove(key);
    }
    Ok(doc)
}

/// A lesson file, as written.
fn document(name: &str) -> Result<Map<String, Value>> {
    let doc: Value = serde_json::from_str(json(name)?).map_err(|e| Error::json(&e))?;
    let Value::Object(doc) = doc else {
        return Err(Error::field(
            "",
            format!("lesson '{name}' is not a JSON object"),
        ));
    };
    Ok(doc)
}

/// What a list of lessons shows of one.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct LessonInfo {
    pub name: &'static str,
    pub model: String,
    /// The model's paper, as its registry entry titles it.
    pub paper: String,
    /// The paper's section and figures the lesson is about ("section 3.2.5, figure 4").
    pub section: String,
    /// The exercise's title.
    pub title: String,
    pub description: String,
}

/// Every lesson, in name order.
pub fn list() -> Result<Vec<LessonInfo>> {
    names()
        .map(|name| {
            let s = scenario(name)?;
            let title = s
                .exercise
                .as_ref()
                .map(|e| e.title.clone())
                .ok_or_else(|| {
                    Error::field("exercise", format!("lesson '{name}' has no exercise"))
                })?;
            Ok(LessonInfo {
                name,
                paper: models::entry(s.model())?.title.to_string(),
                section: section(&s.description).unwrap_or_default().to_string(),
                model: s.model().to_string(),
                title,
                description: s.description,
            })
        })
        .collect()
}

/// The teachers' guide's table of lessons (docs/teaching.md, written by `kumiki schema`): each
/// lesson, in name order, with its model, the paper's section, its exercise's title and goal.
pub fn markdown() -> Result<String> {
    let mut out = String::from(
        "| lesson | model | paper section | title | goal |\n| --- | --- | --- | --- | --- |\n",
    );
    for l in list()? {
        let goal = scenario(l.name)?
            .exercise
            .map(|e| e.goal)
            .unwrap_or_default();
        out.push_str(&format!(
            "| `{}` | {} | {} | {} | `{goal}` |\n",
            l.name, l.model, l.section, l.title
        ));
    }
    Ok(out)
}

/// The SECTION of a description that starts `Lesson (SECTION): `.
fn section(description: &str) -> Option<&str> {
    let rest = description.strip_prefix("Lesson (")?;
    let end = rest.find("): ")?;
    Some(&rest[..end])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grading::{grade, Teacher};

    #[test]
    fn every_lesson_is_an_exercise_named_after_its_file_and_citing_its_section() {
        assert!(names().count() >= 8, "at least eight lessons");
        for info in list().unwrap() {
            let s = scenario(info.name).unwrap();
            assert_eq!(
                s.name, info.name,
                "lesson file {0}.json must carry \"name\": \"{0}\"",
                info.name
            );
            assert!(
                info.name.starts_with("lesson-"),
                "{}: lesson names start with 'lesson-'",
                info.name
            );
            assert!(
                !info.section.is_empty(),
                "{}: the description starts 'Lesson (SECTION): '",
                info.name
            );
            let exercise = s.exercise.unwrap();
            assert!(
                exercise.instructions.contains("section"),
                "{}: the instructions cite the paper's section",
                info.name
            );
            assert!(
                !exercise.locked.is_empty(),
                "{}: a lesson locks what it is not about",
                info.name
            );
            assert!(
                !crate::presets::names().any(|p| p == info.name),
                "{} is also a preset",
                info.name
            );
        }
    }

    #[test]
    fn the_lessons_cover_every_model() {
        let lessons = list().unwrap();
        for m in models::MODELS {
            assert!(
                lessons.iter().filter(|l| l.model == m.name).count() >= 2,
                "model {} needs at least two lessons",
                m.name
            );
        }
    }

    #[test]
    fn every_lesson_fails_as_given_and_is_met_by_its_solution() {
        for name in names() {
            let lesson = scenario(name).unwrap();
            let teacher = Teacher::given(&lesson).unwrap();
            let given = grade(lesson.clone(), &teacher, &mut || 0.0).unwrap();
            assert!(
                !given.met,
                "{name}: the goal is met before any edit ({})",
                given.because
            );
            assert!(
                given.locked_edited.is_empty() && given.disturbances.is_empty(),
                "{name}: the unedited lesson breaks its own rules: {:?} {:?}",
                given.locked_edited,
                given.disturbances
            );
            let edits = solution(name).unwrap_or_else(|e| {
                panic!("{e}: add the edit that solves it to the lesson's file")
            });
            let solved = lesson.with_overrides(&edits).unwrap();
            let graded = grade(solved, &teacher, &mut || 0.0).unwrap();
            assert!(
                graded.met,
                "{name}: the intended solution does not meet the goal: {}",
                graded.because
            );
            assert_eq!(
                graded.changed,
                edits.iter().map(|(p, _)| p.clone()).collect::<Vec<_>>(),
                "{name}"
            );
        }
    }

    /// docs/teaching.md lists every lesson, as the files say, and nothing else: its table is
    /// the one [`markdown`] writes, and has a row a lesson.
    #[test]
    fn the_teachers_guide_lists_the_lessons_as_they_are() {
        let guide = include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../docs/teaching.md"
        ));
        let table = markdown().unwrap();
        assert!(
            guide.contains(&format!(
                "<!-- lessons:begin -->\n{table}<!-- lessons:end -->"
            )),
            "the lessons table in docs/teaching.md is not the lesson files': run 'kumiki schema'"
        );
        assert_eq!(
            table
                .lines()
                .filter(|l| l.starts_with("| `lesson-"))
                .count(),
            names().count()
        );
    }

    #[test]
    fn section_is_read_from_the_description() {
        assert_eq!(
            section("Lesson (section 3.3, figure 5): the triangle"),
            Some("section 3.3, figure 5")
        );
        assert_eq!(section("The triangle (section 3.3): no"), None);
    }
}
