//! A class's hand-ins read from what a teacher has: links pasted one a line (as `kumiki check
//! --file` always read them), or the export of a form or a learning platform, one hand-in a row
//! with the student's name in another column, as CSV or text (RFC 4180: quoted cells with
//! separators, quotes and line breaks in them; a byte-order mark; comma, semicolon or tab between
//! cells, as spreadsheets write them; UTF-8, UTF-16 or Windows-1252) or as a workbook (.xlsx, and
//! .ods and .xls). Anything else is refused with one message. `kumiki check` and the page's Grade
//! view (through the lab module) read files with this code, so both find the same hand-ins, and
//! number them as the grade table does.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

mod sheet;
mod text;

/// The one message for a file that is neither text nor a workbook.
pub const NOT_HANDINS: &str = "this file is neither text (links one a line, or a form's CSV export) nor a workbook (.xlsx, .ods, .xls): save the export as CSV or .xlsx";

/// The most hand-ins one file may hold.
pub const MAX_HANDINS: usize = 1_000_000;

/// One hand-in of a class's file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct Handin {
    /// Its number in the grade table, from 1.
    pub row: usize,
    /// The line of the file (a workbook's row) it starts on, from 1.
    pub line: usize,
    /// The student's name from the file's other cells; empty when it has none.
    pub student: String,
    /// The Kumiki link in it, or `None` when the row holds none (it is then graded as an error).
    pub link: Option<String>,
    /// The row as it was, its cells joined by the file's separator, for a row without a link.
    pub text: String,
}

impl Handin {
    /// Why this row cannot be graded, when it holds no link.
    pub fn no_link(&self) -> String {
        let shown: String = self.text.chars().take(80).collect();
        let more = if self.text.chars().count() > 80 {
            "…"
        } else {
            ""
        };
        format!(
            "holds no Kumiki link (line {} of the file): {shown}{more}",
            self.line
        )
    }
}

/// A record of the file: the line it starts on and its cells.
struct Record {
    line: usize,
    cells: Vec<String>,
}

/// The hand-ins in a file's bytes, whatever its kind: a workbook's first sheet, or text.
pub fn read(bytes: &[u8]) -> Result<Vec<Handin>> {
    let (records, separator) = match sheet::is_workbook(bytes) {
        true => (sheet::records(bytes)?, ","),
        false => text::records(bytes)?,
    };
    handins(records, separator)
}

/// The hand-ins in records: blank rows and rows starting with `#` that hold no link skipped (as
/// `kumiki check --file` always did); a first row without a link is a header, which may say which
/// column names the student.
fn handins(records: Vec<Record>, separator: &str) -> Result<Vec<Handin>> {
    let mut out = Vec::new();
    let mut names: Option<NameColumns> = None;
    for record in records {
        if record.cells.iter().all(|c| c.trim().is_empty()) {
            continue;
        }
        let link = record.cells.iter().find_map(|c| find_link(c));
        let first = record.cells[0].trim_start();
        if link.is_none() && first.starts_with('#') {
            continue;
        }
        if names.is_none() && out.is_empty() && link.is_none() {
            names = Some(NameColumns::of(&record.cells));
            continue;
        }
        if out.len() == MAX_HANDINS {
            return Err(Error::field(
                "",
                format!("more than {MAX_HANDINS} hand-ins in one file"),
            ));
        }
        let student = names
            .as_ref()
            .and_then(|n| n.name(&record.cells))
            .unwrap_or_else(|| guessed_name(&record.cells));
        out.push(Handin {
            row: out.len() + 1,
            line: record.line,
            student,
            link: link.map(str::to_string),
            text: shown_cells(&record.cells).join(separator),
        });
    }
    Ok(out)
}

/// A row's cells up to its last that holds something.
fn shown_cells(cells: &[String]) -> &[String] {
    let end = cells
        .iter()
        .rposition(|c| !c.trim().is_empty())
        .map_or(0, |i| i + 1);
    &cells[..end]
}

/// The columns of a header that name the student: one (`Name`, `Student`, `Learner`, `User`), or
/// a first and a last name together.
struct NameColumns {
    first: Option<usize>,
    last: Option<usize>,
    whole: Option<usize>,
}

impl NameColumns {
    fn of(header: &[String]) -> NameColumns {
        let find = |words: &[&str]| {
            header.iter().position(|h| {
                let h = h.to_lowercase();
                words.iter().any(|w| h.contains(w))
            })
        };
        NameColumns {
            first: find(&["first name", "firstname", "given name"]),
            last: find(&["last name", "lastname", "surname", "family name"]),
            whole: find(&["name", "student", "learner", "user"]),
        }
    }

    fn name(&self, cells: &[String]) -> Option<String> {
        let cell = |i: Option<usize>| {
            i.and_then(|i| cells.get(i))
                .map(|c| c.trim())
                .filter(|c| !c.is_empty() && find_link(c).is_none())
        };
        match (cell(self.first), cell(self.last)) {
            (Some(f), Some(l)) => Some(format!("{f} {l}")),
            _ => cell(self.whole).map(str::to_string),
        }
    }
}

/// The first cell that is neither a link, a number nor a time: the student's name when the file
/// has no header that says.
fn guessed_name(cells: &[String]) -> String {
    cells
        .iter()
        .map(|c| c.trim())
        .find(|c| !c.is_empty() && find_link(c).is_none() && !number_or_time(c))
        .unwrap_or_default()
        .to_string()
}

/// A number, a date or a time, as forms write them (`2026/11/28 10:15:00 AM GMT+1`).
fn number_or_time(cell: &str) -> bool {
    let words: Vec<&str> = cell
        .split_whitespace()
        .filter(|w| {
            let w = w.to_ascii_uppercase();
            !(w == "AM" || w == "PM" || w.starts_with("GMT") || w.starts_with("UTC"))
        })
        .collect();
    !words.is_empty()
        && words.iter().all(|w| {
            w.chars()
                .all(|c| c.is_ascii_digit() || ":./+-TZ,".contains(c))
        })
}

/// The Kumiki link in a cell: a URL whose fragment is `#k1.…`, or the bare `#k1.…` or `k1.…`.
pub fn find_link(cell: &str) -> Option<&str> {
    let prefix = crate::link::PREFIX;
    cell.split(|c: char| c.is_whitespace() || "\"'<>,;()[]".contains(c))
        .find_map(|token| {
            let at = token.find(prefix)?;
            let start = match &token[..at] {
                "" | "#" => 0,
                before if before.ends_with('#') && before.contains("://") => 0,
                _ => return None,
            };
            let payload = &token[at + prefix.len()..];
            let len = payload
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '-'))
                .unwrap_or(payload.len());
            (len > 0).then(|| &token[start..at + prefix.len() + len])
        })
}

#[cfg(test)]
mod tests;
