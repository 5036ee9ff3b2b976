use std::collections::VecDeque;

use super::field::FAR;
use super::state::{code, CLAIMED, CONVEYOR, FRONT, MODULE, SOURCE, VACANT};
use super::view::action;
use super::*;
use crate::run::Run;
use crate::scenario::Scenario;
use proptest::prelude::*;

impl Amas {
    /// The model of a test scenario, built the way a run builds it.
    fn new(s: &Scenario) -> crate::Result<Amas> {
        let crate::models::ModelSpec::Amas(spec) = &s.spec else {
            panic!("not a amas scenario");
        };
        Ok(Amas::from_checked(
            crate::models::Spec::validate(spec, s.limits)?,
            s.seed,
        ))
    }
}

const L: &str = "##....\n##....\n##....\n######\n######\n";

fn scenario(body: Value) -> Scenario {
    let mut doc = json!({
        "version": 1, "model": "amas", "name": "t", "seed": 1, "max_steps": 20000,
        "target": L, "robots": 3
    });
    for (k, v) in body.as_object().unwrap() {
        doc[k] = v.clone();
    }
    Scenario::from_value(doc).unwrap()
}

fn model(body: Value) -> Amas {
    Amas::new(&scenario(body)).unwrap()
}

fn structure(m: &Amas) -> u64 {
    m.state
        .iter()
        .filter(|&&s| s & MODULE != 0 && s & CONVEYOR == 0)
        .count() as u64
}

/// No module lost or created, one robot per module at most, robots only on modules.
fn check_invariants(m: &Amas, initial: u64) {
    assert_eq!(
        structure(m),
        initial + m.placed - m.dismantled - m.removed,
        "modules in the structure were lost or created"
    );
    let carried = m.robots.iter().filter(|r| r.loaded).count() as u64;
    assert_eq!(
        carried + m.placed + m.returned,
        m.picked + m.dismantled,
        "carried modules were lost or created"
    );
    let mut seen = vec![false; m.state.len()];
    for (r, robot) in m.robots.iter().enumerate() {
        let c = robot.cell as usize;
        assert!(
            m.state[c] & MODULE != 0,
            "robot {r} stands off the structure"
        );
        assert!(!seen[c], "two robots on cell {c}");
        seen[c] = true;
        assert_eq!(m.occupant[c], r as u32);
    }
    assert_eq!(
        m.occupant.iter().filter(|&&o| o != NONE).count(),
        m.robots.len()
    );
    assert!(m.state.iter().all(|&s| s & CLAIMED == 0));
    let vacant = m.state.iter().filter(|&&s| s & VACANT != 0).count() as u64;
    assert_eq!(vacant, m.vacant);
}

/// Every module is joined to the supply through modules.
fn connected(m: &Amas) -> bool {
    let mut seen = vec![false; m.state.len()];
    let mut stack: Vec<usize> = (m.supply_top * m.w..m.state.len()).collect();
    for &i in &stack {
        seen[i] = true;
    }
    while let Some(i) = stack.pop() {
        let (nb, k) = m.neighbours(i);
        for &j in &nb[..k] {
            if m.state[j] & MODULE != 0 && !seen[j] {
                seen[j] = true;
                stack.push(j);
            }
        }
    }
    (0..m.state.len()).all(|i| m.state[i] & MODULE == 0 || seen[i])
}

fn run_to_end(m: &mut Amas, limit: u64) {
    while !m.completed() && m.steps < limit {
        m.step();
    }
}

#[test]
fn builds_the_l_shape_with_every_field_and_rule() {
    for field in ["continuous", "discrete"] {
        for collision in ["token", "relay", "blackboard"] {
            let mut m = model(json!({"field": field, "collision": collision, "robots": 4}));
            run_to_end(&mut m, 20000);
            assert!(m.completed(), "{field} {collision}: {:?}", m.metrics());
            assert_eq!(m.placed, 18);
            assert_eq!(m.metrics()["built"], json!(1.0));
        }
    }
}

#[test]
fn total_steps_never_below_either_bound() {
    let t = "######\n######\n..##..\n..##..\n..##..\n";
    for target in [L, t] {
        for field in ["continuous", "discrete"] {
            for collision in ["token", "relay", "blackboard"] {
                for (seed, robots) in [(1, 1), (2, 2), (3, 5)] {
                    let mut s = scenario(json!({
                        "target": target, "field": field, "collision": collision,
                        "robots": robots, "seed": seed
                    }));
                    s.seed = seed;
                    let mut run = Run::new(s).unwrap();
                    run.run_to_end();
                    let m = run.outcome().metrics;
                    let total = m["total_steps"].as_u64().unwrap();
                    let lower = m["lower_bound"].as_u64().unwrap();
                    let path = m["path_bound"].as_u64().unwrap();
                    assert!(run.model().completed(), "{m:?}");
                    assert!(path >= lower, "{m:?}");
                    assert!(total >= path, "{field} {collision}: {m:?}");
                }
            }
        }
    }
}

#[test]
fn footnote_bound_is_as_written() {
    // One column of 3 above the supply, 2 robots: 2·(1+2+3) − 2·3.
    let m = model(json!({"target": "#\n#\n#\n", "robots": 1}));
    assert_eq!(m.lower_bound, 12 - 3);
    // The T's arms are further through the shape than straight down.
    let m = model(json!({"target": "###\n.#.\n", "robots": 1}));
    assert_eq!(m.lower_bound, 2 * (1 + 2 + 2 + 2) - 2);
    assert_eq!(m.path_bound, 2 * (1 + 2 + 3 + 3) - 3);
}

/// Breadth-first distances through communicating modules from the cells `source` accepts.
fn bfs(m: &Amas, source: impl Fn(u8) -> bool) -> Vec<u16> {
    let mut d = vec![FAR; m.state.len()];
    let mut q = VecDeque::new();
    for (i, di) in d.iter_mut().enumerate() {
        let s = m.state[i];
        if s & MODULE != 0 && source(s) {
            *di = 0;
            q.push_back(i);
        }
    }
    while let Some(i) = q.pop_front() {
        let (nb, k) = m.neighbours(i);
        for &j in &nb[..k] {
            if m.state[j] & MODULE != 0 && d[j] == FAR {
                d[j] = d[i] + 1;
                q.push_back(j);
            }
        }
    }
    d
}

#[test]
fn discrete_field_converges_to_breadth_first_distance() {
    for seed in 1..4 {
        let mut m = model(json!({"field": "discrete", "seed": seed, "field_updates_per_step": 1}));
        for _ in 0..25 {
            m.step();
        }
        for _ in 0..m.state.len() {
            m.field.update(&m.state, m.w, m.top);
        }
        let Field::Discrete {
            to_supply,
            to_front,
            ..
        } = &m.field
        else {
            unreachable!()
        };
        assert_eq!(to_supply, &bfs(&m, |s| s & SOURCE != 0));
        assert_eq!(to_front, &bfs(&m, |s| s & FRONT != 0));
    }
}

#[test]
fn continuous_field_on_a_strip_converges_to_the_linear_profile() {
    // A strip of 9 modules on one supply module; the top one is the growth front.
    let target = "#\n".repeat(10);
    let initial = "#\n".repeat(9);
    let mut m = model(json!({"target": target, "initial": initial, "robots": 1}));
    for _ in 0..5000 {
        m.field.update(&m.state, m.w, m.top);
    }
    let Field::Continuous { p, .. } = &m.field else {
        unreachable!()
    };
    // Row 10 is the supply (0), row 1 the growth front (1).
    for (y, &v) in p.iter().enumerate().skip(1) {
        let want = (10 - y) as f32 / 9.0;
        assert!((v - want).abs() < 1e-4, "row {y}: {v} vs {want}");
    }
    assert_eq!(p[10], 0.0);
    assert!(p[0] == 0.0 && m.state[0] & VACANT != 0);
}

#[test]
fn continuous_field_leaks_nothing_at_completed_edges() {
    // A wide block: at the steady state every row holds one value (no flux sideways).
    let target = "#####\n".repeat(6);
    let initial = "#####\n".repeat(5);
    let mut m = model(json!({"target": target, "initial": initial, "robots": 1}));
    for _ in 0..3000 {
        m.field.update(&m.state, m.w, m.top);
    }
    let Field::Continuous { p, .. } = &m.field else {
        unreachable!()
    };
    for y in 1..7 {
        let row = &p[y * 5..y * 5 + 5];
        assert!(
            row.iter().all(|&v| (v - row[0]).abs() < 1e-5),
            "row {y}: {row:?}"
        );
    }
}

#[test]
fn blackboard_never_records_a_collision_and_relay_relays() {
    for seed in 1..6 {
        for field in ["continuous", "discrete"] {
            let mut m = model(json!({
                "target": "######\n######\n######\n######\n", "robots": 6, "seed": seed,
                "field": field, "collision": "blackboard"
            }));
            while !m.completed() && m.steps < 5000 {
                m.step();
                assert!(m.events.is_empty());
            }
            assert!(m.completed());
            assert_eq!(m.collisions, 0);
            assert_eq!(m.relays, 0);
        }
    }
    let mut relays = 0;
    for seed in 1..6 {
        let mut m = model(json!({"robots": 6, "seed": seed, "collision": "relay"}));
        run_to_end(&mut m, 20000);
        assert!(m.completed());
        relays += m.relays;
        let mut m = model(json!({"robots": 6, "seed": seed, "collision": "token"}));
        run_to_end(&mut m, 20000);
        assert_eq!(m.relays, 0);
    }
    assert!(relays > 0);
}

#[test]
fn durations_slow_the_robots_down() {
    let steps = |body: Value| {
        let mut m = model(body);
        run_to_end(&mut m, 100000);
        assert!(m.completed());
        m.steps
    };
    let base = steps(json!({"robots": 1}));
    assert!(steps(json!({"robots": 1, "move_duration": 3})) > base);
    assert!(steps(json!({"robots": 1, "pick_duration": 4, "place_duration": 4})) > base + 18 * 5);
}

#[test]
fn turns_take_time_and_radius_two_communication_builds() {
    let run = |body: Value| {
        let mut m = model(body);
        run_to_end(&mut m, 100000);
        assert!(m.completed(), "{:?}", m.metrics());
        m.steps
    };
    let base = run(json!({"robots": 1}));
    assert!(run(json!({"robots": 1, "turn_duration": 2})) > base);
    for collision in ["token", "relay", "blackboard"] {
        run(json!({"robots": 4, "collision": collision, "communication": "radius2"}));
    }
}

#[test]
fn loaded_robots_fill_sites_beside_broken_modules() {
    // Every built module breaks at step 6: no module announces the growth front any more.
    for seed in 1..6 {
        let mut m = model(json!({"robots": 3, "seed": seed, "field": "discrete"}));
        for _ in 0..6 {
            m.step();
        }
        m.apply(&action(json!({"kind": "break", "count": 1000})))
            .unwrap();
        run_to_end(&mut m, 200000);
        assert!(m.completed(), "seed {seed}: {:?}", m.metrics());
    }
}

#[test]
fn same_seed_same_run_other_seed_other_run() {
    let out = |seed: u64| {
        let mut s = scenario(json!({"robots": 3}));
        s.seed = seed;
        let mut r = Run::new(s).unwrap();
        r.run_to_end();
        r.outcome()
    };
    assert_eq!(out(9), out(9));
    assert_ne!(out(9).hash, out(10).hash);
}

#[test]
fn removal_turns_neighbours_into_growth_front_and_is_rebuilt() {
    let mut m = model(json!({"robots": 3, "seed": 2}));
    run_to_end(&mut m, 20000);
    assert!(m.completed());
    // The bar's middle cell: x = 0, y = 1; move any robot off it first.
    let i = 6;
    if m.occupant[i] != NONE {
        return;
    }
    m.apply(&action(json!({"kind": "remove", "cells": [i]})))
        .unwrap();
    assert!(!m.completed());
    assert_eq!(m.display[i], code::VACANT);
    let (nb, k) = m.neighbours(i);
    assert!(nb[..k]
        .iter()
        .filter(|&&j| m.state[j] & MODULE != 0)
        .all(|&j| m.state[j] & FRONT != 0));
    let initial = structure(&m) - m.placed + m.dismantled + m.removed;
    while !m.completed() {
        m.step();
        check_invariants(&m, initial);
    }
    assert_eq!(m.placed, 19);
}

#[test]
fn broken_modules_keep_their_last_value_and_robots_on_them_wander() {
    let mut m = model(json!({"robots": 3, "field": "discrete"}));
    for _ in 0..40 {
        m.step();
    }
    let free: Vec<usize> = (0..m.state.len())
        .filter(|&i| m.state[i] & MODULE != 0 && m.state[i] & CONVEYOR == 0)
        .collect();
    let c = free[0];
    m.apply(&action(json!({"kind": "break", "cells": [c]})))
        .unwrap();
    assert_eq!(m.display[c], code::BROKEN);
    let before = m.field("to_front").unwrap()[c];
    let mut wandered = 0;
    for _ in 0..200 {
        let r = m.occupant[c] as usize;
        let plans_here = r != NONE as usize && m.robots[r].busy == 0 && !m.robots[r].give_way;
        m.step();
        assert_eq!(m.field("to_front").unwrap()[c], before);
        if plans_here {
            // The broken module told the robot nothing: it moved at random.
            assert!(m.robots[r].lost);
            wandered += 1;
        }
    }
    assert!(wandered > 0, "no robot crossed the broken module");
    assert!(m
        .apply(&action(json!({"kind": "break", "cells": [c]})))
        .unwrap_err()
        .to_string()
        .contains("already broken"));
}

#[test]
fn clicked_disturbances_are_recorded_and_replayed() {
    let mut live = Run::new(scenario(json!({"robots": 3, "seed": 4}))).unwrap();
    live.advance(30);
    live.apply_now(action(json!({"kind": "remove", "count": 2})))
        .unwrap();
    live.apply_now(action(json!({"kind": "break", "count": 1})))
        .unwrap();
    live.run_to_end();
    let mut replay = Run::new(live.scenario().clone()).unwrap();
    replay.run_to_end();
    assert_eq!(live.outcome(), replay.outcome());
    assert_eq!(live.scenario().disturbances.len(), 2);
    assert_eq!(live.scenario().disturbances[0].at, 30);
}

const BLOCK_STAGES: [&str; 2] = [
    "........\n........\n########\n########\n",
    "........\n########\n##....##\n##....##\n",
];
const BLOCK_FINAL: &str = "########\n##....##\n##....##\n##....##\n";

#[test]
fn staged_targets_switch_and_keep_the_structure_connected() {
    for collision in ["token", "relay", "blackboard"] {
        for seed in 1..4 {
            let mut m = model(json!({
                "stages": BLOCK_STAGES, "target": BLOCK_FINAL, "robots": 3, "seed": seed,
                "field": "discrete", "collision": collision
            }));
            let mut stages_seen = vec![m.stage];
            while !m.completed() && m.steps < 20000 {
                m.step();
                check_invariants(&m, 0);
                assert!(connected(&m), "disconnected at step {}", m.steps);
                if stages_seen.last() != Some(&m.stage) {
                    stages_seen.push(m.stage);
                }
            }
            assert!(m.completed(), "{collision} seed {seed}: {:?}", m.metrics());
            assert_eq!(stages_seen, vec![0, 1, 2]);
            // 16 + 8 + 8 placed; 8 + 4 taken away.
            assert_eq!(m.dismantled, 8 + 4);
            assert_eq!(structure(&m), 20);
            // Dismantled modules are reused: the conveyor gives only what the final
            // structure needs, and what robots still hold.
            assert!(
                m.picked <= 20 + 3,
                "{collision} seed {seed}: {:?}",
                m.metrics()
            );
        }
    }
}

#[test]
fn dismantled_modules_go_back_to_the_supply_when_the_target_is_full() {
    let mut m = model(json!({"robots": 3, "seed": 3, "field": "discrete"}));
    run_to_end(&mut m, 20000);
    // The top of the bar leaves the target: nothing is vacant, so it goes back to the supply.
    m.apply(&action(json!({"kind": "dismantle", "cells": [0, 1]})))
        .unwrap();
    assert!(m.return_mode && !m.completed());
    while !m.completed() && m.steps < 20000 {
        m.step();
        check_invariants(&m, 0);
        assert!(connected(&m));
    }
    assert!(m.completed());
    assert_eq!(m.dismantled, 2);
    assert!(m.returned + m.robots.iter().filter(|r| r.loaded).count() as u64 >= 2);
    // And a cell added to the target is built.
    m.apply(&action(json!({"kind": "extend", "cells": [0]})))
        .unwrap();
    run_to_end(&mut m, 40000);
    assert!(m.completed());
}

#[test]
fn removal_rule_keeps_bridging_modules() {
    // x marks the module to remove; removing the middle of a one-wide bridge is refused
    // locally but allowed when the two sides meet elsewhere.
    let m = model(json!({"target": "###\n#.#\n#.#\n", "robots": 1, "initial": "###\n#.#\n#.#\n"}));
    assert!(
        m.removable(1),
        "the top middle joins two piers that meet at the supply"
    );
    let m = model(json!({"target": "#..\n#..\n#..\n", "initial": "#..\n#..\n#..\n", "robots": 1}));
    assert!(!m.removable(3), "the middle of a column holds its top");
    assert!(m.removable(0), "the top of a column has one connection");
}

#[test]
fn bad_scenarios_name_the_field() {
    let bad = |body: Value| {
        let mut doc = json!({"version": 1, "model": "amas", "target": L, "robots": 2});
        for (k, v) in body.as_object().unwrap() {
            doc[k] = v.clone();
        }
        Scenario::from_value(doc).unwrap_err().to_string()
    };
    assert!(bad(json!({"robots": 0})).starts_with("robots:"));
    assert!(bad(json!({"robots": 99})).starts_with("robots:"));
    assert!(bad(json!({"robots": "two"})).starts_with("robots:"));
    let e = bad(json!({"target": "##\n..\n##\n"}));
    assert!(
        e.starts_with("target:") && e.contains("not connected"),
        "{e}"
    );
    let e = bad(json!({"stages": ["#.\n#.\n", "#.\n.#\n"]}));
    assert!(
        e.starts_with("stages[1]:") && e.contains("not connected"),
        "{e}"
    );
    assert!(bad(json!({"initial": "#.\n.#\n"})).starts_with("initial:"));
    assert!(bad(json!({"target": "#x"})).starts_with("target:"));
    assert!(bad(json!({"target": ".."})).starts_with("target:"));
    assert!(bad(json!({"target": 7})).starts_with("target:"));
    assert!(bad(json!({"target": {"rect": [0, 3]}})).starts_with("target.rect:"));
    let huge = format!(
        "{}\n",
        "#".repeat(crate::Limits::PAGE.amas.side as usize + 1)
    );
    assert!(bad(json!({"target": huge})).contains("exceeds the limit"));
    let e = bad(json!({"target": {"rect": [10, crate::Limits::PAGE.amas.side]}}));
    assert!(
        e.starts_with("target:") && e.contains("exceeds the limit"),
        "{e}"
    );
    let big = json!({"rect": [2048, 2000]});
    let e = bad(json!({"target": big, "stages": vec![big.clone(); 20]}));
    assert!(
        e.starts_with("stages:") && e.contains("cells in all"),
        "{e}"
    );
    let e = bad(json!({"field": "lumpy"}));
    assert!(e.starts_with("field:") && e.contains("continuous"), "{e}");
    assert!(bad(json!({"collision": "bump"})).starts_with("collision:"));
    assert!(bad(json!({"field_updates_per_step": 0})).starts_with("field_updates_per_step:"));
    assert!(bad(json!({"diffusion": 0.3})).starts_with("diffusion:"));
    assert!(bad(json!({"gradient_threshold": -1})).starts_with("gradient_threshold:"));
    assert!(bad(json!({"relay_duration": 0})).starts_with("relay_duration:"));
    assert!(bad(json!({"collision_penalty": 5000})).starts_with("collision_penalty:"));
    assert!(bad(json!({"supply_rows": 0})).starts_with("supply_rows:"));
    assert!(bad(json!({"robtos": 2})).contains("unknown field"));
    assert!(
        bad(json!({"disturbances": [{"at": 3, "kind": "explode", "count": 1}]}))
            .starts_with("disturbances[0].kind")
    );
    assert!(
        bad(json!({"disturbances": [{"kind": "remove", "count": 1}]}))
            .starts_with("disturbances[0].at")
    );
    assert!(
        bad(json!({"disturbances": [{"at": 1, "kind": "remove", "cells": [999]}]}))
            .starts_with("disturbances[0].cells[0]")
    );
    assert!(bad(json!({"disturbances": [{"at": 1, "kind": "remove"}]}))
        .starts_with("disturbances[0].count"));
}

#[test]
fn large_lattices_are_cheap_to_hold() {
    let m = model(json!({"target": {"rect": [256, 256]}, "robots": 256}));
    assert_eq!((m.w, m.h), (256, 257));
    // Robots beyond one supply row need more supply rows.
    let s = Scenario::from_value(json!({
        "version": 1, "model": "amas", "target": {"rect": [64, 64]}, "robots": 200
    }));
    assert!(s.unwrap_err().to_string().contains("supply_rows"));
    let m = model(json!({"target": {"rect": [64, 64]}, "robots": 200, "supply_rows": 4}));
    assert_eq!(m.h, 68);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    #[test]
    fn invariants_hold_on_every_step(
        seed in 0u64..1_000_000,
        robots in 1u32..7,
        rows in proptest::collection::vec(proptest::collection::vec(any::<bool>(), 6), 1..5),
        field in 0usize..2,
        collision in 0usize..3,
        kind in 0usize..4,
        at in 5u64..80,
        count in 0u32..4,
        radius2 in any::<bool>(),
        turn in 0u32..3,
    ) {
        // Random shapes, kept connected by a full bottom row.
        let mut text = String::new();
        for row in &rows {
            text.extend(row.iter().map(|&b| if b { '#' } else { '.' }));
            text.push('\n');
        }
        text.push_str("######\n");
        let kind = ["remove", "break", "dismantle", "extend"][kind];
        let field_name = ["continuous", "discrete"][field];
        let collision_name = ["token", "relay", "blackboard"][collision];
        let s = Scenario::from_value(json!({
            "version": 1, "model": "amas", "seed": seed, "target": text, "robots": robots,
            "field": field_name,
            "collision": collision_name,
            "field_updates_per_step": 2,
            "communication": if radius2 { "radius2" } else { "chain" },
            "turn_duration": turn,
            "disturbances": [{"at": at, "kind": kind, "count": count}]
        }));
        let Ok(s) = s else { return Ok(()); };
        let mut run = Run::new(s.clone()).unwrap();
        let mut m = Amas::new(&s).unwrap();
        for _ in 0..300 {
            if run.finished() { break; }
            // A bare model alongside the run, disturbed by hand.
            if m.steps() == at {
                m.apply(&action(json!({"kind": kind, "count": count}))).unwrap();
            }
            if !run.step() { break; }
            m.step();
            check_invariants(&m, 0);
            if kind != "remove" {
                prop_assert!(connected(&m));
            }
            if collision == 2 {
                prop_assert_eq!(m.collisions, 0);
            }
        }
        prop_assert_eq!(run.state_hash(), {
            let mut h = StateHasher::new();
            h.u64(m.steps());
            m.hash_state(&mut h);
            h.finish()
        });
    }
}

#[test]
fn layout_describes_what_the_model_draws() {
    for field in ["continuous", "discrete"] {
        let mut m = model(json!({"field": field, "collision": "relay", "robots": 4}));
        for _ in 0..30 {
            m.step();
        }
        let layout = m.layout();
        assert_eq!(m.cells().len(), (layout.dims[0] * layout.dims[1]) as usize);
        let codes: Vec<u8> = layout.cells.iter().map(|e| e.code).collect();
        assert!(m.cells().iter().all(|c| *c == 0 || codes.contains(c)));
        for f in &layout.fields {
            let values = m.field(&f.name).expect("every listed field is served");
            assert_eq!(values.len(), m.cells().len());
            assert!(values.iter().any(|v| v.is_finite()));
        }
        assert!(m.field("no such field").is_none());
        let kinds: Vec<u8> = layout.agents.iter().map(|e| e.code).collect();
        assert!(m.agents().iter().all(|a| kinds.contains(&a.kind)));
        for tool in &layout.tools {
            // Every tool's action is valid once a cell is added (a wrong cell is a clear error).
            let mut a = tool.action.clone();
            a.insert("cells".into(), json!([0]));
            let checked = m.check_action(&a);
            assert!(checked.is_ok() || checked.unwrap_err().to_string().starts_with("cells[0]"));
        }
        let facts = m.inspect(m.robots[0].cell as usize);
        assert!(facts.contains_key("robot") && facts.contains_key("cell"));
        assert!(m.inspect(usize::MAX).is_empty());
    }
}

#[test]
fn the_corner_is_the_row_where_the_target_narrows() {
    // L: rows 0-2 are the stem (2 wide), rows 3-4 the foot (6 wide): the corner row is 2.
    let m = model(json!({}));
    assert_eq!(m.corner_row, 2);
    // A rectangle never narrows: its top row.
    let m = model(json!({"target": {"rect": [4, 3]}}));
    assert_eq!(m.corner_row, 0);
    // Robots that stay on the supply never pass it; relays are counted where they happen.
    let mut m = model(json!({"robots": 3, "collision": "relay", "seed": 2}));
    assert_eq!(m.metrics()["never_past_corner"], json!(1.0));
    run_to_end(&mut m, 20000);
    assert!(m.corner_relays <= m.relays);
    assert!(m.metrics()["never_past_corner"].as_f64().unwrap() < 1.0);
    // Somebody placed the stem's modules.
    assert!(m.metrics()["corner_assemblers"].as_f64().unwrap() > 0.0);
}
