//! `kumiki reproduce`: runs every model's paper experiments and writes the reproduction report.

use std::path::Path;

use kumiki_core::experiment::{Experiment, Row};
use kumiki_core::reproduce::{self, Paper, Results, Section};

use crate::{pool, Failure};

/// Where the report lives, relative to the repository root.
pub const MARKDOWN: &str = "docs/reproduction.md";
pub const JSON: &str = "docs/reproduction.json";

pub enum Mode {
    /// Write the report files under a root folder.
    Write,
    /// Compare with the files under a root folder; fail when they differ.
    Check,
    /// Print one model's part as Markdown.
    Print,
}

/// Runs the experiments of `papers` on `threads` threads and returns their sections.
pub fn sections(papers: &[&Paper], threads: usize) -> Result<Vec<Section>, Failure> {
    let mut names: Vec<&str> = papers
        .iter()
        .flat_map(|p| p.experiments.iter().copied())
        .collect();
    names.sort_unstable();
    names.dedup();
    let experiments = names
        .iter()
        .map(|n| Experiment::named_or_json(n).map_err(|e| Failure::Run(format!("{n}: {e}"))))
        .collect::<Result<Vec<_>, _>>()?;
    let jobs: Vec<(usize, kumiki_core::experiment::Job)> = experiments
        .iter()
        .enumerate()
        .flat_map(|(e, x)| x.jobs().into_iter().map(move |j| (e, j)))
        .collect();
    let bar = crate::runs::progress_bar("reproduce", jobs.len());
    let mut rows: Vec<Vec<Row>> = vec![Vec::new(); experiments.len()];
    pool::run_ordered(
        jobs.len(),
        threads,
        |i| experiments[jobs[i].0].run_job(&jobs[i].1),
        |i, row| {
            let row = row.map_err(|e| Failure::Run(format!("{}: {e}", names[jobs[i].0])))?;
            rows[jobs[i].0].push(row);
            bar.inc(1);
            Ok::<(), Failure>(())
        },
    )?;
    bar.finish_and_clear();
    let mut results = Results::new();
    for (name, rows) in names.iter().zip(rows) {
        results.insert(name, rows);
    }
    Ok(papers.iter().map(|p| Section::new(p, &results)).collect())
}

/// The report files' texts: Markdown and JSON.
pub fn texts(sections: &[Section]) -> (String, String) {
    let json = serde_json::to_string_pretty(&reproduce::json(sections)).expect("JSON serialises");
    (reproduce::markdown(sections), json + "\n")
}

pub fn run(model: Option<&str>, mode: Mode, root: &Path, threads: usize) -> Result<(), Failure> {
    let papers: Vec<&Paper> = match model {
        Some(m) => vec![reproduce::paper(m).ok_or_else(|| {
            Failure::Usage(format!(
                "no paper is registered for model '{m}'; known: {}",
                reproduce::papers()
                    .map(|p| p.model)
                    .collect::<Vec<_>>()
                    .join(", ")
            ))
        })?],
        None => reproduce::papers().collect(),
    };
    let (markdown, json) = texts(&sections(&papers, threads)?);
    match mode {
        Mode::Print => {
            print!("{markdown}");
            Ok(())
        }
        Mode::Write => {
            for (file, text) in [(MARKDOWN, &markdown), (JSON, &json)] {
                let path = root.join(file);
                std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
                eprintln!("wrote {}", path.display());
            }
            Ok(())
        }
        Mode::Check => {
            let stale = stale(root, &[(MARKDOWN, &markdown), (JSON, &json)]);
            match stale.is_empty() {
                true => {
                    eprintln!("the reproduction report is current");
                    Ok(())
                }
                false => Err(Failure::Run(format!(
                    "{} {} not what the experiments give now: run 'npm run reproduce' and commit the result",
                    stale.join(" and "),
                    if stale.len() == 1 { "is" } else { "are" }
                ))),
            }
        }
    }
}

/// The files under `root` whose text is not the one given (or that cannot be read).
fn stale<'a>(root: &Path, files: &[(&'a str, &String)]) -> Vec<&'a str> {
    files
        .iter()
        .filter(|(file, text)| {
            std::fs::read_to_string(root.join(file)).ok().as_deref() != Some(text.as_str())
        })
        .map(|(file, _)| *file)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stale_names_the_files_that_differ_or_are_missing() {
        let root = std::env::temp_dir().join(format!("kumiki-stale-{}", std::process::id()));
        std::fs::create_dir_all(root.join("docs")).unwrap();
        let (md, json) = ("# report\n".to_string(), "{}\n".to_string());
        let files = [(MARKDOWN, &md), (JSON, &json)];
        assert_eq!(stale(&root, &files), vec![MARKDOWN, JSON]);
        std::fs::write(root.join(MARKDOWN), &md).unwrap();
        std::fs::write(root.join(JSON), &json).unwrap();
        assert!(stale(&root, &files).is_empty());
        std::fs::write(root.join(MARKDOWN), "# report\nedited by hand\n").unwrap();
        assert_eq!(stale(&root, &files), vec![MARKDOWN]);
        std::fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn the_report_texts_are_markdown_and_json_of_the_same_sections() {
        let (md, json) = texts(&[]);
        assert!(md.starts_with("# Reproduction report"));
        let parsed: serde_json::Value = serde_json::from_str(&json).unwrap();
        assert!(parsed["models"].is_object());
    }
}
