//! Rule scripts: a scenario's `rules: { slot: source }` made into [`Script`]s a model's rule slots
//! call (see `kumiki_model::slot`). The engine is [Rhai](https://rhai.rs), sandboxed:
//!
//! - no I/O (no `print` output, no file or module loading), no clock (`no_time`, no `sleep`),
//!   no `eval`;
//! - caps on operations per call and per step, call depth, expression depth, string, array and
//!   map sizes, live variables and functions ([`caps`]), which bound a call's memory
//!   ([`caps::MEMORY_BYTES`]); going past one stops the run with a message naming the rule,
//!   the line and the cap;
//! - maths only through the model's portable functions (`kumiki_model::math`: one libm on every
//!   target) and IEEE 754's exactly rounded operations, randomness only from the model's seeded
//!   generator; floats are formatted by Rust's own code on every target.
//!
//! So a scripted rule gives the same state hashes natively and in wasm. docs/rules.md documents
//! the language, the slots and the caps.
//!
//! - [`sandbox`]: the engine; [`caps`]: what a script may spend;
//! - [`script`]: a compiled rule, the [`Script`] a model calls; [`convert`]: values crossing.

use std::rc::Rc;

use kumiki_model::slot::{Script, SlotInfo};
use kumiki_model::Error;

pub mod caps;
mod convert;
mod sandbox;
mod script;

#[cfg(test)]
mod tests;

/// Reads `source` as the script of slot `info` (the error names `rules.<slot>`, the line and the
/// column), ready to be installed in a model.
pub fn compile(info: SlotInfo, source: &str) -> Result<Rc<dyn Script>, Error> {
    Ok(Rc::new(script::compile(info, source)?))
}

/// Checks `source` as the script of slot `info` without keeping it.
pub fn check(info: SlotInfo, source: &str) -> Result<(), Error> {
    script::compile(info, source).map(|_| ())
}
