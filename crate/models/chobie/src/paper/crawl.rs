//! Section 3.3's crawl and section IV's initial forms, methods and leaders.

use super::*;

const CRAWLS: [&str; 4] = [
    "chobie-crawl3",
    "chobie-crawl5",
    "chobie-crawl7",
    "chobie-crawl9",
];

fn sum(v: &[f64]) -> f64 {
    v.iter().sum()
}

pub(super) fn crawl(r: &Results, out: &mut Vec<Finding>) {
    let e = "chobie-crawl";
    let temporary = |s: &str, m: &str| {
        r.values(
            e,
            &[("scenario", json!(s)), ("leader", json!("temporary"))],
            m,
        )
    };
    // Each case (3, 5, 7, 9 robots): one cell per crawl cycle, every election a leader whose
    // command was carried out.
    let mut per_cycle = Vec::new();
    let mut good_cases = 0;
    let (mut elections, mut good_elections) = (0, 0);
    for s in CRAWLS {
        let d = temporary(s, "distance");
        let t = temporary(s, "transformations");
        let cycle: Vec<f64> = d.iter().zip(&t).map(|(d, t)| d / (t / 4.0)).collect();
        let failures = sum(&temporary(s, "election_failures"));
        let refused = sum(&temporary(s, "refused"));
        let ok = !cycle.is_empty() && cycle.iter().all(|c| (c - 1.0).abs() < 1e-9);
        if ok && failures == 0.0 && refused == 0.0 {
            good_cases += 1;
        }
        per_cycle.extend(cycle);
        for row in r.select(e, &[("scenario", json!(s)), ("leader", json!("temporary"))]) {
            let leaders = traced(row, "leaders");
            let refusals = per_cycle_of(row, "refused");
            for (l, f) in leaders.iter().skip(1).zip(&refusals) {
                elections += 1;
                if *l == 1.0 && *f == 0.0 {
                    good_elections += 1;
                }
            }
        }
    }
    out.push(Finding::new(
        "§3.3, figs. 7, 9, 10",
        "Crawl motion with 3, 5, 7 and 9 robots was successfully demonstrated in all cases; the four forms move the whole structure by the unit length of a robot.",
        format!(
            "{good_cases} of {} cases crawled one cell per crawl cycle (4 transformations) with no election failing and no command refused: cells per cycle {}",
            CRAWLS.len(),
            Stats::of(&per_cycle).describe(3)
        ),
        per_cycle.len(),
        Verdict::of_all(good_cases, CRAWLS.len()),
        "40 transformations per run, n = 3, 5, 7, 9; distance is the move of the centre of mass along x; the verdict asks it of every case (\"in all cases\")",
    ));
    out.push(Finding::new(
        "§3.3, figs. 7, 8",
        "In each form the three rules make one robot, at a position fixed by the form, the temporary leader; its kind tells the form and the line to drive.",
        format!(
            "{good_elections} of {elections} elections elected exactly one leader whose command was carried out"
        ),
        elections,
        Verdict::of_all(good_elections, elections),
        "every cycle of the four crawls (n = 3, 5, 7, 9), traced: the leaders elected and whether the cycle's commands were refused; the verdict asks it of every election (\"in each form\")",
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
    let fewer = t_msg.iter().zip(&p_msg).filter(|(t, p)| t < p).count();
    let order = Ordering::new(&t_msg, &p_msg, true, Size::Any);
    out.push(Finding::new(
        "§1, §3.1",
        "The temporary leader decreases the amount of information communicated between the robots, compared with a leader that handles the whole structure's information.",
        format!(
            "messages per robot per transformation: temporary {}; permanent {}",
            Stats::of(&t_msg).describe(1),
            Stats::of(&p_msg).describe(1)
        ),
        t_msg.len() + p_msg.len(),
        order.verdict(),
        &format!(
            "n = 3, 5, 7, 9, 21, 41, 81; fewer with temporary leaders at {fewer} of {} n. {}. The text claims a decrease without a size, so any significant effect in its direction holds; the permanent leader's messages grow with n, so the two overlap at the smallest structures",
            t_msg.len(),
            order.describe()
        ),
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

pub(super) fn forms(r: &Results, out: &mut Vec<Finding>) {
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
        Verdict::of_all(
            sum(&failed) as usize,
            ["b", "c"].iter().map(|f| sum(&pick(f, "first", false, "steps"))).sum::<f64>() as usize,
        ),
        "20 cycles each; forms (b) and (c) reconstructed as a lone row and a 4 × 2 block (interpretation 7); the verdict asks that no election of either form elects a leader",
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
        Verdict::of_all(
            leaders.iter().zip(&moved).filter(|(&l, &d)| l >= 2.0 && d == 0.0).count(),
            leaders.len(),
        ),
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
        Verdict::of_all(te.iter().filter(|&&d| d > 0.0).count(), te.len()),
        "form (b)'s row slides whole on the base, the only move figure 3's constraints leave it (interpretation 7): a cell per cycle, at the least work a move can cost (1: every robot one cell)",
    ));
    // Like with like: the slots each cycle took, over the same forms under both methods.
    let mut text = Vec::new();
    let (mut t_cycles, mut c_cycles) = (Vec::new(), Vec::new());
    for f in ["a", "b", "c", "d"] {
        let cycles = |method: &str| {
            r.select(
                e,
                &[
                    ("scenario", json!(format!("chobie-form-{f}"))),
                    ("method", json!(method)),
                    ("priority", Value::Bool(false)),
                ],
            )
            .first()
            .map(|row| per_cycle_of(row, "slots"))
            .unwrap_or_default()
        };
        let (t, c) = (cycles("trial_and_error"), cycles("cautious"));
        let mean = |v: &[f64]| sum(v) / v.len().max(1) as f64;
        text.push(format!("({f}) {:.2} vs {:.2}", mean(&t), mean(&c)));
        // Forms (a) and (d): the first algorithm elects a leader, and both methods begin with
        // it, so their cycles are the same and tell nothing of the difference.
        if matches!(f, "b" | "c") {
            t_cycles.extend(t);
            c_cycles.extend(c);
        }
    }
    let order = Ordering::new(&c_cycles, &t_cycles, true, Size::Any);
    out.push(Finding::new(
        "§IV, fig. 17",
        "The cautious method, which checks the structure's characteristics first, is thought to be more efficient than trial and error.",
        format!(
            "slots per cycle, trial-and-error vs cautious: {}; over the {} cycles of forms (b) and (c): {}",
            text.join("; "),
            c_cycles.len(),
            order.describe()
        ),
        t_cycles.len() + c_cycles.len(),
        order.verdict(),
        "each cycle's slots, traced, for the same forms under both methods (cautious first). Where the first algorithm elects a leader, forms (a) and (d), both methods run it alone and their cycles are the same, so the comparison is over the forms where it elects none, (b) and (c), where trial and error spends the first algorithm's silent slots before the next one's. The text claims more efficient without a size",
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
        Verdict::of_all(
            fixed.iter().zip(&refused).filter(|(&d, &x)| d > 0.0 && x == 0.0).count(),
            fixed.len(),
        ),
        "sequence top + left, bottom + right, top + right, bottom + left (interpretation 8)",
    ));
}

/// Section IV's last paragraph: leaders of the same kind are elected whatever the priority
/// sequence, and since their commands go the same way, both transformations are made at once.
pub(super) fn leaders(r: &Results, out: &mut Vec<Finding>) {
    let e = "chobie-leaders";
    let (mut cycles, mut together) = (0, 0);
    let mut moved = Vec::new();
    for row in r.rows(e) {
        let leaders = traced(row, "leaders");
        let made = per_cycle_of(row, "transformations");
        let refused = per_cycle_of(row, "refused");
        for ((l, m), x) in leaders.iter().skip(1).zip(&made).zip(&refused) {
            if *l >= 2.0 {
                cycles += 1;
                if *m == 1.0 && *x == 0.0 {
                    together += 1;
                }
            }
        }
        moved.extend(kumiki_model::report::value(row, "distance"));
    }
    out.push(Finding::new(
        "§IV, fig. 18",
        "The priority sequence cannot avoid leaders of the same kind being elected, but their commands go the same way, so the two transformations can be performed simultaneously.",
        format!(
            "{together} of {cycles} cycles with two leaders of one kind carried out their commands together; cells moved in 9 cycles {}",
            Stats::of(&moved).describe(2)
        ),
        r.rows(e).len(),
        Verdict::of_all(together, cycles),
        "a tier of twelve with two robots on it one cell apart (chobie-leaders), with and without the priority sequence, until the right robot reaches the tier's end: the three rules elect two top + right leaders every cycle, each driving its top neighbour's line right. Driven alone the left robot would meet the right one head-on (figure 3b), so a cycle that moved made both commands; the verdict asks it of every cycle with two leaders",
    ));
}
