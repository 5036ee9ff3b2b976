//! Runs: assembly, faults, replay, seeds, errors, queries and the view.

use super::*;

#[test]
fn the_two_line_start_assembles_the_triangle_with_its_spare() {
    let mut done = 0;
    for seed in 1..=6 {
        let mut s = presets::scenario("fracta-triangle10").unwrap();
        s.seed = seed;
        let mut m = Fracta::of_scenario(&s).unwrap();
        assert!(!m.completed());
        let mut moves = 0;
        while m.steps < 3000 && !m.completed() {
            m.step();
            check_invariants(&m);
            assert!(m.moves >= moves);
            moves = m.moves;
        }
        if m.completed() {
            done += 1;
            assert!(m.working.iter().all(|&u| m.diff[u as usize] == 0));
            assert_eq!(m.metrics()["convergence_steps"], json!(m.steps));
            // Ten units form the triangle: exactly one s, and its six neighbours.
            let s_units: Vec<u32> = m
                .working
                .iter()
                .copied()
                .filter(|&u| types().name(m.class[u as usize]) == "s")
                .collect();
            assert_eq!(s_units.len(), 1);
        } else {
            assert_eq!(m.metrics()["convergence_steps"], Value::Null);
        }
    }
    assert!(done >= 5, "only {done} of 6 runs assembled");
}

#[test]
fn a_fault_is_cut_off_and_the_triangle_repaired() {
    let s = presets::scenario("fracta-repair").unwrap();
    let mut m = Fracta::of_scenario(&s).unwrap();
    assert!(m.completed());
    let fault = s.disturbances[0].clone();
    assert_eq!(fault.at, 10);
    let u = fault.action["unit"].as_u64().unwrap() as usize;
    for _ in 0..10 {
        m.step();
    }
    assert_eq!(m.moves, 0);
    m.apply(&fault.action).unwrap();
    assert!(!m.completed(), "a faulty unit is pending");
    assert_eq!(m.units[u].status, Status::Faulty);
    assert_eq!(m.cells()[m.units[u].cell as usize], code::FAULTY);
    m.step();
    assert_eq!(m.units[u].status, Status::CutOff);
    assert_eq!(m.working.len(), 10);
    assert_eq!(m.cut_off, 1);
    assert!(m
        .events()
        .iter()
        .any(|e| e.kind == event::CUT_OFF && e.cell == m.units[u].cell));
    check_invariants(&m);
    while !m.completed() && m.steps < 5000 {
        m.step();
        check_invariants(&m);
    }
    assert!(m.completed(), "not repaired in 5000 steps");
    assert_eq!(m.metrics()["repair_steps"], json!(m.steps - 10));
    // The same through a run, which applies the scheduled fault itself.
    let mut run = Run::new(s).unwrap();
    run.run_to_end();
    assert_eq!(run.outcome().steps, m.steps);
}

#[test]
fn a_fault_that_splits_the_system_strands_the_smaller_part() {
    let s = scenario(
        "# # # # #\n . # . .\n",
        "i{e, e}",
        1,
        json!({"disturbances": [{"at": 0, "kind": "fault", "unit": 1}]}),
    );
    let mut m = Fracta::of_scenario(&s).unwrap();
    m.apply(&s.disturbances[0].action).unwrap();
    m.step();
    // Unit 1 held unit 0 to the rest: 0 is stranded, 2, 3, 4 and 5 carry on.
    assert_eq!(m.units[0].status, Status::Stranded);
    assert_eq!(m.working, [2, 3, 4, 5]);
    assert_eq!(m.stranded, 1);
    assert_eq!(m.cells()[m.units[0].cell as usize], code::STRANDED);
    check_invariants(&m);
}

#[test]
fn clicked_faults_are_recorded_and_replayed() {
    let mut live = Run::new(presets::scenario("fracta-triangle10").unwrap()).unwrap();
    live.advance(30);
    let cell = live
        .model()
        .cells()
        .iter()
        .position(|&c| (1..=12).contains(&c))
        .unwrap();
    let mut action = Map::new();
    action.insert("kind".into(), "fault".into());
    action.insert("cells".into(), json!([cell]));
    live.apply_now(action).unwrap();
    live.run_to_end();
    let mut replay = Run::new(live.scenario().clone()).unwrap();
    replay.run_to_end();
    assert_eq!(live.outcome(), replay.outcome());
    assert_eq!(live.outcome().metrics["faults"], json!(1));
}

#[test]
fn same_seed_same_run_other_seed_other_run() {
    let run = |seed| {
        let mut s = presets::scenario("fracta-triangle10").unwrap();
        s.seed = seed;
        let mut r = Run::new(s).unwrap();
        r.run_to_end();
        r.outcome()
    };
    assert_eq!(run(4), run(4));
    assert_ne!(run(4).hash, run(5).hash);
}

#[test]
fn bad_scenarios_and_actions_name_the_field() {
    let bad = |extra: Value| {
        let mut doc =
            json!({"version": 1, "model": "fracta", "start": TRIANGLE, "goal": TRIANGLE_GOAL});
        for (k, v) in extra.as_object().unwrap() {
            doc[k] = v.clone();
        }
        Scenario::from_value(doc).unwrap_err().to_string()
    };
    assert!(bad(json!({"K": 0.5})).starts_with("K:"));
    assert!(bad(json!({"K": -0.1})).starts_with("K:"));
    assert!(bad(json!({"L": "lots"})).starts_with("L:"));
    assert!(bad(json!({"I_th": 0})).starts_with("I_th:"));
    assert!(bad(json!({"temperature": 0})).starts_with("temperature:"));
    assert!(bad(json!({"priorities": "random"})).starts_with("priorities:"));
    assert!(bad(json!({"margin": 1000})).starts_with("margin:"));
    assert!(bad(json!({"start": "# . #"})).contains("fall apart"));
    assert!(bad(json!({"start": ". ."})).starts_with("start:"));
    assert!(bad(json!({"start": "#x"})).starts_with("start:"));
    let wide = format!("{}\n", vec!["#"; 1100].join(" "));
    assert!(bad(json!({"start": wide})).contains("limit"));
    assert!(bad(json!({"goal": ""})).starts_with("goal:"));
    assert!(bad(json!({"speed": 2})).contains("unknown field"));
    let fault = |a: Value| bad(json!({"disturbances": [a]}));
    assert!(
        fault(json!({"at": 1, "kind": "explode", "unit": 1})).starts_with("disturbances[0].kind")
    );
    assert!(
        fault(json!({"at": 1, "kind": "fault", "unit": 99})).starts_with("disturbances[0].unit")
    );
    assert!(fault(json!({"at": 1, "kind": "fault", "cells": [1_000_000]})).contains("outside"));
    assert!(fault(json!({"at": 1, "kind": "fault"})).contains("give either cells"));
    assert!(fault(json!({"at": 1, "kind": "fault", "unit": 1, "cells": [3]})).contains("either"));
}

#[test]
fn queries_derive_and_check_goals() {
    let goal = |args: Value| {
        models::query("fracta", "derive", &args).map(|v| v["goal"].as_str().unwrap().to_string())
    };
    assert_eq!(goal(json!({"shape": TRIANGLE})).unwrap(), TRIANGLE_GOAL);
    let two = format!("{TRIANGLE}---\n. # # .\n . # # .\n. # # #\n # # # #\n");
    let out = goal(json!({"shape": two})).unwrap();
    assert!(
        out.starts_with(TRIANGLE_GOAL) && out.contains("\n2: o{ε, c}"),
        "{out}"
    );
    let e = goal(json!({"shape": "# . #"})).unwrap_err().to_string();
    assert!(e.contains("apart"), "{e}");
    let e = goal(json!({"shape": ""})).unwrap_err().to_string();
    assert!(e.starts_with("shape:"), "{e}");
    let e = goal(json!({"shape": format!("{TRIANGLE}---\n#?")}))
        .unwrap_err()
        .to_string();
    assert!(e.contains("shape 2"), "{e}");
    let e = goal(json!({"shapes": TRIANGLE})).unwrap_err().to_string();
    assert!(e.starts_with("shape:"), "{e}");
    let check = |text: &str| models::query("fracta", "check", &json!({"goal": text}));
    assert_eq!(check("k{s, K, o, k}").unwrap()["goal"], "K{o, K, K, s}\n");
    let e = check("o{K,K}\nK{o}").unwrap_err().to_string();
    assert!(e.starts_with("goal: line 2:"), "{e}");
    let types = models::query("fracta", "types", &json!({})).unwrap();
    assert_eq!(types["types"].as_array().unwrap().len(), 12);
    assert!(models::query("fracta", "nothing", &json!({})).is_err());
    assert!(models::query("amas", "derive", &json!({})).is_err());
}

#[test]
fn layout_cells_fields_and_bonds_agree() {
    let mut m = Fracta::of_scenario(&presets::scenario("fracta-triangle10").unwrap()).unwrap();
    for _ in 0..20 {
        m.step();
    }
    let layout = m.layout();
    assert_eq!(layout.lattice, LatticeKind::Hex);
    assert_eq!(layout.cells.len(), 15);
    let cells = m.cells();
    let bonds = m.bonds();
    assert_eq!(cells.len(), m.lattice.len());
    assert_eq!(bonds.len(), cells.len());
    for f in &layout.fields {
        let values = m.field(&f.name).unwrap();
        for (i, v) in values.iter().enumerate() {
            assert_eq!(
                v.is_nan(),
                !(1..=12).contains(&cells[i]),
                "{} at {i}",
                f.name
            );
        }
    }
    assert!(m.field("nothing").is_none());
    for i in 0..cells.len() {
        for d in 0..6 {
            let bonded = bonds[i] & (1 << d) != 0;
            let j = m.lattice.neighbour(i, d);
            let other = j.is_some_and(|j| (1..=13).contains(&cells[j]));
            assert_eq!(bonded, other && (1..=13).contains(&cells[i]));
            if let (true, Some(j)) = (bonded, j) {
                assert_ne!(bonds[j] & (1 << Hex::opposite(d)), 0);
            }
        }
    }
    let cell = m.units[0].cell as usize;
    let facts = m.inspect(cell);
    assert_eq!(facts["unit"], json!(0));
    assert!(facts["statement"].as_str().unwrap().contains('{'));
    assert!(m.inspect(usize::MAX).is_empty());
    // A click on an empty cell is refused when applied, naming the cell.
    let empty = cells.iter().position(|&c| c == 0).unwrap();
    let mut click = Map::new();
    click.insert("kind".into(), "fault".into());
    click.insert("cells".into(), json!([empty]));
    assert!(m.check_action(&click).is_ok());
    let e = m.apply(&click).unwrap_err().to_string();
    assert!(e.contains("holds no working unit"), "{e}");
}
