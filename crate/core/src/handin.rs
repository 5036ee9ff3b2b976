//! A hand-in's own record, the scenario's `handin` section: when the student handed in, how many
//! checks and hints it took, and the answer to the exercise's question. The page writes it into
//! the hand-in link (the core has no clock: the page gives the time); the grade table shows it.
//! Nothing in it changes the run.
//!
//! ```json
//! "handin": { "made": "2026-11-28T10:15:00Z", "checks": 3, "hints": 1, "answer": "The relay…" }
//! ```

use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::error::{Error, Result};
use crate::exercise::MAX_HINTS;

/// The longest answer, in characters.
pub const MAX_ANSWER_CHARS: usize = 10_000;
/// The most checks a hand-in records.
pub const MAX_CHECKS: u32 = 1_000_000;

/// A hand-in's record of itself.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Handin {
    /// When it was handed in: an RFC 3339 time in UTC, `2026-11-28T10:15:00Z`, as the student's
    /// clock had it.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[schemars(length(max = 30))]
    pub made: String,
    /// How many times the student checked the goal before handing in.
    #[serde(default)]
    #[schemars(range(max = MAX_CHECKS))]
    pub checks: u32,
    /// How many of the exercise's hints the student revealed.
    #[serde(default)]
    #[schemars(range(max = MAX_HINTS))]
    pub hints: u32,
    /// The answer to the exercise's question, in words (not graded).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[schemars(length(max = MAX_ANSWER_CHARS))]
    pub answer: String,
}

impl Handin {
    /// Reads and checks a `handin` section.
    pub fn from_value(value: Value) -> Result<Handin> {
        let handin: Handin = crate::error::from_value(value)?;
        if !handin.made.is_empty() && !is_utc_time(&handin.made) {
            return Err(Error::field(
                "made",
                format!(
                    "'{}' is not a time such as 2026-11-28T10:15:00Z (RFC 3339, UTC)",
                    handin.made.chars().take(40).collect::<String>()
                ),
            ));
        }
        if handin.checks > MAX_CHECKS {
            return Err(Error::field(
                "checks",
                format!("{} is larger than the limit {MAX_CHECKS}", handin.checks),
            ));
        }
        if handin.hints as usize > MAX_HINTS {
            return Err(Error::field(
                "hints",
                format!(
                    "{} is more than the {MAX_HINTS} hints an exercise has",
                    handin.hints
                ),
            ));
        }
        let n = handin.answer.chars().count();
        if n > MAX_ANSWER_CHARS {
            return Err(Error::field(
                "answer",
                format!("{n} characters is too long; at most {MAX_ANSWER_CHARS}"),
            ));
        }
        Ok(handin)
    }
}

/// `YYYY-MM-DDTHH:MM:SS` with optional fractions of a second, then `Z`: the form JavaScript's
/// `Date.toISOString` writes.
fn is_utc_time(text: &str) -> bool {
    let Some(body) = text.strip_suffix('Z') else {
        return false;
    };
    let (main, fraction) = body.split_once('.').unwrap_or((body, "0"));
    let b = main.as_bytes();
    let digits = |r: std::ops::Range<usize>| b[r].iter().all(u8::is_ascii_digit);
    let number = |r: std::ops::Range<usize>| main[r].parse::<u32>().unwrap_or(99);
    b.len() == 19
        && digits(0..4)
        && b[4] == b'-'
        && digits(5..7)
        && b[7] == b'-'
        && digits(8..10)
        && b[10] == b'T'
        && digits(11..13)
        && b[13] == b':'
        && digits(14..16)
        && b[16] == b':'
        && digits(17..19)
        && (1..=12).contains(&number(5..7))
        && (1..=31).contains(&number(8..10))
        && number(11..13) < 24
        && number(14..16) < 60
        && number(17..19) < 61
        && !fraction.is_empty()
        && fraction.len() <= 9
        && fraction.bytes().all(|c| c.is_ascii_digit())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn a_handin_record_travels_in_the_link_and_is_checked() {
        let mut doc = crate::presets::scenario("amas-L").unwrap().to_value();
        doc["handin"] = json!({"made": "2026-11-28T10:15:00.123Z", "checks": 3, "hints": 1, "answer": "Fewer robots."});
        let s = crate::Scenario::from_value(doc.clone()).unwrap();
        assert_eq!(s.handin.as_ref().unwrap().checks, 3);
        let back = crate::link::decode(&crate::link::encode(&s)).unwrap();
        assert_eq!(back, s);
        let err = |handin: Value| {
            let mut d = doc.clone();
            d["handin"] = handin;
            crate::Scenario::from_value(d).unwrap_err().to_string()
        };
        assert_eq!(
            err(json!({"made": "yesterday"})),
            "handin.made: 'yesterday' is not a time such as 2026-11-28T10:15:00Z (RFC 3339, UTC)"
        );
        assert!(err(json!({"made": "2026-13-28T10:15:00Z"})).contains("is not a time"));
        assert_eq!(
            err(json!({"hints": 11})),
            "handin.hints: 11 is more than the 10 hints an exercise has"
        );
        assert!(err(json!({"grade": 10})).contains("unknown field 'grade'"));
    }
}
