//! The exercise a class's hand-ins are graded by ([`Teacher`]): the teacher's, given as a link, a
//! file or a lesson, or when none is given the one most of the hand-ins carry. A hand-in's own
//! exercise is never trusted: one that differs from the class's is a failed row that says so.

use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::error::{Error, Result};
use crate::exercise::{differences, same, Exercise, DISTURBANCES};
use crate::scenario::canonical;

/// Where the class's exercise came from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(tag = "from", rename_all = "snake_case")]
pub enum Source {
    /// The teacher gave it: a link, a file or a lesson.
    Given,
    /// No exercise was given: it is the one `carried` of the `of` hand-ins that hold one carry.
    Handins { carried: usize, of: usize },
}

/// The class's exercise as the Grade view shows it and hands it to its grading workers.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct ClassExercise {
    /// The teacher as JSON ([`Teacher::to_json`]), handed to each grading worker.
    pub teacher: String,
    pub title: String,
    /// Where it came from, in words: "“Fewer collisions”, given".
    pub describe: String,
    pub source: Source,
    /// The question students answer in words; empty when the exercise asks none.
    pub question: String,
    /// The CSV header of the class's grade table.
    pub header: String,
}

/// The exercise hand-ins are graded by, with the teacher's scenario when it is known (the fields a
/// hand-in changed are listed against it). It travels to grading workers as JSON.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Teacher {
    exercise: Value,
    /// The teacher's scenario, when it was given.
    scenario: Option<Value>,
    source: Source,
    #[serde(skip)]
    read: Option<Exercise>,
}

/// An exercise the hand-ins carry: its canonical text, how many carry it, the first scenario that
/// does, and the disturbance lists of those that do, each with how many have it.
struct Carried {
    key: String,
    count: usize,
    doc: Value,
    lists: Vec<(String, usize, Value)>,
}

/// The list most of `lists` are (ties to the first met).
fn most_common(lists: &[(String, usize, Value)]) -> Value {
    let most = lists.iter().map(|(_, n, _)| *n).max().unwrap_or(0);
    lists
        .iter()
        .find(|(_, n, _)| *n == most)
        .map_or(Value::Array(Vec::new()), |(.., list)| list.clone())
}

impl Teacher {
    /// The teacher's own scenario: its exercise is the class's.
    pub fn given(scenario: &crate::Scenario) -> Result<Teacher> {
        let exercise = scenario.exercise.clone().ok_or_else(|| {
            Error::field("exercise", "the teacher's scenario has no exercise section")
        })?;
        Ok(Teacher {
            exercise: serde_json::to_value(&exercise).expect("an exercise serialises"),
            scenario: Some(scenario.to_value()),
            source: Source::Given,
            read: Some(exercise),
        })
    }

    /// The exercise most of the hand-ins `docs` carry (each a hand-in's scenario document, as its
    /// link holds it). When two or more are carried equally often none is the class's (a student
    /// who made their own exercise must not be graded by it): the teacher's must be given. An exercise made before disturbances could be
    /// locked does not say which disturbances are the teacher's: they are the ones most of the
    /// hand-ins that carry it have (a student's clicks are the student's own).
    pub fn from_handins(docs: impl IntoIterator<Item = Value>) -> Result<Teacher> {
        let mut seen: Vec<Carried> = Vec::new();
        let mut of = 0;
        for doc in docs {
            let Some(section) = doc.get("exercise") else {
                continue;
            };
            of += 1;
            let key = canonical(section.clone()).to_string();
            let list = Value::Array(crate::exercise::listed(&doc).to_vec());
            let at = match seen.iter().position(|c| c.key == key) {
                Some(at) => at,
                None => {
                    seen.push(Carried {
                        key,
                        count: 0,
                        doc: doc.clone(),
                        lists: Vec::new(),
                    });
                    seen.len() - 1
                }
            };
            let carried = &mut seen[at];
            carried.count += 1;
            let list_key = canonical(list.clone()).to_string();
            match carried.lists.iter_mut().find(|(k, ..)| *k == list_key) {
                Some((_, n, _)) => *n += 1,
                None => carried.lists.push((list_key, 1, list)),
            }
        }
        let most = seen.iter().map(|c| c.count).max().ok_or_else(|| {
            Error::field(
                "exercise",
                "none of the hand-ins carries an exercise: give the teacher's exercise (its link or a lesson's name)",
            )
        })?;
        let tied = seen.iter().filter(|c| c.count == most).count();
        if tied > 1 {
            return Err(Error::field(
                "exercise",
                format!(
                    "the hand-ins carry {tied} different exercises equally often ({most} each), so none is the class's: give the teacher's exercise (its link or a lesson's name)"
                ),
            ));
        }
        let carried = seen
            .into_iter()
            .find(|c| c.count == most)
            .expect("the most carried exercise is among those seen");
        let mut section = carried.doc["exercise"].clone();
        if let Some(Value::Object(locked)) = section.get_mut("locked") {
            locked
                .entry(DISTURBANCES.to_string())
                .or_insert_with(|| most_common(&carried.lists));
        } else if let Value::Object(map) = &mut section {
            map.insert(
                "locked".into(),
                serde_json::json!({ DISTURBANCES: most_common(&carried.lists) }),
            );
        }
        let exercise =
            Exercise::from_value(section, &carried.doc).map_err(|e| e.within("exercise"))?;
        Ok(Teacher {
            exercise: serde_json::to_value(&exercise).expect("an exercise serialises"),
            scenario: None,
            source: Source::Handins {
                carried: carried.count,
                of,
            },
            read: Some(exercise),
        })
    }

    /// A teacher sent as JSON ([`Teacher::to_json`]), its exercise checked again.
    pub fn from_json(text: &str) -> Result<Teacher> {
        let mut teacher: Teacher = serde_json::from_str(text).map_err(|e| Error::json(&e))?;
        let exercise = Exercise::checked(teacher.exercise.clone())?;
        teacher.read = Some(exercise);
        Ok(teacher)
    }

    /// This teacher as JSON, for a grading worker.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).expect("a teacher serialises")
    }

    /// The class's exercise.
    pub fn exercise(&self) -> &Exercise {
        self.read
            .as_ref()
            .expect("a teacher's exercise is read when it is made")
    }

    /// Where it came from.
    pub fn source(&self) -> &Source {
        &self.source
    }

    /// What the Grade view shows of the class's exercise, and the teacher for its workers.
    pub fn summary(&self) -> ClassExercise {
        ClassExercise {
            teacher: self.to_json(),
            title: self.exercise().title.clone(),
            describe: self.describe(),
            source: self.source.clone(),
            question: self.exercise().question.clone(),
            header: super::table::csv_header(self),
        }
    }

    /// The class's exercise in words: `“Fewer collisions”, given` or `“Fewer collisions”, which
    /// 28 of the 30 hand-ins with an exercise carry`.
    pub fn describe(&self) -> String {
        let title = &self.exercise().title;
        match self.source {
            Source::Given => format!("“{title}”, given"),
            Source::Handins { carried, of } => format!(
                "“{title}”, which {carried} of the {of} hand-ins with an exercise carry (none was given)"
            ),
        }
    }

    /// Where the hand-in's exercise `theirs` differs from the class's, as the exercise's paths
    /// (`goal`, `locked.seed`); `None` when it is the class's. The teacher's disturbances are left
    /// aside: the class's are the ones kept, and a hand-in's are judged as disturbances.
    pub fn exercise_differences(&self, theirs: Option<&Exercise>) -> Option<Vec<String>> {
        let Some(theirs) = theirs else {
            return Some(vec!["(the hand-in has no exercise)".into()]);
        };
        let strip = |mut v: Value| {
            if let Some(Value::Object(locked)) = v.get_mut("locked") {
                locked.remove(DISTURBANCES);
            }
            v
        };
        let ours = strip(self.exercise.clone());
        let theirs = strip(serde_json::to_value(theirs).expect("an exercise serialises"));
        if same(&ours, &theirs) {
            return None;
        }
        let paths: Vec<String> = differences(&ours, &theirs);
        Some(match paths.is_empty() {
            true => vec!["(numbers written differently)".into()],
            false => paths,
        })
    }

    /// The fields of the hand-in `doc` that differ from the teacher's scenario, when it is known
    /// (the exercise, the hand-in's record and the name, which Hand in sets, left out).
    pub fn changed(&self, doc: &Value) -> Vec<String> {
        let Some(ours) = &self.scenario else {
            return Vec::new();
        };
        differences(ours, doc)
            .into_iter()
            .filter(|p| {
                !(p == "exercise"
                    || p.starts_with("exercise.")
                    || p == "name"
                    || p == "handin"
                    || p.starts_with("handin."))
            })
            .collect()
    }
}
