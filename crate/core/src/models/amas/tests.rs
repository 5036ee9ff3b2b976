use super::*;
use crate::run::Run;
use proptest::prelude::*;
use std::collections::VecDeque;

fn scenario(target: &str, robots: u32, seed: u64) -> Scenario {
    Scenario::from_value(json!({
        "version": 1, "model": "amas", "name": "t", "seed": seed, "max_steps": 20000,
        "target": target, "robots": robots
    }))
    .unwrap()
}

fn model(s: &Scenario) -> Amas {
    Amas::new(s).unwrap()
}

fn check_invariants(m: &Amas) {
    let built = m
        .cells
        .iter()
        .filter(|&&c| cell::is_module(c) && !cell::is_supply(c))
        .count() as u64;
    assert_eq!(built, m.placed - m.removed, "modules were lost or created");
    assert_eq!(u64::from(m.target_cells - m.vacant), built);
    let mut seen = vec![false; m.cells.len()];
    for (r, robot) in m.robots.iter().enumerate() {
        let c = robot.cell as usize;
        assert!(
            cell::is_module(m.cells[c]),
            "robot {r} stands off the structure"
        );
        assert!(!seen[c], "two robots on cell {c}");
        seen[c] = true;
        assert_eq!(m.occupant[c], r as u32);
    }
    assert_eq!(
        m.occupant.iter().filter(|&&o| o != u32::MAX).count(),
        m.robots.len()
    );
}

/// Breadth-first distances through modules from the cells `source` accepts.
fn bfs(m: &Amas, source: impl Fn(u8) -> bool) -> Vec<u16> {
    let mut d = vec![FAR; m.cells.len()];
    let mut q = VecDeque::new();
    for (i, di) in d.iter_mut().enumerate() {
        if source(m.cells[i]) {
            *di = 0;
            q.push_back(i);
        }
    }
    while let Some(i) = q.pop_front() {
        for j in m.lattice.neighbours(i) {
            if cell::is_module(m.cells[j]) && d[j] == FAR {
                d[j] = d[i] + 1;
                q.push_back(j);
            }
        }
    }
    d
}

const L: &str = "##....\n##....\n##....\n######\n######\n";

#[test]
fn builds_the_l_shape() {
    let s = scenario(L, 3, 5);
    let mut run = Run::new(s).unwrap();
    run.run_to_end();
    let out = run.outcome();
    assert!(out.completed, "{out:?}");
    assert_eq!(out.metrics["placed"], json!(18));
    assert_eq!(out.metrics["built"], json!(1.0));
}

#[test]
fn total_steps_never_below_the_lower_bound() {
    for seed in 1..6 {
        for robots in [1, 2, 4] {
            let mut run = Run::new(scenario(L, robots, seed)).unwrap();
            run.run_to_end();
            let m = run.outcome().metrics;
            assert!(
                m["total_steps"].as_u64().unwrap() >= m["lower_bound"].as_u64().unwrap(),
                "{m:?}"
            );
        }
    }
}

#[test]
fn discrete_field_converges_to_breadth_first_distance() {
    let s = scenario(L, 2, 3);
    let mut m = model(&s);
    for _ in 0..40 {
        m.step();
    }
    // Freeze the structure and let the field settle.
    for _ in 0..(m.cells.len()) {
        m.update_fields();
    }
    let modules: Vec<usize> = (0..m.cells.len())
        .filter(|&i| cell::is_module(m.cells[i]))
        .collect();
    let bs = bfs(&m, cell::is_supply);
    let bf = bfs(&m, cell::is_front);
    for &i in &modules {
        assert_eq!(m.to_supply[i], bs[i], "to_supply at {i}");
        assert_eq!(m.to_front[i], bf[i], "to_front at {i}");
    }
}

#[test]
fn same_seed_same_run_other_seed_other_run() {
    let a = {
        let mut r = Run::new(scenario(L, 3, 9)).unwrap();
        r.run_to_end();
        r.outcome()
    };
    let b = {
        let mut r = Run::new(scenario(L, 3, 9)).unwrap();
        r.run_to_end();
        r.outcome()
    };
    let c = {
        let mut r = Run::new(scenario(L, 3, 10)).unwrap();
        r.run_to_end();
        r.outcome()
    };
    assert_eq!(a, b);
    assert_ne!(a.hash, c.hash);
}

#[test]
fn removal_turns_neighbours_into_growth_front_and_is_rebuilt() {
    let mut run = Run::new(scenario(L, 3, 2)).unwrap();
    run.run_to_end();
    assert!(run.model().completed());
    let s = run.scenario().clone();
    let mut m = model(&s);
    while !m.completed() {
        m.step();
    }
    // The bar's middle cell: x = 0, y = 1.
    let i = 6;
    assert_eq!(m.cells[i], cell::MODULE);
    if m.occupant[i] == u32::MAX {
        m.apply(json!({"kind": "remove", "cells": [i]}).as_object().unwrap())
            .unwrap();
        assert_eq!(m.cells[i], cell::VACANT);
        assert!(m
            .lattice
            .neighbours(i)
            .filter(|&j| cell::is_module(m.cells[j]))
            .all(|j| cell::is_front(m.cells[j])));
        while !m.completed() {
            m.step();
            check_invariants(&m);
        }
    }
}

#[test]
fn clicked_disturbances_are_recorded_and_replayed() {
    let mut live = Run::new(scenario(L, 3, 4)).unwrap();
    live.advance(60);
    live.apply_now(
        json!({"kind": "remove", "count": 2})
            .as_object()
            .unwrap()
            .clone(),
    )
    .unwrap();
    live.run_to_end();
    let mut replay = Run::new(live.scenario().clone()).unwrap();
    replay.run_to_end();
    assert_eq!(live.outcome(), replay.outcome());
    assert_eq!(live.scenario().disturbances.len(), 1);
    assert_eq!(live.scenario().disturbances[0].at, 60);
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
    assert!(bad(json!({"target": "#x"})).starts_with("target:"));
    let huge = format!("{}\n", "#".repeat(MAX_SIDE as usize + 1));
    assert!(bad(json!({"target": huge})).contains("exceeds the limit"));
    assert!(bad(json!({"robtos": 2})).contains("unknown field"));
    assert!(
        bad(json!({"disturbances": [{"at": 3, "kind": "explode", "count": 1}]}))
            .starts_with("disturbances[0].kind")
    );
    assert!(
        bad(json!({"disturbances": [{"kind": "remove", "count": 1}]}))
            .starts_with("disturbances[0].at")
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn invariants_hold_on_every_step(
        seed in 0u64..1_000_000,
        robots in 1u32..6,
        rows in proptest::collection::vec(proptest::collection::vec(any::<bool>(), 6), 1..5),
        removal_at in 5u64..80,
    ) {
        // Random shapes, kept connected by a full bottom row.
        let mut text = String::new();
        for row in &rows {
            text.extend(row.iter().map(|&b| if b { '#' } else { '.' }));
            text.push('\n');
        }
        text.push_str("######\n");
        let s = Scenario::from_value(json!({
            "version": 1, "model": "amas", "seed": seed, "target": text, "robots": robots,
            "disturbances": [{"at": removal_at, "kind": "remove", "count": 2}]
        }));
        let Ok(s) = s else { return Ok(()); };
        let mut run = Run::new(s.clone()).unwrap();
        let mut m = model(&s);
        for _ in 0..400 {
            if run.finished() { break; }
            // Drive a bare model alongside, applying the disturbance by hand.
            if m.steps() == removal_at {
                m.apply(json!({"kind": "remove", "count": 2}).as_object().unwrap()).unwrap();
            }
            m.step();
            run.step();
            check_invariants(&m);
        }
    }
}
