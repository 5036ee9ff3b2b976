//! The reproduction report: every claim a paper's text makes about a result, beside Kumiki's
//! figure for it.
//!
//! Each model names its paper in a [`Paper`] ([`kumiki_model::report`], re-exported here): the built-in experiments whose rows it reads, and a
//! function that turns those rows into [`Finding`]s, one per claim. The verdict of a finding is
//! computed from the rows, never written down. `kumiki reproduce` runs the experiments (seeded, so
//! the report is deterministic), and [`markdown`] and [`json`] write the report that
//! `docs/reproduction.md` holds and the page's About panel shows.

use std::collections::BTreeMap;

use serde::Serialize;
use serde_json::{json, Value};

pub use kumiki_model::report::*;

/// Every model's paper, in report order (the registry's, [`crate::models::MODELS`]).
pub fn papers() -> impl Iterator<Item = &'static Paper> {
    crate::models::PAPERS.iter()
}

/// The paper of one model.
pub fn paper(model: &str) -> Option<&'static Paper> {
    papers().find(|p| p.model == model)
}

/// One row of the report: a finding, named so that a link can open it, with the experiments
/// whose rows it is computed from.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Claim {
    /// The model and the claim's first words, for example `chobie-with-five-robots-a-load-at`
    /// (a second claim with the same words gets `-2`). The page opens it from `#claim=ID`.
    pub id: String,
    #[serde(flatten)]
    pub finding: Finding,
    /// The built-in experiments whose rows the figure reads: recomputed from their rows alone,
    /// the finding is the same. Empty for a row that reads no experiment (a pointer to another
    /// section, a statement of the paper with nothing to run).
    pub experiments: Vec<String>,
}

/// How many words of a claim its id takes.
const ID_WORDS: usize = 6;

/// The ids of a model's findings, in order: the model and the claim's first [`ID_WORDS`]
/// words, lower case, letters and digits only; a repeated id gets `-2`, `-3`, ….
fn ids(model: &str, findings: &[Finding]) -> Vec<String> {
    let mut seen: BTreeMap<String, usize> = BTreeMap::new();
    findings
        .iter()
        .map(|f| {
            let words: Vec<String> = f
                .claim
                .split(|c: char| !c.is_alphanumeric())
                .filter(|w| !w.is_empty())
                .take(ID_WORDS)
                .map(str::to_lowercase)
                .collect();
            let base = format!("{model}-{}", words.join("-"));
            let n = seen.entry(base.clone()).or_insert(0);
            *n += 1;
            match *n {
                1 => base,
                n => format!("{base}-{n}"),
            }
        })
        .collect()
}

/// The findings of `paper` from `results`, each with its id: the one computation of a report
/// row, for `kumiki reproduce` ([`Section::new`]) and the page's re-run ([`recompute`]).
fn claims(paper: &Paper, results: &Results) -> Vec<(String, Finding)> {
    let findings = (paper.findings)(results);
    ids(paper.model, &findings)
        .into_iter()
        .zip(findings)
        .collect()
}

/// The claim `id` of `paper` computed from `results`, which need hold only the rows of the
/// claim's own experiments (the others are withheld, see [`Results::for_paper`]). With those
/// rows it is the report's row, figure, runs and verdict alike: [`Section::new`] checks it.
pub fn recompute(paper: &Paper, id: &str, results: &Results) -> Option<Finding> {
    claims(paper, results)
        .into_iter()
        .find(|(i, _)| i == id)
        .map(|(_, f)| f)
}

/// One model's part of the report.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Section {
    pub model: String,
    pub citation: String,
    pub experiments: Vec<String>,
    pub findings: Vec<Claim>,
}

impl Section {
    /// The section from the rows of every experiment of the paper. Each claim's experiments
    /// are the ones without whose rows its finding changes; the section then checks that the
    /// finding recomputed from those rows alone is the same, so that a claim re-run in the page
    /// gives the report's row. Panics when it is not: a finding that reads rows its experiments
    /// do not name is a programming error in the paper's findings.
    pub fn new(paper: &Paper, results: &Results) -> Section {
        let all = claims(paper, results);
        let mut uses: Vec<Vec<String>> = vec![Vec::new(); all.len()];
        for e in paper.experiments {
            let without = claims(paper, &results.without(e));
            assert_eq!(
                without.len(),
                all.len(),
                "{}: the findings must not depend in number on the rows",
                paper.model
            );
            for (i, (full, less)) in all.iter().zip(&without).enumerate() {
                if full != less {
                    uses[i].push(e.to_string());
                }
            }
        }
        let mut checked: BTreeMap<&[String], Vec<(String, Finding)>> = BTreeMap::new();
        for ((id, finding), experiments) in all.iter().zip(&uses) {
            let again = checked
                .entry(experiments)
                .or_insert_with(|| claims(paper, &results.only(experiments)));
            let same = again.iter().find(|(i, _)| i == id).map(|(_, f)| f);
            assert_eq!(
                same,
                Some(finding),
                "{id}: recomputed from {experiments:?} alone, the finding is not the report's"
            );
        }
        Section {
            model: paper.model.into(),
            citation: paper.citation.into(),
            experiments: paper.experiments.iter().map(|e| e.to_string()).collect(),
            findings: all
                .into_iter()
                .zip(uses)
                .map(|((id, finding), experiments)| Claim {
                    id,
                    finding,
                    experiments,
                })
                .collect(),
        }
    }
}

/// The report as Markdown: a table of findings per model.
pub fn markdown(sections: &[Section]) -> String {
    let mut out = String::from(
        "# Reproduction report\n\n\
         Every claim the papers' text makes about a result, beside Kumiki's figure for it. \
         Generated by `kumiki reproduce` (`npm run reproduce`) from the built-in experiments, \
         every run seeded, so the same program writes the same report; `npm test` checks that \
         this file is current. Do not edit it by hand.\n\n\
         A verdict is given where the paper states a comparison, and tests the claim as strongly \
         as the text states it: **holds** when Kumiki's runs show it so (a comparison of two \
         conditions by its effect size and a two-sided Mann-Whitney U test at the 5 % level; \
         \"always\" in every run, \"most\" in more than half); **partial** when they point the \
         way the text says but less strongly (a small or non-significant effect, or the \
         behaviour in only some runs); **differs** when they do not (the note says what is \
         known of why); **not stated** where the paper gives a figure or a behaviour but no \
         comparison to judge.\n",
    );
    for s in sections {
        let holds = s
            .findings
            .iter()
            .filter(|c| c.finding.verdict == Verdict::Holds)
            .count();
        let partial = s
            .findings
            .iter()
            .filter(|c| c.finding.verdict == Verdict::Partial)
            .count();
        let differs = s
            .findings
            .iter()
            .filter(|c| c.finding.verdict == Verdict::Differs)
            .count();
        out.push_str(&format!(
            "\n## {} — {}\n\n{} claims: {} hold, {} in part, {} differ, {} with no comparison \
             stated. Experiments: {}.\n\n\
             | § | the paper's claim | Kumiki | runs (experiments) | verdict |\n| --- | --- | --- | --- | --- |\n",
            s.model,
            cell(&s.citation),
            s.findings.len(),
            holds,
            partial,
            differs,
            s.findings.len() - holds - partial - differs,
            s.experiments
                .iter()
                .map(|e| format!("`{e}`"))
                .collect::<Vec<_>>()
                .join(", "),
        ));
        for c in &s.findings {
            let f = &c.finding;
            let runs = match c.experiments.is_empty() {
                true => f.runs.to_string(),
                false => format!(
                    "{} ({})",
                    f.runs,
                    c.experiments
                        .iter()
                        .map(|e| format!("`{e}`"))
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            };
            let kumiki = match f.note.is_empty() {
                true => cell(&f.kumiki),
                false => format!("{}<br>*{}*", cell(&f.kumiki), cell(&f.note)),
            };
            out.push_str(&format!(
                "| {} | {} | {} | {} | {} |\n",
                cell(&f.section),
                cell(&f.claim),
                kumiki,
                runs,
                match f.verdict {
                    Verdict::NotStated => f.verdict.label().to_string(),
                    v => format!("**{}**", v.label()),
                }
            ));
        }
    }
    out
}

/// Text safe inside a Markdown table cell.
fn cell(text: &str) -> String {
    text.replace('|', "\\|").replace('\n', " ")
}

/// The report as JSON, for the page's About panel: `{"models": {model: section}}`.
pub fn json(sections: &[Section]) -> Value {
    let models: serde_json::Map<String, Value> = sections
        .iter()
        .map(|s| {
            (
                s.model.clone(),
                serde_json::to_value(s).expect("a section serialises"),
            )
        })
        .collect();
    json!({ "models": models })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::experiment::Row;
    use crate::run::Outcome;
    use serde_json::Map;

    fn row(scenario: &str, robots: u64, steps: u64, collisions: u64) -> Row {
        let mut params = Map::new();
        params.insert("robots".into(), robots.into());
        let mut metrics = Map::new();
        metrics.insert("collisions".into(), collisions.into());
        Row {
            outcome: Outcome {
                scenario: scenario.into(),
                seed: 1,
                completed: steps < 100,
                steps,
                hash: String::new(),
                metrics,
                stopped: None,
            },
            params,
            scenario_hash: String::new(),
            version: String::new(),
            trace: None,
        }
    }

    fn results() -> Results {
        let mut r = Results::new();
        r.insert(
            "e",
            vec![
                row("a", 1, 10, 3),
                row("a", 2, 20, 5),
                row("b", 1, 200, 7),
                row("b", 2, 40, 9),
            ],
        );
        r
    }

    /// The registry is the one list of papers: each entry's paper is its own model's, and the
    /// report has one section per model.
    #[test]
    fn every_registered_model_names_its_own_paper() {
        let models: Vec<&str> = crate::models::MODELS.iter().map(|m| m.name).collect();
        let papers: Vec<&str> = papers().map(|p| p.model).collect();
        assert_eq!(papers, models);
        assert_eq!(
            paper("cubes3d").map(|p| p.experiments[0]),
            Some("cubes-fig8")
        );
        assert!(paper("nope").is_none());
    }

    #[test]
    fn select_filters_by_scenario_and_parameter() {
        let r = results();
        assert_eq!(r.select("e", &[("scenario", json!("a"))]).len(), 2);
        assert_eq!(r.select("e", &[("robots", json!(1))]).len(), 2);
        assert_eq!(r.select("e", &[("robots", json!(1.0))]).len(), 2);
        let one = r.select("e", &[("scenario", json!("b")), ("robots", json!(2))]);
        assert_eq!(one.len(), 1);
        assert_eq!(one[0].steps, 40);
        assert!(r.select("e", &[("robots", json!("1"))]).is_empty());
        assert_eq!(
            r.values("e", &[("scenario", json!("b"))], "collisions"),
            vec![7.0, 9.0]
        );
        assert_eq!(r.values("e", &[], "completed"), vec![1.0, 1.0, 0.0, 1.0]);
        assert!(r.values("e", &[], "no-such-metric").is_empty());
    }

    #[test]
    fn every_paper_computes_its_findings_without_rows() {
        // A claim re-run in the page has only its own experiments' rows: the other findings of
        // its paper must still compute (from none), in the same number.
        for paper in papers() {
            let none = claims(paper, &Results::for_paper(paper));
            assert!(!none.is_empty(), "{}", paper.model);
        }
    }

    #[test]
    #[should_panic(expected = "was not run")]
    fn an_unlisted_experiment_is_a_programming_error() {
        results().rows("other");
    }

    #[test]
    fn stats_match_hand_computed_values() {
        let s = Stats::of(&[4.0, 1.0, 3.0, 2.0]);
        assert_eq!(
            (s.n, s.mean, s.median, s.min, s.max),
            (4, 2.5, 2.5, 1.0, 4.0)
        );
        assert_eq!((s.q1, s.q3), (1.75, 3.25));
        assert!((s.sd - 1.290_994_448_735_805_6).abs() < 1e-12);
        assert_eq!(
            s.describe(1),
            "mean 2.5 (sd 1.3; median 2.5, IQR 1.8–3.2, range 1.0–4.0; n = 4)"
        );
        assert_eq!(Stats::of(&[7.0]).describe(0), "7 (n = 1)");
        assert_eq!(Stats::of(&[]).describe(0), "no runs");
        assert!(Stats::of(&[]).mean.is_nan());
        assert_eq!(fmt(-0.0001, 2), "0.00");
        assert_eq!(fmt(-1.5, 1), "-1.5");
    }

    #[test]
    fn markdown_counts_verdicts_and_escapes_cells() {
        let section = Section {
            model: "m".into(),
            citation: "A & B, Title".into(),
            experiments: vec!["e".into()],
            findings: vec![
                Claim {
                    id: "m-x-y".into(),
                    finding: Finding {
                        section: "§1".into(),
                        claim: "x | y".into(),
                        kumiki: "3".into(),
                        runs: 10,
                        verdict: Verdict::from(true),
                        note: String::new(),
                    },
                    experiments: vec!["e".into()],
                },
                Claim {
                    id: "m-z".into(),
                    finding: Finding {
                        section: "§2".into(),
                        claim: "z".into(),
                        kumiki: "4".into(),
                        runs: 5,
                        verdict: Verdict::from(false),
                        note: "why\nnot".into(),
                    },
                    experiments: Vec::new(),
                },
            ],
        };
        let md = markdown(std::slice::from_ref(&section));
        assert!(md.contains("2 claims: 1 hold, 0 in part, 1 differ, 0 with no comparison stated"));
        assert!(md.contains("| §1 | x \\| y | 3 | 10 (`e`) | **holds** |"));
        assert!(md.contains("| §2 | z | 4<br>*why not* | 5 | **differs** |"));
        let j = json(&[section]);
        assert_eq!(j["models"]["m"]["findings"][1]["verdict"], "differs");
        assert_eq!(j["models"]["m"]["findings"][0]["id"], "m-x-y");
        assert_eq!(j["models"]["m"]["findings"][0]["experiments"][0], "e");
    }

    /// A paper of two claims over experiments "e" and "f": the first reads "e" only, the second
    /// both, the third none.
    fn two_experiment_findings(r: &Results) -> Vec<Finding> {
        let a = r.stats("e", &[], "steps");
        let b = r.stats("f", &[], "steps");
        vec![
            Finding::new(
                "§1",
                "Runs of e end.",
                a.describe(0),
                a.n,
                Verdict::from(a.n > 0),
                "",
            ),
            Finding::new(
                "§2",
                "Runs of e and f end.",
                format!("{} / {}", a.short(0), b.short(0)),
                a.n + b.n,
                Verdict::from(a.mean < b.mean),
                "",
            ),
            Finding::new(
                "§3",
                "Runs of e end.",
                "see §1".into(),
                0,
                Verdict::NotStated,
                "",
            ),
        ]
    }

    const TWO: Paper = Paper {
        model: "m",
        citation: "",
        experiments: &["e", "f"],
        findings: two_experiment_findings,
    };

    #[test]
    fn each_claim_names_the_experiments_it_reads_and_is_recomputed_from_them_alone() {
        let mut r = results();
        r.insert("f", vec![row("c", 1, 500, 0), row("c", 2, 700, 0)]);
        let section = Section::new(&TWO, &r);
        let ids: Vec<&str> = section.findings.iter().map(|c| c.id.as_str()).collect();
        assert_eq!(
            ids,
            [
                "m-runs-of-e-end",
                "m-runs-of-e-and-f-end",
                "m-runs-of-e-end-2"
            ]
        );
        let uses: Vec<&[String]> = section
            .findings
            .iter()
            .map(|c| c.experiments.as_slice())
            .collect();
        assert_eq!(
            uses,
            [&["e".to_string()][..], &["e".into(), "f".into()], &[]]
        );
        // The page's re-run: only the claim's experiments have run.
        let mut page = Results::for_paper(&TWO);
        page.insert("e", r.rows("e").to_vec());
        assert_eq!(
            recompute(&TWO, "m-runs-of-e-end", &page).as_ref(),
            Some(&section.findings[0].finding)
        );
        // Without f the second claim is not the report's: its runs and figure say so.
        let partial = recompute(&TWO, "m-runs-of-e-and-f-end", &page).unwrap();
        assert_ne!(partial, section.findings[1].finding);
        assert_eq!(partial.runs, 4);
        assert_eq!(recompute(&TWO, "m-no-such-claim", &page), None);
    }
}
