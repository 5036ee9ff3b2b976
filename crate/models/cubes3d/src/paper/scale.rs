//! Section 7: "works well for small number of units, say, up to twenty units", under both readings
//! of equation 8's "log".

use serde_json::json;

use kumiki_model::report::{self, Finding, Ordering, Results, Size, Stats, Verdict};

use super::figures;

/// The readings of "log" in equation 8: the grid value and the schedule in words.
const READINGS: [(&str, &str); 2] = [
    (
        "natural",
        "T = C / ln(1 + t), natural log (Geman and Geman's schedule; the model's reading)",
    ),
    (
        "ten",
        "T = C / log10(1 + t), base 10 (ln 10 ≈ 2.3 times hotter at every step)",
    ),
];

/// Holds when most runs complete and not significantly fewer than the 12-unit box's under the
/// same reading; partial when most complete but significantly fewer; differs when half or
/// fewer do.
fn works_well(done: usize, n: usize, shortfall: &Ordering) -> Verdict {
    match Verdict::of_most(done, n) {
        Verdict::Holds if shortfall.verdict() == Verdict::Holds => Verdict::Partial,
        Verdict::Holds => Verdict::Holds,
        _ => Verdict::Differs,
    }
}

pub(super) fn findings(results: &Results) -> Vec<Finding> {
    let mut out = Vec::new();
    for (log, schedule) in READINGS {
        let filter = |scenario: &str| [("scenario", json!(scenario)), ("log", json!(log))];
        let completed =
            |scenario: &str| results.values("cubes-scale", &filter(scenario), "completed");
        let steps_done = |scenario: &str| {
            let v: Vec<f64> = results
                .select("cubes-scale", &filter(scenario))
                .into_iter()
                .filter(|r| r.completed)
                .map(|r| r.steps as f64)
                .collect();
            Stats::of(&v)
        };
        let box12 = completed("cubes-box12-ladder");
        let box12_steps = steps_done("cubes-box12-ladder");
        for (scenario, units) in [("cubes-box16-ladder", 16), ("cubes-box20-ladder", 20)] {
            let v = completed(scenario);
            let (done, n) = (v.iter().sum::<f64>() as usize, v.len());
            let all = results.stats("cubes-scale", &filter(scenario), "mean_difference");
            let stuck: Vec<f64> = results
                .select("cubes-scale", &filter(scenario))
                .into_iter()
                .filter(|r| !r.completed)
                .filter_map(|r| report::value(r, "mean_difference"))
                .collect();
            let shortfall = Ordering::new(&v, &box12, true, Size::Any);
            let short = match shortfall.verdict() {
                Verdict::Holds => "significantly fewer than 12 units complete",
                _ => "not significantly fewer than 12 units complete",
            };
            let stuck = match stuck.is_empty() {
                true => String::new(),
                false => format!(
                    ", the runs that did not complete {}",
                    Stats::of(&stuck).short(2)
                ),
            };
            out.push(Finding {
                section: format!("§7, eq. 8 with log {}", if log == "ten" { "base 10" } else { "natural" }),
                claim: format!("The stochastic method works well for small numbers of units, say up to twenty ({units} units, a 2×{} ladder to a 2×2×{} box).", units / 2, units / 4),
                kumiki: format!(
                    "completed within 20,000 steps: {done}/{n}, median step {} (12 units under the same reading: {}/{}, median step {}); {short} ({}); D per unit at the end, all runs {}{stuck}",
                    report::fmt(steps_done(scenario).median, 0),
                    box12.iter().sum::<f64>() as usize,
                    box12.len(),
                    report::fmt(box12_steps.median, 0),
                    figures(&shortfall),
                    all.short(2),
                ),
                runs: n,
                verdict: works_well(done, n, &shortfall),
                note: format!(
                    "The parameters of section 5 (W = 3, a = 1, C = 10) with {schedule}; the 12-unit box runs in the same experiment with the same parameters, schedule and step limit. Holds when most runs complete and not significantly fewer than the 12-unit box's (Mann-Whitney U on completion, 1 or 0); partial when most complete but significantly fewer; differs when half or fewer complete. The runs that do not complete end in local minima the schedule no longer leaves. The paper calls C a constant concerning system size but gives it only for 8 and 12 units, and equation 8 writes log without a base (crate/models/cubes3d/README.md, interpretations 11 and 20)."
                ),
            });
        }
    }
    out
}
