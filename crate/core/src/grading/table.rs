//! The grade table: one [`Row`] a hand-in, numbered as the table shows it, and its CSV, the same
//! bytes from `kumiki check --format csv` and the page's Grade view (both write it here).

use serde::{Deserialize, Serialize};
use serde_json::Value;

use super::{Graded, Teacher};
use crate::export::csv_text;

/// One row of the grade table: the hand-in's number (its row in the table, from 1), the student's
/// name as the class's file gives it, its link, and its grade or why it could not be graded.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct Row {
    pub handin: usize,
    /// The student's name from the class's file (empty when the file gives none; the grade's
    /// `name` is the one the hand-in carries).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub student: String,
    /// The hand-in's link, as the file gave it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub link: Option<String>,
    #[serde(flatten)]
    pub graded: Graded,
}

/// The fixed columns before the metrics.
const HEAD: &[&str] = &[
    "handin",
    "student",
    "name",
    "met",
    "points",
    "max_points",
    "because",
    "completed",
    "steps",
    "over_budget",
    "hash",
    "locked_edited",
    "disturbances",
    "changed",
    "exercise_edited",
    "credit",
    "made",
    "checks",
    "hints",
    "answer",
];

/// The CSV header of a class graded by `teacher`: the fixed columns, one `metrics.NAME` column for
/// each metric its goal and credit read, then `error` and `link`.
pub fn csv_header(teacher: &Teacher) -> String {
    let metrics = teacher
        .exercise()
        .metric_names()
        .into_iter()
        .map(|m| format!("metrics.{m}"));
    HEAD.iter()
        .map(|h| h.to_string())
        .chain(metrics)
        .chain(["error".to_string(), "link".to_string()])
        .collect::<Vec<_>>()
        .join(",")
}

/// One row as CSV, its columns as [`csv_header`] names them for `teacher`. Text a spreadsheet
/// would read as a formula is neutralised ([`csv_text`]).
pub fn csv_row(row: &Row, teacher: &Teacher) -> String {
    let metrics = teacher.exercise().metric_names();
    let list = |items: &[String]| csv_text(&items.join("; "));
    let number = |n: Option<u32>| n.map_or_else(String::new, |n| n.to_string());
    let mut cells = vec![row.handin.to_string(), csv_text(&row.student)];
    match &row.graded {
        Graded::Graded {
            grade: g,
            goal_metrics,
        } => {
            let handin = g.record.clone().unwrap_or_default();
            let credit: Vec<String> = g
                .credit
                .iter()
                .map(|c| format!("{}: {} of {}", c.goal, c.earned, c.points))
                .collect();
            cells.extend([
                csv_text(&g.name),
                g.met.to_string(),
                number(g.points),
                number(g.max_points),
                csv_text(&g.because),
                g.completed.to_string(),
                g.steps.to_string(),
                g.over_budget.to_string(),
                g.hash.clone(),
                list(&g.locked_edited),
                list(&g.disturbances),
                list(&g.changed),
                g.exercise_edited.to_string(),
                list(&credit),
                csv_text(&handin.made),
                match g.record {
                    Some(_) => handin.checks.to_string(),
                    None => String::new(),
                },
                match g.record {
                    Some(_) => handin.hints.to_string(),
                    None => String::new(),
                },
                csv_text(&handin.answer),
            ]);
            cells.extend(metrics.iter().map(|m| match goal_metrics.get(m) {
                Some(Value::String(s)) => csv_text(s),
                Some(v) => v.to_string(),
                None => String::new(),
            }));
            cells.push(String::new());
        }
        Graded::Failed { error } => {
            cells.extend((2..HEAD.len()).map(|i| match HEAD[i] {
                "met" => "false".to_string(),
                _ => String::new(),
            }));
            cells.extend(metrics.iter().map(|_| String::new()));
            cells.push(csv_text(error));
        }
    }
    cells.push(csv_text(row.link.as_deref().unwrap_or_default()));
    cells.join(",")
}

/// The whole table as CSV: the header, then a line a row.
pub fn csv(rows: &[Row], teacher: &Teacher) -> String {
    let mut out = csv_header(teacher);
    out.push('\n');
    for row in rows {
        out.push_str(&csv_row(row, teacher));
        out.push('\n');
    }
    out
}

/// One line a row for a terminal: `3. Ada: met in 209 steps`, or why it could not be graded.
pub fn text_row(row: &Row) -> String {
    match &row.graded {
        Graded::Graded { grade, .. } => format!("{}. {}", row.handin, grade.summary()),
        Graded::Failed { error } => format!("{}. could not be graded: {error}", row.handin),
    }
}
