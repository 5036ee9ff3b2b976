use std::collections::VecDeque;

use super::field::FAR;
use super::state::{code, CLAIMED, CONVEYOR, FRONT, MODULE, SOURCE, VACANT};
use super::view::action;
use super::*;
use kumiki_core::run::Run;
use kumiki_core::scenario::Scenario;
use proptest::prelude::*;
use serde_json::json;

impl Amas {
    /// The model of a test scenario, built the way a run builds it. Its keys are read again
    /// into this crate's `Spec`: the core (a dev-dependency, for scenarios, presets and runs)
    /// links its own build of this crate, whose `Spec` is another type to the tests.
    fn new(s: &Scenario) -> kumiki_model::Result<Amas> {
        assert_eq!(s.model(), ENTRY.name, "not a amas scenario");
        let spec: Spec = kumiki_model::error::from_value(Value::Object(s.body()))?;
        Ok(Amas::from_checked(
            kumiki_model::model::Spec::validate(&spec, s.limits)?,
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
    assert_eq!(
        m.mixed_collisions + m.loaded_collisions + m.unloaded_collisions,
        m.collisions,
        "every collision has one kind"
    );
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

mod checks;
mod disturbances;
mod fields;
mod robots;
