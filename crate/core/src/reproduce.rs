//! The reproduction report: every claim a paper's text makes about a result, beside Kumiki's
//! figure for it.
//!
//! Each model names its paper in a [`Paper`]: the built-in experiments whose rows it reads, and a
//! function that turns those rows into [`Finding`]s, one per claim. The verdict of a finding is
//! computed from the rows, never written down. `kumiki reproduce` runs the experiments (seeded, so
//! the report is deterministic), and [`markdown`] and [`json`] write the report that
//! `docs/reproduction.md` holds and the page's About panel shows.

use std::collections::{BTreeMap, BTreeSet};

use serde::Serialize;
use serde_json::{json, Value};

use crate::experiment::Row;

/// A model's paper and the claims the report checks.
pub struct Paper {
    pub model: &'static str,
    pub citation: &'static str,
    /// Built-in experiments (`crate/core/experiments/<name>.json`) whose rows the findings read.
    pub experiments: &'static [&'static str],
    pub findings: fn(&Results) -> Vec<Finding>,
}

/// Every model's paper, in report order.
pub const PAPERS: &[Paper] = &[
    crate::models::amas::paper::PAPER,
    crate::models::chobie::paper::PAPER,
    crate::models::cubes3d::paper::PAPER,
    crate::models::fracta::paper::PAPER,
];

/// The paper of one model.
pub fn paper(model: &str) -> Option<&'static Paper> {
    PAPERS.iter().find(|p| p.model == model)
}

/// Whether the paper's claim holds in Kumiki, where the paper states a comparison.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    Holds,
    Differs,
    /// The text states a figure or a behaviour but no comparison to judge.
    NotStated,
}

impl Verdict {
    /// Holds when `ok`, differs otherwise.
    pub fn from(ok: bool) -> Verdict {
        if ok {
            Verdict::Holds
        } else {
            Verdict::Differs
        }
    }

    pub fn label(self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::Differs => "differs",
            Verdict::NotStated => "not stated",
        }
    }
}

/// One claim of the paper beside Kumiki's figure.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Finding {
    /// Where the paper makes the claim: "§5.2, fig. 23".
    pub section: String,
    /// The claim, quoted or closely paraphrased.
    pub claim: String,
    /// Kumiki's figure with its spread.
    pub kumiki: String,
    /// How many runs the figure rests on.
    pub runs: usize,
    pub verdict: Verdict,
    /// How it was measured, and for a difference the evidence of why.
    pub note: String,
}

impl Finding {
    pub fn new(
        section: &str,
        claim: &str,
        kumiki: String,
        runs: usize,
        verdict: Verdict,
        note: &str,
    ) -> Finding {
        Finding {
            section: section.into(),
            claim: claim.into(),
            kumiki,
            runs,
            verdict,
            note: note.into(),
        }
    }
}

/// The rows of every experiment a paper reads, by experiment name, each in job order.
#[derive(Clone, Debug, Default)]
pub struct Results {
    rows: BTreeMap<String, Vec<Row>>,
    /// Experiments known to the report but not run this time: they read as no rows (a claim
    /// recomputed from its own experiments only, see [`recompute`]).
    withheld: BTreeSet<String>,
}

impl Results {
    pub fn new() -> Results {
        Results::default()
    }

    /// Results for `paper` where none of its experiments has run yet: each reads as no rows
    /// until its rows are inserted.
    pub fn for_paper(paper: &Paper) -> Results {
        Results {
            rows: BTreeMap::new(),
            withheld: paper.experiments.iter().map(|e| e.to_string()).collect(),
        }
    }

    pub fn insert(&mut self, experiment: &str, rows: Vec<Row>) {
        self.withheld.remove(experiment);
        self.rows.insert(experiment.to_string(), rows);
    }

    /// These results with the rows of `experiment` withheld.
    fn without(&self, experiment: &str) -> Results {
        let mut out = self.clone();
        out.rows.remove(experiment);
        out.withheld.insert(experiment.to_string());
        out
    }

    /// These results with only the rows of `keep`; every other experiment is withheld.
    fn only(&self, keep: &[String]) -> Results {
        let mut out = Results::new();
        for (name, rows) in &self.rows {
            match keep.contains(name) {
                true => out.insert(name, rows.clone()),
                false => {
                    out.withheld.insert(name.clone());
                }
            }
        }
        out.withheld.extend(self.withheld.iter().cloned());
        out
    }

    /// The rows of an experiment (none when it is withheld). Panics when the paper did not list
    /// it: that is a programming error in the paper's findings, not bad input.
    pub fn rows(&self, experiment: &str) -> &[Row] {
        match self.rows.get(experiment) {
            Some(rows) => rows,
            None if self.withheld.contains(experiment) => &[],
            None => panic!("experiment '{experiment}' was not run for this report"),
        }
    }

    /// The rows whose scenario name and grid parameters match every `(key, value)` of the
    /// filter; `key` is `"scenario"` or a grid path such as `"robots"`.
    pub fn select(&self, experiment: &str, filter: &[(&str, Value)]) -> Vec<&Row> {
        self.rows(experiment)
            .iter()
            .filter(|row| filter.iter().all(|(k, v)| matches(row, k, v)))
            .collect()
    }

    /// One number per selected row: `"steps"`, `"completed"` (1 or 0), or a metric's name. A row
    /// without the metric, or with a value that is not a number, gives no number.
    pub fn values(&self, experiment: &str, filter: &[(&str, Value)], metric: &str) -> Vec<f64> {
        self.select(experiment, filter)
            .into_iter()
            .filter_map(|row| value(row, metric))
            .collect()
    }

    /// [`Stats`] of [`Results::values`].
    pub fn stats(&self, experiment: &str, filter: &[(&str, Value)], metric: &str) -> Stats {
        Stats::of(&self.values(experiment, filter, metric))
    }
}

fn matches(row: &Row, key: &str, want: &Value) -> bool {
    if key == "scenario" {
        return want.as_str() == Some(row.scenario.as_str());
    }
    match (row.params.get(key), want) {
        (Some(Value::Number(a)), Value::Number(b)) => a.as_f64() == b.as_f64(),
        (Some(got), want) => got == want,
        (None, _) => false,
    }
}

/// A row's value of `"steps"`, `"completed"` or a metric.
pub fn value(row: &Row, metric: &str) -> Option<f64> {
    match metric {
        "steps" => Some(row.steps as f64),
        "completed" => Some(if row.completed { 1.0 } else { 0.0 }),
        name => match row.metrics.get(name)? {
            Value::Number(n) => n.as_f64(),
            Value::Bool(b) => Some(if *b { 1.0 } else { 0.0 }),
            _ => None,
        },
    }
}

/// Summary statistics of a sample. Quartiles are interpolated between order statistics (the
/// "linear" rule of R type 7 and NumPy's default).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Stats {
    pub n: usize,
    pub mean: f64,
    /// Sample standard deviation (n − 1); 0 for fewer than two values.
    pub sd: f64,
    pub median: f64,
    pub q1: f64,
    pub q3: f64,
    pub min: f64,
    pub max: f64,
}

impl Stats {
    /// NaN statistics for an empty sample, so a missing measurement shows rather than hides.
    pub fn of(values: &[f64]) -> Stats {
        let n = values.len();
        if n == 0 {
            return Stats {
                n,
                mean: f64::NAN,
                sd: f64::NAN,
                median: f64::NAN,
                q1: f64::NAN,
                q3: f64::NAN,
                min: f64::NAN,
                max: f64::NAN,
            };
        }
        let mut sorted = values.to_vec();
        sorted.sort_by(f64::total_cmp);
        let mean = sorted.iter().sum::<f64>() / n as f64;
        let sd = if n > 1 {
            (sorted.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n - 1) as f64).sqrt()
        } else {
            0.0
        };
        Stats {
            n,
            mean,
            sd,
            median: quantile(&sorted, 0.5),
            q1: quantile(&sorted, 0.25),
            q3: quantile(&sorted, 0.75),
            min: sorted[0],
            max: sorted[n - 1],
        }
    }

    /// "mean 1187 (sd 95; median 1170, IQR 1100–1250, range 1010–1400; n = 10)", with `digits`
    /// decimals.
    pub fn describe(&self, digits: usize) -> String {
        if self.n == 0 {
            return "no runs".into();
        }
        let f = |v: f64| fmt(v, digits);
        if self.n == 1 {
            return format!("{} (n = 1)", f(self.mean));
        }
        format!(
            "mean {} (sd {}; median {}, IQR {}–{}, range {}–{}; n = {})",
            f(self.mean),
            f(self.sd),
            f(self.median),
            f(self.q1),
            f(self.q3),
            f(self.min),
            f(self.max),
            self.n
        )
    }

    /// "1187 ± 95" (mean ± sd), for compact comparisons.
    pub fn short(&self, digits: usize) -> String {
        format!("{} ± {}", fmt(self.mean, digits), fmt(self.sd, digits))
    }
}

/// Linear interpolation between order statistics of sorted values (Hyndman and Fan's type 7, the
/// default of R and NumPy).
pub fn quantile(sorted: &[f64], q: f64) -> f64 {
    let pos = q * (sorted.len() - 1) as f64;
    let lo = pos.floor() as usize;
    let hi = pos.ceil() as usize;
    sorted[lo] + (sorted[hi] - sorted[lo]) * (pos - lo as f64)
}

/// A number with a fixed count of decimals; `-0` is written `0`.
pub fn fmt(v: f64, digits: usize) -> String {
    if v.is_nan() {
        return "n/a".into();
    }
    let s = format!("{v:.digits$}");
    match s
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        true => s.trim_start_matches('-').to_string(),
        false => s,
    }
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
         A verdict is given where the paper states a comparison: **holds** when Kumiki's runs \
         show it, **differs** when they do not (the note says what is known of why); **not \
         stated** where the paper gives a figure or a behaviour but no comparison to judge.\n",
    );
    for s in sections {
        let holds = s
            .findings
            .iter()
            .filter(|c| c.finding.verdict == Verdict::Holds)
            .count();
        let differs = s
            .findings
            .iter()
            .filter(|c| c.finding.verdict == Verdict::Differs)
            .count();
        out.push_str(&format!(
            "\n## {} — {}\n\n{} claims: {} hold, {} differ, {} with no comparison stated. \
             Experiments: {}.\n\n\
             | § | the paper's claim | Kumiki | runs (experiments) | verdict |\n| --- | --- | --- | --- | --- |\n",
            s.model,
            cell(&s.citation),
            s.findings.len(),
            holds,
            differs,
            s.findings.len() - holds - differs,
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
    use serde_json::Map;

    fn row(scenario: &str, robots: u64, steps: u64, collisions: u64) -> Row {
        let mut params = Map::new();
        params.insert("robots".into(), robots.into());
        let mut metrics = Map::new();
        metrics.insert("collisions".into(), collisions.into());
        Row {
            scenario: scenario.into(),
            seed: 1,
            completed: steps < 100,
            steps,
            hash: String::new(),
            metrics,
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
        for paper in PAPERS {
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
        assert!(md.contains("2 claims: 1 hold, 1 differ, 0 with no comparison stated"));
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
