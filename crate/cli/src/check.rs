//! `kumiki check`: grades classroom hand-ins. Each hand-in link is replayed to its end and judged
//! by its exercise's goal (the core's `grading::grade`); one row per hand-in, in input order.

use std::io::Write;
use std::path::Path;

use kumiki_core::export::csv_text;
use kumiki_core::grading::{self, Grade};
use kumiki_core::Scenario;
use serde::Serialize;

use crate::{pool, Failure};

/// One hand-in's row: its place in the input, and its grade or why it could not be graded.
#[derive(Serialize)]
struct Row {
    handin: usize,
    #[serde(flatten)]
    grade: Option<Grade>,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<String>,
}

/// The hand-ins named on the command line, then those in `file`, one a line (blank lines and
/// lines starting with `#` skipped: a link's own `#` comes after its address).
pub fn handins(links: Vec<String>, file: Option<&Path>) -> Result<Vec<String>, Failure> {
    let mut all = links;
    if let Some(file) = file {
        let text = std::fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
        all.extend(
            text.lines()
                .map(str::trim)
                .filter(|l| !l.is_empty() && !l.starts_with('#'))
                .map(str::to_string),
        );
    }
    if all.is_empty() {
        return Err(Failure::Usage(
            "check needs hand-in links, as arguments or with --file".into(),
        ));
    }
    Ok(all)
}

/// How `kumiki check` writes its rows.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum CheckFormat {
    /// One JSON object a line
    Json,
    /// A CSV table with a header
    Csv,
    /// One line a student: `Ada: met in 209 steps`
    Text,
}

/// How many hand-ins met the goal, did not, and could not be graded.
#[derive(Default)]
pub struct Tally {
    pub met: usize,
    pub unmet: usize,
    pub errors: usize,
}

impl Tally {
    pub fn all_met(&self) -> bool {
        self.unmet == 0 && self.errors == 0
    }
}

impl std::fmt::Display for Tally {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let total = self.met + self.unmet + self.errors;
        let s = if total == 1 { "" } else { "s" };
        write!(
            f,
            "{total} hand-in{s}: {} met, {} not met, {} could not be graded",
            self.met, self.unmet, self.errors
        )
    }
}

pub fn run(
    handins: &[String],
    original: Option<&Scenario>,
    format: CheckFormat,
    threads: usize,
    load: impl Fn(&str) -> Result<Scenario, Failure> + Sync,
    out: &mut impl Write,
) -> Result<Tally, Failure> {
    if format == CheckFormat::Csv {
        writeln!(
            out,
            "handin,name,met,because,completed,steps,hash,locked_edited,changed,exercise_edited,error"
        )?;
    }
    let mut tally = Tally::default();
    pool::run_ordered(
        handins.len(),
        threads,
        |i| {
            let graded = load(&handins[i])
                .map_err(|e| match e {
                    Failure::Usage(m) | Failure::Run(m) => m,
                })
                .and_then(|s| grading::grade(&s, original).map_err(|e| e.to_string()));
            match graded {
                Ok(grade) => Row {
                    handin: i + 1,
                    grade: Some(grade),
                    error: None,
                },
                Err(error) => Row {
                    handin: i + 1,
                    grade: None,
                    error: Some(error),
                },
            }
        },
        |_, row| -> Result<(), Failure> {
            match &row.grade {
                Some(g) if g.met => tally.met += 1,
                Some(_) => tally.unmet += 1,
                None => tally.errors += 1,
            }
            match format {
                CheckFormat::Json => writeln!(
                    out,
                    "{}",
                    serde_json::to_string(&row).expect("rows serialise")
                )?,
                CheckFormat::Csv => writeln!(out, "{}", csv_row(&row))?,
                CheckFormat::Text => writeln!(out, "{}", text_row(&row))?,
            }
            Ok(())
        },
    )?;
    Ok(tally)
}

/// `3. Ada: met in 209 steps`, or the reason it could not be graded.
fn text_row(row: &Row) -> String {
    match (&row.grade, &row.error) {
        (Some(g), _) => format!("{}. {}", row.handin, g.summary()),
        (None, error) => format!(
            "{}. could not be graded: {}",
            row.handin,
            error.as_deref().unwrap_or_default()
        ),
    }
}

fn csv_row(row: &Row) -> String {
    let list = |items: &[String]| csv_text(&items.join("; "));
    match (&row.grade, &row.error) {
        (Some(g), _) => format!(
            "{},{},{},{},{},{},{},{},{},{},",
            row.handin,
            csv_text(&g.name),
            g.met,
            csv_text(&g.because),
            g.completed,
            g.steps,
            g.hash,
            list(&g.locked_edited),
            list(&g.changed),
            g.exercise_edited
        ),
        (None, error) => format!(
            "{},,false,,,,,,,,{}",
            row.handin,
            csv_text(error.as_deref().unwrap_or_default())
        ),
    }
}
