//! Registers every file in the `presets/`, `lessons/` and `experiments/` folders of each model
//! crate (`../models/<model>/presets/`, ...) by its name, so adding a preset or a lesson is adding
//! one file; and records the commit the core is built from (`KUMIKI_COMMIT`, "unknown" outside a
//! git checkout) for the provenance of exports.

use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;

/// The folders holding built-in files of `kind` (`presets`, `lessons`, `experiments`): the one of
/// each model crate under `../models/` that has any.
fn folders(kind: &str) -> Vec<String> {
    println!("cargo::rerun-if-changed=../models");
    let mut models: Vec<String> = std::fs::read_dir("../models")
        .map(|dir| {
            dir.filter_map(|entry| {
                Some(format!(
                    "../models/{}/{kind}",
                    entry.ok()?.file_name().to_str()?
                ))
            })
            .filter(|d| Path::new(d).is_dir())
            .collect()
        })
        .unwrap_or_default();
    models.sort();
    models
}

fn table(kind: &str, konst: &str, out: &mut String) {
    let mut files: Vec<(String, String)> = Vec::new();
    for dir in folders(kind) {
        println!("cargo::rerun-if-changed={dir}");
        files.extend(
            std::fs::read_dir(&dir)
                .unwrap_or_else(|e| panic!("reading {dir}: {e}"))
                .filter_map(|entry| {
                    let path = entry.ok()?.path();
                    (path.extension()? == "json")
                        .then(|| path.file_stem()?.to_str().map(str::to_string))?
                })
                .map(|name| (name, dir.clone())),
        );
    }
    files.sort();
    if let Some(w) = files.windows(2).find(|w| w[0].0 == w[1].0) {
        panic!(
            "two built-in {kind} named {}: in {} and {}",
            w[0].0, w[0].1, w[1].1
        );
    }
    writeln!(out, "pub const {konst}: &[(&str, &str)] = &[").unwrap();
    for (name, dir) in files {
        println!("cargo::rerun-if-changed={dir}/{name}.json");
        writeln!(
            out,
            "    ({name:?}, include_str!(concat!(env!(\"CARGO_MANIFEST_DIR\"), \"/{dir}/{name}.json\"))),"
        )
        .unwrap();
    }
    writeln!(out, "];").unwrap();
}

fn git(args: &[&str]) -> Option<String> {
    let out = Command::new("git").args(args).output().ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
        .filter(|s| !s.is_empty())
}

fn commit() {
    let commit = git(&["rev-parse", "--short=12", "HEAD"]).unwrap_or_else(|| "unknown".into());
    println!("cargo::rustc-env=KUMIKI_COMMIT={commit}");
    // Built again when HEAD moves: a new commit on the branch, or another branch checked out.
    let mut watched = vec!["HEAD".to_string(), "packed-refs".to_string()];
    watched.extend(git(&["symbolic-ref", "-q", "HEAD"]));
    for path in watched {
        // A path that does not exist would make cargo run this script on every build.
        if let Some(p) = git(&["rev-parse", "--git-path", &path]).filter(|p| Path::new(p).exists())
        {
            println!("cargo::rerun-if-changed={p}");
        }
    }
}

fn main() {
    commit();
    let mut out = String::new();
    table("presets", "PRESET_FILES", &mut out);
    table("lessons", "LESSON_FILES", &mut out);
    table("experiments", "EXPERIMENT_FILES", &mut out);
    let dest = Path::new(&std::env::var("OUT_DIR").unwrap()).join("registry.rs");
    std::fs::write(dest, out).unwrap();
}
