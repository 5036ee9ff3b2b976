//! Errors are values: every bad input becomes an [`Error`] whose message names the field and the
//! reason, so the page can show it and the CLI can print it on one line.

use thiserror::Error as ThisError;

/// Everything that can go wrong when reading a scenario, a link or an experiment.
#[derive(Debug, Clone, PartialEq, Eq, ThisError)]
pub enum Error {
    /// A field of a scenario or experiment holds an invalid value.
    #[error("{path}: {reason}")]
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
        Error::field(path, strip_position(&err.inner().to_string()))
    })
}

pub type Result<T, E = Error> = std::result::Result<T, E>;
