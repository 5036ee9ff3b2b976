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

pub(super) fn fig27_findings(r: &Results, out: &mut Vec<Finding>) {
    let base = fig27_steps(r, REMOVE, 0);
    let done: Vec<f64> = [REMOVE, BREAK]
        .iter()
        .flat_map(|s| r.values("amas-fig27", &[("scenario", json!(s))], "completed"))
        .collect();
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
    let runs = done.len();
    let finished = done.iter().filter(|&&v| v == 1.0).count();
    out.push(Finding::new(
        "§5.5, fig. 27",
        "Communication breakdown is more serious than module removal, because the robots cannot \
         restore the broken gradient field.",
        format!(
            "median steps (IQR) by disturbed modules — {}; breakdown takes longer at {worse} of \
             {} counts; {finished} of {runs} runs finish",
            text.join("; "),
            disturbed.len()
        ),
        runs,
        Verdict::from(worse == disturbed.len()),
        "Disturbance at step 360, modules drawn at random among those built. Medians, because \
         breakdown has a long tail: robots carrying modules climb to the stale high values \
         broken modules keep and wander there. A run that does not finish (with the most \
         removals, every robot left on a part cut off from the supply) counts at its cap of \
         50 000 steps.",
    ));
    // The knee: flat up to a threshold, rising after it.
    let mut text = Vec::new();
    let mut flat = true;
    let plural = |n: u32| if n == 1 { "module" } else { "modules" };
    // Without rows (a claim re-run from other experiments) every count reads as 0.
    let first = disturbed.first().copied().unwrap_or(0);
    let last = disturbed.last().copied().unwrap_or(0);
    // The lower half of the counts, and their top quarter, for the cost per added module.
    let half = disturbed
        .iter()
        .copied()
        .rev()
        .find(|&c| 2 * c <= last)
        .unwrap_or(0);
    let quarter = disturbed
        .iter()
        .copied()
        .find(|&c| 4 * c >= 3 * last)
        .unwrap_or(0);
    for scenario in [REMOVE, BREAK] {
        let name = if scenario == REMOVE {
            "removal"
        } else {
            "breakdown"
        };
        let median = |c: u32| fig27_steps(r, scenario, c).median;
        let rise = |c: u32| 100.0 * (median(c) / base.median - 1.0);
        let slope = |a: u32, b: u32| (median(b) - median(a)) / f64::from(b.max(a + 1) - a);
        flat &= rise(first) < 5.0;
        let collisions = |c: u32| {
            r.stats(
                "amas-fig27",
                &[
                    ("scenario", json!(scenario)),
                    ("disturbances.0.count", json!(c)),
                ],
                "collisions",
            )
            .median
        };
        text.push(format!(
            "{name}: +{:.0} % with {first} disturbed {}, +{:.0} % with {half}, +{:.0} % with \
             {last}; {:.1} steps per added module from {first} to {half}, {:.1} from {quarter} \
             to {last}; median collisions {:.0} undisturbed, {:.0} with {first} disturbed {}",
            rise(first),
            plural(first),
            rise(half),
            rise(last),
            slope(first, half),
            slope(quarter, last),
            collisions(0),
            collisions(first),
            plural(first),
        ));
    }
    // The same first removals with each field and rule: is the jump the setup's or the rule's?
    let rules_steps = |field: &str, rule: &str, count: u32, metric: &str| {
        r.stats(
            "amas-fig27-rules",
            &[
                ("field", json!(field)),
                ("collision", json!(rule)),
                ("disturbances.0.count", json!(count)),
            ],
            metric,
        )
    };
    let mut rules = Vec::new();
    for (field, _) in FIELDS {
        for rule in ["token", "relay", "blackboard"] {
            let base = rules_steps(field, rule, 0, "steps").median;
            let rise = |c: u32| 100.0 * (rules_steps(field, rule, c, "steps").median / base - 1.0);
            rules.push(format!(
                "{field} {rule} +{:.0} % / +{:.0} % ({:.0} / {:.0} collisions)",
                rise(1),
                rise(10),
                rules_steps(field, rule, 1, "collisions").median,
                rules_steps(field, rule, 10, "collisions").median,
            ));
        }
    }
    // total_steps = steps × robots.
    let robots = rules_steps("continuous", "token", 0, "total_steps").mean
        / rules_steps("continuous", "token", 0, "steps").mean;
    let bound = rules_steps("continuous", "token", 0, "lower_bound").mean / robots;
    // The same square where the robots do not start one under each column.
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
            "median steps against the undisturbed run: {}. Undisturbed {:.0} steps against the \
             footnote-2 bound of {bound:.0}. Removal of 1 / 10 modules with each field and rule \
             (amas-fig27-rules, medians): {}. Removal on a conveyor wider than the square \
             (amas-fig27-supply, medians): {}",
            text.join("; "),
            base.median,
            rules.join(", "),
            wide.join("; ")
        ),
        r.rows("amas-fig27").len()
            + r.rows("amas-fig27-rules").len()
            + r.rows("amas-fig27-supply").len(),
        Verdict::from(flat),
        "Holds if the fewest disturbances tried cost less than 5 % of the undisturbed median. \
         There is a knee: over the top quarter of the counts each further module costs far more \
         than one did over the lower half (the steps per added module above), as robots lose their way among growth-front \
         modules (5.4, next row) and, with the most removals, a run may never finish because \
         every robot is left on a part of the structure cut off from the supply (previous row; \
         5.4: the assembly is not deadlocked 'as long as there is at least one robot that can \
         escape'). Below the knee the cost is not flat. Undisturbed, each of the 28 robots \
         starts under its own column and builds it, no robot meets another and all place their \
         last module in the same step. Any disturbance ends that order, whatever notices or \
         refills the hole: the blackboard records no collision at all and one removed module \
         still costs about as much as with the other rules; a hole at a column's top, refilled the \
         next step by that column's robot with no collision and no sideways move, still costs \
         a trip (a step-by-step trace, crate/models/amas/README.md, interpretation 30), because the \
         robot whose column is one module behind reaches its column's top first on every trip \
         and no other robot can share its extra trip. Where the robots do not start one under \
         each column (the same square in the middle of a conveyor 36 modules wide), the \
         undisturbed run is already slower, its robots meeting from the start, and the first \
         removals add little more than their refill trips: the paper's plateau. The text gives the 28 robots and the 28 columns but neither the \
         conveyor's width nor the counts figure 27 plots.",
    ));
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
