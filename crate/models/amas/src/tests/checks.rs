//! Refused scenarios, large lattices, random runs and the view.

use super::*;

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
        "#".repeat(crate::limits::LIMITS.page.side as usize + 1)
    );
    assert!(bad(json!({"target": huge})).contains("exceeds the limit"));
    let e = bad(json!({"target": {"rect": [10, crate::limits::LIMITS.page.side]}}));
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
    // The L upside down (stem on the supply) turns where it widens: the arm's lowest row.
    let m = model(json!({"target": "######\n######\n##....\n##....\n##....\n"}));
    assert_eq!(m.corner_row, 1);
    // Robots that stay on the supply never pass it; relays are counted where they happen.
    let mut m = model(json!({"robots": 3, "collision": "relay", "seed": 2}));
    assert_eq!(m.metrics()["never_past_corner"], json!(1.0));
    run_to_end(&mut m, 20000);
    assert!(m.corner_relays <= m.relays);
    assert!(m.metrics()["never_past_corner"].as_f64().unwrap() < 1.0);
    // Somebody placed the stem's modules.
    assert!(m.metrics()["corner_assemblers"].as_f64().unwrap() > 0.0);
}

#[test]
fn the_heat_map_places_every_collision_at_the_cell_the_robot_wanted() {
    for rule in ["token", "relay"] {
        let mut m = model(json!({"robots": 6, "collision": rule, "field": "discrete"}));
        let mut wanted = std::collections::BTreeMap::new();
        while !m.completed() && m.steps < 20000 {
            m.step();
            for e in m.events().iter().filter(|e| e.kind == EV_COLLISION) {
                *wanted.entry(e.cell).or_insert(0u32) += 1;
            }
        }
        assert!(
            m.collisions > 0,
            "{rule}: six robots on the small L collide"
        );
        // The map holds each collision event's cell, once per collision.
        assert_eq!(m.collision_cells, wanted, "{rule}");
        let heat = m.field("collisions").unwrap();
        for (i, v) in heat.iter().enumerate() {
            let count = wanted.get(&(i as u32)).copied().unwrap_or(0);
            if count > 0 || m.state[i] & MODULE != 0 {
                assert_eq!(*v, count as f32, "{rule}: cell {i}");
            } else {
                assert!(
                    v.is_nan(),
                    "{rule}: cell {i} holds no module and saw no collision"
                );
            }
        }
        assert_eq!(
            m.inspect(*wanted.keys().next().unwrap() as usize)["collisions"],
            json!(wanted.values().next().unwrap())
        );
        // The zones split the collisions by row: corner rows, above, supply, and the rest below.
        let by_row = |keep: &dyn Fn(u32) -> bool| -> u64 {
            wanted
                .iter()
                .filter(|(&c, _)| keep(c / m.w as u32))
                .map(|(_, &n)| u64::from(n))
                .sum()
        };
        let corner = m.corner_row;
        assert_eq!(
            m.corner_collisions,
            by_row(&|y| y == corner || y == corner + 1)
        );
        assert_eq!(m.above_corner_collisions, by_row(&|y| y < corner));
        assert_eq!(
            m.supply_collisions,
            by_row(&|y| y > corner + 1 && y as usize >= m.supply_top)
        );
        assert!(m
            .layout()
            .fields
            .iter()
            .any(|f| f.name == "collisions" && !f.arrows));
    }
}
