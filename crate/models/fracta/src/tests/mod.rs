use std::collections::BTreeSet;

use super::derive::derive;
use super::goal::{realisable, Statement};
use super::pattern::{canonical, images, reflect, rotate};
use super::types::CLASSES;
use super::*;
use kumiki_core::run::Run;
use kumiki_core::scenario::Scenario;
use kumiki_core::{models, presets};
use kumiki_model::lattice::Coord;
use proptest::prelude::*;
use search::Spare;

impl Fracta {
    /// The model of a scenario, built the way a run builds it. Its keys are read again into
    /// this crate's `Spec`: the core (a dev-dependency, for scenarios, presets and runs) links
    /// its own build of this crate, whose `Spec` is another type to the tests.
    fn of_scenario(s: &Scenario) -> Result<Fracta> {
        if s.model() != ENTRY.name {
            return Err(Error::field("model", "not a fracta scenario"));
        }
        let spec: Spec = kumiki_model::error::from_value(Value::Object(s.body()))?;
        Ok(Fracta::from_checked(
            model::Spec::validate(&spec, s.limits)?,
            s.seed,
        ))
    }
}

const TRIANGLE: &str = ". . # .\n . # # .\n. # # #\n # # # #\n";
const TRIANGLE_GOAL: &str = "o{K, K}  K{o, K, K, s}  s{K, K, K, K, K, K}\n";

fn scenario(start: &str, goal: &str, seed: u64, extra: Value) -> Scenario {
    let mut doc = json!({
        "version": 1, "model": "fracta", "name": "t", "seed": seed, "max_steps": 5000,
        "start": start, "goal": goal
    });
    for (k, v) in extra.as_object().unwrap() {
        doc[k] = v.clone();
    }
    Scenario::from_value(doc).unwrap()
}

fn class_named(name: &str) -> u8 {
    types().parse(name).unwrap()
}

fn mask_of(bits: &[usize]) -> u8 {
    bits.iter().fold(0, |m, &d| m | 1 << d)
}

/// Checks what must hold after every step: units and cells agree one to one, no two units on a
/// cell, the working units form one connected group, and the per-unit data is current.
fn check_invariants(m: &Fracta) {
    let mut seen = BTreeSet::new();
    for (u, unit) in m.units.iter().enumerate() {
        match unit.status {
            Status::Working | Status::Faulty => {
                assert!(seen.insert(unit.cell), "two units on cell {}", unit.cell);
                assert_eq!(m.occ[unit.cell as usize], u as u32, "occupancy of unit {u}");
            }
            Status::CutOff | Status::Stranded => {
                assert_ne!(m.occ[unit.cell as usize], u as u32)
            }
        }
        assert!(
            unit.x >= 0.0 && unit.x.is_finite(),
            "x of unit {u}: {}",
            unit.x
        );
        assert!(unit.irr >= 0.0 && unit.irr.is_finite());
    }
    let occupied = m.occ.iter().filter(|&&o| o != NO_UNIT).count();
    assert_eq!(
        occupied,
        seen.len(),
        "a cell names a unit that is not there"
    );
    if !m.working.is_empty() {
        assert_eq!(m.components().len(), 1, "the system fell apart");
    }
    let t = types();
    for &u in &m.working {
        let cell = m.units[u as usize].cell;
        assert_eq!(
            m.class[u as usize],
            t.of(m.ring(cell)),
            "stale type of unit {u}"
        );
    }
    assert_eq!(
        m.zero,
        m.working
            .iter()
            .filter(|&&u| m.diff[u as usize] == 0)
            .count()
    );
}

mod fixed_points;
mod goals;
mod holes;
mod motions;
mod patterns;
mod properties;
mod runs;
