//! Section 3.2.5's figure 4: a deadlock, and irritation dissolving it.

use super::*;

const EXP: &str = "fracta-deadlock";

pub(super) fn findings(r: &Results) -> Vec<Finding> {
    let with = |spare: Spare, i_th: u64, metric: &str| {
        r.values(
            EXP,
            &[("scenario", json!(spare.deadlock())), ("I_th", json!(i_th))],
            metric,
        )
    };
    let off = 1_000_000_000;
    let [still, still_corner] = Spare::BOTH.map(|s| with(s, off, "moves"));
    let [moved, moved_corner] = Spare::BOTH.map(|s| with(s, 10, "moves"));
    let [done, done_corner] = Spare::BOTH.map(|s| with(s, 10, "completed"));
    let s = Stats::of(&with(Spare::Edge, 10, "convergence_steps"));
    let idle = |v: &[f64]| v.iter().filter(|&&m| m == 0.0).count();
    let on = [
        ("scenario", json!(Spare::Edge.deadlock())),
        ("I_th", json!(10)),
    ];
    let on_corner = [
        ("scenario", json!(Spare::Corner.deadlock())),
        ("I_th", json!(10)),
    ];
    vec![
        Finding::new(
            "§3.2.5, fig. 4",
            "A configuration whose movable units are all type o with neighbours {K, K} \
             (difference 0) is in deadlock.",
            format!(
                "{} of {} runs made no move in 5000 steps without irritation; with the spare \
                 beside a corner {} of {}",
                idle(&still),
                still.len(),
                idle(&still_corner),
                still_corner.len()
            ),
            still.len() + still_corner.len(),
            Verdict::of_all(idle(&still), still.len()),
            "fracta-deadlock (two triangles of six sharing a corner unit, goal the triangle \
             with its spare in the middle of an edge; fracta-deadlock-corner, the spare beside \
             a corner) with I_th = 10^9, so that condition 5 never fires. Of the 11-cell \
             polyhexes this is the only one whose movable units are all o{K, K} with \
             difference 0, under either reading (an enumeration, in the tests); the middle of \
             an edge also has two 11-unit deadlocks whose o units are o{K, c}.",
        ),
        Finding::new(
            "§3.2.5",
            "Irritation (equations 4 and 5) dissolves the deadlock locally.",
            format!(
                "{} runs left the deadlock; {} reached the goal, in {} steps; with the spare \
                 beside a corner {} left it and {} reached the goal",
                ratio(&moved),
                ratio(&done),
                s.describe(1),
                ratio(&moved_corner),
                ratio(&done_corner)
            ),
            moved.len() + moved_corner.len(),
            match Verdict::of_all(count(&moved), moved.len()) {
                // Every run left figure 4's deadlock; where some then end in another that
                // irritation does not dissolve, the claim holds in part.
                Verdict::Holds if count(&done) < done.len() => Verdict::Partial,
                v => v,
            },
            &format!(
                "fracta-deadlock with I_th = 10: the o units' irritation fires and they roll; \
                 the verdict asks that every run leaves the deadlock and, as \"deadlock states \
                 can be dissolved\", that none ends in another it cannot leave (partial when \
                 every run leaves figure 4's but some are caught in another). Edge: {} The middle of an edge has two more 11-unit deadlocks, \
                 whose o units are o{{K, c}} (an enumeration, in the tests); one of them is \
                 symmetric under a half turn, and in it symmetric units' irritation fires in \
                 the same step and their rolls, each the only one open to it, mirror each \
                 other, so the runs that reach it cycle there (crate/models/fracta/README.md, \
                 \"Beside the paper\"). Corner: {}",
                failures(r, EXP, &on),
                failures(r, EXP, &on_corner)
            ),
        ),
    ]
}
