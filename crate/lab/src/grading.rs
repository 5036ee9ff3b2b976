//! Hand-ins graded as `kumiki check` grades them, for the gallery's Grade view and its workers:
//! the class's file read ([`read_handins`]: text, CSV or a workbook), the class's exercise found
//! ([`class_exercise`]: the teacher's, or the one most hand-ins carry), each row graded within the
//! exercise's budget ([`grade_row`], or in slices with [`RowReplay`] so a worker can say which row
//! is running and how far it is), and the table's CSV ([`grades_csv`]): the same code as the CLI's.

use kumiki_core::grading::table::{self, Row};
use kumiki_core::grading::{self, Graded, Replay, Teacher};
use kumiki_core::handins::{self, Handin};
use kumiki_core::{lessons, link, Limits, Scenario};
use wasm_bindgen::prelude::*;

use crate::{js_err, to_js};

/// The teacher's exercise for grading: a link, or a lesson's name, as `kumiki check --exercise`
/// takes them; a scenario with no exercise section is refused.
fn teacher_exercise(text: &str) -> Result<Scenario, JsError> {
    let text = text.trim();
    let scenario = match lessons::names().any(|n| n == text) {
        true => lessons::scenario(text).map_err(js_err)?,
        false => {
            link::open_within(text, &Limits::PAGE)
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

/// The hand-ins in a class's file (its bytes: links one a line, a form's CSV or text export, or a
/// workbook), numbered as the grade table numbers them: a list of `Handin` records. A file that is
/// neither is refused with one message.
#[wasm_bindgen]
pub fn read_handins(bytes: &[u8]) -> Result<JsValue, JsError> {
    to_js(&handins::read(bytes).map_err(js_err)?)
}

/// The class's exercise: the teacher's (`exercise`: a link or a lesson's name) or, when none is
/// given, the one most of the hand-ins' `links` carry. Never a hand-in's own: a hand-in whose
/// exercise differs from it fails, saying so. Its `ClassExercise`.
#[wasm_bindgen]
pub fn class_exercise(exercise: Option<String>, links: Vec<String>) -> Result<JsValue, JsError> {
    let teacher = match exercise.as_deref().map(str::trim).filter(|e| !e.is_empty()) {
        Some(e) => Teacher::given(&teacher_exercise(e)?).map_err(js_err)?,
        None => Teacher::from_handins(
            links
                .iter()
                .filter_map(|l| link::unpack(l).ok().map(|(doc, _)| doc)),
        )
        .map_err(js_err)?,
    };
    to_js(&teacher.summary())
}

/// A row of the class's file, as [`read_handins`] gave it (`handin_json`), graded by the class's
/// exercise (`teacher_json`, from [`class_exercise`]) within its budget, timed by the worker's
/// clock: its `Row` of the grade table.
#[wasm_bindgen]
pub fn grade_row(handin_json: &str, teacher_json: &str) -> Result<JsValue, JsError> {
    let (handin, teacher) = parts(handin_json, teacher_json)?;
    let started = js_sys::Date::now();
    let mut clock = || (js_sys::Date::now() - started) / 1000.0;
    let graded = opened(&handin)
        .and_then(|s| grading::grade(s, &teacher, &mut clock).map_err(|e| e.to_string()));
    to_js(&row(&handin, graded))
}

/// One row being graded in slices: a worker advances it a few steps at a time, says which row
/// is running and at which step between slices, stops it at the exercise's time budget, and can
/// drop it when the teacher skips a stuck row.
#[wasm_bindgen]
pub struct RowReplay {
    handin: Handin,
    /// The replay, or why the row cannot be graded.
    replay: Result<Replay, String>,
    /// The exercise's time budget, in seconds.
    seconds: Option<f64>,
}

#[wasm_bindgen]
impl RowReplay {
    /// Starts grading a row (`handin_json`, from [`read_handins`]) by the class's exercise
    /// (`teacher_json`): its rules judged and its run built.
    #[wasm_bindgen(constructor)]
    pub fn new(handin_json: &str, teacher_json: &str) -> Result<RowReplay, JsError> {
        let (handin, teacher) = parts(handin_json, teacher_json)?;
        let replay =
            opened(&handin).and_then(|s| Replay::start(s, &teacher).map_err(|e| e.to_string()));
        Ok(RowReplay {
            handin,
            replay,
            seconds: teacher.exercise().budget.and_then(|b| b.seconds),
        })
    }

    /// The row's number in the grade table.
    pub fn row(&self) -> u32 {
        self.handin.row as u32
    }

    /// The steps replayed so far.
    pub fn steps(&self) -> f64 {
        self.replay.as_ref().map_or(0.0, |r| r.steps() as f64)
    }

    /// The exercise's time budget in seconds; undefined when it has none.
    pub fn time_budget(&self) -> Option<f64> {
        self.seconds
    }

    /// Replays at most `steps` more; true when there is no more to replay.
    pub fn advance(&mut self, steps: f64) -> bool {
        match &mut self.replay {
            Ok(r) => r.advance(steps as u64),
            Err(_) => true,
        }
    }

    /// The row's `Row`: `out_of_time` when the worker stopped it at the time budget.
    pub fn finish(self, out_of_time: bool) -> Result<JsValue, JsError> {
        let graded = self.replay.map(|r| r.finish(out_of_time));
        to_js(&row(&self.handin, graded))
    }
}

/// The grade table's CSV (`rows_json`: the rows, as JSON), exactly as `kumiki check --format csv`
/// writes it for the same class.
#[wasm_bindgen]
pub fn grades_csv(rows_json: &str, teacher_json: &str) -> Result<String, JsError> {
    let teacher = Teacher::from_json(teacher_json).map_err(js_err)?;
    let rows: Vec<Row> = serde_json::from_str(rows_json).map_err(js_err)?;
    Ok(table::csv(&rows, &teacher))
}

/// Grades one hand-in as `kumiki check` does (page limits): the link replayed to its end and
/// judged by the teacher's exercise (`exercise`: a link or a lesson's name) when given, else by
/// the one it carries (the Grade view as it is today; [`class_exercise`] finds the class's
/// exercise among all the hand-ins). Its `Graded` row.
#[wasm_bindgen]
pub fn grade_handin(handin: &str, exercise: Option<String>) -> Result<JsValue, JsError> {
    let given = exercise.map(|e| teacher_exercise(&e)).transpose()?;
    let graded = link::open_within(handin.trim(), &Limits::PAGE).and_then(|o| {
        let teacher = match &given {
            Some(t) => Teacher::given(t)?,
            None => Teacher::given(&o.scenario)?,
        };
        let started = js_sys::Date::now();
        let mut clock = || (js_sys::Date::now() - started) / 1000.0;
        grading::grade(o.scenario, &teacher, &mut clock)
    });
    to_js(&Graded::of(graded))
}

fn parts(handin_json: &str, teacher_json: &str) -> Result<(Handin, Teacher), JsError> {
    let handin: Handin = serde_json::from_str(handin_json).map_err(js_err)?;
    let teacher = Teacher::from_json(teacher_json).map_err(js_err)?;
    Ok((handin, teacher))
}

/// A row's scenario, from its link (the page's limits).
fn opened(handin: &Handin) -> Result<Scenario, String> {
    match &handin.link {
        Some(l) => link::open_within(l, &Limits::PAGE)
            .map(|o| o.scenario)
            .map_err(|e| e.to_string()),
        None => Err(handin.no_link()),
    }
}

fn row(handin: &Handin, graded: Result<grading::Grade, String>) -> Row {
    Row {
        handin: handin.row,
        student: handin.student.clone(),
        link: handin.link.clone(),
        graded: match graded {
            Ok(g) => Graded::from(g),
            Err(error) => Graded::Failed { error },
        },
    }
}
