use super::election::{self, Kind};
use super::frame;
use super::init::PRIORITY;
use super::motion::{Drive, Refusal, DOWN, RIGHT, UP};
use super::signals::Comm;
use super::spec::{self, Mechanics};
use super::*;
use crate::models::Model;
use crate::scenario::Scenario;
use serde_json::json;

impl Chobie {
    /// The model of a test scenario, built the way a run builds it.
    fn new(s: &Scenario) -> crate::Result<Chobie> {
        let crate::models::ModelSpec::Chobie(spec) = &s.spec else {
            panic!("not a chobie scenario");
        };
        Ok(Chobie::from_checked(crate::models::Spec::validate(
            spec, s.limits,
        )?))
    }
}

fn scenario(world: &str, extra: serde_json::Value) -> Scenario {
    let mut v = json!({
        "version": 1, "model": "chobie", "name": "t", "description": "", "seed": 1,
        "max_steps": 100, "world": world,
    });
    for (k, x) in extra.as_object().unwrap() {
        v[k] = x.clone();
    }
    Scenario::from_json(&v.to_string()).unwrap()
}

/// The message a bad world or parameter is refused with (the scenario reader checks it).
fn refusal(world: &str, extra: serde_json::Value) -> String {
    let mut v = json!({
        "version": 1, "model": "chobie", "name": "t", "description": "", "seed": 1,
        "max_steps": 100, "world": world,
    });
    for (k, x) in extra.as_object().unwrap() {
        v[k] = x.clone();
    }
    match Scenario::from_json(&v.to_string()) {
        Ok(s) => Chobie::new(&s).err().expect("refused").to_string(),
        Err(e) => e.to_string(),
    }
}

fn model(world: &str, extra: serde_json::Value) -> Chobie {
    Chobie::new(&scenario(world, extra)).unwrap()
}

fn crawl(n: u64, form: u64) -> String {
    queries::crawl_world(n, form, 12)
}

/// Steps the model and checks the motion invariants of every transformation: whole lines move
/// one cell along their axis, nothing else moves, the structure stays one piece on the terrain,
/// and no pair of robots meets or parts face-on along the motion.
fn step_checked(m: &mut Chobie) {
    let before = m.body.clone();
    m.step();
    let after = &m.body;
    assert!(
        after.sound(),
        "the structure fell apart or left the terrain"
    );
    let moved: Vec<u32> = (0..before.len() as u32)
        .filter(|&r| before.pos[r as usize] != after.pos[r as usize])
        .collect();
    assert_eq!(moved.len(), m.last.driven.len());
    for &r in &moved {
        let (a, b) = (before.pos[r as usize], after.pos[r as usize]);
        assert_eq!(
            (a.0 - b.0).abs() + (a.1 - b.1).abs(),
            1,
            "one cell per move"
        );
        let dir = (0..4)
            .find(|&d| (a.0 + motion::DX[d], a.1 + motion::DY[d]) == b)
            .unwrap();
        // The line constraint: the whole line along the motion moved, the same way.
        for s in before.line(r, dir) {
            let p = before.pos[s as usize];
            assert_eq!(
                after.pos[s as usize],
                (p.0 + motion::DX[dir], p.1 + motion::DY[dir]),
                "robot {s} is on the line of robot {r} but did not move with it"
            );
        }
        // No detachment or head-on join along the motion axis.
        for e in [dir, (dir + 2) % 4] {
            let was = before.nbr(r, e);
            if was != motion::NONE {
                assert_eq!(after.nbr(r, e), was, "robot {r} parted from {was}");
            }
            let now = after.nbr(r, e);
            if now != motion::NONE {
                assert_eq!(before.nbr(r, e), now, "robot {r} met {now} head-on");
            }
        }
    }
}

#[test]
fn world_text_errors_name_the_line() {
    let bad = |w: &str| refusal(w, json!({}));
    assert_eq!(
        bad("....\n.#x.\n===="),
        "world: line 2, column 3: 'x' is not a tile; use '=' for terrain, '#' for a robot and '.' for empty"
    );
    assert!(
        bad("#...\n..#.\n====").starts_with("world: line 2, column 3: this robot is not connected")
    );
    assert!(bad("##..\n....\n====").contains("no robot rests on the terrain"));
    assert!(bad("....\n====").contains("there is no robot"));
    assert!(bad("\n\n").contains("the world is empty"));
}

#[test]
fn parameters_are_checked() {
    let bad = |extra| refusal("#\n=", extra);
    assert!(bad(json!({"board": 0.2})).starts_with("board:"));
    assert!(bad(json!({"safety_factor": 0})).starts_with("safety_factor:"));
    assert!(bad(json!({"method": "guess"})).starts_with("method:"));
    assert!(bad(json!({"goal": 0})).starts_with("goal:"));
    assert!(bad(json!({"colour": 1})).contains("unknown field"));
}

#[test]
fn extend_copies_the_rightmost_terrain_column() {
    let w = spec::parse_world("#.\n==\n", 3, &crate::Limits::PAGE).unwrap();
    assert_eq!(w.w, 5);
    assert_eq!(w.get(4, 1), spec::Tile::Ground);
    assert_eq!(w.get(4, 0), spec::Tile::Empty);
}

#[test]
fn a_line_moves_whole_and_needs_something_to_slide_against() {
    // A robot on top of a tier of two, on the terrain's left end, beside a gap.
    let m = model("...\n#..\n##.\n==.\n", json!({}));
    let b = &m.body;
    let top = b.robot_at(0, 1);
    // Half a line may not move: the tier's left robot alone would leave its neighbour head-on.
    let half = Drive {
        robots: vec![b.robot_at(0, 2)],
        dir: RIGHT,
    };
    assert_eq!(b.check(&[half]), Err(Refusal::Blocked));
    let lone = Drive {
        robots: vec![b.robot_at(1, 2)],
        dir: RIGHT,
    };
    assert_eq!(b.check(&[lone]), Err(Refusal::HeadOn));
    // The top robot slides right over the tier.
    assert!(b
        .check(&[Drive {
            robots: vec![top],
            dir: RIGHT
        }])
        .is_ok());
    // Moving up it would leave everything: nothing keeps it attached.
    assert_eq!(
        b.check(&[Drive {
            robots: b.line(top, UP),
            dir: UP
        }]),
        Err(Refusal::Disconnected)
    );
    // The whole structure lifted has nothing fixed to push against.
    let all = [
        Drive {
            robots: b.line(b.robot_at(0, 2), UP),
            dir: UP,
        },
        Drive {
            robots: b.line(b.robot_at(1, 2), UP),
            dir: UP,
        },
    ];
    assert_eq!(b.check(&all), Err(Refusal::NoPartner));
    // Two orders that send one robot two ways conflict.
    let two = [
        Drive {
            robots: vec![top],
            dir: RIGHT,
        },
        Drive {
            robots: vec![top],
            dir: DOWN,
        },
    ];
    assert_eq!(b.check(&two), Err(Refusal::Conflict));
}

#[test]
fn exactly_one_leader_in_each_crawl_form() {
    let expected = [
        Kind::TopRight,
        Kind::TopLeft,
        Kind::BottomLeft,
        Kind::BottomRight,
    ];
    for n in [3, 5, 7, 9, 21] {
        for form in 1..=4 {
            let m = model(&crawl(n, form), json!({}));
            let leaders = election::three_rule(&m.body, &mut Comm::default());
            assert_eq!(leaders.len(), 1, "n = {n}, form {form}");
            assert_eq!(
                leaders[0].kind,
                expected[form as usize - 1],
                "n = {n}, form {form}"
            );
        }
    }
}

#[test]
fn a_crawl_cycle_moves_the_structure_one_cell() {
    for n in [3, 5, 7, 9] {
        let mut m = model(&crawl(n, 1), json!({}));
        let start = m.body.pos.clone();
        for cycle in 1..=3 {
            for _ in 0..4 {
                step_checked(&mut m);
                assert_eq!(m.last.leaders.len(), 1);
            }
            assert!((m.distance() - cycle as f64).abs() < 1e-12, "n = {n}");
            // Form 1 again, shifted: the same set of cells moved right by `cycle`.
            let mut a: Vec<_> = start.iter().map(|&(x, y)| (x + cycle, y)).collect();
            let mut b = m.body.pos.clone();
            a.sort();
            b.sort();
            assert_eq!(a, b, "n = {n}");
        }
        assert_eq!(
            m.totals.slots,
            12 * 7,
            "seven slots per transformation whatever n"
        );
    }
}

const FORM_B: &str = "..............\n#######.......\n==============\n";
const FORM_C: &str = "..............\n####..........\n####..........\n==============\n";
const FORM_D: &str = "..............\n.##...........\n#####.........\n==============\n";

#[test]
fn forms_b_and_c_elect_nobody_and_the_fallbacks_recover() {
    for form in [FORM_B, FORM_C] {
        let m = model(form, json!({}));
        assert!(election::three_rule(&m.body, &mut Comm::default()).is_empty());
        let mut first = model(form, json!({}));
        first.step();
        assert_eq!(first.totals.transformations, 0);
        assert_eq!(first.totals.election_failures, 1);
        let mut spent = Vec::new();
        for method in ["trial_and_error", "cautious"] {
            let mut m = model(form, json!({"method": method}));
            step_checked(&mut m);
            assert_eq!(m.last.leaders.len(), 1, "{method}");
            spent.push(m.totals.slots);
            for _ in 0..5 {
                step_checked(&mut m);
            }
            assert!(m.distance() >= 2.0, "{method}: {}", m.distance());
        }
        assert!(
            spent[1] < spent[0],
            "cautious spends fewer slots: {spent:?}"
        );
    }
}

#[test]
fn form_d_elects_several_and_the_priority_sequence_resolves_them() {
    let m = model(FORM_D, json!({}));
    let leaders = election::three_rule(&m.body, &mut Comm::default());
    let mut kinds: Vec<Kind> = leaders.iter().map(|e| e.kind).collect();
    kinds.dedup();
    assert!(kinds.len() >= 2, "{leaders:?}");
    let mut plain = model(FORM_D, json!({}));
    plain.step();
    assert_eq!(
        plain.totals.transformations, 0,
        "conflicting orders: nothing moves"
    );
    let mut with = model(FORM_D, json!({"priority": true}));
    for _ in 0..16 {
        step_checked(&mut with);
        assert_eq!(
            with.last
                .leaders
                .iter()
                .map(|e| e.kind)
                .collect::<std::collections::BTreeSet<_>>()
                .len(),
            1
        );
    }
    assert!(with.distance() >= 3.0);
    assert_eq!(PRIORITY[0], Kind::TopLeft);
}

#[test]
fn the_permanent_leader_sends_more_as_the_structure_grows() {
    let per = |n, leader: &str| {
        let mut m = model(&crawl(n, 1), json!({"leader": leader}));
        for _ in 0..8 {
            step_checked(&mut m);
        }
        (m.totals.slots as f64 / 8.0, m.distance())
    };
    let (t3, d3) = per(3, "temporary");
    let (t21, d21) = per(21, "temporary");
    let (p3, _) = per(3, "permanent");
    let (p21, e21) = per(21, "permanent");
    assert_eq!(t3, t21);
    assert_eq!((d3, d21, e21), (2.0, 2.0, 2.0));
    assert!(p21 > 3.0 * p3, "{p3} → {p21}");
}

fn mech() -> Mechanics {
    let s: spec::Spec = serde_json::from_value(json!({"world": "#\n="})).unwrap();
    Mechanics::from_spec(&s).unwrap()
}

/// A straight horizontal cantilever: a clamped robot and `n` robots beyond it.
fn cantilever(n: i32, m: &Mechanics, tip: f64, weight: bool) -> (frame::Solution, Vec<(u32, u32)>) {
    let pos: Vec<(i32, i32)> = (0..=n).map(|x| (x, 0)).collect();
    let elems = frame::elements(&pos, &|x, y| {
        (y == 0 && (0..=n).contains(&x)).then_some(x as u32)
    });
    let fixed: Vec<bool> = (0..=n).map(|x| x == 0).collect();
    let loads: Vec<[f64; 3]> = (0..=n)
        .map(|x| {
            let w = if weight { m.weight } else { 0.0 };
            [0.0, -(w + if x == n { tip } else { 0.0 }), 0.0]
        })
        .collect();
    (
        frame::solve(m, &pos, &elems, &fixed, &loads).unwrap(),
        elems,
    )
}

#[test]
fn tip_loaded_cantilever_matches_beam_theory() {
    let m = mech();
    let p = 50.0;
    for n in [1, 3, 8, 20] {
        let (sol, _) = cantilever(n, &m, p, false);
        let l = n as f64 * m.length;
        let root = sol.forces[0][1].abs();
        assert!(
            (root - p * l).abs() <= 1e-9 * p * l,
            "n = {n}: root moment {root} vs {}",
            p * l
        );
        let tip = -sol.disp[n as usize][1];
        let theory = p * l * l * l / (3.0 * m.e * m.inertia);
        assert!(
            (tip - theory).abs() <= 1e-9 * theory,
            "n = {n}: tip {tip} vs {theory}"
        );
    }
}

#[test]
fn self_weight_root_moment_grows_with_the_square_of_the_length() {
    let m = mech();
    let root = |n| cantilever(n, &m, 0.0, true).0.forces[0][1].abs();
    for n in [5, 10, 20, 40] {
        // Exactly w·a·n(n + 1)/2 with nodal weights: ~ L² / 2 per unit length.
        let exact = m.weight * m.length * (n * (n + 1)) as f64 / 2.0;
        assert!((root(n) - exact).abs() <= 1e-9 * exact);
    }
    let ratio = root(80) / root(40);
    assert!(
        (ratio - 4.0).abs() < 0.06,
        "doubling the length multiplies the moment by {ratio}"
    );
}

#[test]
fn thickening_the_root_lowers_the_peak_stress() {
    let world = |top: &str| {
        model(
            &format!("{top}\n##########\n====......\n"),
            json!({"tip_load": 100.0}),
        )
        .peak()
    };
    let bare = world("..........");
    let thick = world("..###.....");
    // The peak moves to the end of the thickened part, one cell nearer the load.
    assert!(thick < 0.9 * bare, "bare {bare}, thickened {thick}");
}

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
    let preset = crate::presets::scenario("chobie-crawl5").unwrap();
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
    let preset = crate::presets::scenario("chobie-bridge").unwrap();
    let mut m = Chobie::new(&preset).unwrap();
    let mut modes = Vec::new();
    for _ in 0..30 {
        step_checked(&mut m);
        modes.push(m.mode);
    }
    let first = modes
        .iter()
        .position(|&x| x == Mode::Adaptation)
        .expect("an overload");
    let back = modes[first..]
        .iter()
        .position(|&x| x == Mode::Construction)
        .expect("back to construction");
    // Between the two, the reserves moved right (leader 2) and the overload went away.
    assert!(back > 1);
    assert!(m.totals.adaptations >= 1);
    let mut without = Chobie::new(&preset).unwrap();
    without.p.adaptation = false;
    for _ in 0..30 {
        step_checked(&mut without);
    }
    assert!(m.worst < without.worst);
}
