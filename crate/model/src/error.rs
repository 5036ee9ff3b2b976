//! Errors are values: every bad input becomes an [`Error`] whose message names the field and the
//! reason, so the page can show it and the CLI can print it on one line.

use std::fmt;

/// Everything that can go wrong when reading a scenario, a link or an experiment.
///
/// Shown with `{}` an error is brief: under [`BRIEF_CHARS`] characters, naming where the problem
/// is and what it is (a long quoted input is cut, a list of allowed names becomes the nearest
/// one). `{:#}` gives all of it, for whoever asks.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Error {
    /// A field of a scenario or experiment holds an invalid value. With an empty path the
    /// document as a whole is meant, and only the reason is shown.
    Field { path: String, reason: String },
    /// The text is not JSON at all.
    Json {
        line: usize,
        column: usize,
        reason: String,
    },
    /// A share link could not be decoded.
    Link(String),
    /// A preset or experiment name that is not registered.
    Unknown {
        kind: &'static str,
        name: String,
        known: String,
    },
}

/// A brief message is shorter than this many characters.
pub const BRIEF_CHARS: usize = 200;

impl std::error::Error for Error {}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let full = self.full();
        if f.alternate() || full.chars().count() < BRIEF_CHARS {
            f.write_str(&full)
        } else {
            f.write_str(&self.brief())
        }
    }
}

impl Error {
    /// The whole message.
    fn full(&self) -> String {
        match self {
            Error::Field { path, reason } if path.is_empty() => reason.clone(),
            Error::Field { path, reason } => format!("{path}: {reason}"),
            Error::Json {
                line,
                column,
                reason,
            } => format!("not valid JSON (line {line}, column {column}): {reason}"),
            Error::Link(reason) => format!("link: {reason}"),
            Error::Unknown { kind, name, known } => {
                format!("unknown {kind} '{name}'; known: {known}")
            }
        }
    }

    /// The message cut to under BRIEF_CHARS: the place (a long path keeps its ends), then the
    /// problem (an unknown name with the nearest allowed one instead of them all, long quoted
    /// input cut), and as a last resort the end dropped.
    fn brief(&self) -> String {
        let text = match self {
            Error::Field { path, reason } => {
                let reason = short_quotes(&nearest_instead_of_list(reason));
                if path.is_empty() {
                    reason
                } else {
                    format!("{}: {reason}", short_middle(path, 60))
                }
            }
            Error::Json {
                line,
                column,
                reason,
            } => format!(
                "not valid JSON (line {line}, column {column}): {}",
                short_quotes(reason)
            ),
            Error::Link(reason) => format!("link: {}", short_quotes(reason)),
            Error::Unknown { kind, name, known } => {
                let names: Vec<&str> = known.split(", ").collect();
                match nearest(name, &names) {
                    Some(n) => format!(
                        "unknown {kind} '{}'; did you mean '{n}'?",
                        short_middle(name, 40)
                    ),
                    None => format!(
                        "unknown {kind} '{}'; {} are known",
                        short_middle(name, 40),
                        names.len()
                    ),
                }
            }
        };
        if text.chars().count() < BRIEF_CHARS {
            text
        } else {
            let mut cut: String = text.chars().take(BRIEF_CHARS - 2).collect();
            cut.push('…');
            cut
        }
    }

    /// An invalid value at a dotted path of the document.
    pub fn field(path: impl Into<String>, reason: impl Into<String>) -> Self {
        Error::Field {
            path: path.into(),
            reason: reason.into(),
        }
    }

    /// The same error, reported one level deeper: `disturbances[2]` + `count` gives
    /// `disturbances[2].count`.
    pub fn within(self, prefix: &str) -> Self {
        match self {
            Error::Field { path, reason } if path.is_empty() => Error::field(prefix, reason),
            Error::Field { path, reason } if path.starts_with('[') => {
                Error::field(format!("{prefix}{path}"), reason)
            }
            Error::Field { path, reason } => Error::field(format!("{prefix}.{path}"), reason),
            other => other,
        }
    }

    /// Text that is not JSON, with the line and column where reading stopped.
    pub fn json(err: &serde_json::Error) -> Self {
        Error::Json {
            line: err.line(),
            column: err.column(),
            reason: strip_position(&err.to_string()),
        }
    }
}

/// `text` with its ends kept and its middle elided when it has more than `max` characters.
fn short_middle(text: &str, max: usize) -> String {
    let n = text.chars().count();
    if n <= max {
        return text.to_string();
    }
    let head: String = text.chars().take(max / 2).collect();
    let tail: String = text.chars().skip(n - (max - max / 2 - 1)).collect();
    format!("{head}…{tail}")
}

/// Every quoted span ('…', "…" or `…`) longer than 40 characters cut in the middle: a message
/// that quotes the input back need not quote all of it. A quote inside a word (an apostrophe)
/// opens nothing.
fn short_quotes(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let opens = matches!(c, '\'' | '"' | '`') && (i == 0 || !chars[i - 1].is_alphanumeric());
        if opens {
            if let Some(len) = chars[i + 1..].iter().position(|&d| d == c) {
                let inner: String = chars[i + 1..i + 1 + len].iter().collect();
                out.push(c);
                out.push_str(&short_middle(&inner, 40));
                out.push(c);
                i += len + 2;
                continue;
            }
        }
        out.push(c);
        i += 1;
    }
    out
}

/// "unknown field 'robtos'; expected one of 'a', 'b', …" (serde's list of every allowed name,
/// as [`plain`] words it) becomes "unknown field 'robtos'; did you mean 'robots'?", or says how
/// many names are allowed when none is near.
fn nearest_instead_of_list(reason: &str) -> String {
    let Some((head, list)) = reason
        .split_once("; expected one of ")
        .or_else(|| reason.split_once("; expected "))
    else {
        return reason.to_string();
    };
    let Some(name) = head
        .strip_prefix("unknown field '")
        .and_then(|r| r.strip_suffix('\''))
    else {
        return reason.to_string();
    };
    let names: Vec<&str> = list
        .split(", ")
        .flat_map(|n| n.split(" or "))
        .map(|n| n.trim_matches('\''))
        .collect();
    match nearest(name, &names) {
        Some(n) => format!("{head}; did you mean '{n}'?"),
        None => format!("{head}; {} names are allowed here", names.len()),
    }
}

/// The allowed name closest to `name` by edit distance, if it is close (at most a third of its
/// letters differ, and at least one may).
fn nearest<'a>(name: &str, names: &[&'a str]) -> Option<&'a str> {
    nearest_within(
        name,
        names.iter().copied(),
        (name.chars().count() / 3).max(1),
    )
}

/// The candidate closest to `word` by edit distance, if at most `limit` edits away; of equally
/// close ones, the first by name.
pub fn nearest_within<'a>(
    word: &str,
    candidates: impl IntoIterator<Item = &'a str>,
    limit: usize,
) -> Option<&'a str> {
    candidates
        .into_iter()
        .map(|c| (edit_distance(word, c), c))
        .filter(|&(d, _)| d <= limit)
        .min()
        .map(|(_, c)| c)
}

/// Levenshtein distance, in characters.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let above = row[j + 1];
            row[j + 1] = (above + 1)
                .min(row[j] + 1)
                .min(diagonal + usize::from(ca != cb));
            diagonal = above;
        }
    }
    row[b.len()]
}

/// serde_json appends " at line L column C"; the position is reported separately.
fn strip_position(message: &str) -> String {
    match message.rfind(" at line ") {
        Some(cut) => message[..cut].to_string(),
        None => message.to_string(),
    }
}

/// Deserialises a model's typed description from the JSON object, naming the offending field.
pub fn from_value<T: serde::de::DeserializeOwned>(value: serde_json::Value) -> Result<T, Error> {
    crate::read::read(&value).map_err(located)
}

/// Reads an action, `{"kind": "<variant>", ...}`, into the enum `T` of its kinds, naming the
/// offending field. `T` derives serde's externally tagged form (and tells its schema
/// `#[schemars(tag = "kind")]`): the object is not buffered, as serde's internally tagged form
/// would, so errors name the field inside the action too.
pub fn from_action<T: serde::de::DeserializeOwned>(
    action: &serde_json::Map<String, serde_json::Value>,
) -> Result<T, Error> {
    let mut rest = action.clone();
    let kind = rest.remove("kind");
    let rest = serde_json::Value::Object(rest);
    crate::read::read_tagged("kind", kind.as_ref(), &rest).map_err(located)
}

/// A reader's error at its path ("." is the document itself), in plain words.
fn located((err, path): (serde_json::Error, String)) -> Error {
    let path = if path == "." { String::new() } else { path };
    Error::field(path, plain(&strip_position(&err.to_string())))
}

/// serde's messages in the words a person reads: "invalid type: floating point `1e12`, expected
/// u32" becomes "1e12 is not a whole number from 0 to 4294967295". Messages it does not know pass
/// through unchanged.
pub(crate) fn plain(message: &str) -> String {
    let ticked = |s: &str| s.replace('`', "'");
    if let Some(rest) = message.strip_prefix("missing field ") {
        return format!("{} is required", ticked(rest));
    }
    if let Some(rest) = message.strip_prefix("unknown field ") {
        return format!(
            "unknown field {}",
            ticked(rest).replace(", expected", "; expected")
        );
    }
    if let Some(rest) = message.strip_prefix("unknown variant ") {
        return ticked(rest).replace(", expected", " is not a choice; expected");
    }
    let found_expected = message
        .strip_prefix("invalid type: ")
        .or_else(|| message.strip_prefix("invalid value: "))
        .and_then(|rest| rest.split_once(", expected "));
    let Some((found, expected)) = found_expected else {
        return message.to_string();
    };
    let value = found.split('`').nth(1).map(str::to_string);
    let found = match (found.split('`').next().map(str::trim), &value) {
        (Some("floating point" | "integer"), Some(v)) => v.trim_end_matches(".0").to_string(),
        _ => match found.strip_prefix("string ") {
            Some(text) => format!("the text {text}"),
            None => found.to_string(),
        },
    };
    let expected = match expected {
        "u8" => format!("a whole number from 0 to {}", u8::MAX),
        "u16" => format!("a whole number from 0 to {}", u16::MAX),
        "u32" => format!("a whole number from 0 to {}", u32::MAX),
        "u64" | "usize" => format!("a whole number from 0 to {}", u64::MAX),
        "i32" | "i64" => "a whole number".to_string(),
        "f32" | "f64" => "a number".to_string(),
        "a boolean" => "true or false".to_string(),
        other => ticked(other),
    };
    match value {
        Some(_) => format!("{found} is not {expected}"),
        None => format!("expected {expected}, found {found}"),
    }
}

pub type Result<T, E = Error> = std::result::Result<T, E>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serde_messages_read_as_plain_words() {
        let cases = [
            (
                "invalid type: floating point `1000000000000.0`, expected u32",
                "1000000000000 is not a whole number from 0 to 4294967295",
            ),
            (
                "invalid value: integer `-3`, expected u32",
                "-3 is not a whole number from 0 to 4294967295",
            ),
            (
                "invalid type: floating point `2.5`, expected u32",
                "2.5 is not a whole number from 0 to 4294967295",
            ),
            (
                "invalid type: string \"five\", expected u32",
                "expected a whole number from 0 to 4294967295, found the text \"five\"",
            ),
            (
                "invalid type: sequence, expected a boolean",
                "expected true or false, found sequence",
            ),
            ("missing field `robots`", "'robots' is required"),
            (
                "unknown field `robot`, expected `robots` or `target`",
                "unknown field 'robot'; expected 'robots' or 'target'",
            ),
            (
                "unknown variant `fast`, expected `token` or `relay`",
                "'fast' is not a choice; expected 'token' or 'relay'",
            ),
            ("something else", "something else"),
        ];
        for (serde, want) in cases {
            assert_eq!(plain(serde), want, "from {serde}");
        }
    }

    #[test]
    fn a_long_message_is_brief_and_the_whole_of_it_is_kept() {
        let list = [
            "target",
            "stages",
            "initial",
            "robots",
            "field",
            "collision",
            "diffusion",
            "supply_rows",
            "move_duration",
            "pick_duration",
            "gradient_threshold",
            "field_updates_per_step",
            "turn_duration",
        ]
        .map(|n| format!("'{n}'"))
        .join(", ");
        let e = Error::field(
            "robtos",
            format!("unknown field 'robtos'; expected one of {list}"),
        );
        assert!(format!("{e:#}").len() > BRIEF_CHARS);
        assert_eq!(
            e.to_string(),
            "robtos: unknown field 'robtos'; did you mean 'robots'?"
        );
        let far = Error::field(
            "zzzzzz",
            format!("unknown field 'zzzzzz'; expected one of {list}"),
        );
        assert_eq!(
            far.to_string(),
            "zzzzzz: unknown field 'zzzzzz'; 13 names are allowed here"
        );
        // Input quoted back is cut in the middle; an apostrophe opens no quote.
        let echo = Error::field(
            "leader",
            format!(
                "'{}' is not a choice; the paper's rule is 'temporary'",
                "t".repeat(300)
            ),
        );
        let brief = echo.to_string();
        assert!(brief.chars().count() < BRIEF_CHARS, "{brief}");
        assert!(
            brief.starts_with("leader: 'tttt")
                && brief.ends_with("the paper's rule is 'temporary'")
        );
        // A path too long keeps its ends; anything still too long loses its end.
        let deep = Error::field(format!("a.{}z", "b.".repeat(200)), "x".repeat(400));
        let brief = deep.to_string();
        assert!(
            brief.starts_with("a.b.") && brief.contains("…") && brief.contains("b.z: xxx"),
            "{brief}"
        );
        assert_eq!(brief.chars().count(), BRIEF_CHARS - 1);
        // Short messages are left whole.
        assert_eq!(
            Error::field("a.b", "bad").to_string(),
            format!("{:#}", Error::field("a.b", "bad"))
        );
    }

    #[test]
    fn an_error_about_the_whole_document_has_no_leading_colon() {
        assert_eq!(
            Error::field("", "a scenario is a JSON object").to_string(),
            "a scenario is a JSON object"
        );
        assert_eq!(Error::field("a.b", "bad").to_string(), "a.b: bad");
    }
}
