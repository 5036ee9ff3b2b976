//! Figures 23 and 24: the shapes, the fields, the collision rules and the number of robots.

use super::*;

pub(super) fn fig23_findings(r: &Results, out: &mut Vec<Finding>) {
    // The L's efficiency suffers as robots are added.
    let mut text = Vec::new();
    let mut ok = true;
    for (field, name) in FIELDS {
        let one = fig23(r, "L", field, "token", 1, "total_steps");
        let ten = fig23(r, "L", field, "token", 10, "total_steps");
        ok &= ten.mean > one.mean;
        text.push(format!(
            "{name}: 1 robot {}; 10 robots {}",
            one.describe(0),
            ten.describe(0)
        ));
    }
    out.push(Finding::new(
        "§5.2, fig. 23",
        "When assembling the L-shaped structure, the efficiency suffers as the number of robots \
         is increased because of collisions.",
        text.join("; "),
        40,
        Verdict::from(ok),
        "Total steps (steps × robots) of the L, token rule; holds if 10 robots take more total \
         steps than 1 with both fields.",
    ));

    // Continuous against discrete at high density, on the L.
    let mut text = Vec::new();
    let mut better = 0;
    for rule in ["token", "relay", "blackboard"] {
        let c = fig23(r, "L", "continuous", rule, 10, "total_steps");
        let d = fig23(r, "L", "discrete", rule, 10, "total_steps");
        if c.mean < d.mean {
            better += 1;
        }
        text.push(format!(
            "{rule}: continuous {}, discrete {}",
            c.short(0),
            d.short(0)
        ));
    }
    let grow = |field: &str| {
        let one = fig23(r, "L", field, "token", 1, "total_steps").mean;
        let ten = fig23(r, "L", field, "token", 10, "total_steps").mean;
        100.0 * (ten / one - 1.0)
    };
    let collisions = |field: &str| fig23(r, "L", field, "token", 10, "collisions").mean;
    let corner = |field: &str, rule: &str, robots: u32, metric: &str| {
        r.stats(
            "amas-fig23-corner",
            &[
                ("field", json!(field)),
                ("collision", json!(rule)),
                ("robots", json!(robots)),
            ],
            metric,
        )
    };
    let turned: Vec<String> = ["token", "relay", "blackboard"]
        .iter()
        .map(|rule| {
            format!(
                "{rule}: continuous {}, discrete {}",
                corner("continuous", rule, 10, "total_steps").short(0),
                corner("discrete", rule, 10, "total_steps").short(0)
            )
        })
        .collect();
    out.push(Finding::new(
        "§5.2, fig. 23",
        "The continuous field is better than the discrete field at high robot densities (the \
         discrete field concentrates every path at the corner of the L).",
        format!(
            "L, 10 robots, total steps (mean ± sd, 10 runs each): {}. From 1 to 10 robots the \
             token total grows {:.0} % with the continuous field and {:.0} % with the discrete; \
             collisions at 10 robots, token: continuous {:.0}, discrete {:.0}. The L turned \
             upside down (amas-fig23-corner: stem on the supply, arm at the top), 10 robots: {}; \
             1 robot: continuous {:.0}, discrete {:.0}.",
            text.join("; "),
            grow("continuous"),
            grow("discrete"),
            collisions("continuous"),
            collisions("discrete"),
            turned.join("; "),
            corner("continuous", "token", 1, "total_steps").mean,
            corner("discrete", "token", 1, "total_steps").mean,
        ),
        60 + r.rows("amas-fig23-corner").len(),
        Verdict::from(better == 3),
        "Holds if the continuous field takes fewer total steps than the discrete one at 10 robots \
         under all three rules, on figure 23's L. Figure 22's L is not in the text: \
         amas-fig23-corner builds the same 88 modules upside down, so that every module of the \
         arm is carried round the inner corner, where 5.2 and figure 20 put the discrete \
         field's paths. The field's update rate and the number of robots (up to the 14 the \
         supply holds) were checked too (crate/models/amas/README.md, interpretation 27).",
    ));

    // The T (two corners) against the L (one).
    let mut text = Vec::new();
    let mut corners = Vec::new();
    let mut ok = true;
    for (field, name) in FIELDS {
        let l = fig23(r, "L", field, "token", 10, "collisions");
        let t = fig23(r, "T", field, "token", 10, "collisions");
        ok &= t.mean < l.mean;
        text.push(format!("{name}: T {}, L {}", t.describe(0), l.describe(0)));
        let corner = |shape: &str| fig23(r, shape, field, "token", 10, "corner_collisions").mean;
        corners.push(format!(
            "{name} T {:.1} ({:.0} %), L {:.1} ({:.0} %)",
            corner("T"),
            100.0 * corner("T") / t.mean,
            corner("L"),
            100.0 * corner("L") / l.mean
        ));
    }
    out.push(Finding::new(
        "§5.2, fig. 23",
        "The T-shaped structure has two corners, the L-shaped structure one: the T suffers \
         fewer collisions.",
        format!(
            "collisions per run, 10 robots, token rule: {}. On the two corner rows (mean per \
             run, share of the shape's collisions): {}",
            text.join("; "),
            corners.join("; ")
        ),
        40,
        Verdict::from(ok),
        "Figure 22's shapes are not in the text: the L and the T have the same rows (a foot of \
         14×4 on the supply, a stem 4 wide and 8 tall, 88 modules); the L's stem stands at the \
         edge, the T's in the middle, so robots pass one corner or two.",
    ));

    let turned = |experiment: &str, field: &str, metric: &str| {
        let mut sel = vec![("field", json!(field))];
        if experiment == "amas-fig23-corner" {
            sel.push(("collision", json!("token")));
            sel.push(("robots", json!(10)));
        }
        r.stats(experiment, &sel, metric)
    };

    // The same comparison with both shapes upside down: figure 22's orientation is not in the
    // text, so the other one is reported beside it.
    let mut text = Vec::new();
    let mut corners = Vec::new();
    let mut ok = true;
    for (field, name) in FIELDS {
        let l = turned("amas-fig23-corner", field, "collisions");
        let t = turned("amas-fig23-turned", field, "collisions");
        ok &= t.mean < l.mean;
        text.push(format!("{name}: T {}, L {}", t.describe(0), l.describe(0)));
        let tc = turned("amas-fig23-turned", field, "corner_collisions").mean;
        let lc = turned("amas-fig23-corner", field, "corner_collisions").mean;
        corners.push(format!(
            "{name} T {tc:.1} ({:.0} %), L {lc:.1} ({:.0} %)",
            100.0 * tc / t.mean,
            100.0 * lc / l.mean
        ));
    }
    out.push(Finding::new(
        "§5.2, fig. 23",
        "The T-shaped structure has two corners, the L-shaped structure one: the T suffers \
         fewer collisions (both shapes upside down).",
        format!(
            "collisions per run, 10 robots, token rule, stems on the supply: {}. On the two \
             corner rows (mean per run, share of the shape's collisions): {}",
            text.join("; "),
            corners.join("; ")
        ),
        r.rows("amas-fig23-turned").len() + 20,
        Verdict::from(ok),
        "The same 88 modules with the stem on the supply and the foot (the T's crossbar) on top \
         (amas-fig23-corner, amas-fig23-turned): every module of the top is carried up the stem \
         and round one corner (L) or split between two (T). 5.2's words ('all of the robots \
         paths are concentrated in the corner', robots that 'need to go through the corner') \
         fit this orientation better than the upright one, where modules rise straight up \
         from the supply beneath them, but the text does not give figure 22's drawing, so both \
         are reported (crate/models/amas/README.md, interpretation 29).",
    ));

    // Where the collisions happen (the heat map's zones): the corner rows against the rest.
    let mut text = Vec::new();
    let mut ok = true;
    let turned =
        |experiment: &str, field: &str, metric: &str| turned(experiment, field, metric).mean;
    for (field, _) in FIELDS {
        for shape in ["L", "T", "L upside down", "T upside down"] {
            let m = |metric: &str| match shape {
                "L upside down" => turned("amas-fig23-corner", field, metric),
                "T upside down" => turned("amas-fig23-turned", field, metric),
                _ => fig23(r, shape, field, "token", 10, metric).mean,
            };
            let all = m("collisions");
            let corner = m("corner_collisions");
            let above = m("above_corner_collisions");
            let supply = m("supply_collisions");
            let foot = all - corner - above - supply;
            if shape == "L" {
                ok &= corner > above && corner > foot && corner > supply;
            }
            let pct = |v: f64| 100.0 * v / all;
            text.push(format!(
                "{shape} {field}: {all:.1} per run, corner rows {corner:.1} ({:.0} %), above \
                 them {above:.1} ({:.0} %), below them {foot:.1} ({:.0} %), supply row \
                 {supply:.1} ({:.0} %)",
                pct(corner),
                pct(above),
                pct(foot),
                pct(supply)
            ));
        }
    }
    out.push(Finding::new(
        "§5.2, fig. 23",
        "Paths at the corner become the bottleneck in the L-shaped structure.",
        format!(
            "where the collisions happen, 10 robots, token rule (mean per run over 10 runs): {}",
            text.join("; ")
        ),
        40 + 10 * 2 + r.rows("amas-fig23-turned").len(),
        Verdict::from(ok),
        "Each collision is recorded at the cell the waiting robot wanted (the page's collision \
         heat map). The corner rows are the two rows where the shape turns: the lowest row whose \
         width differs from the row below, and that row below (2 of the 12 rows). Holds if, on \
         the L standing on its foot (figure 23's L), these two rows see more collisions than the \
         rows above them, the rows below them and the supply row, each taken together, with \
         both fields. The T, and both shapes upside down (stem on the supply: every module of \
         the top is carried up the stem and round the corner), are shown beside it; where the \
         rest of the collisions happen is discussed in crate/models/amas/README.md, interpretation 29.",
    ));

    // Module relay prevents chains of collisions, the blackboard does not.
    let mut text = Vec::new();
    let mut ok = true;
    for shape in ["L", "T"] {
        for (field, _) in FIELDS {
            let relay = fig23(r, shape, field, "relay", 10, "total_steps");
            let board = fig23(r, shape, field, "blackboard", 10, "total_steps");
            let token = fig23(r, shape, field, "token", 10, "total_steps");
            ok &= relay.mean < board.mean && relay.mean < token.mean;
            text.push(format!(
                "{shape} {field}: relay {}, blackboard {}, token {}",
                relay.short(0),
                board.short(0),
                token.short(0)
            ));
        }
    }
    out.push(Finding::new(
        "§5.2, fig. 23",
        "Module relay prevents a chain of collisions while blackboard planning does not.",
        format!("total steps at 10 robots (mean ± sd): {}", text.join("; ")),
        120,
        Verdict::from(ok),
        "Holds if relay takes the fewest total steps of the three rules at 10 robots in all four \
         panels.",
    ));
}

pub(super) fn fig24_findings(r: &Results, out: &mut Vec<Finding>) {
    let sel = |field: &str, rule: &str| -> Vec<(&'static str, Value)> {
        vec![("field", json!(field)), ("collision", json!(rule))]
    };
    let d_relay = sel("discrete", "relay");
    let corner = r.stats("amas-fig24", &d_relay, "corner_relays");
    let relays = r.stats("amas-fig24", &d_relay, "relays");
    let never = r.stats("amas-fig24", &d_relay, "never_past_corner");
    let assemblers = r.stats("amas-fig24", &d_relay, "corner_assemblers");
    let token_assemblers = r.stats("amas-fig24", &sel("discrete", "token"), "corner_assemblers");
    out.push(Finding::new(
        "§5.2, fig. 24",
        "With the discrete field and module relay, robots are spontaneously grouped into two \
         sets: the first carries modules to the corner, the second assembles the modules \
         received from the first.",
        format!(
            "L, 10 robots, discrete field: share of robots that place modules at the corner row \
             or above, with relay {}, with tokens {}; relays per run {}, of them at the corner \
             {}; share of robots that never pass the corner {}",
            assemblers.describe(2),
            token_assemblers.describe(2),
            relays.describe(1),
            corner.describe(1),
            never.describe(2)
        ),
        assemblers.n + token_assemblers.n,
        Verdict::from(assemblers.mean < token_assemblers.mean),
        "Holds if, with relay, a smaller share of the robots assembles past the corner than with \
         tokens (where every robot does). A relay is at the corner when the handing robot stands \
         on the row where the L narrows or the row below it. The grouping is partial: most \
         robots still place some stem modules, and nearly every robot passes the corner at some \
         time, since everyone builds the foot first.",
    ));
    let mut text = Vec::new();
    let mut ok = true;
    for (field, _) in FIELDS {
        let token = r.stats("amas-fig24", &sel(field, "token"), "collisions");
        let relay = r.stats("amas-fig24", &sel(field, "relay"), "collisions");
        ok &= relay.mean < token.mean;
        text.push(format!(
            "{field}: relay {}, token {}",
            relay.describe(0),
            token.describe(0)
        ));
    }
    out.push(Finding::new(
        "§5.2, fig. 24",
        "By dividing the labour, the frequency of collisions is decreased because the robots do \
         not need to go through the corner.",
        format!("collisions per run, L, 10 robots: {}", text.join("; ")),
        80,
        Verdict::from(ok),
        "",
    ));
}
