//! JSON text in and out for the crates built on the core (the wasm bindings).
//!
//! serde_json's reader and writer are generic, and each crate that calls them compiles its own
//! copy: the same parser twice in the wasm module, tens of kilobytes. Calling these instead keeps
//! one copy, the core's, which parses scenarios, experiments and links already.

use serde_json::Value;

use crate::experiment::Row;

/// `serde_json::from_str::<Value>`.
pub fn parse(text: &str) -> serde_json::Result<Value> {
    #[cfg(test)]
    crate::counts::parse();
    serde_json::from_str(text)
}

/// `serde_json::to_string_pretty` of a value.
pub fn pretty(value: &Value) -> serde_json::Result<String> {
    serde_json::to_string_pretty(value)
}

/// `serde_json::from_str::<Vec<Row>>`: rows as the experiment runner writes them.
pub fn parse_rows(text: &str) -> serde_json::Result<Vec<Row>> {
    serde_json::from_str(text)
}
