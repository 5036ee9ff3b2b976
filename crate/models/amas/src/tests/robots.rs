//! Robots: the blackboard, durations, turns, loaded robots and seeds.

use super::*;

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
    // Every built module breaks at step 6: no module announces the growth front any more. A
    // loaded robot that plans on a broken module beside a vacant site fills it, unless a larger
    // token claimed the site first.
    let mut filled = 0;
    for seed in 1..6 {
        let mut m = model(json!({"robots": 3, "seed": seed, "field": "discrete"}));
        for _ in 0..6 {
            m.step();
        }
        m.apply(&action(json!({"kind": "break", "count": 1000})))
            .unwrap();
        while !m.completed() && m.steps < 5000 {
            let beside: Vec<usize> = (0..m.robots.len())
                .filter(|&r| {
                    let rb = m.robots[r];
                    let (nb, k) = m.neighbours(rb.cell as usize);
                    rb.loaded
                        && rb.busy == 0
                        && !rb.give_way
                        && m.state[rb.cell as usize] & state::BROKEN != 0
                        && nb[..k].iter().any(|&j| m.state[j] & VACANT != 0)
                })
                .collect();
            m.step();
            for r in beside {
                match m.plans[r] {
                    Plan::Place(_) => {
                        assert!(
                            !m.robots[r].loaded,
                            "seed {seed}: robot {r} kept its module"
                        );
                        filled += 1;
                    }
                    plan => assert!(matches!(plan, Plan::Blocked(_)), "seed {seed}: {plan:?}"),
                }
            }
        }
    }
    assert!(
        filled > 0,
        "no loaded robot stood on a broken module beside a site"
    );
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

/// Links made before model version 3 pin the per-robot draw and every loser giving way, and
/// links made before version 4 relaying only with robots that planned this step (`ENTRY.pins`),
/// so every AMAS link of the fixture replays to the state it reached when it was made.
#[test]
fn links_of_earlier_versions_replay_as_they_did() {
    let text = include_str!("../../../../../tests/fixtures/links.json");
    let links: Vec<Value> = serde_json::from_str(text).unwrap();
    let mut checked = 0;
    let older = |e: &&Value| e["model"] == "amas" && e["model_version"].as_u64() < Some(4);
    for entry in links.iter().filter(older) {
        let opened = kumiki_core::link::open(entry["link"].as_str().unwrap()).unwrap();
        let body = opened.scenario.body();
        assert!(opened.made_with < 4, "{}", entry["preset"]);
        if opened.made_with < 3 {
            assert_eq!(body["direction"], json!("robot"));
            assert_eq!(body["give_way"], json!("every_loser"));
        }
        assert_eq!(body["relay_with"], json!("idle"));
        let mut run = Run::new(opened.scenario).unwrap();
        run.advance(entry["steps"].as_u64().unwrap());
        assert_eq!(
            kumiki_core::hash::hex(run.state_hash()),
            entry["hash"].as_str().unwrap(),
            "{}",
            entry["preset"]
        );
        checked += 1;
    }
    assert!(checked >= 13, "{checked} AMAS links");
    // A link made now opens with this version's readings.
    let now = kumiki_core::link::encode(&kumiki_core::presets::scenario("amas-L").unwrap());
    let body = kumiki_core::link::open(&now).unwrap().scenario.body();
    assert_eq!(body["direction"], json!("module"));
    assert_eq!(body["give_way"], json!("locked"));
    assert_eq!(body["relay_with"], json!("waiting"));
}

/// The L of figure 23 standing on its stem.
const STEM: &str = "######\n######\n##....\n##....\n##....\n";

/// Footnote 3: where the field shows a gradient, the module's display decides the way, not the
/// robot's random stream; with the per-robot draw the stream decides among equal neighbours.
#[test]
fn the_module_shows_every_robot_the_same_way() {
    let mut differs = 0;
    for direction in ["module", "robot"] {
        let mut m = model(json!({"target": STEM, "robots": 4, "field": "discrete",
            "direction": direction}));
        for step in 0..60 {
            m.step();
            for r in 0..m.robots.len() {
                let i = m.robots[r].cell as usize;
                if m.state[i] & state::ACTIVE_MASK != MODULE {
                    continue;
                }
                let loaded = m.robots[r].loaded;
                let mut other = m.clone();
                other.rng = kumiki_model::rng::Rng::new(1000 + step);
                let (a, b) = (
                    m.follow(r, i, loaded, false),
                    other.follow(r, i, loaded, false),
                );
                let wandered = m.robots[r].lost;
                match direction {
                    "module" if !wandered => assert_eq!(a, b, "step {step}, robot {r}"),
                    _ => differs += usize::from(a != b),
                }
            }
        }
    }
    assert!(differs > 0, "the per-robot draw never chose otherwise");
}

/// Only the robots a lock holds give way: figure 23's L on its stem, with the discrete field and
/// the token rule, finishes although its robots meet head-on at the corner, and with a penalty
/// of several steps too.
#[test]
fn locks_are_resolved_and_other_losers_wait() {
    let mut waited = 0;
    for (seed, penalty) in [(1, 1), (2, 1), (3, 3)] {
        let mut m = model(
            json!({"target": STEM, "robots": 6, "seed": seed, "field": "discrete",
            "collision": "token", "collision_penalty": penalty}),
        );
        while !m.completed() && m.steps < 20000 {
            m.step();
            for &(r, _, conflict) in &m.losers {
                let r = r as usize;
                match collision::outcome(conflict, m.p.give_way) {
                    collision::Outcome::Waits => {
                        assert!(!m.robots[r].give_way);
                        waited += 1;
                    }
                    collision::Outcome::GivesWay => assert!(m.robots[r].give_way),
                    collision::Outcome::Keeps => assert_eq!(m.robots[r].busy, 0),
                }
            }
        }
        assert!(
            m.completed(),
            "seed {seed}, penalty {penalty}: {:?}",
            m.metrics()
        );
    }
    assert!(waited > 0, "no loser waited");
}

/// 4.6.1: "When two robots collide with each other, the one carrying the module hands it off to
/// the other", a robot still waiting out the penalty of an earlier collision too. Appendix B's
/// L with ten robots, the discrete field, a relay of five steps and a penalty of five: every run
/// finishes. When only robots that planned this step may relay (the reading before model
/// version 4), a loaded robot and an unloaded one each meet the other's penalty or relay in
/// turn and never plan together, and some runs hand the same module back and forth for good.
#[test]
fn a_robot_waiting_out_a_penalty_relays() {
    let unfinished = |relay_with: &str| {
        let mut n = 0;
        for seed in 1..=10 {
            let mut doc = kumiki_core::presets::scenario("amas-L").unwrap().to_value();
            for (k, v) in [
                ("seed", json!(seed)),
                ("robots", json!(10)),
                ("field", json!("discrete")),
                ("collision", json!("relay")),
                ("collision_penalty", json!(5)),
                ("relay_duration", json!(5)),
                ("relay_with", json!(relay_with)),
            ] {
                doc[k] = v;
            }
            let mut m = Amas::new(&Scenario::from_value(doc).unwrap()).unwrap();
            run_to_end(&mut m, 20000);
            n += usize::from(!m.completed());
        }
        n
    };
    assert_eq!(unfinished("waiting"), 0);
    assert!(unfinished("idle") > 0);
}
