use super::election::{self, Kind};
use super::frame;
use super::init::PRIORITY;
use super::motion::{Drive, Refusal, DOWN, RIGHT, UP};
use super::signals::Comm;
use super::spec::{self, Mechanics};
use super::*;
use kumiki_core::scenario::Scenario;
use kumiki_model::model::Model;
use serde_json::json;

impl Chobie {
    /// The model of a test scenario, built the way a run builds it. Its keys are read again
    /// into this crate's `Spec`: the core (a dev-dependency, for scenarios, presets and runs)
    /// links its own build of this crate, whose `Spec` is another type to the tests.
    fn new(s: &Scenario) -> kumiki_model::Result<Chobie> {
        assert_eq!(s.model(), ENTRY.name, "not a chobie scenario");
        let spec: spec::Spec =
            kumiki_model::error::from_value(serde_json::Value::Object(s.body()))?;
        Ok(Chobie::from_checked(kumiki_model::model::Spec::validate(
            &spec, s.limits,
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

mod beams;
mod crawl;
mod loads;
mod world;
