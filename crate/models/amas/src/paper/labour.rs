//! Figure 24 (the division of labour at the corner) and appendix A.1 (which robots collide).

use super::*;

/// The L of figure 24 in each reading: `amas-L` stands on its stem.
const SHAPES: [(&str, &str); 2] = [("amas-L", "on its stem"), ("L on its foot", "on its foot")];

fn fig24(r: &Results, shape: &str, field: &str, rule: &str, metric: &str) -> Vec<f64> {
    r.values(
        "amas-fig24",
        &[
            ("scenario", json!(shape)),
            ("field", json!(field)),
            ("collision", json!(rule)),
        ],
        metric,
    )
}

pub(super) fn fig24_findings(r: &Results, out: &mut Vec<Finding>) {
    // The two groups: robots that never pass the corner (carrying to it) and robots that place
    // modules past it (assembling).
    let mut text = Vec::new();
    let mut verdict = Verdict::Differs;
    for (shape, reading) in SHAPES {
        let never = fig24(r, shape, "discrete", "relay", "never_past_corner");
        let never_token = fig24(r, shape, "discrete", "token", "never_past_corner");
        let assemblers = fig24(r, shape, "discrete", "relay", "corner_assemblers");
        let o = Ordering::new(&never, &never_token, false, Size::Large);
        // A set is a group of robots: two of the ten at least.
        let both = (0..never.len())
            .filter(|&i| never[i] >= 0.2 && assemblers[i] >= 0.2)
            .count();
        if shape == "amas-L" {
            verdict = weakest([o.verdict(), Verdict::of_most(both, never.len())]);
        }
        let relays = Stats::of(&fig24(r, shape, "discrete", "relay", "relays"));
        let corner = Stats::of(&fig24(r, shape, "discrete", "relay", "corner_relays"));
        text.push(format!(
            "{reading}: share of robots that never pass the corner, with relay {}, with tokens \
             {:.2} ({}); share that place modules at the corner row or above, with relay {:.2}; \
             both sets of two robots or more in {both} of {} runs; relays per run {:.1}, of \
             them at the corner {:.1}",
            Stats::of(&never).describe(2),
            Stats::of(&never_token).mean,
            o.describe(),
            Stats::of(&assemblers).mean,
            never.len(),
            relays.mean,
            corner.mean
        ));
    }
    out.push(Finding::new(
        "§5.2, fig. 24",
        "With the discrete field and module relay, robots are spontaneously grouped into two \
         sets: the first carries modules to the corner, the second assembles the modules \
         received from the first.",
        format!("L, 10 robots, discrete field — {}", text.join(". L ")),
        80,
        verdict,
        "The first set are the robots that never pass the corner (they hand their modules over \
         below it), the second those that place modules at the corner row or above. Holds if, \
         on the L standing on its stem, relay leaves more robots below the corner than tokens \
         do (where every robot carries its modules all the way) by a significant, large \
         effect, and in most runs each set holds at least two of the ten robots. A relay is at \
         the corner when the handing robot stands on the row where the L changes width or the \
         row below it.",
    ));
    let mut text = Vec::new();
    let mut verdicts = Vec::new();
    for (shape, reading) in SHAPES {
        for (field, _) in FIELDS {
            let relay = fig24(r, shape, field, "relay", "collisions");
            let token = fig24(r, shape, field, "token", "collisions");
            let o = Ordering::new(&relay, &token, true, Size::Large);
            if shape == "amas-L" {
                verdicts.push(o.verdict());
            }
            text.push(format!(
                "{reading}, {field}: relay {}, token {} ({})",
                Stats::of(&relay).short(0),
                Stats::of(&token).short(0),
                o.describe()
            ));
        }
    }
    out.push(Finding::new(
        "§5.2, fig. 24",
        "By dividing the labour, the frequency of collisions is decreased because the robots do \
         not need to go through the corner.",
        format!(
            "collisions per run, L, 10 robots (mean ± sd): {}",
            text.join("; ")
        ),
        160,
        weakest(verdicts),
        "Holds if, on the L standing on its stem, relay has fewer collisions than tokens with \
         both fields by a significant, large effect.",
    ));
    loaded_unloaded(r, out);
}

/// Appendix A.1: collisions between a loaded and an unloaded robot are the most common.
fn loaded_unloaded(r: &Results, out: &mut Vec<Finding>) {
    let mut text = Vec::new();
    let (mut most, mut runs) = (0, 0);
    for shape in ["L", "T"] {
        for (field, _) in FIELDS {
            let v = |metric| fig23_values(r, "amas-fig23", shape, field, "token", 10, metric);
            let (all, mixed, loaded, unloaded) = (
                v("collisions"),
                v("mixed_collisions"),
                v("loaded_collisions"),
                v("unloaded_collisions"),
            );
            most += (0..all.len())
                .filter(|&i| mixed[i] > loaded[i] && mixed[i] > unloaded[i])
                .count();
            runs += all.len();
            let share = |xs: &[f64]| 100.0 * xs.iter().sum::<f64>() / all.iter().sum::<f64>();
            text.push(format!(
                "{shape} {field}: {:.0} per run, loaded with unloaded {:.0} %, both loaded \
                 {:.0} %, both unloaded {:.0} %",
                Stats::of(&all).mean,
                share(&mixed),
                share(&loaded),
                share(&unloaded)
            ));
        }
    }
    out.push(Finding::new(
        "App. A.1",
        "Collisions between a loaded robot (with a module) and an unloaded robot (without the \
         module) are most commonly observed in the simulation; module relay solves them.",
        format!(
            "collisions by the loads of the two robots, 10 robots, token rule, the shapes on \
             their stems: {}; the loaded-unloaded kind is the most common in {most} of {runs} \
             runs",
            text.join("; ")
        ),
        runs,
        Verdict::of_most(most, runs),
        "A collision's two robots are the one that waits and the one in its way (the robot on \
         the module it wanted, or the robot that claimed the cell first), with the loads they \
         had when they planned (metrics mixed_collisions, loaded_collisions, \
         unloaded_collisions). Holds if in most runs the loaded-unloaded kind outnumbers each \
         of the other two. Relay turns these meetings into hand-overs (previous rows).",
    ));
}
