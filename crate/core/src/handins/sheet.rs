//! A workbook's records, read by `calamine`: its first sheet's rows, each cell as its text (a
//! number as written, a date as the serial number a spreadsheet keeps). A form or a learning
//! platform exports one sheet; other sheets are not read.

use std::io::Cursor;

use calamine::{open_workbook_auto_from_rs, Data, Reader};

use super::{Record, NOT_HANDINS};
use crate::error::{Error, Result};

/// A ZIP archive (.xlsx, .xlsm, .xlsb, .ods) or an OLE compound file (.xls).
pub(super) fn is_workbook(bytes: &[u8]) -> bool {
    bytes.starts_with(b"PK\x03\x04") || bytes.starts_with(&[0xd0, 0xcf, 0x11, 0xe0])
}

/// The rows of a workbook's first sheet, numbered as the spreadsheet numbers them.
pub(super) fn records(bytes: &[u8]) -> Result<Vec<Record>> {
    let mut book = open_workbook_auto_from_rs(Cursor::new(bytes))
        .map_err(|_| Error::field("", NOT_HANDINS))?;
    let range = match book.worksheet_range_at(0) {
        Some(Ok(range)) => range,
        Some(Err(e)) => {
            return Err(Error::field(
                "",
                format!("the workbook's first sheet cannot be read: {e}"),
            ))
        }
        None => return Err(Error::field("", "the workbook has no sheet")),
    };
    let first = range.start().map_or(0, |(row, _)| row as usize);
    let lead = range.start().map_or(0, |(_, column)| column as usize);
    Ok(range
        .rows()
        .enumerate()
        .map(|(i, row)| Record {
            line: first + i + 1,
            cells: std::iter::repeat_n(String::new(), lead)
                .chain(row.iter().map(cell))
                .collect(),
        })
        .collect())
}

/// A cell as text: a whole number without its `.0`.
fn cell(data: &Data) -> String {
    match data {
        Data::Float(f) if f.fract() == 0.0 && f.abs() < 1e15 => format!("{}", *f as i64),
        other => other.to_string(),
    }
}
