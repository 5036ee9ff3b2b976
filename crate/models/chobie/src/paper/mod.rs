//! What the paper claims and what Kumiki measures. The paper reports behaviours, not numbers;
//! each finding below reads the built-in experiments' rows and decides its verdict from them.

use serde_json::{json, Value};

use kumiki_model::report::{Finding, Paper, Results, Stats, Verdict};
use kumiki_model::row::Row;

pub const PAPER: Paper = Paper {
    model: "chobie",
    citation: "Y. Suzuki, N. Inou, H. Kimura and M. Koseki, \"Reconfigurable group robots adaptively transforming a mechanical structure – Crawl motion and adaptive transformation with new algorithms\"",
    experiments: &[
        "chobie-crawl",
        "chobie-forms",
        "chobie-bridge",
        "chobie-load",
        "chobie-mechanics",
    ],
    findings,
};

const CRAWLS: [&str; 4] = [
    "chobie-crawl3",
    "chobie-crawl5",
    "chobie-crawl7",
    "chobie-crawl9",
];

fn sum(v: &[f64]) -> f64 {
    v.iter().sum()
}

fn findings(r: &Results) -> Vec<Finding> {
    let mut out = Vec::new();
    crawl(r, &mut out);
    forms(r, &mut out);
    bridge(r, &mut out);
    out
}

fn crawl(r: &Results, out: &mut Vec<Finding>) {
    let e = "chobie-crawl";
    let temporary = |s: &str, m: &str| {
        r.values(
            e,
            &[("scenario", json!(s)), ("leader", json!("temporary"))],
            m,
        )
    };
    let mut per_cycle = Vec::new();
    let (mut failures, mut refused, mut leaders) = (0.0, 0.0, Vec::new());
    for s in CRAWLS {
        let d = temporary(s, "distance");
        let t = temporary(s, "transformations");
        per_cycle.extend(d.iter().zip(&t).map(|(d, t)| d / (t / 4.0)));
        failures += sum(&temporary(s, "election_failures"));
        refused += sum(&temporary(s, "refused"));
        leaders.extend(temporary(s, "leaders"));
    }
    let one_cell = !per_cycle.is_empty() && per_cycle.iter().all(|c| (c - 1.0).abs() < 1e-9);
    out.push(Finding::new(
        "§3.3, figs. 7, 9, 10",
        "Crawl motion with 3, 5, 7 and 9 robots was successfully demonstrated in all cases; the four forms move the whole structure by the unit length of a robot.",
        format!("cells moved per crawl cycle (4 transformations): {}", Stats::of(&per_cycle).describe(3)),
        per_cycle.len(),
        Verdict::from(one_cell && failures == 0.0 && refused == 0.0),
        "40 transformations per run, n = 3, 5, 7, 9; distance is the move of the centre of mass along x",
    ));
    out.push(Finding::new(
        "§3.3, figs. 7, 8",
        "In each form the three rules make one robot, at a position fixed by the form, the temporary leader; its kind tells the form and the line to drive.",
        format!(
            "leaders in the last election: {}; elections without a leader: {failures}; commands refused: {refused}",
            Stats::of(&leaders).describe(0)
        ),
        leaders.len(),
        Verdict::from(leaders.iter().all(|&l| l == 1.0) && failures == 0.0 && refused == 0.0),
        "every one of the 160 elections elected a leader whose command was carried out",
    ));

    let rows = |leader: &str, m: &str| r.values(e, &[("leader", json!(leader))], m);
    let robots = rows("temporary", "robots");
    let t_slots = rows("temporary", "slots_per_transformation");
    let p_slots = rows("permanent", "slots_per_transformation");
    let flat = t_slots.iter().all(|&s| Some(&s) == t_slots.first());
    let grows = p_slots.windows(2).all(|w| w[1] > w[0]);
    let ends = |v: &[f64]| {
        (
            v.first().copied().unwrap_or(f64::NAN),
            v.last().copied().unwrap_or(f64::NAN),
        )
    };
    let (n0, n1) = ends(&robots);
    let (p0, p1) = ends(&p_slots);
    out.push(Finding::new(
        "§3.1, §3.3",
        "The temporary leader scheme is independent of the scale of the structure: it follows a simple local rule whatever the number of robots.",
        format!(
            "slots per transformation with temporary leaders, n = {n0}–{n1}: {}; with a permanent leader: {p0:.1} at n = {n0} to {p1:.1} at n = {n1}",
            Stats::of(&t_slots).describe(1)
        ),
        t_slots.len() + p_slots.len(),
        Verdict::from(flat && grows),
        "the baseline gathers every robot's cell at a fixed leader and floods the driving robots' ids (interpretation 10)",
    ));
    let t_msg = rows("temporary", "messages_per_robot");
    let p_msg = rows("permanent", "messages_per_robot");
    let fewer = !t_msg.is_empty() && t_msg.iter().zip(&p_msg).all(|(t, p)| t < p);
    out.push(Finding::new(
        "§1, §3.1",
        "The temporary leader decreases the amount of information communicated between the robots, compared with a leader that handles the whole structure's information.",
        format!(
            "messages per robot per transformation: temporary {}; permanent {}",
            Stats::of(&t_msg).describe(1),
            Stats::of(&p_msg).describe(1)
        ),
        t_msg.len() + p_msg.len(),
        Verdict::from(fewer),
        "n = 3, 5, 7, 9, 21, 41, 81; compared at each n",
    ));
    let slot = rows("temporary", "slot_us");
    let (s0, s1) = ends(&slot);
    out.push(Finding::new(
        "§3.2",
        "Each time step must be longer than a signal's round trip between both ends of the structure (about 10 µs per robot).",
        format!("slot length needed: {s0:.0} µs at n = {n0} to {s1:.0} µs at n = {n1}"),
        slot.len(),
        Verdict::NotStated,
        "twice the structure's diameter in hops × 10 µs",
    ));
}

fn forms(r: &Results, out: &mut Vec<Finding>) {
    let e = "chobie-forms";
    let pick = |form: &str, method: &str, priority: bool, m: &str| {
        r.values(
            e,
            &[
                ("scenario", json!(format!("chobie-form-{form}"))),
                ("method", json!(method)),
                ("priority", Value::Bool(priority)),
            ],
            m,
        )
    };
    let none: Vec<f64> = ["b", "c"]
        .iter()
        .flat_map(|f| pick(f, "first", false, "distance"))
        .collect();
    let failed: Vec<f64> = ["b", "c"]
        .iter()
        .flat_map(|f| pick(f, "first", false, "election_failures"))
        .collect();
    out.push(Finding::new(
        "§IV, fig. 15",
        "Forms (b) and (c) have the problem that no leader is elected.",
        format!(
            "first algorithm alone: cells moved {}; elections without a leader per run {}",
            Stats::of(&none).describe(1),
            Stats::of(&failed).describe(0)
        ),
        none.len(),
        Verdict::from(!none.is_empty() && none.iter().all(|&d| d == 0.0) && failed.iter().all(|&f| f == 20.0)),
        "20 cycles each; forms (b) and (c) reconstructed as a lone row and a 4 × 2 block (interpretation 7)",
    ));
    let leaders = pick("d", "first", false, "leaders");
    let moved = pick("d", "first", false, "distance");
    out.push(Finding::new(
        "§IV, fig. 15",
        "In form (d) several leaders are elected at once; if their commands go different ways the transformation may be impossible.",
        format!(
            "leaders elected: {}; cells moved without the priority sequence: {}",
            Stats::of(&leaders).describe(0),
            Stats::of(&moved).describe(1)
        ),
        leaders.len(),
        Verdict::from(leaders.iter().all(|&l| l >= 2.0) && moved.iter().all(|&d| d == 0.0)),
        "a top + left and a top + right leader: a vertical and a horizontal command that cannot be made together",
    ));
    let te: Vec<f64> = ["b", "c"]
        .iter()
        .flat_map(|f| pick(f, "trial_and_error", false, "distance"))
        .collect();
    // Like with like, the work a move costs: robot-cells driven per robot and per cell the
    // centre of mass moved (1 is the least any move can cost: every robot one cell).
    let work = |row: &&Row| {
        let v = |m: &str| kumiki_model::report::value(row, m).unwrap_or(f64::NAN);
        v("energy") / v("robots") / v("distance")
    };
    let te_work: Vec<String> = ["b", "c"]
        .iter()
        .filter_map(|f| {
            let rows = r.select(
                e,
                &[
                    ("scenario", json!(format!("chobie-form-{f}"))),
                    ("method", json!("trial_and_error")),
                    ("priority", Value::Bool(false)),
                ],
            );
            rows.first().map(|row| format!("({f}) {:.2}", work(row)))
        })
        .collect();
    let crawl_work: Vec<f64> = r
        .select("chobie-crawl", &[("leader", json!("temporary"))])
        .iter()
        .map(work)
        .collect();
    out.push(Finding::new(
        "§IV, fig. 16",
        "The trial-and-error method, trying a second and a third algorithm when no leader is detected, makes forms (b) and (c) move.",
        format!(
            "cells moved in 20 cycles: {}; robot-cells driven per robot and cell moved: {}, the crawl {}",
            Stats::of(&te).describe(1),
            te_work.join(", "),
            Stats::of(&crawl_work).describe(2)
        ),
        te.len(),
        Verdict::from(!te.is_empty() && te.iter().all(|&d| d > 0.0)),
        "form (b)'s row slides whole on the base, the only move figure 3's constraints leave it (interpretation 7): a cell per cycle, at the least work a move can cost (1: every robot one cell)",
    ));
    let mut cheaper = 0;
    let mut worse = 0;
    let mut text = Vec::new();
    for f in ["a", "b", "c", "d"] {
        let t = pick(f, "trial_and_error", false, "slots_per_transformation");
        let c = pick(f, "cautious", false, "slots_per_transformation");
        if let (Some(t), Some(c)) = (t.first(), c.first()) {
            text.push(format!("({f}) {t:.2} vs {c:.2}"));
            if c < t {
                cheaper += 1;
            }
            if c > t {
                worse += 1;
            }
        }
    }
    out.push(Finding::new(
        "§IV, fig. 17",
        "The cautious method, which checks the structure's characteristics first, is thought to be more efficient than trial and error.",
        format!("slots per cycle, trial-and-error vs cautious: {}", text.join("; ")),
        2 * text.len(),
        Verdict::from(cheaper > 0 && worse == 0),
        "equal where the first algorithm already elects a leader",
    ));
    let fixed = pick("d", "first", true, "distance");
    let refused = pick("d", "first", true, "refused");
    out.push(Finding::new(
        "§IV, fig. 18",
        "Checking leader kinds in a priority sequence avoids plural leaders of different kinds in form (d).",
        format!(
            "cells moved in 20 cycles with the sequence: {}; refused cycles {}",
            Stats::of(&fixed).describe(2),
            Stats::of(&refused).describe(0)
        ),
        fixed.len(),
        Verdict::from(!fixed.is_empty() && fixed.iter().all(|&d| d > 0.0) && refused.iter().all(|&x| x == 0.0)),
        "sequence top + left, bottom + right, top + right, bottom + left (interpretation 8)",
    ));
}

/// A traced metric of a row, one value per cycle.
fn traced(row: &kumiki_model::row::Row, metric: &str) -> Vec<f64> {
    row.trace
        .as_ref()
        .and_then(|t| t.values.get(metric))
        .and_then(Value::as_array)
        .map(|a| a.iter().filter_map(Value::as_f64).collect())
        .unwrap_or_default()
}

/// The plain run (adaptation off) that matches an adaptive row: same reserves, tip load, goal.
fn plain<'a>(r: &'a Results, row: &Row) -> Option<&'a Row> {
    let mut filter = vec![
        ("scenario", json!(row.scenario)),
        ("adaptation", Value::Bool(false)),
    ];
    for key in ["tip_load", "goal"] {
        if let Some(v) = row.params.get(key) {
            filter.push((key, v.clone()));
        }
    }
    r.select("chobie-bridge", &filter).first().copied()
}

fn bridge(r: &Results, out: &mut Vec<Finding>) {
    let e = "chobie-bridge";
    let rows = r.select(e, &[("adaptation", Value::Bool(true))]);
    // Overload episodes: a switch to adaptation mode. One is cleared when the robots go back to
    // construction, or when the run ends complete in it (a complete bridge has no robot over
    // the threshold).
    let (mut episodes, mut cleared, mut resumed_runs, mut complete) = (0, 0, 0, 0);
    let (mut stuck, mut used_up) = (0, 0);
    let mut by_goal: Vec<(i64, usize, usize)> = Vec::new();
    for row in &rows {
        let modes = traced(row, "mode");
        let (mut run_episodes, mut run_resumed) = (0, 0);
        for w in modes.windows(2) {
            if w[0] != 2.0 && w[1] == 2.0 {
                run_episodes += 1;
            }
            if w[0] == 2.0 && w[1] == 1.0 {
                run_resumed += 1;
            }
        }
        let ended_clear = row.completed && modes.last() == Some(&2.0);
        episodes += run_episodes;
        cleared += run_resumed + ended_clear as usize;
        if run_resumed > 0 {
            resumed_runs += 1;
        }
        let value = |m: &str| kumiki_model::report::value(row, m);
        if row.completed {
            complete += 1;
        } else if value("mode") == Some(2.0) && value("stalled") == Some(1.0) {
            stuck += 1;
            if value("reserves") == Some(0.0) {
                used_up += 1;
            }
        }
        let goal = row.params.get("goal").and_then(Value::as_i64).unwrap_or(0);
        match by_goal.iter_mut().find(|g| g.0 == goal) {
            Some(g) => {
                g.1 += row.completed as usize;
                g.2 += 1;
            }
            None => by_goal.push((goal, row.completed as usize, 1)),
        }
    }
    let goals: Vec<String> = by_goal
        .iter()
        .map(|(g, c, n)| format!("{c} of {n} to {g}"))
        .collect();
    out.push(Finding::new(
        "§3.4, fig. 12",
        "When a robot's stress exceeds the threshold all robots switch to load-adaptation mode, and when the overload is done away with they switch back to bridge construction.",
        format!(
            "{episodes} overloads in {} runs, {cleared} of them cleared; {resumed_runs} of {} runs resumed construction at least once; {complete} cleared every overload and reached their goal span ({}); {stuck} stalled in adaptation mode, still overloaded, no leader elected: {used_up} with no reserve left, {} with reserves left, all of them right of the overloaded root",
            rows.len(),
            rows.len(),
            goals.join(", "),
            stuck - used_up,
        ),
        rows.len(),
        Verdict::from(cleared > 0 && resumed_runs == rows.len() && complete > 0),
        "1, 3, 5, 7 or 9 reserves × goal spans 13, 16, 19 × tip loads 0, 10, 20 N; each step 7 puts one reserve into the tier over the void and its tier robot under it, against the cliff face or the robot an earlier step 7 put there (interpretation 13); leader 2 drives the reserves only right",
    ));
    // Enough reserves: for each goal and load, the fewest reserves with which the bridge got
    // there (the reserves a run starts with are its first traced count).
    let mut need = Vec::new();
    for goal in [13, 16, 19] {
        let mut per_load = Vec::new();
        for load in [0, 10, 20] {
            let fewest = r
                .select(
                    e,
                    &[
                        ("adaptation", Value::Bool(true)),
                        ("goal", json!(goal)),
                        ("tip_load", json!(load)),
                    ],
                )
                .into_iter()
                .filter(|row| row.completed)
                .filter_map(|row| traced(row, "reserves").first().copied())
                .fold(f64::INFINITY, f64::min);
            per_load.push(if fewest.is_finite() {
                format!("{fewest}")
            } else {
                "none".into()
            });
        }
        need.push(format!("{goal} cells: {}", per_load.join(" / ")));
    }
    out.push(Finding::new(
        "§3.4, fig. 11",
        "The robots on the upper tier are used for load adaptation: when overload occurs, they move and reinforce the overloaded position.",
        format!(
            "fewest reserves (of 1, 3, 5, 7, 9) that took the bridge to its goal, at 0 / 10 / 20 N: {}",
            need.join("; ")
        ),
        rows.len(),
        Verdict::NotStated,
        "a goal marked none is out of reach with up to 9 reserves: the tie of the root (the tier's last robot on the flat part and its first over the void) overloads before the goal, and the reserves, which leader 2 drives only right, cannot reach it (interpretation 13)",
    ));
    // Equal span: each adaptive run at its final span (its goal when complete) against the
    // plain run with the same reserves, tip load and goal at that span (the last cycle it had
    // that span).
    let (mut lower, mut pairs) = (0, 0);
    let (mut with, mut without, mut spans) = (Vec::new(), Vec::new(), Vec::new());
    for row in &rows {
        let (Some(plain), Some(span)) = (plain(r, row), kumiki_model::report::value(row, "span"))
        else {
            continue;
        };
        let (p_span, p_peak) = (traced(plain, "span"), traced(plain, "peak_stress"));
        let at = p_span.iter().rposition(|&s| s == span);
        let (Some(at), Some(peak)) = (at, kumiki_model::report::value(row, "peak_stress")) else {
            continue;
        };
        pairs += 1;
        with.push(peak);
        without.push(p_peak[at]);
        spans.push(span);
        if peak < p_peak[at] {
            lower += 1;
        }
    }
    out.push(Finding::new(
        "§3.4, figs. 1, 11",
        "Load adaptation equalises the robots' stressed states: overloaded parts are thickened by other robots instead of the stress concentrating.",
        format!(
            "peak stress at equal span (the adaptive run's final span, {}), MPa: with adaptation {}; without {}; lower with adaptation in {lower} of {pairs} pairs",
            Stats::of(&spans).describe(0),
            Stats::of(&with).describe(2),
            Stats::of(&without).describe(2)
        ),
        with.len() + without.len(),
        Verdict::from(pairs > 0 && lower == pairs),
        "threshold 4 MPa; the plain run (same reserves, load and goal) taken at the last cycle it had the same span",
    ));
    let span_with = r.values(e, &[("adaptation", Value::Bool(true))], "span");
    let span_without = r.values(e, &[("adaptation", Value::Bool(false))], "span");
    out.push(Finding::new(
        "§3.4, fig. 11",
        "The lower tier slides right over the cliff and builds the bridge.",
        format!(
            "span reached (cells beyond the edge): with adaptation {}; without {}",
            Stats::of(&span_with).describe(1),
            Stats::of(&span_without).describe(1)
        ),
        span_with.len() + span_without.len(),
        Verdict::NotStated,
        "without adaptation the tier runs out to its goal whatever the stress (the base's guide holds it: no tipping, interpretation 18); with it construction stops while an overload is being removed, and for good where no reserve can remove it",
    ));
    let l = "chobie-load";
    let moved = r.values(l, &[("adaptation", Value::Bool(true))], "energy");
    let idle = r.values(l, &[("adaptation", Value::Bool(false))], "energy");
    let peak_with = r.values(l, &[("adaptation", Value::Bool(true))], "peak_stress");
    let peak_without = r.values(l, &[("adaptation", Value::Bool(false))], "peak_stress");
    let left = r.values(l, &[("adaptation", Value::Bool(true))], "overloads");
    out.push(Finding::new(
        "§3.4, figs. 13, 14",
        "With five robots, a load at the cantilever's end overloads robot B near the root, and robot A moves so that the stressed part becomes thick: load information is the trigger.",
        format!(
            "300 N on the tip: robot-cells driven with adaptation {}, without {}; peak stress at the end, MPa: with {}, without {}; robots still overloaded {}",
            Stats::of(&moved).describe(0),
            Stats::of(&idle).describe(0),
            Stats::of(&peak_with).describe(2),
            Stats::of(&peak_without).describe(2),
            Stats::of(&left).describe(0)
        ),
        moved.len() + idle.len(),
        Verdict::from(
            moved.iter().all(|&m| m > 0.0)
                && idle.iter().all(|&m| m == 0.0)
                && peak_with.iter().zip(&peak_without).all(|(w, o)| w < o)
                && left.iter().all(|&x| x == 0.0)
        ),
        "A moves right over B (step 8), then B's column drives down (step 7): A takes B's place in the tier and B presses against the cliff face under the root",
    ));
    let m = "chobie-mechanics";
    let frame = r.values(m, &[], "peak_stress");
    let theory = r.values(m, &[], "beam_theory_stress");
    let worst = frame
        .iter()
        .zip(&theory)
        .map(|(f, t)| ((f - t) / t).abs())
        .fold(0.0, f64::max);
    out.push(Finding::new(
        "§3.4 (strain gauges)",
        "The robots sense their stress with strain gauges; Kumiki computes it with a plane-frame model.",
        format!("largest relative difference between the frame's root stress and beam theory, cantilevers of 1–20 robots: {worst:.1e}"),
        frame.len(),
        Verdict::NotStated,
        "a check of the stress model, not a claim of the paper",
    ));
}
