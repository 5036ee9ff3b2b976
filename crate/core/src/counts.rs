//! What loading and editing a scenario cost on this thread, counted in test builds: JSON texts of
//! scenarios parsed, model descriptions checked and models built. Tests read them to show that a
//! load or an edit parses and checks once.

use std::cell::Cell;

thread_local! {
    static PARSES: Cell<u64> = const { Cell::new(0) };
    static CHECKS: Cell<u64> = const { Cell::new(0) };
    static BUILDS: Cell<u64> = const { Cell::new(0) };
}

fn add(counter: &'static std::thread::LocalKey<Cell<u64>>) {
    counter.with(|c| c.set(c.get() + 1));
}

pub(crate) fn parse() {
    add(&PARSES);
}

pub(crate) fn check() {
    add(&CHECKS);
}

pub(crate) fn build() {
    add(&BUILDS);
}

/// JSON texts parsed so far (scenarios, links' payloads).
pub fn parses() -> u64 {
    PARSES.with(Cell::get)
}

/// Model descriptions checked so far: each lays out its shapes and checks them.
pub fn checks() -> u64 {
    CHECKS.with(Cell::get)
}

/// Models built so far.
pub fn builds() -> u64 {
    BUILDS.with(Cell::get)
}
