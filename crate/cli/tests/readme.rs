//! The README's sample of `kumiki run`'s output is what the CLI prints: a reader who runs the
//! README's command sees the line the README shows.

use std::process::Command;

#[test]
fn readme_sample_output_is_current() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../README.md"))
        .expect("README.md is readable");
    let sample = readme
        .lines()
        .find(|l| l.starts_with(r#"{"scenario":"amas-L","seed":1,"#))
        .expect("the README shows a sample line for amas-L, seed 1");
    let out = Command::new(env!("CARGO_BIN_EXE_kumiki"))
        .args(["run", "amas-L", "--seed", "1"])
        .output()
        .expect("the kumiki binary runs");
    assert!(out.status.success());
    let printed = String::from_utf8(out.stdout).unwrap();
    assert_eq!(
        printed.trim_end(),
        sample,
        "update the README's sample output"
    );
}
