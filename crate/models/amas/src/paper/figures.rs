//! Figure 23: the shapes, the fields, the collision rules and the number of robots, in both
//! readings of figure 22 (the verdicts read the primary one, the shapes on their stems).

use super::*;

const RULES: [&str; 3] = ["token", "relay", "blackboard"];
const PRIMARY: &str = "amas-fig23";
const FOOT: &str = "amas-fig23-foot";

/// "L continuous: 3129 ± 143 against 2010 ± 49 (d 9.1, r 1.00, p = 1.1e-05)".
fn versus(label: &str, a: &[f64], b: &[f64], o: &Ordering) -> String {
    let c = o.comparison;
    let effect = c.map_or("nothing to compare".into(), |c| {
        format!(
            "d {:.1}, r {:.2}, p = {}",
            c.cohens_d,
            c.rank_biserial,
            kumiki_model::report::p_value(c.p)
        )
    });
    format!(
        "{label}: {} against {} ({effect})",
        Stats::of(a).short(0),
        Stats::of(b).short(0)
    )
}

pub(super) fn fig23_findings(r: &Results, out: &mut Vec<Finding>) {
    suffers(r, out);
    fields(r, out);
    corners(r, out);
    bottleneck(r, out);
    rules(r, out);
    best(r, out);
}

/// The L's efficiency suffers as robots are added.
fn suffers(r: &Results, out: &mut Vec<Finding>) {
    let mut text = Vec::new();
    let mut verdicts = Vec::new();
    for (experiment, reading) in READINGS {
        let mut parts = Vec::new();
        for (field, _) in FIELDS {
            let v =
                |robots| fig23_values(r, experiment, "L", field, "token", robots, "total_steps");
            let (ten, one) = (v(10), v(1));
            let o = Ordering::new(&ten, &one, false, Size::Large);
            if experiment == PRIMARY {
                verdicts.push(o.verdict());
            }
            parts.push(versus(&format!("{field}, 10 robots"), &ten, &one, &o));
        }
        text.push(format!("{reading}: {}", parts.join("; ")));
    }
    out.push(Finding::new(
        "§5.2, fig. 23",
        "When assembling the L-shaped structure, the efficiency suffers as the number of robots \
         is increased because of collisions.",
        format!(
            "total steps of the L, token rule, 10 robots against 1 (mean ± sd; Cohen's d, \
             rank-biserial r, Mann-Whitney p), the shapes {}",
            text.join("; the shapes ")
        ),
        80,
        weakest(verdicts),
        "Total steps (steps × robots). Holds if 10 robots take more total steps than 1 with both \
         fields, by a significant, large effect (|d| ≥ 0.8, |r| ≥ 0.5), on the L standing on \
         its stem (figure 22 read so that the traffic turns the corner, \
         crate/models/amas/README.md interpretation 29); the L on its foot is shown beside it.",
    ));
}

/// Continuous against discrete at high density, on the L.
fn fields(r: &Results, out: &mut Vec<Finding>) {
    let mut text = Vec::new();
    let mut verdict = Verdict::Differs;
    for (experiment, reading) in READINGS {
        let v = |field, rule, robots| {
            fig23_values(r, experiment, "L", field, rule, robots, "total_steps")
        };
        let mut parts = Vec::new();
        for rule in RULES {
            let (c, d) = (v("continuous", rule, 10), v("discrete", rule, 10));
            let o = Ordering::new(&c, &d, true, Size::Any);
            if experiment == PRIMARY && rule == "token" {
                verdict = o.verdict();
            }
            parts.push(versus(&format!("{rule}, continuous"), &c, &d, &o));
        }
        let one = |field| Stats::of(&v(field, "token", 1)).short(0);
        let collisions = |field| fig23(r, experiment, "L", field, "token", 10, "collisions").mean;
        text.push(format!(
            "{reading}, 10 robots, continuous against discrete — {}; 1 robot, token: continuous \
             {}, discrete {}; collisions at 10 robots, token: continuous {:.0}, discrete {:.0}",
            parts.join("; "),
            one("continuous"),
            one("discrete"),
            collisions("continuous"),
            collisions("discrete"),
        ));
    }
    out.push(Finding::new(
        "§5.2, fig. 23",
        "The continuous field is better than the discrete field at high robot densities: the \
         discrete field makes only the shortest paths, so all of the robots' paths are \
         concentrated in the corner of the L.",
        format!(
            "total steps of the L, the shapes {}",
            text.join(". The shapes ")
        ),
        240,
        verdict,
        "5.2 compares the two fields first and the collision rules next, so the fields are \
         compared under the plain token rule of 4.6: holds if, at 10 robots, the continuous \
         field takes fewer total steps than the discrete one, significantly, on the L standing \
         on its stem. The other rules and the L on its foot are shown beside it; with one robot \
         the discrete field's shortest paths should be ahead.",
    ));
}

/// The T (two corners) against the L (one): fewer collisions.
fn corners(r: &Results, out: &mut Vec<Finding>) {
    let mut text = Vec::new();
    let mut verdicts = Vec::new();
    for (experiment, reading) in READINGS {
        let mut parts = Vec::new();
        for (field, _) in FIELDS {
            let v = |shape| fig23_values(r, experiment, shape, field, "token", 10, "collisions");
            let (t, l) = (v("T"), v("L"));
            let o = Ordering::new(&t, &l, true, Size::Large);
            if experiment == PRIMARY {
                verdicts.push(o.verdict());
            }
            let corner = |shape| {
                fig23(
                    r,
                    experiment,
                    shape,
                    field,
                    "token",
                    10,
                    "corner_collisions",
                )
                .mean
            };
            parts.push(format!(
                "{}; on the corner rows T {:.1}, L {:.1}",
                versus(&format!("{field}, T"), &t, &l, &o),
                corner("T"),
                corner("L")
            ));
        }
        text.push(format!("{reading}: {}", parts.join("; ")));
    }
    out.push(Finding::new(
        "§5.2, fig. 23",
        "The T-shaped structure has two corners, the L-shaped structure one: the T suffers \
         fewer collisions.",
        format!(
            "collisions per run, 10 robots, token rule, T against L, the shapes {}",
            text.join(". The shapes ")
        ),
        80,
        weakest(verdicts),
        "Figure 22's shapes are not in the text: the L and the T have the same rows (88 modules, \
         strokes 4 wide, a bar of 14×4 and a stem 4 wide and 8 tall) and the same footnote-2 \
         bound. Standing on their stems (the primary reading), every module of the top is \
         carried up the stem and round one corner (L) or split between two (T): the argument \
         that two corners share the traffic one corner takes implies a large effect, so the \
         claim holds if the T has fewer collisions with both fields by a significant, large \
         effect. On their foot the stem's modules rise straight up and no path turns a corner \
         (interpretation 29).",
    ));
}

/// Where the collisions happen: the corner rows against the rest, per cell.
fn bottleneck(r: &Results, out: &mut Vec<Finding>) {
    // Cells of the L on its stem in each zone: the corner rows (row 3 of the bar, 14 cells, and
    // the stem's top row, 4), the bar above them (3 rows of 14), the stem below them (7 rows of
    // 4) and the supply row (14).
    let zones = [
        ("corner rows", 18.0),
        ("above", 42.0),
        ("below", 28.0),
        ("supply row", 14.0),
    ];
    let mut text = Vec::new();
    let mut verdicts = Vec::new();
    for (field, _) in FIELDS {
        let v = |metric| fig23_values(r, PRIMARY, "L", field, "token", 10, metric);
        let (all, corner, above, supply) = (
            v("collisions"),
            v("corner_collisions"),
            v("above_corner_collisions"),
            v("supply_collisions"),
        );
        let below: Vec<f64> = (0..all.len())
            .map(|i| all[i] - corner[i] - above[i] - supply[i])
            .collect();
        let per_cell = |xs: &[f64], cells: f64| xs.iter().map(|x| x / cells).collect::<Vec<_>>();
        let density = [
            per_cell(&corner, zones[0].1),
            per_cell(&above, zones[1].1),
            per_cell(&below, zones[2].1),
            per_cell(&supply, zones[3].1),
        ];
        let mut parts = Vec::new();
        for (k, (zone, _)) in zones.iter().enumerate() {
            parts.push(format!("{zone} {:.2}", Stats::of(&density[k]).mean));
            if k > 0 {
                verdicts
                    .push(Ordering::new(&density[0], &density[k], false, Size::Large).verdict());
            }
        }
        text.push(format!(
            "{field}: {:.1} collisions per run; per cell, {}",
            Stats::of(&all).mean,
            parts.join(", ")
        ));
    }
    let foot = |field| {
        let m = |metric| fig23(r, FOOT, "L", field, "token", 10, metric).mean;
        format!(
            "{field} {:.0} % of {:.1}",
            100.0 * m("corner_collisions") / m("collisions"),
            m("collisions")
        )
    };
    out.push(Finding::new(
        "§5.2, fig. 23",
        "Paths at the corner become the bottleneck in the L-shaped structure.",
        format!(
            "collisions on the L standing on its stem, 10 robots, token rule (mean per run over \
             10 runs), by zone: {}. On the L on its foot the corner rows take {} (share of the \
             run's collisions)",
            text.join("; "),
            [foot("continuous"), foot("discrete")].join(", ")
        ),
        40,
        weakest(verdicts),
        "Each collision is recorded at the cell the waiting robot wanted (the page's collision \
         heat map). A bottleneck is where the robots crowd most: the zones hold different \
         numbers of cells, so they are compared per cell. The corner rows are the row where the \
         shape changes width and the row below it. Holds if, on the L standing on its stem, the \
         corner rows see more collisions per cell than the bar above them, the stem below them \
         and the supply row, each by a significant, large effect, with both fields.",
    ));
}

/// Module relay prevents chains of collisions, the blackboard does not.
fn rules(r: &Results, out: &mut Vec<Finding>) {
    let mut text = Vec::new();
    let mut verdicts = Vec::new();
    let mut reduced = Vec::new();
    let mut fewer = Vec::new();
    for (experiment, reading) in READINGS {
        for shape in ["L", "T"] {
            for (field, _) in FIELDS {
                let v = |rule, metric| fig23_values(r, experiment, shape, field, rule, 10, metric);
                let relay = v("relay", "total_steps");
                let mut parts = Vec::new();
                for other in ["blackboard", "token"] {
                    let o = Ordering::new(&relay, &v(other, "total_steps"), true, Size::Any);
                    if experiment == PRIMARY {
                        verdicts.push(o.verdict());
                    }
                    parts.push(format!(
                        "{other} {}",
                        Stats::of(&v(other, "total_steps")).short(0)
                    ));
                }
                text.push(format!(
                    "{shape} {field} {reading}: relay {}, {}",
                    Stats::of(&relay).short(0),
                    parts.join(", ")
                ));
                let token = v("token", "collisions");
                for rule in ["relay", "blackboard"] {
                    let o = Ordering::new(&v(rule, "collisions"), &token, true, Size::Large);
                    if experiment == PRIMARY {
                        reduced.push(o.verdict());
                    }
                }
                if experiment == PRIMARY {
                    fewer.push(format!(
                        "{shape} {field}: token {:.0}, relay {:.0}, blackboard {:.0}",
                        Stats::of(&token).mean,
                        Stats::of(&v("relay", "collisions")).mean,
                        Stats::of(&v("blackboard", "collisions")).mean
                    ));
                }
            }
        }
    }
    out.push(Finding::new(
        "§5.2, fig. 23",
        "Module relay prevents a chain of collisions while blackboard planning does not.",
        format!("total steps at 10 robots (mean ± sd): {}", text.join("; ")),
        240,
        weakest(verdicts),
        "Holds if relay takes fewer total steps than both the blackboard and the token rule at \
         10 robots, significantly, in all four panels of the shapes on their stems; the shapes \
         on their foot are shown beside them.",
    ));
    out.push(Finding::new(
        "§5.2, fig. 23",
        "In both target structures, the collision avoidance rules effectively reduced \
         collisions.",
        format!(
            "collisions per run at 10 robots, the shapes on their stems: {}",
            fewer.join("; ")
        ),
        120,
        weakest(reduced),
        "Holds if, on the L and on the T with both fields, module relay and the blackboard each \
         have fewer collisions than the token rule by a significant, large effect \
         ('effectively'). The blackboard records none: a robot that finds its way engaged \
         avoids instead (interpretation 11).",
    ));
}

/// The discrete field with module relay gives the best performance.
fn best(r: &Results, out: &mut Vec<Finding>) {
    let mut text = Vec::new();
    let mut verdicts = Vec::new();
    for (experiment, reading) in READINGS {
        for shape in ["L", "T"] {
            let v =
                |field, rule| fig23_values(r, experiment, shape, field, rule, 10, "total_steps");
            let best = v("discrete", "relay");
            let mut others = Vec::new();
            for (field, _) in FIELDS {
                for rule in RULES {
                    if (field, rule) == ("discrete", "relay") {
                        continue;
                    }
                    let o = Ordering::new(&best, &v(field, rule), true, Size::Any);
                    if experiment == PRIMARY {
                        verdicts.push(o.verdict());
                    }
                    others.push(format!(
                        "{field} {rule} {:.0}",
                        Stats::of(&v(field, rule)).mean
                    ));
                }
            }
            text.push(format!(
                "{shape} {reading}: discrete with relay {}; {}",
                Stats::of(&best).short(0),
                others.join(", ")
            ));
        }
    }
    out.push(Finding::new(
        "§5.2, fig. 23",
        "The best performance is given by the combination of a discrete field and module relay.",
        format!("total steps at 10 robots (mean): {}", text.join("; ")),
        240,
        weakest(verdicts),
        "Holds if, on the L and on the T standing on their stems, the discrete field with \
         module relay takes fewer total steps at 10 robots than each of the five other \
         combinations of field and rule, significantly.",
    ));
}
