use std::collections::BTreeSet;

use serde_json::{json, Value};

use super::connect::Scratch;
use super::motion::{Move, Structure, DIRS, PAD};
use super::typelist::{self, TypeList};
use super::types::{self, TYPE_OF_MASK};
use super::*;
use kumiki_core::presets;
use kumiki_core::run::Run;
use kumiki_core::scenario::Scenario;
use kumiki_model::rng::Rng;
use kumiki_model::shape;

impl Cubes {
    /// The model of a test scenario, built the way a run builds it. Its keys are read again
    /// into this crate's `Spec`: the core (a dev-dependency, for scenarios, presets and runs)
    /// links its own build of this crate, whose `Spec` is another type to the tests.
    fn new(s: &Scenario) -> Result<Cubes> {
        assert_eq!(s.model(), ENTRY.name, "not a cubes3d scenario");
        let spec: Spec = kumiki_model::error::from_value(Value::Object(s.body()))?;
        Ok(Cubes::from_checked(
            kumiki_model::model::Spec::validate(&spec, s.limits)?,
            s.seed,
        ))
    }
}

type C = [i32; 3];

/// Where the origin of the test structures lies in their space.
const O: C = [5, 5, 5];

fn scenario(body: Value) -> Result<Scenario> {
    let mut doc = json!({"version": 1, "model": "cubes3d", "name": "t", "max_steps": 3000});
    for (k, v) in body.as_object().unwrap() {
        doc[k] = v.clone();
    }
    Scenario::from_value(doc)
}

fn model(body: Value) -> Cubes {
    Cubes::new(&scenario(body).unwrap()).unwrap()
}

fn add(a: C, b: C) -> C {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// A structure in a 14-cell cube of space, units given relative to (5, 5, 5).
fn structure(units: &[C]) -> Structure {
    let mut st = Structure::new([14; 3], [PAD; 3], [14 - PAD; 3]);
    let cells: Vec<usize> = units
        .iter()
        .map(|&u| st.index(add(u, O)).unwrap())
        .collect();
    st.place(&cells);
    st
}

fn rel(st: &Structure, cell: u32) -> C {
    let c = st.coord(cell as usize);
    [c[0] - 5, c[1] - 5, c[2] - 5]
}

fn reach(st: &Structure, unit: C) -> BTreeSet<C> {
    let mut s = Scratch::default();
    st.reachable(st.index(add(unit, O)).unwrap(), &mut s);
    s.moves.iter().map(|m| rel(st, m.dest)).collect()
}

fn set(cs: &[C]) -> BTreeSet<C> {
    cs.iter().copied().collect()
}

/// A random connected structure of `n` units grown from the origin, with holes likely when
/// `sparse`.
fn random_units(rng: &mut Rng, n: usize, span: i32, sparse: bool) -> BTreeSet<C> {
    let mut units = BTreeSet::from([[0, 0, 0]]);
    while units.len() < n {
        let list: Vec<C> = units.iter().copied().collect();
        let from = list[rng.index(list.len())];
        let d = DIRS[rng.index(6)];
        let c = add(from, d);
        if c.iter().any(|v| v.abs() > span) || units.contains(&c) {
            continue;
        }
        if sparse {
            let around = DIRS.iter().filter(|&&d| units.contains(&add(c, d))).count();
            if around > 1 && rng.chance(0.7) {
                continue;
            }
        }
        units.insert(c);
    }
    units
}

mod light;
mod motion;
mod rules;
mod runs;
mod typelists;
