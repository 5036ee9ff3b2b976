//! A text file's records: its bytes decoded (a UTF-8 or UTF-16 byte-order mark, else UTF-8, else
//! Windows-1252, which older spreadsheets write), its separator found (comma, semicolon or tab:
//! the one that splits its first records alike into most cells), and its records read as RFC
//! 4180 says, by the `csv` crate: quoted cells may hold separators, doubled quotes and line breaks.

use super::{Record, NOT_HANDINS};
use crate::error::{Error, Result};

/// The separators spreadsheets write between cells, in the order a tie goes.
const SEPARATORS: [u8; 3] = [b',', b';', b'\t'];
/// The records the separator is judged on.
const SNIFF_RECORDS: usize = 50;

/// The records of a text file, and its separator (as text, to join a row back).
pub(super) fn records(bytes: &[u8]) -> Result<(Vec<Record>, &'static str)> {
    let text = decode(bytes)?;
    let separator = separator(&text);
    let mut reader = csv::ReaderBuilder::new()
        .delimiter(separator)
        .has_headers(false)
        .flexible(true)
        .from_reader(text.as_bytes());
    let mut out = Vec::new();
    let mut lines = Lines::new(text.as_bytes());
    for record in reader.records() {
        let record = record.map_err(|e| Error::field("", format!("the file's text: {e}")))?;
        let line = lines.at(record.position().map_or(0, |p| p.byte() as usize));
        out.push(Record {
            line,
            cells: record.iter().map(str::to_string).collect(),
        });
    }
    let shown = match separator {
        b';' => ";",
        b'\t' => "\t",
        _ => ",",
    };
    Ok((out, shown))
}

/// The line of the file a record starts on, counted as a person reads it: the reader places a
/// record after the blank lines before it, which the record does not start on.
struct Lines<'a> {
    text: &'a [u8],
    /// Where the count stands, and the line there.
    at: usize,
    line: usize,
}

impl<'a> Lines<'a> {
    fn new(text: &'a [u8]) -> Lines<'a> {
        Lines {
            text,
            at: 0,
            line: 1,
        }
    }

    /// The line of the first character at or after byte `from` that ends no line.
    fn at(&mut self, from: usize) -> usize {
        let mut start = from.min(self.text.len());
        while start < self.text.len() && matches!(self.text[start], b'\r' | b'\n') {
            start += 1;
        }
        if start < self.at {
            return self.line;
        }
        self.line += self.text[self.at..start]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        self.at = start;
        self.line
    }
}

/// The text of a file: UTF-8 (its byte-order mark dropped) or UTF-16 with its byte-order mark, or
/// else Windows-1252. Bytes no text holds (a zero byte, other control bytes) make it no text.
fn decode(bytes: &[u8]) -> Result<String> {
    let text = if let Some(rest) = bytes.strip_prefix(&[0xef, 0xbb, 0xbf]) {
        String::from_utf8(rest.to_vec()).map_err(|_| Error::field("", NOT_HANDINS))?
    } else if let Some(rest) = bytes.strip_prefix(&[0xff, 0xfe]) {
        utf16(rest, u16::from_le_bytes)?
    } else if let Some(rest) = bytes.strip_prefix(&[0xfe, 0xff]) {
        utf16(rest, u16::from_be_bytes)?
    } else {
        match std::str::from_utf8(bytes) {
            Ok(text) => text.to_string(),
            Err(_) => bytes.iter().map(|&b| windows_1252(b)).collect(),
        }
    };
    let binary = text
        .chars()
        .any(|c| c.is_control() && !matches!(c, '\n' | '\r' | '\t' | '\u{0c}'));
    match binary {
        true => Err(Error::field("", NOT_HANDINS)),
        false => Ok(text),
    }
}

fn utf16(bytes: &[u8], unit: fn([u8; 2]) -> u16) -> Result<String> {
    if bytes.len() % 2 != 0 {
        return Err(Error::field("", NOT_HANDINS));
    }
    let units: Vec<u16> = bytes.chunks_exact(2).map(|c| unit([c[0], c[1]])).collect();
    String::from_utf16(&units).map_err(|_| Error::field("", NOT_HANDINS))
}

/// A Windows-1252 byte as its character.
fn windows_1252(b: u8) -> char {
    const HIGH: [char; 32] = [
        '€', '\u{81}', '‚', 'ƒ', '„', '…', '†', '‡', 'ˆ', '‰', 'Š', '‹', 'Œ', '\u{8d}', 'Ž',
        '\u{8f}', '\u{90}', '‘', '’', '“', '”', '•', '–', '—', '˜', '™', 'š', '›', 'œ', '\u{9d}',
        'ž', 'Ÿ',
    ];
    match b {
        0x80..=0x9f => HIGH[(b - 0x80) as usize],
        _ => b as char,
    }
}

/// The separator that splits the first records into the most cells, alike: for each candidate,
/// the number of cells most of those records have (more than one), times how many have it.
fn separator(text: &str) -> u8 {
    let mut best = (0, b',');
    for sep in SEPARATORS {
        let mut reader = csv::ReaderBuilder::new()
            .delimiter(sep)
            .has_headers(false)
            .flexible(true)
            .from_reader(text.as_bytes());
        let widths: Vec<usize> = reader
            .records()
            .take(SNIFF_RECORDS)
            .filter_map(|r| r.ok())
            .filter(|r| r.iter().any(|c| !c.trim().is_empty()))
            .map(|r| r.len())
            .collect();
        let score = widths
            .iter()
            .filter(|&&w| w > 1)
            .map(|&w| w * widths.iter().filter(|&&v| v == w).count())
            .max()
            .unwrap_or(0);
        if score > best.0 {
            best = (score, sep);
        }
    }
    best.1
}
