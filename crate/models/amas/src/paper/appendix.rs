//! Figure B1 of the appendix: the collision penalty and the relay duration.

use super::*;

fn figb1(r: &Results, field: &str, rule: &str, penalty: u32, relay: u32) -> Stats {
    Stats::of(&figb1_values(r, field, rule, penalty, relay))
}

fn figb1_values(r: &Results, field: &str, rule: &str, penalty: u32, relay: u32) -> Vec<f64> {
    r.values(
        "amas-figB1",
        &[
            ("field", json!(field)),
            ("collision", json!(rule)),
            ("collision_penalty", json!(penalty)),
            ("relay_duration", json!(relay)),
        ],
        "total_steps",
    )
}

pub(super) fn figb1_findings(r: &Results, out: &mut Vec<Finding>) {
    let mut text = Vec::new();
    let mut verdicts = Vec::new();
    for (field, _) in FIELDS {
        let v = |rule| figb1_values(r, field, rule, 1, 1);
        let o = Ordering::new(&v("relay"), &v("token"), true, Size::Any);
        verdicts.push(o.verdict());
        text.push(format!(
            "{field}: with relay {}, without {} ({})",
            Stats::of(&v("relay")).short(0),
            Stats::of(&v("token")).short(0),
            o.describe()
        ));
    }
    let unfinished = r
        .values("amas-figB1", &[], "completed")
        .iter()
        .filter(|&&c| c == 0.0)
        .count();
    out.push(Finding::new(
        "App. B, fig. B.1",
        "The total steps to complete the L with ten robots, with and without module relay \
         (durations of one step).",
        format!(
            "total steps, the L standing on its stem: {}. Of the appendix's {} runs, {unfinished} \
             had not finished after 20 000 steps (counted there)",
            text.join("; "),
            r.rows("amas-figB1").len()
        ),
        40,
        weakest(verdicts),
        "Holds if relay takes fewer total steps with both fields, significantly.",
    ));
    // "Next, we increased collision penalty steps and again compared the total steps ... with
    // or without the module relay": relay of one step against no relay, penalty by penalty.
    let mut text = Vec::new();
    let mut ok = true;
    for (field, _) in FIELDS {
        let mut parts = Vec::new();
        for penalty in 1..=5 {
            let relay = figb1(r, field, "relay", penalty, 1);
            let token = figb1(r, field, "token", penalty, 1);
            ok &= relay.mean < token.mean;
            parts.push(format!(
                "penalty {penalty}: {} against {} ({:+.0} %)",
                relay.short(0),
                token.short(0),
                100.0 * (relay.mean / token.mean - 1.0)
            ));
        }
        text.push(format!("{field} — {}", parts.join(", ")));
    }
    out.push(Finding::new(
        "App. B, fig. B.1",
        "With the collision penalty increased, the total steps with and without module relay \
         compared again.",
        format!(
            "total steps with relay (1 step) against without: {}",
            text.join("; ")
        ),
        2 * 2 * 5 * 10,
        Verdict::NotStated,
        &format!(
            "The appendix states the comparison, not its outcome, so no verdict is given: \
             Kumiki's own figures. Relay {} fewer total steps than no relay at every penalty from \
             1 to 5 steps with both fields; the percentages show how the gap changes with the \
             penalty.",
            if ok { "takes" } else { "does not take" }
        ),
    ));
    // Where relay stops paying: the relay duration at which relay is no better than no relay,
    // for each collision penalty.
    let mut text = Vec::new();
    let mut ok = true;
    for (field, _) in FIELDS {
        let mut parts = Vec::new();
        for penalty in 1..=5 {
            let token = figb1(r, field, "token", penalty, 1);
            let cross = (1..=5).find(|&d| figb1(r, field, "relay", penalty, d).mean >= token.mean);
            // A relay lasting no longer than the penalty it saves should still pay.
            ok &= cross.is_none_or(|d| d > penalty);
            parts.push(match cross {
                Some(d) => format!("penalty {penalty}: relay of {d} steps or more"),
                None => format!("penalty {penalty}: never up to 5 steps"),
            });
        }
        text.push(format!("{field} — {}", parts.join(", ")));
    }
    out.push(Finding::new(
        "App. B, fig. B.1",
        "The parameters are the duration of the module relay and the penalty for collision: \
         whether the simplification that every operation takes one step changes the comparison.",
        format!(
            "relay duration from which relay is no better than no relay: {}",
            text.join("; ")
        ),
        r.rows("amas-figB1").len(),
        Verdict::NotStated,
        &format!(
            "The appendix states the comparison, not its outcome, so no verdict is given: \
             Kumiki's own figures. Relay {} at every penalty while a relay takes no longer than \
             the collision it replaces (the crossing, if any, lies above the penalty). Without \
             relay the relay duration plays no part: its row at relay duration 1 is the \
             reference.",
            if ok {
                "still pays"
            } else {
                "does not always pay"
            }
        ),
    ));
    // Which field is better (5.2: the continuous field, for its clearance at the corner) as
    // collisions cost more: the field with fewer collisions should gain.
    let mut text = Vec::new();
    let mut gains = true;
    for rule in ["token", "relay"] {
        let mut parts = Vec::new();
        let mut gaps = Vec::new();
        for penalty in 1..=5 {
            let c = figb1(r, "continuous", rule, penalty, 1);
            let d = figb1(r, "discrete", rule, penalty, 1);
            let gap = 100.0 * (c.mean / d.mean - 1.0);
            gaps.push(gap);
            parts.push(format!(
                "penalty {penalty}: continuous {}, discrete {} ({}, {gap:+.0} %)",
                c.short(0),
                d.short(0),
                if c.mean < d.mean {
                    "continuous better"
                } else {
                    "discrete better"
                }
            ));
        }
        let cc = |f: &str, p: u32| {
            r.stats(
                "amas-figB1",
                &[
                    ("field", json!(f)),
                    ("collision", json!(rule)),
                    ("collision_penalty", json!(p)),
                    ("relay_duration", json!(1)),
                ],
                "collisions",
            )
            .mean
        };
        gains &= gaps[4] < gaps[0];
        text.push(format!(
            "{rule} (collisions at penalty 1: continuous {:.0}, discrete {:.0}) — {}",
            cc("continuous", 1),
            cc("discrete", 1),
            parts.join(", ")
        ));
    }
    out.push(Finding::new(
        "App. B, fig. B.1; §5.2",
        "The better field as the collision penalty grows: the continuous field, whose paths have \
         more clearance (5.2), should gain on the discrete field as collisions cost more.",
        format!(
            "L, 10 robots, total steps (relay of 1 step): {}",
            text.join("; ")
        ),
        2 * 2 * 5 * 10,
        Verdict::NotStated,
        &format!(
            "The appendix does not say which field is better at which penalty; the expectation \
             is Kumiki's reading of 5.2, so no verdict is given. Under both rules the continuous \
             field's total steps relative to the discrete field's are {} at a penalty of 5 than \
             at 1 (the percentages show whether they move steadily). Figure B.1's text names only \
             the relay duration and the penalty; both fields are run (interpretation 20).",
            if gains { "lower" } else { "not lower" }
        ),
    ));
}
