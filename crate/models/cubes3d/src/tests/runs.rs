//! Runs: invariants, disturbances, the selection rules, light, the view and the checks.

use super::*;
use kumiki_core::models;

/// Everything the incremental bookkeeping maintains, recomputed from scratch.
pub(super) fn check_invariants(m: &Cubes) {
    let occupied: Vec<usize> = m.st.units();
    assert_eq!(
        occupied.len(),
        m.units.len(),
        "units lost, created or stacked"
    );
    let mut listed: Vec<usize> = m.units.iter().map(|&u| u as usize).collect();
    listed.sort_unstable();
    assert_eq!(
        listed, occupied,
        "two units share a cell or a unit is missing"
    );
    assert_eq!(m.diff.len(), m.units.len());
    assert_eq!(m.stable.len(), m.units.len());
    assert_eq!(m.took.len(), m.units.len());
    assert!(m.took.iter().all(|&t| t <= m.steps));
    for (k, &u) in m.units.iter().enumerate() {
        assert_eq!(m.upos[u as usize], k as u32);
    }
    assert!(m.st.connected(), "the structure came apart");
    let mut zero = 0;
    for &c in &occupied {
        assert!(!m.st.wall[c]);
        assert_eq!(m.st.types[c], TYPE_OF_MASK[m.st.mask(c) as usize]);
        let prof = m.st.profile(c);
        let d = m.difference(m.target[c], &prof);
        assert_eq!(m.d0(c).to_bits(), d.to_bits(), "stale difference at {c}");
        // D is zero exactly when the unit's type-list is one of the target's.
        let matches = m.targets[m.target[c] as usize].lists.contains(&prof);
        assert_eq!(d == 0.0, matches, "cell {c}: D = {d}");
        zero += usize::from(d == 0.0);
        assert_eq!(m.mpos[c] != u32::MAX, m.eligible(c));
    }
    assert_eq!(zero, m.zero);
    if let Some(z) = m.st.plane {
        let on = occupied.iter().filter(|&&c| m.st.coord(c)[2] == z).count();
        assert_eq!(on as u32, m.st.on_plane, "units counted on the plane");
        assert!(on > 0, "the structure let go of its holding plane");
    }
    assert_eq!(
        m.movable.len(),
        occupied.iter().filter(|&&c| m.eligible(c)).count()
    );
}

fn run_checked(m: &mut Cubes, steps: usize) {
    check_invariants(m);
    for _ in 0..steps {
        m.step();
        check_invariants(m);
    }
}

#[test]
fn invariants_hold_on_every_step_of_random_runs() {
    for (i, sel) in ["mrf", "random", "steepest"].iter().enumerate() {
        for preset in ["cubes-cube8-zigzag", "cubes-box12-ladder", "cubes-light"] {
            let mut s = presets::scenario(preset).unwrap();
            s.seed = 40 + i as u64;
            let s = s.with_override("selection", json!(sel)).unwrap();
            let mut m = Cubes::new(&s).unwrap();
            run_checked(&mut m, 250);
        }
    }
    // Random blobs, several movers per step, every type movable, tight walls.
    let mut rng = Rng::new(8);
    for round in 0..6 {
        let units = random_units(&mut rng, 20 + round * 4, 2, round % 2 == 1);
        let mut text = String::new();
        for z in -2..=2 {
            if z > -2 {
                text.push_str("---\n");
            }
            for y in -2..=2 {
                for x in -2..=2 {
                    text.push(if units.contains(&[x, y, z]) { '#' } else { '.' });
                }
                text.push('\n');
            }
        }
        let selection = ["random", "mrf"][round % 2];
        let mut m = model(json!({
            "seed": round, "shape": text, "margin": 1 + round % 3,
            "movers": 1 + round % 3, "mover_distance": 1 + round,
            "movable": ["C1", "C20", "C21", "C30", "C31", "C40", "C41", "C5"],
            "selection": selection,
            "targets": [{"shape": "###\n###\n---\n###\n###\n"}]
        }));
        run_checked(&mut m, 300);
    }
}

#[test]
fn disturbances_keep_the_books_straight() {
    let mut m = Cubes::new(&presets::scenario("cubes-box12-ladder").unwrap()).unwrap();
    let act = |kind: &str, cell: usize| -> Action {
        json!({"kind": kind, "cells": [cell]})
            .as_object()
            .cloned()
            .unwrap()
    };
    for _ in 0..20 {
        m.step();
    }
    // An end unit of the ladder can go; then add it back beside another unit.
    let victim = *m
        .units
        .iter()
        .find(|&&c| {
            let mut s = Scratch::default();
            m.st.stays_connected(c as usize, None, &mut s)
        })
        .unwrap() as usize;
    m.apply(&act("remove", victim)).unwrap();
    check_invariants(&m);
    assert_eq!(m.units.len(), 11);
    assert!(
        m.apply(&act("remove", victim)).is_err(),
        "no unit there any more"
    );
    let spot = (0..m.st.len())
        .find(|&c| !m.st.wall[c] && !m.st.occupied(c) && m.st.mask(c) != 0)
        .unwrap();
    m.apply(&act("add", spot)).unwrap();
    check_invariants(&m);
    assert!(m.apply(&act("add", spot)).is_err());
    let lonely = (0..m.st.len())
        .find(|&c| !m.st.wall[c] && m.st.mask(c) == 0 && !m.st.occupied(c))
        .unwrap();
    assert!(m
        .apply(&act("add", lonely))
        .unwrap_err()
        .to_string()
        .contains("touches no unit"));
    // Hold a movable unit: it leaves the movable set; release it again.
    let held = m.movable[0] as usize;
    m.apply(&act("hold", held)).unwrap();
    assert!(!m.eligible(held));
    check_invariants(&m);
    run_checked(&mut m, 100);
    assert!(m.check_action(&act("explode", 1)).is_err());
    assert!(m.check_action(&act("remove", usize::MAX >> 8)).is_err());
    let switch = json!({"kind": "switch"}).as_object().cloned().unwrap();
    assert!(m.check_action(&switch).is_err(), "one target only");
    // A cut unit of a chain may not be removed.
    let mut chain = model(json!({"shape": "###\n", "targets": [{"type_lists": "C1[C1]"}]}));
    let middle = (0..chain.st.len())
        .find(|&c| chain.st.types[c] == types::C20)
        .unwrap();
    let err = chain.apply(&act("remove", middle)).unwrap_err().to_string();
    assert!(err.contains("split"), "{err}");
    // On a holding plane the last unit touching it stays: the structure stays fixed to it.
    let mut tower = model(json!({"shape": "#\n---\n#\n---\n#\n", "ground": "anchor",
                                 "targets": [{"type_lists": "C1[C20]"}]}));
    let foot = tower.units.iter().map(|&c| c as usize).min().unwrap();
    assert!(tower
        .st
        .stays_connected(foot, None, &mut Scratch::default()));
    let err = tower.apply(&act("remove", foot)).unwrap_err().to_string();
    assert!(err.contains("ground plane holds"), "{err}");
    check_invariants(&tower);
}

#[test]
fn a_run_stops_when_every_unit_matches_and_is_deterministic() {
    let s = presets::scenario("cubes-cube8-zigzag").unwrap();
    let mut a = Run::new(s.clone()).unwrap();
    a.run_to_end();
    let mut b = Run::new(s).unwrap();
    b.run_to_end();
    assert_eq!(a.outcome(), b.outcome());
    let out = a.outcome();
    if out.completed {
        assert_eq!(out.metrics["mean_difference"], json!(0.0));
        assert_eq!(out.metrics["completed"], json!(1));
        assert!(out.steps < 5000);
    }
    let mut other = presets::scenario("cubes-cube8-zigzag").unwrap();
    other.seed = 2;
    let mut c = Run::new(other).unwrap();
    c.run_to_end();
    assert_ne!(c.outcome().hash, a.outcome().hash);
}

#[test]
fn the_mrf_rule_beats_its_baselines_on_the_cube() {
    // Qualitative check of section 5 (not a number from the paper): over a few seeds, MRF
    // reaches a lower mean difference after 1500 steps than the random and steepest rules.
    let mean_after = |sel: &str| -> f64 {
        (1..=6)
            .map(|seed| {
                let mut s = presets::scenario("cubes-cube8-zigzag")
                    .unwrap()
                    .with_override("selection", json!(sel))
                    .unwrap()
                    .with_override("max_steps", json!(1500))
                    .unwrap();
                s.seed = seed;
                let mut r = Run::new(s).unwrap();
                r.run_to_end();
                r.outcome().metrics["mean_difference"].as_f64().unwrap()
            })
            .sum::<f64>()
            / 6.0
    };
    let (mrf, random, steepest) = (
        mean_after("mrf"),
        mean_after("random"),
        mean_after("steepest"),
    );
    assert!(mrf < random && mrf < steepest, "{mrf} {random} {steepest}");
}

#[test]
fn the_light_seeking_structure_stays_on_its_plane_and_counts_its_moves() {
    // Section 6's structure is placed on a plane and fixed to it: while units are carried off
    // the plane and back, one always touches it (without rule 5, most runs let go of it within
    // 1000 steps and went on in free space).
    for seed in 1..=5 {
        let mut s = presets::scenario("cubes-light").unwrap();
        s.seed = seed;
        let mut m = Cubes::new(&s).unwrap();
        let mut left_plane = 0;
        for _ in 0..1000 {
            let before = m.st.on_plane;
            m.step();
            assert!(m.st.on_plane > 0, "seed {seed}: let go of the plane");
            left_plane += usize::from(m.st.on_plane < before);
        }
        assert!(left_plane > 0, "seed {seed}: units do leave the plane");
        check_invariants(&m);
        // A move changes a unit's place along the light by one cell at most, so the centre of
        // mass of eight units moves an eighth of a cell per move toward or away.
        let metrics = m.metrics();
        let count = |k: &str| metrics[k].as_f64().unwrap();
        assert!(count("moves_toward") + count("moves_away") <= count("moves"));
        let net = (count("moves_toward") - count("moves_away")) / 8.0;
        assert_eq!(metrics["displacement"].as_f64().unwrap(), net);
    }
}

#[test]
fn light_switches_targets_and_holds_the_lit_units() {
    let s = presets::scenario("cubes-light").unwrap();
    let mut m = Cubes::new(&s).unwrap();
    assert_eq!(m.metrics()["displacement"], json!(0.0));
    let lit: Vec<usize> = m
        .units
        .iter()
        .map(|&c| c as usize)
        .filter(|&c| m.lit(c))
        .collect();
    assert_eq!(lit.len(), 4, "the cube's face toward the light");
    // Each unit switches on its own D_0, after it has stayed under the threshold for 30
    // steps.
    while m.switches == 0 && m.steps < 1000 {
        m.step();
        assert!(m.steps >= 30 || m.switches == 0);
    }
    assert!(
        m.switches > 0,
        "units of the cube stay under their threshold"
    );
    for &c in &m.units {
        let c = c as usize;
        if m.target[c] == 1 {
            assert_eq!(m.stable[m.upos[c] as usize], 0);
        }
    }
    // The units that switched to the ladder and see the light are held.
    for &c in &m.units {
        let c = c as usize;
        assert_eq!(
            m.flags[c] & HELD_LIT != 0,
            m.target[c] == 1 && m.lit(c),
            "cell {c}"
        );
        if m.target[c] == 1 && m.lit(c) {
            assert!(!m.eligible(c));
        }
    }
    check_invariants(&m);
    // A switch by click moves every unit on from the target most units hold.
    if m.main_target() == 0 {
        m.apply(&json!({"kind": "switch"}).as_object().cloned().unwrap())
            .unwrap();
    }
    assert!(m.units.iter().all(|&c| m.target[c as usize] == 1));
    m.apply(&json!({"kind": "switch"}).as_object().cloned().unwrap())
        .unwrap();
    assert!(m.units.iter().all(|&c| m.target[c as usize] == 0));
    assert!(m.units.iter().all(|&c| m.flags[c as usize] & HELD_LIT == 0));
    check_invariants(&m);
}

#[test]
fn scene_and_layout_describe_the_view() {
    let m = Cubes::new(&presets::scenario("cubes-light").unwrap()).unwrap();
    let scene = m.scene();
    assert_eq!(scene.light, Some([1.0, 0.0, 0.0]));
    assert_eq!(scene.ground, Some(PAD));
    assert_eq!(scene.ghost.len(), 8);
    let layout = m.layout();
    assert_eq!(layout.cells.len(), 9);
    assert_eq!(layout.cells[0].name, "C1");
    let n = m.st.len();
    assert_eq!(m.cells().len(), n);
    for f in &layout.fields {
        assert_eq!(m.field(&f.name).unwrap().len(), n, "{}", f.name);
    }
    // The inspector lists the reachable positions as cell indices.
    let p = m.movable[0] as usize;
    let info = m.inspect(p);
    assert_eq!(info["unit"], json!(true));
    let listed: Vec<u64> = info["reachable"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_u64().unwrap())
        .collect();
    let expect: Vec<u64> = m.reach_report(p).iter().map(|r| u64::from(r.0)).collect();
    assert_eq!(listed, expect);
    assert_eq!(info["type_list"], json!("C31[C31, C31, C31]"));
    assert!(m.inspect(usize::MAX).is_empty());
}

#[test]
fn scenarios_with_bad_values_are_errors_that_name_the_field() {
    let base = || json!({"shape": "##\n", "targets": [{"type_lists": "C1[C1]"}]});
    let cases = [
        ("w", json!(0.0), "w"),
        ("a", json!(-1.0), "a"),
        ("c", json!(0), "c"),
        ("selection", json!("greedy"), "selection"),
        ("light", json!("up"), "light"),
        ("ground", json!("lava"), "ground"),
        ("movable", json!(["C1", "C9"]), "movable[1]"),
        ("margin", json!(1000), "margin"),
        ("movers", json!(0), "movers"),
        ("stable_steps", json!(0), "stable_steps"),
        ("shape", json!("#.#\n"), "shape"),
        ("shape", json!("#\n"), "shape"),
        ("shape", json!(""), "shape"),
        ("targets", json!([]), "targets"),
        ("targets", json!([{}]), "targets[0]"),
        ("targets", json!([{"shape": "#x\n"}]), "targets[0].shape"),
        (
            "targets",
            json!([{"type_lists": "C1[C1]", "hold_lit": true}]),
            "targets[0].hold_lit",
        ),
        ("bogus", json!(1), "bogus"),
    ];
    for (key, value, path) in cases {
        let mut body = base();
        body[key] = value;
        let err = scenario(body).unwrap_err().to_string();
        assert!(err.starts_with(&format!("{path}:")), "{key}: {err}");
    }
    // A space too large is refused before anything is allocated.
    let mut body = base();
    body["shape"] = json!("#".repeat(600));
    assert!(scenario(body)
        .unwrap_err()
        .to_string()
        .contains("exceeds the limit"));
}

#[test]
fn queries_derive_and_check_descriptions() {
    let out = models::query(
        "cubes3d",
        "derive",
        &json!({"shape": "##\n##\n---\n##\n##\n"}),
    )
    .unwrap();
    assert_eq!(out["type_lists"], json!("C31[C31, C31, C31]\n"));
    assert_eq!(out["units"], json!(8));
    let out = models::query(
        "cubes3d",
        "derive",
        &json!({"units": [[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1],[0,0,2],[1,0,2],[0,1,2],[1,1,2]]}),
    )
    .unwrap();
    assert_eq!(
        out["type_lists"],
        json!("C31[C41, C31, C31]\nC41[C41, C41, C31, C31]\n")
    );
    let err = models::query("cubes3d", "check", &json!({"type_lists": "C31[C31]"})).unwrap_err();
    assert!(err.to_string().starts_with("type_lists: line 1"), "{err}");
    assert!(models::query("cubes3d", "nope", &json!({})).is_err());
    assert!(models::query("amas", "derive", &json!({})).is_err());
    assert!(models::query("cubes3d", "derive", &json!({"units": "x"})).is_err());
}

#[test]
fn derived_descriptions_hold_for_the_shape_they_came_from() {
    // A structure placed in its own target shape has D = 0 everywhere: it is complete.
    for shape in [
        "###\n#.#\n###\n---\n#..\n...\n...\n",
        "####\n####\n",
        "##\n##\n---\n#.\n..\n",
    ] {
        let m = model(json!({"shape": shape, "targets": [{"shape": shape}]}));
        assert!(m.completed(), "{shape}");
        let lists = typelist::describe_grid(&shape::parse_cubic(shape).unwrap()).unwrap();
        let padded: Vec<[u8; 7]> = lists.iter().map(TypeList::padded).collect();
        assert_eq!(padded, m.targets[0].lists);
    }
}

#[test]
fn the_box_preset_has_the_self_repair_papers_goal_and_movable_types() {
    // Equation 6 of "Experiment of self-repairing modular machine", as printed.
    let eq6 = typelist::parse("C31{C31, C31, C41} C41{C31, C31, C41, C41}").unwrap();
    let m = Cubes::new(&presets::scenario("cubes-box12-ladder").unwrap()).unwrap();
    let padded: Vec<[u8; 7]> = eq6.iter().map(TypeList::padded).collect();
    assert_eq!(m.targets[0].lists, padded);
    let movable = (1u16 << types::C1) | (1u16 << types::C21) | (1u16 << types::C31);
    assert_eq!(m.movable_types, movable);
}

#[test]
fn steepest_descent_takes_each_units_least_option_staying_included() {
    // From the ladder no unit has a reachable position below its own D_0: steepest descent,
    // with "no motion" as option 0, never moves.
    let mut m = model(json!({
        "shape": "######\n######\n", "selection": "steepest",
        "targets": [{"type_lists": "C31[C41, C31, C31]\nC41[C41, C41, C31, C31]"}]
    }));
    for &u in &m.movable.clone() {
        let least = m
            .reach_report(u as usize)
            .iter()
            .map(|r| r.1)
            .fold(f64::INFINITY, f64::min);
        assert!(least > m.d0(u as usize), "unit {u}: {least}");
    }
    for _ in 0..50 {
        m.step();
    }
    assert_eq!(m.moves, 0);
    // From the zigzag, every move goes to a position of least difference among the mover's
    // options, no higher than its D_0, and the run stops in a minimum short of the cube.
    let mut s = presets::scenario("cubes-cube8-zigzag")
        .unwrap()
        .with_override("selection", json!("steepest"))
        .unwrap();
    s.seed = 3;
    let mut m = Cubes::new(&s).unwrap();
    for _ in 0..300 {
        let before: Vec<(usize, f64, f64)> = m
            .movable
            .iter()
            .map(|&u| {
                let u = u as usize;
                let least = m
                    .reach_report(u)
                    .iter()
                    .map(|r| r.1)
                    .fold(f64::INFINITY, f64::min);
                (u, m.d0(u), least)
            })
            .collect();
        let moves = m.moves;
        m.step();
        if m.moves == moves {
            assert!(before.iter().all(|&(_, d0, least)| least > d0));
            continue;
        }
        let left = m.events.iter().find(|e| e.kind == LEFT).unwrap().cell as usize;
        let (_, d0, least) = before.iter().find(|b| b.0 == left).copied().unwrap();
        assert!(least <= d0, "moved from {left} though staying was better");
    }
    assert!(m.moves > 0 && !m.completed(), "{} moves", m.moves);
}

#[test]
fn without_stop_at_goal_a_run_goes_on_past_the_goal() {
    let shape = "##\n##\n---\n##\n##\n";
    let s = |stop: bool, selection: &str| {
        model(json!({
            "shape": shape, "selection": selection, "stop_at_goal": stop,
            "targets": [{"type_lists": "C31[C31, C31, C31]"}]
        }))
    };
    // The cube is its own goal from step 0.
    assert!(s(true, "random").completed());
    let mut m = s(false, "random");
    assert!(!m.completed());
    assert_eq!(m.reached, Some(0));
    // Random selection takes staying and each position alike, so the cube does not last.
    for _ in 0..20 {
        m.step();
    }
    assert!(m.moves > 0 && m.reached == Some(0));
}

#[test]
fn the_total_difference_read_in_lanes_is_the_chain_of_additions_bit_for_bit() {
    let chain = |m: &Cubes| m.diff.iter().sum::<f64>().to_bits();
    let mut lanes = 0;
    for (preset, w, a) in [
        ("cubes-box27-plank", 3.0, 1.0),
        ("cubes-box16-movers", 2.0, 3.0),
        ("cubes-light", 3.0, 1.0),
        ("cubes-box12-ladder", 2.5, 0.3),
    ] {
        let s = presets::scenario(preset)
            .unwrap()
            .with_override("w", json!(w))
            .unwrap()
            .with_override("a", json!(a))
            .unwrap();
        let mut m = Cubes::new(&s).unwrap();
        assert_eq!(
            m.whole_diffs,
            w == 3.0 || w == 2.0,
            "{preset}: W {w}, a {a}"
        );
        for _ in 0..300 {
            assert_eq!(
                m.total_difference().to_bits(),
                chain(&m),
                "{preset} at {}",
                m.steps
            );
            lanes += usize::from(m.whole_diffs && m.diff.len() >= crate::state::LANES);
            m.step();
        }
    }
    assert!(lanes > 600, "{lanes} sums in lanes");
}
