//! Registers every file in `presets/`, `lessons/` and `experiments/` by its name, so adding a preset
//! or a lesson is adding one file.

use std::fmt::Write as _;
use std::path::Path;

fn table(dir: &str, konst: &str, out: &mut String) {
    println!("cargo::rerun-if-changed={dir}");
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("reading {dir}: {e}"))
        .filter_map(|entry| {
            let path = entry.ok()?.path();
            (path.extension()? == "json").then(|| path.file_stem()?.to_str().map(str::to_string))?
        })
        .collect();
    names.sort();
    writeln!(out, "pub const {konst}: &[(&str, &str)] = &[").unwrap();
    for name in names {
        println!("cargo::rerun-if-changed={dir}/{name}.json");
        writeln!(
            out,
            "    ({name:?}, include_str!(concat!(env!(\"CARGO_MANIFEST_DIR\"), \"/{dir}/{name}.json\"))),"
        )
        .unwrap();
    }
    writeln!(out, "];").unwrap();
}

fn main() {
    let mut out = String::new();
    table("presets", "PRESET_FILES", &mut out);
    table("lessons", "LESSON_FILES", &mut out);
    table("experiments", "EXPERIMENT_FILES", &mut out);
    let dest = Path::new(&std::env::var("OUT_DIR").unwrap()).join("registry.rs");
    std::fs::write(dest, out).unwrap();
}
