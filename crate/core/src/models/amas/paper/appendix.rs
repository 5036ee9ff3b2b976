//! Figure B1 of the appendix: the collision penalty and the relay duration.

use super::*;

fn figb1(r: &Results, field: &str, rule: &str, penalty: u32, relay: u32) -> Stats {
    r.stats(
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
    let mut ok = true;
    for (field, _) in FIELDS {
        let relay = figb1(r, field, "relay", 1, 1);
        let token = figb1(r, field, "token", 1, 1);
        ok &= relay.mean < token.mean;
        text.push(format!(
            "{field}: with relay {}, without {}",
            relay.describe(0),
            token.describe(0)
        ));
    }
    out.push(Finding::new(
        "App. B, fig. B.1",
        "The total steps to complete the L with ten robots, with and without module relay \
         (durations of one step).",
        format!("total steps: {}", text.join("; ")),
        40,
        Verdict::from(ok),
        "Holds if relay takes fewer total steps with both fields.",
    ));
    // Where relay stops paying: the relay duration at which relay is no better than no relay,
    // for each collision penalty.
    let mut text = Vec::new();
    for (field, _) in FIELDS {
        let mut parts = Vec::new();
        for penalty in 1..=5 {
            let token = figb1(r, field, "token", penalty, 1);
            let cross = (1..=5).find(|&d| figb1(r, field, "relay", penalty, d).mean >= token.mean);
            parts.push(match cross {
                Some(d) => format!("penalty {penalty}: relay of {d} steps or more"),
                None => format!("penalty {penalty}: never up to 5 steps"),
            });
        }
        text.push(format!("{field} — {}", parts.join(", ")));
    }
    out.push(Finding::new(
        "App. B, fig. B.1",
        "As the collision penalty increases, total steps with and without module relay compare \
         differently against the duration of a relay.",
        format!(
            "relay duration from which relay is no better than no relay: {}",
            text.join("; ")
        ),
        r.rows("amas-figB1").len(),
        Verdict::NotStated,
        "Kumiki's own figures; no comparison is judged. Without relay the relay duration plays \
         no part: its row at relay duration 1 is the reference.",
    ));
}
