//! Errors are values: every bad input becomes an [`Error`] whose message names the field and the
//! reason, so the page can show it and the CLI can print it on one line.

use thiserror::Error as ThisError;

/// Everything that can go wrong when reading a scenario, a link or an experiment.
#[derive(Debug, Clone, PartialEq, Eq, ThisError)]
pub enum Error {
    /// A field of a scenario or experiment holds an invalid value. With an empty path the
    /// document as a whole is meant, and only the reason is shown.
    #[error("{}{reason}", if path.is_empty() { String::new() } else { format!("{path}: ") })]
    Field { path: String, reason: String },
    /// The text is not JSON at all.
    #[error("not valid JSON (line {line}, column {column}): {reason}")]
    Json {
        line: usize,
        column: usize,
        reason: String,
    },
    /// A share link could not be decoded.
    #[error("link: {0}")]
    Link(String),
    /// A preset or experiment name that is not registered.
    #[error("unknown {kind} '{name}'; known: {known}")]
    Unknown {
        kind: &'static str,
        name: String,
        known: String,
    },
}

impl Error {
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

    pub(crate) fn json(err: &serde_json::Error) -> Self {
        Error::Json {
            line: err.line(),
            column: err.column(),
            reason: strip_position(&err.to_string()),
        }
    }
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
    serde_path_to_error::deserialize(value).map_err(|err| {
        let path = err.path().to_string();
        let path = if path == "." { String::new() } else { path };
        Error::field(path, plain(&strip_position(&err.inner().to_string())))
    })
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
    fn an_error_about_the_whole_document_has_no_leading_colon() {
        assert_eq!(
            Error::field("", "a scenario is a JSON object").to_string(),
            "a scenario is a JSON object"
        );
        assert_eq!(Error::field("a.b", "bad").to_string(), "a.b: bad");
    }
}
