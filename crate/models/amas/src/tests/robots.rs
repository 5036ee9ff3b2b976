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

/// Links made before model version 3 pin the per-robot draw and every loser giving way
/// (`ENTRY.pins`), so every AMAS link of the fixture replays to the state it reached when it
/// was made.
#[test]
fn links_of_earlier_versions_replay_as_they_did() {
    let text = include_str!("../../../../../tests/fixtures/links.json");
    let links: Vec<Value> = serde_json::from_str(text).unwrap();
    let mut checked = 0;
    for entry in links.iter().filter(|e| e["model"] == "amas") {
        let opened = kumiki_core::link::open(entry["link"].as_str().unwrap()).unwrap();
        assert!(opened.made_with < 3, "{}", entry["preset"]);
        assert_eq!(opened.scenario.body()["direction"], json!("robot"));
        assert_eq!(opened.scenario.body()["give_way"], json!("every_loser"));
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
    assert!(checked >= 12, "{checked} AMAS links");
    // A link made now opens with this version's readings.
    let now = kumiki_core::link::encode(&kumiki_core::presets::scenario("amas-L").unwrap());
    let opened = kumiki_core::link::open(&now).unwrap();
    assert_eq!(opened.scenario.body()["direction"], json!("module"));
    assert_eq!(opened.scenario.body()["give_way"], json!("locked"));
}
