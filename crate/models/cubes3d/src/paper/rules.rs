//! Figures 8 and 9: the MRF rule against random and steepest-descent selection.

use serde_json::json;

use kumiki_model::report::{self, Finding, Ordering, Results, Size, Verdict};
use kumiki_model::row::Row;

use super::{traced, traced_values, weakest};

/// The step by which steepest descent must have settled.
const SETTLED: u64 = 50;

/// Whether the run's traced `metric` stays at one value from `step` on.
fn settled_from(row: &Row, metric: &str, step: u64) -> bool {
    let Some(trace) = row.trace.as_ref() else {
        return false;
    };
    let Some(values) = trace.values.get(metric).and_then(|v| v.as_array()) else {
        return false;
    };
    let after: Vec<_> = trace
        .step
        .iter()
        .zip(values)
        .filter(|(s, _)| **s >= step)
        .map(|(_, v)| v.as_f64())
        .collect();
    !after.is_empty() && after.iter().all(|v| v.is_some() && *v == after[0])
}

/// The three selection rules of one figure: MRF ends lowest; steepest descent falls into a
/// local minimum it never leaves; random stays high. The runs go on for the figure's whole
/// length (`stop_at_goal` false): a rule that reaches the goal and leaves it is seen leaving.
pub(super) fn rules(
    results: &Results,
    exp: &str,
    figure: &str,
    start: &str,
    end: u64,
) -> Vec<Finding> {
    let rule = |name: &str| [("selection", json!(name))];
    let d = |name: &str, step: u64| traced(results, exp, &rule(name), "mean_difference", step);
    let d_runs = |name: &str| traced_values(results, exp, &rule(name), "mean_difference", end);
    // Runs that reached the goal at some step, and runs at the goal at the end.
    let done = |name: &str| {
        let rows = results.select(exp, &rule(name));
        let reached = rows
            .iter()
            .filter(|r| report::value(r, "reached").is_some())
            .count();
        let at_end = rows
            .iter()
            .filter(|r| report::value(r, "mean_difference") == Some(0.0))
            .count();
        (reached, at_end, rows.len())
    };
    let least = |name: &str| {
        (0..=end)
            .step_by(10)
            .map(|s| d(name, s).mean)
            .fold(f64::INFINITY, f64::min)
    };
    let moves = |name: &str| results.stats(exp, &rule(name), "moves");
    let (mrf0, mrf, rnd, st10, st50, st) = (
        d("mrf", 0),
        d("mrf", end),
        d("random", end),
        d("steepest", 10),
        d("steepest", SETTLED),
        d("steepest", end),
    );
    let (mrf_end, rnd_end, st_end) = (d_runs("mrf"), d_runs("random"), d_runs("steepest"));
    let steps = results.stats(exp, &rule("mrf"), "reached");
    let (mr, me, mn) = done("mrf");
    let (rr, re, rn) = done("random");
    let (sr, se, sn) = done("steepest");
    let rnd_least = least("random");

    let below_random = Ordering::new(&mrf_end, &rnd_end, true, Size::Large);
    let below_steepest = Ordering::new(&mrf_end, &st_end, true, Size::Large);
    let stuck = results
        .select(exp, &rule("steepest"))
        .into_iter()
        .filter(|r| {
            report::value(r, "reached").is_none() && settled_from(r, "mean_difference", SETTLED)
        })
        .count();
    let steepest_above = Ordering::new(&st_end, &mrf_end, false, Size::Large);
    let random_above = Ordering::new(&rnd_end, &mrf_end, false, Size::Large);
    let ladder_note = match start {
        "ladder" => " From the ladder no run moves at all: its only movable units are the four C21 corners (the eight C30 units may not move, section 3.3), each with D_0 = 8 and four reachable positions, over or under the C30 beside it (D = 13) and over or under the C21 across (D = 14): each corner would become a C1, whose own term alone is W · 2 a = 6. No tie, so no option of least difference is a move: the ladder is itself a local minimum of every unit's difference (a test enumerates it).",
        _ => "",
    };
    vec![
        Finding {
            section: format!("§5, {figure}"),
            claim: format!("From the {start}, the proposed MRF rule brings the average difference per unit lower than random or steepest-descent selection."),
            kumiki: format!(
                "D per unit at step {end}: MRF {}, random {}, steepest {}; MRF against random: {}; against steepest: {}; MRF reached the goal in {mr}/{mn} runs (first at step {}) and was at it at step {end} in {me}/{mn}",
                mrf.short(2), rnd.short(2), st.short(2), below_random.describe(), below_steepest.describe(), steps.describe(0)
            ),
            runs: mn + rn + sn,
            verdict: weakest(&[below_random.verdict(), below_steepest.verdict()]),
            note: format!("Mean ± sd over runs, starting from D = {} per unit. The figure sets a rule that converges against two that do not, so each comparison is judged as a large effect (Cohen's d and the rank-biserial correlation of the runs' D at step {end}, Mann-Whitney U). Every run goes on for {end} steps, also after it reached the goal (the figure plots every step; the MRF at a finished structure stays, as no move has a lower D than D_0 = 0).", report::fmt(mrf0.mean, 2)),
        },
        Finding {
            section: format!("§5, {figure}"),
            claim: "Steepest descent (the reachable position of least difference always selected, \"no motion\" being position 0) falls into a local minimum, from which the goal cannot be reached.".into(),
            kumiki: format!(
                "D per unit {} at step 0, {} at step 10, {} at step {SETTLED}, {} at step {end}; {} moves per run; {stuck}/{sn} runs settled by step {SETTLED} without reaching the goal (reached in {sr}/{sn}); against MRF at step {end}: {}",
                report::fmt(mrf0.mean, 2), st10.short(2), st50.short(2), st.short(2), moves("steepest").short(1), steepest_above.describe()
            ),
            runs: sn,
            verdict: weakest(&[Verdict::of_all(stuck, sn), steepest_above.verdict()]),
            note: format!("Each unit takes the option of least D_i among staying and its reachable positions (section 4.2 counts \"no motion\" as position i = 0; ties at random), and of the units that choose to move one moves, as with the MRF. Holds when every run settles by step {SETTLED} (its D per unit no longer changes) without having reached the goal, and ends above the MRF by a large effect. At the end {se}/{sn} runs are at the goal.{ladder_note}"),
        },
        Finding {
            section: format!("§5, {figure}"),
            claim: "Random selection of a reachable position does not converge: the difference stays high.".into(),
            kumiki: format!("D per unit at step {end}: {}; lowest mean over the run {}; touched the goal in {rr}/{rn} runs, at it at step {end} in {re}/{rn}; against MRF at step {end}: {}", rnd.short(2), report::fmt(rnd_least, 2), random_above.describe()),
            runs: rn,
            verdict: weakest(&[
                Verdict::from(rnd_least > 0.9 * mrf0.mean),
                Verdict::of_all(rn - re, rn),
                random_above.verdict(),
            ]),
            note: "Random selection takes each of the unit's options alike, \"no motion\" (i = 0) among them as for the other two rules (crate/models/cubes3d/README.md, interpretation 10). Holds when the mean D never falls below 90 % of its start, no run is at the goal at the end, and the runs end above the MRF's by a large effect. A run that touches the goal leaves it again (nothing makes it stay): a run stopped at the goal would count a passing touch as a convergence. Its level, about 9 per unit from either start, is the mean of equation 4 over the structures a random walk visits: against C31[C31, C31, C31] an inner C21 unit of a chain scores 3 for its own type (W times a valence apart) and 1 + 1 + 3 for its neighbours' (the third missing, valence 3), 8 in all, and a C1 end 6 + 7 = 13 (the zigzag's 9.50), while the ladder's corners score 8 and its C30 units 6 against equation 3 (its 6.67), more ordered than what the walk visits.".into(),
        },
    ]
}
