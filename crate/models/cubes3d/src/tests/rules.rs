//! The selection rule (step iii): its three built-in forms over the same options, and what each
//! does from the figures' starts.

use super::super::select::{Position, Select, Senses};
use super::*;
use kumiki_model::slot::Slot;

const HERE: u32 = 100;

/// "No motion" at D = 5 and two reachable positions at D = 4 and 7.
fn options() -> Vec<Position> {
    let at = |cell, difference| Position {
        cell,
        difference,
        stay: cell == HERE,
    };
    vec![at(HERE, 5.0), at(1, 4.0), at(2, 7.0)]
}

/// How often each option is chosen in `n` draws.
fn shares(rule: Selection, options: &[Position], temperature: f64, n: usize) -> [f64; 3] {
    let mut rng = Rng::new(9);
    let unit = Senses {
        selection: rule,
        temperature,
        t: 0,
        options: options.to_vec(),
    };
    let mut count = [0usize; 3];
    for _ in 0..n {
        let k = match options[Select::paper(&unit, Some(&mut rng))].cell {
            HERE => 0,
            c => c as usize,
        };
        count[k] += 1;
    }
    count.map(|c| c as f64 / n as f64)
}

#[test]
fn the_three_rules_choose_among_the_same_options_no_motion_included() {
    let n = 30_000;
    // Random: every option alike, "no motion" among them (sd of a share about 0.003).
    for share in shares(Selection::Random, &options(), 1.0, n) {
        assert!((share - 1.0 / 3.0).abs() < 0.015, "{share}");
    }
    // Steepest: always the least difference; with a tie, each of the tied alike.
    assert_eq!(
        shares(Selection::Steepest, &options(), 1.0, 100),
        [0.0, 1.0, 0.0]
    );
    let mut tied = options();
    tied[0].difference = 4.0;
    let [stay, move1, move2] = shares(Selection::Steepest, &tied, 1.0, n);
    assert!((stay - 0.5).abs() < 0.02 && (move1 - 0.5).abs() < 0.02 && move2 == 0.0);
    // MRF: equation 7, P_i proportional to exp(-D_i / T).
    let t = 2.0;
    let w = [
        (-5.0f64 / t).exp(),
        (-4.0f64 / t).exp(),
        (-7.0f64 / t).exp(),
    ];
    let z: f64 = w.iter().sum();
    for (share, wi) in shares(Selection::Mrf, &options(), t, n).iter().zip(w) {
        assert!((share - wi / z).abs() < 0.015, "{share} against {}", wi / z);
    }
    // Cold, it is steepest descent; without "no motion" among the options it never stays.
    assert_eq!(
        shares(Selection::Mrf, &options(), 1e-3, 100),
        [0.0, 1.0, 0.0]
    );
    let moves_only = &options()[1..];
    assert_eq!(shares(Selection::Random, moves_only, 1.0, 1000)[0], 0.0);
}

#[test]
fn random_selection_may_stay_unless_a_link_of_version_4_pins_the_old_reading() {
    let run = |stays: bool| {
        let mut s = presets::scenario("cubes-cube8-zigzag")
            .unwrap()
            .with_override("selection", json!("random"))
            .unwrap()
            .with_override("stop_at_goal", json!(false))
            .unwrap()
            .with_override("random_stays", json!(stays))
            .unwrap();
        s.seed = 4;
        let mut m = Cubes::new(&s).unwrap();
        for _ in 0..1000 {
            m.step();
        }
        m.moves
    };
    // Old: a unit that can move does, so every step has a move. Now a step passes without one
    // when every unit asked chose "no motion".
    assert_eq!(run(false), 1000);
    let moves = run(true);
    assert!((800..1000).contains(&moves), "{moves}");
}

#[test]
fn the_ladder_is_a_local_minimum_of_every_movable_units_difference() {
    // Section 3.3's movable types leave only the ladder's four C21 corners free to move; each
    // has D_0 = 8 against equation 3 and four reachable positions, over or under its C30
    // neighbour (it becomes a C1 beside a C31: 6 + 1 + 3 + 3 = 13) or over or under its C21
    // neighbour (a C1 beside a C21: 6 + 2 + 3 + 3 = 14). No option of least difference is a
    // move, so steepest descent never moves from the ladder.
    let m = model(json!({
        "shape": "######\n######\n", "selection": "steepest",
        "targets": [{"type_lists": "C31[C41, C31, C31]\nC41[C41, C41, C31, C31]"}]
    }));
    assert_eq!(m.movable.len(), 4);
    for &u in &m.movable {
        let u = u as usize;
        assert_eq!(m.st.types[u], types::C21);
        assert_eq!(m.d0(u), 8.0);
        let mut ds: Vec<f64> = m.reach_report(u).iter().map(|r| r.1).collect();
        ds.sort_by(f64::total_cmp);
        assert_eq!(ds, [13.0, 13.0, 14.0, 14.0], "unit {u}");
    }
    let c30 = m
        .units
        .iter()
        .filter(|&&c| m.st.types[c as usize] == types::C30);
    assert_eq!(c30.count(), 8);
}
