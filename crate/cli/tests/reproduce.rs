//! `kumiki reproduce`'s arguments. Writing and checking the report itself runs every paper's
//! experiments, which `npm test` does once in release mode (`kumiki reproduce --check`); the
//! comparison is unit-tested in `src/reproduce.rs`.

use std::process::Command;

fn kumiki(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_kumiki"))
        .args(args)
        .output()
        .expect("the kumiki binary runs")
}

#[test]
fn check_covers_every_model_so_it_refuses_a_model() {
    let out = kumiki(&["reproduce", "--check", "--model", "amas"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn an_unknown_model_is_named() {
    let out = kumiki(&["reproduce", "--model", "no-such"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no-such"));
}
