//! Loads, the move tool, the slot trace and the switch to adaptation under overload.

use super::*;

#[test]
fn loads_are_checked_and_stay_with_their_robot() {
    let mut m = model(
        "....\n###.\n=...\n",
        json!({"task": "bridge", "construction": false}),
    );
    let load = |cells: serde_json::Value, force: f64| {
        json!({"kind": "load", "cells": cells, "force": force})
            .as_object()
            .unwrap()
            .clone()
    };
    assert!(m
        .check_action(&load(json!([6]), -1.0))
        .unwrap_err()
        .to_string()
        .starts_with("force:"));
    // The form is checked whatever the state (a recorded click must read as valid from step
    // 0); the cell is checked when the action is applied.
    assert!(m.check_action(&load(json!([0]), 10.0)).is_ok());
    assert_eq!(
        m.apply(&load(json!([0]), 10.0)).unwrap_err().to_string(),
        "cells[0]: cell 0 holds no robot"
    );
    let before = m.peak();
    m.apply(&load(json!([6]), 50.0)).unwrap();
    assert!(m.peak() > before);
    m.apply(&load(json!([6]), 0.0)).unwrap();
    assert!((m.peak() - before).abs() < 1e-9 * before);
}

#[test]
fn the_move_tool_lifts_a_load_and_puts_it_down_and_unload_takes_it_off() {
    let mut m = model(
        "....\n###.\n=...\n",
        json!({"task": "bridge", "construction": false}),
    );
    let act = |v: serde_json::Value| v.as_object().unwrap().clone();
    let bare = m.peak();
    m.apply(&act(json!({"kind": "load", "cells": [5], "force": 40.0})))
        .unwrap();
    let near = m.peak();
    assert_eq!(
        m.apply(&act(json!({"kind": "move", "cells": [6]})))
            .unwrap_err()
            .to_string(),
        "cells[0]: the robot at cell 6 carries no load to move"
    );
    m.apply(&act(json!({"kind": "move", "cells": [5]})))
        .unwrap();
    assert_eq!(m.held, 40.0);
    assert!((m.peak() - bare).abs() < 1e-9 * bare);
    m.apply(&act(json!({"kind": "move", "cells": [6]})))
        .unwrap();
    assert_eq!((m.held, m.loads[1], m.loads[2]), (0.0, 0.0, 40.0));
    // Further out on the cantilever, the same load stresses the root more.
    assert!(m.peak() > near);
    m.apply(&act(json!({"kind": "unload", "cells": [6]})))
        .unwrap();
    assert!((m.peak() - bare).abs() < 1e-9 * bare);
}

#[test]
fn the_slot_trace_names_every_slot_and_its_senders() {
    let preset = kumiki_core::presets::scenario("chobie-crawl5").unwrap();
    let mut m = Chobie::new(&preset).unwrap();
    step_checked(&mut m);
    let trace = &m.last.trace;
    assert_eq!(
        trace.iter().map(|s| s.count).sum::<u64>(),
        m.last.slots,
        "one entry per slot"
    );
    let meanings: Vec<&str> = trace.iter().map(|s| s.meaning).collect();
    assert_eq!(meanings[0], election::RULE_1);
    assert_eq!(meanings[1], election::RULE_2);
    for word in ["announcement", "route", "drive", "direction", "completion"] {
        assert!(
            meanings.iter().any(|m| m.contains(word)),
            "{word} in {meanings:?}"
        );
    }
    // Rule 1: every robot lights each face it shares; rule 2: only the robots with no
    // vertical neighbour send, and only left or right.
    assert_eq!(trace[0].senders.len(), m.body.len());
    assert!(trace[1]
        .senders
        .iter()
        .all(|&(_, faces)| faces != 0 && faces & (1 << UP | 1 << DOWN) == 0));
    let messages: u64 = trace
        .iter()
        .flat_map(|s| &s.senders)
        .map(|&(_, f)| f.count_ones() as u64)
        .sum();
    assert!(messages <= m.last.messages);
}

#[test]
fn an_overload_switches_to_adaptation_and_back_once_the_reserves_thicken_the_root() {
    // The preset: three reserves to a goal of 14 cells.
    let preset = kumiki_core::presets::scenario("chobie-bridge").unwrap();
    let mut m = Chobie::new(&preset).unwrap();
    let mut modes = Vec::new();
    while !m.completed() && m.steps < preset.max_steps {
        step_checked(&mut m);
        modes.push(m.mode);
    }
    assert!(m.completed(), "the bridge reaches 14 cells");
    assert_eq!((m.span(), m.reserves()), (14, 0));
    assert!(m.peak() < m.p.mech.threshold, "no robot overloaded");
    // Three overloads (at 12, 13 and 14 cells), each cleared: two resumed construction, and the
    // last one's clearing completed the bridge. The first was cleared by the reserves standing
    // on the root, the two others by step 7, once and twice: each reserve went into the tier.
    let switches = modes
        .windows(2)
        .filter(|w| w[0] == Mode::Construction && w[1] == Mode::Adaptation)
        .count();
    assert_eq!((switches, m.resumed), (3, 2));
    assert_eq!(m.totals.reinforcements, 3);
    let mut without = Chobie::new(&preset).unwrap();
    without.p.adaptation = false;
    while !without.completed() {
        step_checked(&mut without);
    }
    assert_eq!(without.span(), 14);
    assert!(m.worst < without.worst && without.peak() > without.p.mech.threshold);
    // A goal of 15 cells is out of reach of three reserves.
    let mut further = Chobie::new(&preset).unwrap();
    further.p.goal = Some(15);
    for _ in 0..preset.max_steps {
        step_checked(&mut further);
    }
    assert!(!further.completed() && further.reserves() == 0);
    assert_eq!((further.span(), further.mode), (15, Mode::Adaptation));
}

#[test]
fn figure_14_step_7_thickens_the_root_and_lowers_b_stress() {
    let preset = kumiki_core::presets::scenario("chobie-load5").unwrap();
    let mut m = Chobie::new(&preset).unwrap();
    let act = json!({"kind": "load", "cells": [19], "force": 300.0});
    m.apply(act.as_object().unwrap()).unwrap();
    // B: the first robot over the void, next to the cliff edge.
    let b = m.body.robot_at(2, 2);
    let before = m.stress[b as usize];
    assert!(m.overloaded(before));
    let mut fired = false;
    for _ in 0..10 {
        step_checked(&mut m);
        fired |= m.last.moved && m.last.leaders.iter().any(|e| e.kind == Kind::Leader1);
    }
    assert!(fired, "leader 1's command (step 7) was carried out");
    // B went down against the cliff face under the root; robot A took its place in the tier.
    assert_eq!(m.body.pos[b as usize], (2, 3));
    assert_eq!(m.body.robot_at(2, 2), 0, "robot A");
    assert!(m.stress[b as usize] < before);
    assert!(m.peak() < m.p.mech.threshold, "the overload is removed");
    assert_eq!(m.mode, Mode::Construction);
}

#[test]
fn same_kind_leaders_move_together_when_only_their_joint_command_is_feasible() {
    let mut m = model("#.#....\n#######\n=======\n", json!({}));
    let leaders = election::three_rule(&m.body, &mut Comm::default());
    assert_eq!(leaders.len(), 2);
    assert!(leaders.iter().all(|e| e.kind == Kind::TopRight));
    step_checked(&mut m);
    assert_eq!(m.body.pos[0], (1, 0));
    assert_eq!(m.body.pos[1], (3, 0));
}

#[test]
fn an_unanchored_bridge_tips_over_the_cliff_edge_and_stops() {
    let world = "#...............\n########........\n========........\n";
    let mut m = model(
        world,
        json!({"task": "bridge", "adaptation": false, "anchored": false}),
    );
    let mut spans = Vec::new();
    for _ in 0..12 {
        m.step();
        spans.push(m.span());
    }
    // A tier of eight on an eight-cell base with a reserve riding on its left end: about the
    // edge's corner (x = 7.5) the weights' moment is 8(s − 4) + (s − 7.5) at span s, positive
    // from s = 5.
    assert_eq!(m.failure, Failure::Tipped);
    assert_eq!(m.span(), 5);
    assert!(m.overturning() > 0.0);
    assert!(spans.ends_with(&[5, 5]), "a tipped structure moves no more");
    assert!(m.cells().contains(&view::code::FAILED));
    // The same bridge on a base that holds it does not tip.
    let mut held = model(world, json!({"task": "bridge", "adaptation": false}));
    for _ in 0..12 {
        held.step();
    }
    assert_eq!(held.failure, Failure::Standing);
    assert!(held.span() > 5);
}

#[test]
fn a_robot_beyond_the_breaking_stress_breaks_the_structure() {
    let mut m = model(
        "....\n###.\n=...\n",
        json!({"task": "bridge", "construction": false}),
    );
    let load = json!({"kind": "load", "cells": [6], "force": 20000.0});
    m.apply(load.as_object().unwrap()).unwrap();
    assert!(m.peak() > m.p.mech.strength);
    assert_eq!(m.failure, Failure::Broken);
}

#[test]
fn figure_13_reserve_a_reaches_the_overloaded_root_and_step_7_makes_it_thick() {
    let preset = kumiki_core::presets::scenario("chobie-fig13").unwrap();
    let mut m = Chobie::new(&preset).unwrap();
    let a = m.body.robot_at(0, 1);
    let mut overloaded_before = false;
    let mut after_step7 = None;
    while !m.completed() && m.steps < 40 {
        overloaded_before |= m.totals.reinforcements == 0 && m.peak() > m.p.mech.threshold;
        step_checked(&mut m);
        if m.totals.reinforcements == 1 && after_step7.is_none() {
            after_step7 = Some((m.peak(), m.body.pos[a as usize], m.steps));
            // Robot A took B's place in the tier, and B is under it, against the cliff face.
            let under = m.body.robot_at(m.edge + 1, 3);
            assert_ne!(
                under,
                super::motion::NONE,
                "a robot under the root, beside the cliff"
            );
            assert_eq!(
                m.body.pos[a as usize],
                (m.edge + 1, 2),
                "robot A in the tier"
            );
        }
    }
    assert!(overloaded_before, "the load overloads the root first");
    let (peak, _, at) = after_step7.expect("step 7 fired");
    assert!(
        peak < m.p.mech.threshold,
        "the overload is gone after step 7"
    );
    assert_eq!(m.totals.reinforcements, 1, "step 7 fires once");
    // A crossed the top from the left end (leader 2, step 8) before step 7.
    assert!(m.totals.adaptations >= 2 && at > 2);
    assert_eq!(m.resumed, 1, "construction resumes");
    // The next cell of span, the goal of 10, overloads the new root again with no reserve left:
    // the bridge spans its goal but is not complete, and stalls in adaptation mode.
    assert_eq!((m.span(), m.reserves(), m.mode), (10, 0, Mode::Adaptation));
    assert!(m.peak() > m.p.mech.threshold && !m.last.moved);
    assert!(!m.completed(), "an overloaded bridge is not complete");
    // Without adaptation nobody checks the load: the same span completes it.
    let mut plain = Chobie::new(&preset).unwrap();
    plain.p.adaptation = false;
    while !plain.completed() && plain.steps < 40 {
        step_checked(&mut plain);
    }
    assert_eq!((plain.span(), plain.steps), (10, 6));
    assert!(plain.peak() > plain.p.mech.threshold);
}

/// The bridge world of `chobie-bridge` with `reserves` robots on the upper tier's left and
/// `depth` rows of terrain.
fn bridge_world(reserves: usize, depth: usize) -> String {
    let row = |robots: usize, terrain: char| {
        let mut r = String::new();
        for x in 0..48 {
            r.push(if x < robots { terrain } else { '.' });
        }
        r.push('\n');
        r
    };
    let mut w = row(0, '#') + row(reserves, '#').as_str() + row(20, '#').as_str();
    for _ in 0..depth {
        w += row(20, '=').as_str();
    }
    w
}

#[test]
fn a_robot_thick_already_is_not_leader_1_so_a_deep_cliff_costs_no_more_reserves() {
    // Each step 7 puts one reserve into the tier and one tier robot under it; with the tier two
    // deep there, the robot is not leader 1 again (its column would only push the robot under
    // it deeper, to the bottom of the world), and the reserves go on to the next cell.
    let mut runs = Vec::new();
    for depth in [2, 6] {
        let mut m = model(
            &bridge_world(5, depth),
            json!({"task": "bridge", "goal": 16, "max_steps": 120}),
        );
        while !m.completed() && m.steps < 120 {
            step_checked(&mut m);
            let tier = 2;
            assert!(
                m.body.pos.iter().all(|p| p.1 <= tier + 1),
                "depth {depth}: nothing goes more than one row under the tier"
            );
        }
        assert!(m.completed(), "depth {depth}: the bridge reaches 16 cells");
        runs.push((m.steps, m.totals.reinforcements, m.reserves()));
    }
    assert_eq!(runs[0], runs[1], "the cliff's depth changes nothing");
    assert_eq!(runs[0].1, 5, "one step 7 per reserve");
}

#[test]
fn a_bridge_stalled_with_reserves_left_is_overloaded_at_its_root_left_of_every_reserve() {
    // Nine reserves to a goal of 19 cells: the two-tier part grows under the tier, but the tie of
    // the root (the last tier robot on the flat part and the first over the void) overloads
    // before the goal, and leader 2 drives the reserves only right, away from it.
    for load in [0.0, 10.0, 20.0] {
        let mut m = model(
            &bridge_world(9, 2),
            json!({"task": "bridge", "goal": 19, "max_steps": 120, "tip_load": load}),
        );
        for _ in 0..120 {
            step_checked(&mut m);
        }
        assert!(!m.completed() && !m.last.moved && m.last.leaders.is_empty());
        assert_eq!(m.mode, Mode::Adaptation);
        assert!(m.reserves() > 0, "{load} N: reserves left");
        let tier = 2;
        let reserve_x = (0..m.body.len())
            .filter(|&r| m.body.pos[r].1 < tier)
            .map(|r| m.body.pos[r].0);
        let over: Vec<i32> = (0..m.body.len())
            .filter(|&r| m.overloaded(m.stress[r]))
            .map(|r| m.body.pos[r].0)
            .collect();
        assert_eq!(over, vec![m.edge, m.edge + 1], "{load} N: the root's tie");
        assert!(reserve_x.min().unwrap() > m.edge + 1, "{load} N");
    }
}

#[test]
fn the_reserves_count_the_robots_above_the_tier() {
    let m = model(&bridge_world(3, 2), json!({"task": "bridge"}));
    assert_eq!(m.reserves(), 3);
    let crawl = model(&crawl(7, 1), json!({}));
    assert_eq!(crawl.reserves(), 3, "the crawl's upper tier");
}

#[test]
fn the_reinforcement_count_is_the_cycles_in_which_a_leader_1_moved() {
    // Figure 14: B's column goes down once, under robot A.
    let preset = kumiki_core::presets::scenario("chobie-load5").unwrap();
    let mut m = Chobie::new(&preset).unwrap();
    let act = json!({"kind": "load", "cells": [19], "force": 300.0});
    m.apply(act.as_object().unwrap()).unwrap();
    let mut counted = 0;
    for _ in 0..20 {
        let before = m.totals.reinforcements;
        step_checked(&mut m);
        if m.totals.reinforcements > before {
            counted += 1;
            assert!(m.last.moved && m.last.leaders.iter().any(|e| e.kind == Kind::Leader1));
        }
    }
    assert_eq!((m.totals.reinforcements, counted), (1, 1));
    let bridge = kumiki_core::presets::scenario("chobie-bridge").unwrap();
    let mut adaptive = Chobie::new(&bridge).unwrap();
    let mut plain = Chobie::new(&bridge).unwrap();
    plain.p.adaptation = false;
    for _ in 0..40 {
        step_checked(&mut adaptive);
        step_checked(&mut plain);
    }
    assert!(adaptive.totals.reinforcements >= 1);
    assert_eq!(
        plain.totals.reinforcements, 0,
        "no step 7 without adaptation"
    );
}

#[test]
fn step_7s_rise_would_leave_the_tier_hanging_in_every_bridge() {
    // Section 3.4's step 7 reads "the vertical line of itself drives to downward and the
    // vertical line of its right-side neighbor drives to upward". In every leader-1 election
    // of the chobie-bridge experiment's 45 adaptive runs, the right neighbour is the single
    // tier over the void: rising, with the leader's column or alone, it would leave the tier
    // right of it connected to nothing, while the leader's own column can go down
    // (interpretation 13). Read strictly, both commands or none, step 7 would never move.
    let mut elections = 0;
    for reserves in [1, 3, 5, 7, 9] {
        for load in [0.0, 10.0, 20.0] {
            for goal in [13, 16, 19] {
                let mut m = model(
                    &bridge_world(reserves, 2),
                    json!({"task": "bridge", "goal": goal, "max_steps": 120, "tip_load": load}),
                );
                while !m.completed() && m.steps < 120 {
                    let over: Vec<bool> = m.stress.iter().map(|&s| m.overloaded(s)).collect();
                    if over.iter().any(|&o| o) {
                        let leaders = election::adaptation(&m.body, &over, &mut Comm::default());
                        for e in leaders.iter().filter(|e| e.kind == Kind::Leader1) {
                            let (lines, _) = e.command(&m.body, Mode::Adaptation);
                            assert_eq!(lines.len(), 2);
                            assert_eq!(m.body.check(&lines), Err(Refusal::Disconnected));
                            assert_eq!(m.body.check(&lines[1..]), Err(Refusal::Disconnected));
                            assert!(m.body.check(&lines[..1]).is_ok());
                            elections += 1;
                        }
                    }
                    step_checked(&mut m);
                }
            }
        }
    }
    assert_eq!(elections, 166);
}
