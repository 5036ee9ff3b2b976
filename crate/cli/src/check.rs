//! `kumiki check`: grades classroom hand-ins by the teacher's exercise. The hand-ins are links on
//! the command line and the rows of a file (links one a line, a form's CSV or text export, or a
//! workbook, read by the core's `handins`, as the page's Grade view reads them); the exercise is
//! the teacher's when given, else the one most hand-ins carry (never a hand-in's own). Each
//! hand-in that keeps to the exercise's rules is replayed within its budget and judged (the
//! core's `grading`); one row a hand-in, numbered as the page's table numbers them, in input
//! order.

use std::io::Write;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use kumiki_core::grading::table::{self, Row};
use kumiki_core::grading::{self, Graded, Teacher};
use kumiki_core::handins::{self, Handin};
use kumiki_core::{link, Limits, Scenario};
use serde_json::Value;

use crate::{pool, runs, Failure};

/// The hand-ins named on the command line (links, or scenario files), then the rows of `file`,
/// numbered from 1 in that order.
pub fn handins(links: Vec<String>, file: Option<&Path>) -> Result<Vec<Handin>, Failure> {
    let mut all: Vec<Handin> = links
        .into_iter()
        .map(|text| Handin {
            row: 0,
            line: 0,
            student: String::new(),
            link: handins::find_link(&text).map(str::to_string),
            text,
        })
        .collect();
    if let Some(file) = file {
        let bytes = std::fs::read(file).map_err(|e| format!("{}: {e}", file.display()))?;
        let read = handins::read(&bytes).map_err(|e| format!("{}: {e}", file.display()))?;
        all.extend(read);
    }
    if all.is_empty() {
        return Err(Failure::Usage(
            "check needs hand-in links, as arguments or with --file".into(),
        ));
    }
    for (i, h) in all.iter_mut().enumerate() {
        h.row = i + 1;
    }
    Ok(all)
}

/// A hand-in's scenario: its link, or (a command-line argument, a one-cell row) a scenario file.
/// `older` counts the links made with another behaviour version of their model, said once at the
/// end rather than once a hand-in.
fn load(h: &Handin, limits: &'static Limits, older: &AtomicUsize) -> Result<Scenario, String> {
    let failed = |e: Failure| match e {
        Failure::Usage(m) | Failure::Run(m) => m,
    };
    match &h.link {
        Some(link) => {
            let opened = link::open_within(link, limits).map_err(|e| e.to_string())?;
            if opened.version_differs() {
                older.fetch_add(1, Ordering::Relaxed);
            }
            Ok(opened.scenario)
        }
        None if Path::new(h.text.trim()).is_file() => {
            runs::load_scenario(h.text.trim(), limits).map_err(failed)
        }
        None => Err(h.no_link()),
    }
}

/// A hand-in's scenario document, unread, to find the exercise most hand-ins carry.
fn document(h: &Handin) -> Option<Value> {
    match &h.link {
        Some(l) => link::unpack(l).ok().map(|(doc, _)| doc),
        None => {
            let text = std::fs::read_to_string(h.text.trim()).ok()?;
            serde_json::from_str(&text).ok()
        }
    }
}

/// The class's exercise: the teacher's (`given`), else the one most hand-ins carry.
pub fn teacher(given: Option<&Scenario>, all: &[Handin]) -> Result<Teacher, Failure> {
    let teacher = match given {
        Some(s) => Teacher::given(s),
        None => Teacher::from_handins(all.iter().filter_map(document)),
    };
    teacher.map_err(|e| Failure::Usage(format!("--exercise: {e}")))
}

/// How `kumiki check` writes its rows.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum CheckFormat {
    /// One JSON object a line
    Json,
    /// A CSV table with a header: the page's Grade view exports the same
    Csv,
    /// One line a student: `Ada: met in 209 steps`
    Text,
}

/// How many hand-ins met the goal, did not (and of those, how many ran over the budget), and
/// could not be graded.
#[derive(Default)]
pub struct Tally {
    pub met: usize,
    pub unmet: usize,
    pub over_budget: usize,
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
        let over = match self.over_budget {
            0 => String::new(),
            n => format!(" ({n} over budget)"),
        };
        write!(
            f,
            "{total} hand-in{s}: {} met, {} not met{over}, {} could not be graded",
            self.met, self.unmet, self.errors
        )
    }
}

pub fn run(
    handins: &[Handin],
    teacher: &Teacher,
    format: CheckFormat,
    threads: usize,
    limits: &'static Limits,
    out: &mut impl Write,
) -> Result<Tally, Failure> {
    if format == CheckFormat::Csv {
        writeln!(out, "{}", table::csv_header(teacher))?;
    }
    let mut tally = Tally::default();
    let older = AtomicUsize::new(0);
    pool::run_ordered(
        handins.len(),
        threads,
        |i| {
            let h = &handins[i];
            let started = Instant::now();
            let mut clock = || started.elapsed().as_secs_f64();
            let graded = load(h, limits, &older)
                .and_then(|s| grading::grade(s, teacher, &mut clock).map_err(|e| e.to_string()));
            Row {
                handin: h.row,
                student: h.student.clone(),
                link: h.link.clone(),
                graded: match graded {
                    Ok(grade) => Graded::from(grade),
                    Err(error) => Graded::Failed { error },
                },
            }
        },
        |_, row| -> Result<(), Failure> {
            match row.graded.grade() {
                Some(g) if g.met => tally.met += 1,
                Some(g) => {
                    tally.unmet += 1;
                    tally.over_budget += usize::from(g.over_budget);
                }
                None => tally.errors += 1,
            }
            match format {
                CheckFormat::Json => writeln!(
                    out,
                    "{}",
                    serde_json::to_string(&row).expect("rows serialise")
                )?,
                CheckFormat::Csv => writeln!(out, "{}", table::csv_row(&row, teacher))?,
                CheckFormat::Text => writeln!(out, "{}", table::text_row(&row))?,
            }
            Ok(())
        },
    )?;
    match older.into_inner() {
        0 => {}
        n => eprintln!(
            "kumiki: {n} of the hand-ins were made with another behaviour version of their model than this Kumiki runs; their runs may differ from the ones their students saw"
        ),
    }
    Ok(tally)
}
