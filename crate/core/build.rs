//! Registers the models: each dependency of this crate on a model crate (a path under
//! `../models/`) in `Cargo.toml`, in the order written there (the gallery's), becomes one line of
//! the registry (`models.rs`, read by `src/models/registry.rs`), so Cargo's dependency line is the
//! one line a model needs. Registers every file in the `presets/`, `lessons/` and `experiments/`
//! folders of each model crate (`../models/<model>/presets/`, ...) by its name, so adding a preset
//! or a lesson is adding one file; and records the commit the core is built from (`KUMIKI_COMMIT`,
//! "unknown" outside a git checkout) for the provenance of exports.

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

/// The model crates this crate depends on, as Rust crate names, in the order `manifest` lists them:
/// every entry of its `[dependencies]` table whose `path` is a folder under `../models/`.
fn model_crates(manifest: &str) -> Vec<String> {
    let mut table = "";
    let mut crates = Vec::new();
    for line in manifest
        .lines()
        .map(|l| l.split('#').next().unwrap_or_default().trim())
    {
        if line.starts_with('[') {
            table = line;
            continue;
        }
        if table != "[dependencies]" {
            continue;
        }
        let Some((name, value)) = line.split_once('=') else {
            continue;
        };
        let path = value.split_once("path").and_then(|(_, p)| {
            p.trim_start()
                .strip_prefix('=')?
                .trim_start()
                .strip_prefix('"')?
                .split_once('"')
        });
        if path.is_some_and(|(p, _)| p.starts_with("../models/")) {
            crates.push(name.trim().replace('-', "_"));
        }
    }
    crates
}

/// The registry's one invocation of `register!`, naming every model crate in gallery order.
fn models() -> String {
    println!("cargo::rerun-if-changed=Cargo.toml");
    let manifest = std::fs::read_to_string("Cargo.toml").expect("the core's Cargo.toml");
    let crates = model_crates(&manifest);
    assert!(
        !crates.is_empty(),
        "Cargo.toml: no model crate (a path under ../models/) among the dependencies"
    );
    format!("register! {{ {} }}\n", crates.join(", "))
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
    let dir = std::env::var("OUT_DIR").unwrap();
    std::fs::write(Path::new(&dir).join("registry.rs"), out).unwrap();
    std::fs::write(Path::new(&dir).join("models.rs"), models()).unwrap();
}
