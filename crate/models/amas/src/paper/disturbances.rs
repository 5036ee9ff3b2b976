//! Figure 27: module removal (5.4) and communication breakdown (5.5).

use super::*;

const REMOVE: &str = "square28, module removal (5.4)";
const BREAK: &str = "square28, communication breakdown (5.5)";
const NARROW: &str = "square28, conveyor 28 wide";
const WIDE: &str = "square28, conveyor 36 wide";

fn fig27_steps(r: &Results, scenario: &str, count: u32) -> Stats {
    r.stats(
        "amas-fig27",
        &[
            ("scenario", json!(scenario)),
            ("disturbances.0.count", json!(count)),
        ],
        "steps",
    )
}

fn fig27_counts(r: &Results) -> Vec<u32> {
    let mut counts: Vec<u32> = r
        .rows("amas-fig27")
        .iter()
        .filter_map(|row| row.params.get("disturbances.0.count")?.as_u64())
        .map(|c| c as u32)
        .collect();
    kumiki_model::sort::sort(&mut counts);
    counts.dedup();
    counts
}

/// The runs of a disturbance that did not finish, as the numbers of disturbed modules they had
/// (one entry a run, in order), and how many runs it had.
fn unfinished(r: &Results, scenario: &str) -> (Vec<u32>, usize) {
    let mut counts = Vec::new();
    let mut runs = 0;
    for c in fig27_counts(r) {
        let filter = [
            ("scenario", json!(scenario)),
            ("disturbances.0.count", json!(c)),
        ];
        let done = r.values("amas-fig27", &filter, "completed");
        runs += done.len();
        counts.extend(done.iter().filter(|&&v| v != 1.0).map(|_| c));
    }
    (counts, runs)
}

/// "n of N runs of <what> finish (those that do not had c1, c2 disturbed modules)".
fn finished(r: &Results, scenario: &str, what: &str) -> (String, usize) {
    let (left, runs) = unfinished(r, scenario);
    let mut text = format!("{} of {runs} runs of {what} finish", runs - left.len());
    if !left.is_empty() {
        let counts: Vec<String> = left.iter().map(u32::to_string).collect();
        text += &format!(
            " (those that do not had {} disturbed modules)",
            counts.join(", ")
        );
    }
    (text, runs)
}

pub(super) fn fig27_findings(r: &Results, out: &mut Vec<Finding>) {
    let base = fig27_steps(r, REMOVE, 0);
    out.push(Finding::new(
        "§5.3",
        "28 robots assemble a square of 28×28 modules; under normal conditions the task was \
         completed within [a figure the paper gives] steps.",
        format!("steps, undisturbed: {}", base.describe(0)),
        base.n,
        Verdict::NotStated,
        "The square counts the supply row: 27 rows stand on it. Continuous field, token rule \
         (the paper names neither for 5.3; robots that lose their way among growth-front modules \
         are the continuous field's).",
    ));
    let counts = fig27_counts(r);
    let disturbed: Vec<u32> = counts.iter().copied().filter(|&c| c > 0).collect();
    let mut worse = 0;
    let mut text = Vec::new();
    for &c in &disturbed {
        let rm = fig27_steps(r, REMOVE, c);
        let br = fig27_steps(r, BREAK, c);
        if br.median > rm.median {
            worse += 1;
        }
        if c % 20 == 0 || c == disturbed[0] {
            text.push(format!(
                "{c}: removal {} / breakdown {}",
                median(&rm),
                median(&br)
            ));
        }
    }
    let (removal_done, removal_runs) = finished(r, REMOVE, "removal");
    let (breakdown_done, breakdown_runs) = finished(r, BREAK, "breakdown");
    let runs = removal_runs + breakdown_runs;
    out.push(Finding::new(
        "§5.5, fig. 27",
        "Communication breakdown is more serious than module removal, because the robots cannot \
         restore the broken gradient field.",
        format!(
            "median steps (IQR) by disturbed modules — {}; breakdown takes longer at {worse} of \
             {} counts; {removal_done}; {breakdown_done}",
            text.join("; "),
            disturbed.len()
        ),
        runs,
        Verdict::of_all(worse, disturbed.len()),
        "Disturbance at step 360, modules drawn at random among those built. Medians, because \
         breakdown has a long tail: robots carrying modules climb to the stale high values \
         broken modules keep and wander there. A run that does not finish counts at its cap of \
         50 000 steps: with the most removals, every robot is left on a part cut off from the \
         supply; with the most broken modules, every robot is loaded and held at the stale \
         maxima of modules that broke at the growth front, which keep the front's value, the \
         field the robots 'cannot restore' (traced, interpretation 33). The text gives no \
         number of disturbed modules, so it does not say whether its runs met either.",
    ));
    threshold(r, &disturbed, base.median, out);
    // Section 5.4's mechanism: robots among growth-front modules lose their way and wander.
    let wander = |scenario: &str, c: u32| {
        r.stats(
            "amas-fig27",
            &[
                ("scenario", json!(scenario)),
                ("disturbances.0.count", json!(c)),
            ],
            "wandering",
        )
        .median
    };
    let robots = 28.0;
    let mut text = Vec::new();
    let mut below = 0;
    for scenario in [REMOVE, BREAK] {
        let name = if scenario == REMOVE {
            "removal"
        } else {
            "breakdown"
        };
        let list: Vec<String> = counts
            .iter()
            .map(|&c| format!("{c}: {:.0}", wander(scenario, c)))
            .collect();
        text.push(format!("{name} — {}", list.join(", ")));
        if scenario == REMOVE {
            below = disturbed
                .iter()
                .take_while(|&&c| wander(REMOVE, c) < robots)
                .last()
                .copied()
                .unwrap_or(0);
        }
    }
    // Without rows (a claim re-run from other experiments) every count reads as 0.
    let last = disturbed.last().copied().unwrap_or(0);
    let grows = wander(REMOVE, last) > wander(REMOVE, disturbed.first().copied().unwrap_or(0));
    out.push(Finding::new(
        "§5.4, fig. 25",
        "Robots surrounded by growth-front modules lose their way (no effective gradient) and \
         move randomly; this wandering results in low total construction efficiency.",
        format!(
            "plans made with no effective gradient, median per run by disturbed modules: {}. \
             Removal: fewer than one per robot up to {below} removed modules",
            text.join("; ")
        ),
        r.rows("amas-fig27").len(),
        Verdict::from(grows && wander(REMOVE, last) >= robots),
        "The metric wandering counts the plans a robot makes with no effective gradient \
         (footnote 3) or on a broken module. Holds if, after module removal, robots wander \
         (at least one such plan per robot in the median run with the most removals) and \
         wander more than with the fewest. Wandering after removal has a threshold: none to \
         speak of with a few holes, which are refilled before robots are trapped, and then \
         rising with the count; a robot on a broken module is told nothing, so breakdown \
         makes robots wander from the first module.",
    ));
}

/// The least-squares line through `points`: (slope, intercept, sum of squared residuals).
fn line(points: &[(f64, f64)]) -> (f64, f64, f64) {
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x / n, b + y / n));
    let sxx: f64 = points.iter().map(|&(x, _)| (x - mx) * (x - mx)).sum();
    let sxy: f64 = points.iter().map(|&(x, y)| (x - mx) * (y - my)).sum();
    let slope = if sxx > 0.0 { sxy / sxx } else { 0.0 };
    let icpt = my - slope * mx;
    let sse = points
        .iter()
        .map(|&(x, y)| (y - icpt - slope * x).powi(2))
        .sum();
    (slope, icpt, sse)
}

/// The knee of a curve: the point that splits it into two lines (each through at least three
/// points, sharing the knee) with the least squared residuals; its x and the slopes before and
/// after it.
fn knee(points: &[(f64, f64)]) -> Option<(f64, f64, f64)> {
    (2..points.len().saturating_sub(2))
        .map(|k| {
            let (before, _, e1) = line(&points[..=k]);
            let (after, _, e2) = line(&points[k..]);
            (e1 + e2, points[k].0, before, after)
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, x, before, after)| (x, before, after))
}

/// Figure 27's threshold: where the cost of a further disturbed module turns up, for removal and
/// for breakdown.
fn threshold(r: &Results, disturbed: &[u32], undisturbed: f64, out: &mut Vec<Finding>) {
    let mut text = Vec::new();
    let mut verdicts = Vec::new();
    for (scenario, name) in [(REMOVE, "removal"), (BREAK, "breakdown")] {
        let points: Vec<(f64, f64)> = disturbed
            .iter()
            .map(|&c| (f64::from(c), fig27_steps(r, scenario, c).median))
            .collect();
        let Some((at, before, after)) = knee(&points) else {
            verdicts.push(Verdict::Differs);
            continue;
        };
        let rise = |c: f64| {
            let m = points.iter().find(|p| p.0 == c).map_or(f64::NAN, |p| p.1);
            100.0 * (m / undisturbed - 1.0)
        };
        // A knee: a further module costs three times as much past it as before it; a curve that
        // only bends up points the stated way, less sharply.
        verdicts.push(match after {
            a if a >= 3.0 * before && before >= 0.0 => Verdict::Holds,
            a if a > before => Verdict::Partial,
            _ => Verdict::Differs,
        });
        text.push(format!(
            "{name}: knee at {at:.0} disturbed modules, {before:.1} steps per further module \
             before it, {after:.1} after it; +{:.0} % with {:.0} disturbed, +{:.0} % at the \
             knee, +{:.0} % with {:.0}",
            rise(points[0].0),
            points[0].0,
            rise(at),
            rise(points[points.len() - 1].0),
            points[points.len() - 1].0,
        ));
    }
    let rules_steps = |field: &str, rule: &str, count: u32| {
        r.stats(
            "amas-fig27-rules",
            &[
                ("field", json!(field)),
                ("collision", json!(rule)),
                ("disturbances.0.count", json!(count)),
            ],
            "steps",
        )
        .median
    };
    let mut rules = Vec::new();
    for (field, _) in FIELDS {
        for rule in ["token", "relay", "blackboard"] {
            let base = rules_steps(field, rule, 0);
            let rise = |c: u32| 100.0 * (rules_steps(field, rule, c) / base - 1.0);
            rules.push(format!(
                "{field} {rule} +{:.0} % / +{:.0} %",
                rise(1),
                rise(10)
            ));
        }
    }
    let supply = |scenario: &str, count: u32, metric: &str| {
        r.stats(
            "amas-fig27-supply",
            &[
                ("scenario", json!(scenario)),
                ("disturbances.0.count", json!(count)),
            ],
            metric,
        )
        .median
    };
    let mut wide = Vec::new();
    for scenario in [NARROW, WIDE] {
        let base = supply(scenario, 0, "steps");
        let counts: Vec<String> = [1, 10, 40]
            .iter()
            .map(|&c| {
                format!(
                    "+{:.1} % with {c}",
                    100.0 * (supply(scenario, c, "steps") / base - 1.0)
                )
            })
            .collect();
        wide.push(format!(
            "{scenario}: undisturbed {base:.0} steps ({:.0} collisions), {}",
            supply(scenario, 0, "collisions"),
            counts.join(", ")
        ));
    }
    out.push(Finding::new(
        "§5.5, fig. 27",
        "When the number of disturbances does not exceed some threshold, efficiency is not much \
         affected by the disturbances.",
        format!(
            "median steps by disturbed modules, against the undisturbed {undisturbed:.0}: {}. \
             The first removals (1 / 10 modules) with each field and rule (amas-fig27-rules, \
             medians): {}. On a conveyor wider than the square (amas-fig27-supply, medians): {}",
            text.join("; "),
            rules.join(", "),
            wide.join("; ")
        ),
        r.rows("amas-fig27").len()
            + r.rows("amas-fig27-rules").len()
            + r.rows("amas-fig27-supply").len(),
        weakest(verdicts),
        "The text states a threshold in the number of disturbed modules, so the claim is read as \
         a knee: the medians from one disturbed module up are split into two straight lines \
         where that fits them best, and the claim holds if, for removal and for breakdown \
         alike, a further module costs at least three times as much past the knee as before \
         it (in part where it costs more, but less than three times as much). Past the knee \
         robots lose their way among growth-front modules or stale values \
         (5.4, the wandering row), and with the most disturbed modules a run may never \
         finish (the row above says which). Before the knee the cost per module is \
         small but the first module is not free: undisturbed, each of the 28 robots starts \
         under its own column of a conveyor as wide as the square and builds it in lockstep, \
         one step above the footnote-2 bound, and any hole ends that order, whatever the field \
         or rule (the blackboard records no collision and still pays), because the robot of a \
         column one module behind reaches its top first on every trip (interpretation 30). \
         Where the robots do not start one under each column (a conveyor 36 wide) the first \
         removals cost little more than their refill trips. The text gives neither the \
         conveyor's width nor the counts figure 27 plots.",
    ));
}
