//! The model interface and the registry of models, one module per model.
//!
//! A model owns its state and its [`Rng`](crate::rng::Rng); the [`Run`](crate::run::Run) drives
//! it. Everything a renderer needs is described once by [`Layout`] and then read each frame as
//! flat buffers ([`Model::cells`], [`Model::field`]) plus small lists ([`Model::agents`],
//! [`Model::events`]).

use std::borrow::Cow;

use schemars::JsonSchema;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

use crate::error::{Error, Result};
use crate::hash::StateHasher;
use crate::lattice::LatticeKind;
use crate::limits::Limits;

pub mod amas;
pub mod chobie;
pub mod cubes3d;
pub mod fracta;

/// Named metric values, sorted by name. Counts are integers, ratios floats.
pub type Metrics = Map<String, Value>;

/// One metric's value as a model reports it: given by name to [`Model::each_metric`], so a
/// caller that wants every step's values (the page's chart) needs no map per step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Metric {
    Count(u64),
    /// A ratio or a measure; a non-finite value reads as missing.
    Real(f64),
    Flag(bool),
    /// Not defined yet (a time to completion before completion, a ratio of nothing).
    Missing,
}

impl Metric {
    pub fn to_json(self) -> Value {
        match self {
            Metric::Count(n) => n.into(),
            Metric::Real(x) => serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number),
            Metric::Flag(b) => b.into(),
            Metric::Missing => Value::Null,
        }
    }

    /// The number a chart plots (a flag as 0 or 1), or none.
    pub fn plotted(self) -> Option<f64> {
        match self {
            Metric::Count(n) => Some(n as f64),
            Metric::Real(x) => x.is_finite().then_some(x),
            Metric::Flag(b) => Some(f64::from(u8::from(b))),
            Metric::Missing => None,
        }
    }
}

/// A model action (a disturbance), as written in a scenario or sent by a click in the page.
pub type Action = Map<String, Value>;

/// A code in the cell buffer, an agent kind or an event kind, with its name and colour.
#[derive(Clone, Debug, Serialize, PartialEq, Deserialize, JsonSchema)]
pub struct LegendEntry {
    pub code: u8,
    pub name: String,
    /// CSS colour.
    pub color: String,
}

impl LegendEntry {
    pub fn new(code: u8, name: &str, color: &str) -> Self {
        LegendEntry {
            code,
            name: name.into(),
            color: color.into(),
        }
    }
}

/// A scalar field defined on the cells, drawn as an overlay.
#[derive(Clone, Debug, Serialize, PartialEq, Deserialize, JsonSchema)]
pub struct FieldInfo {
    pub name: String,
    pub label: String,
    /// Draw gradient arrows on top of the heatmap.
    pub arrows: bool,
}

/// A click tool the page offers for this model. Clicking a cell sends `action` with the cell's
/// index added as `"cells": [i]`.
#[derive(Clone, Debug, Serialize, PartialEq, Deserialize, JsonSchema)]
pub struct ToolInfo {
    pub name: String,
    pub label: String,
    pub action: Action,
}

/// What a renderer needs to know once per run.
#[derive(Clone, Debug, Serialize, PartialEq, Deserialize, JsonSchema)]
pub struct Layout {
    pub lattice: LatticeKind,
    /// Width, height, depth in cells.
    pub dims: [u32; 3],
    /// Meaning of each code in the cell buffer. Code 0 is "nothing here" and is not drawn.
    pub cells: Vec<LegendEntry>,
    pub agents: Vec<LegendEntry>,
    pub events: Vec<LegendEntry>,
    pub fields: Vec<FieldInfo>,
    pub tools: Vec<ToolInfo>,
    /// The cell legend's names are short labels (connection types) worth writing on each cell
    /// when it is drawn large enough.
    pub cell_labels: bool,
    /// The metric worth charting against step by default.
    pub chart: String,
    /// The run has a goal it completes. Without one (a structure that keeps moving toward a
    /// light, say) a run that reaches its step limit has simply run its course.
    pub goal: bool,
}

/// Optional scene information for 3-D views, beyond the cells. Models without any return the
/// default (nothing to draw). It may change between steps (a target switched, for instance), so a
/// view reads it again after stepping.
#[derive(Clone, Debug, Default, Serialize, PartialEq, Deserialize, JsonSchema)]
#[serde(default)]
pub struct Scene {
    /// Cells of a reference shape (a target) to draw as a translucent ghost.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub ghost: Vec<u32>,
    /// Unit vector from the structure toward a light source, in lattice axes (x, y, z).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub light: Option<[f32; 3]>,
    /// A ground plane under layer z = `ground` (it touches the bottom faces of that layer's
    /// cells); nothing lies below it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ground: Option<u32>,
}

/// An agent standing on a cell (a robot on a module).
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Eq)]
pub struct Agent {
    pub cell: u32,
    pub kind: u8,
}

/// Something that happened at a cell during the last step (a collision, a relay).
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Eq)]
pub struct Event {
    pub cell: u32,
    pub kind: u8,
}

/// A copy of a model in the middle of its run, for keyframes ([`crate::timeline`]). Every
/// model gets it by deriving `Clone`.
pub trait Snapshot {
    fn snapshot(&self) -> Box<dyn Model>;
}

impl<T: Model + Clone + 'static> Snapshot for T {
    fn snapshot(&self) -> Box<dyn Model> {
        Box::new(self.clone())
    }
}

/// A simulation model. Implementations are deterministic functions of their scenario and seed.
pub trait Model: Snapshot {
    fn layout(&self) -> Layout;
    /// Advances one step.
    fn step(&mut self);
    /// Steps taken so far.
    fn steps(&self) -> u64;
    /// True when the model's goal is reached.
    fn completed(&self) -> bool;
    /// Gives every metric to `f`, by name.
    fn each_metric(&self, f: &mut dyn FnMut(&'static str, Metric));
    /// The metrics as one JSON object, sorted by name.
    fn metrics(&self) -> Metrics {
        let mut m = Map::new();
        self.each_metric(&mut |name, value| {
            m.insert(name.into(), value.to_json());
        });
        m
    }
    /// Feeds every part of the state that later steps depend on.
    fn hash_state(&self, h: &mut StateHasher);
    /// One code per lattice cell; see [`Layout::cells`].
    fn cells(&self) -> Cow<'_, [u8]>;
    /// One value per lattice cell for a field named in [`Layout::fields`]; NaN where undefined.
    fn field(&self, name: &str) -> Option<Cow<'_, [f32]>>;
    fn agents(&self) -> Vec<Agent>;
    /// Events of the last step.
    fn events(&self) -> Vec<Event>;
    /// Checks the form of an action (its kind and fields), whatever the state: a scenario is
    /// checked before its first step, and a disturbance recorded at step 360 must still read as
    /// valid then.
    fn check_action(&self, action: &Action) -> Result<()>;
    /// Applies an action now (a scheduled disturbance or a click). An action that does not fit
    /// the present state (a cell with nothing to remove) is an error and changes nothing; a
    /// scheduled one is then skipped, identically in every replay.
    fn apply(&mut self, action: &Action) -> Result<()>;
    /// A few facts about one cell, for the page's inspector.
    fn inspect(&self, _cell: usize) -> Map<String, Value> {
        Map::new()
    }
    /// Ghost, light and ground for 3-D views; see [`Scene`].
    fn scene(&self) -> Scene {
        Scene::default()
    }
    /// Bonds between units, for models whose units hold on to each other: one bit mask per
    /// lattice cell, bit `d` set when the cell's unit is bonded to the unit in direction `d`
    /// (the lattice's direction numbering). Empty when the model has no bonds to draw.
    fn bonds(&self) -> Cow<'_, [u8]> {
        Cow::Borrowed(&[])
    }
}

/// A registered model.
pub struct ModelEntry {
    pub name: &'static str,
    pub title: &'static str,
    pub default_max_steps: u64,
    /// The version of the model's behaviour, written into every share link. Raise it by one when
    /// a change makes the same scenario and seed run differently (when the golden hashes of its
    /// presets change): links made before then still open, and the page says they were made with
    /// an earlier Kumiki. Links that carry no version were made with version 1.
    pub model_version: u32,
    /// Reads the model's keys of a scenario into its typed description.
    pub parse: fn(Value) -> Result<ModelSpec>,
    /// The JSON Schema of those keys (see `crate::schema`).
    #[cfg(feature = "schema")]
    pub schema: fn(&mut schemars::SchemaGenerator) -> schemars::Schema,
    /// The JSON Schema of one of its actions (a disturbance without its `at`).
    #[cfg(feature = "schema")]
    pub disturbance: fn(&mut schemars::SchemaGenerator) -> schemars::Schema,
}

/// Every model, in gallery order.
pub const MODELS: &[ModelEntry] = &[amas::ENTRY, chobie::ENTRY, cubes3d::ENTRY, fracta::ENTRY];

/// A helper call a model offers beside its runs, for editors and the CLI: deriving a target
/// description from a shape, checking one. JSON arguments, a JSON answer; errors name the
/// argument and the problem like scenario errors do.
pub struct Query {
    pub model: &'static str,
    pub name: &'static str,
    pub description: &'static str,
    pub run: fn(&Value) -> Result<Value>,
}

/// Every helper call, by model.
pub const QUERIES: &[Query] = &[
    Query {
        model: "chobie",
        name: "crawl",
        description: "The world text of a crawl form (figure 7): {\"robots\": odd n ≥ 3, \"form\": 1-4, \"margin\": empty columns}",
        run: chobie::queries::crawl,
    },
    Query {
        model: "cubes3d",
        name: "derive",
        description: "The type-lists of a shape: {\"shape\": cubic layers} or {\"units\": [[x, y, z], ...]}",
        run: cubes3d::query_derive,
    },
    Query {
        model: "cubes3d",
        name: "check",
        description: "Checks type-lists ({\"type_lists\": text}) and returns them in normal form",
        run: cubes3d::query_check,
    },
    Query {
        model: "fracta",
        name: "derive",
        description: "Goal statements of a hex shape ({\"shape\": text}); shapes separated by '---' give priorities 1, 2, ...",
        run: fracta::queries::derive,
    },
    Query {
        model: "fracta",
        name: "check",
        description: "Checks goal statements ({\"goal\": text}) and returns them in normal form",
        run: fracta::queries::check,
    },
    Query {
        model: "fracta",
        name: "types",
        description: "The connection types: name, ASCII spelling, bonds, movable, colour",
        run: fracta::queries::types,
    },
];

/// Runs a model's helper call, see [`QUERIES`].
pub fn query(model: &str, name: &str, args: &Value) -> Result<Value> {
    entry(model)?;
    let q = QUERIES
        .iter()
        .find(|q| q.model == model && q.name == name)
        .ok_or_else(|| {
            let known: Vec<&str> = QUERIES
                .iter()
                .filter(|q| q.model == model)
                .map(|q| q.name)
                .collect();
            Error::field(
                "query",
                match known.is_empty() {
                    true => format!("model '{model}' answers no queries"),
                    false => format!(
                        "model '{model}' has no query '{name}'; known: {}",
                        known.join(", ")
                    ),
                },
            )
        })?;
    (q.run)(args)
}

pub fn entry(name: &str) -> Result<&'static ModelEntry> {
    MODELS.iter().find(|m| m.name == name).ok_or_else(|| {
        Error::field(
            "model",
            format!(
                "unknown model '{name}'; known: {}",
                MODELS.iter().map(|m| m.name).collect::<Vec<_>>().join(", ")
            ),
        )
    })
}

/// A model's typed scenario description: its keys read, every default filled in, and checked
/// by [`Spec::validate`] before any model state is allocated.
pub trait Spec: Serialize + DeserializeOwned + Clone + std::fmt::Debug + PartialEq {
    /// What validation learns that building and action checks need (the lattice size, the
    /// shapes read from their text), so neither reads or checks the description again.
    type Checked;
    /// Checks every field, naming the field and the rule, without building the model; every
    /// size is computed from the text and held to `limits` before anything of that size is
    /// allocated.
    fn validate(&self, limits: &Limits) -> Result<Self::Checked>;
    /// Checks the form of an action (its kind, its fields, cells inside the lattice), whatever
    /// the state; the same check [`Model::check_action`] makes.
    fn check_action(checked: &Self::Checked, action: &Action) -> Result<()>;
    /// The model at step 0.
    fn build(checked: Self::Checked, seed: u64) -> Box<dyn Model>;
}

/// The description of one of the models: the part of a scenario beyond its envelope.
#[derive(Clone, Debug, PartialEq)]
pub enum ModelSpec {
    Amas(amas::Spec),
    Chobie(chobie::spec::Spec),
    Cubes3d(cubes3d::Spec),
    Fracta(fracta::Spec),
}

/// Calls `$f` with the variant's spec, whatever the model.
macro_rules! each_spec {
    ($spec:expr, $s:ident => $f:expr) => {
        match $spec {
            ModelSpec::Amas($s) => $f,
            ModelSpec::Chobie($s) => $f,
            ModelSpec::Cubes3d($s) => $f,
            ModelSpec::Fracta($s) => $f,
        }
    };
}

impl ModelSpec {
    /// Reads the keys of model `model`, naming unknown and invalid fields.
    pub fn read(model: &str, body: Map<String, Value>) -> Result<ModelSpec> {
        (entry(model)?.parse)(Value::Object(body))
    }

    /// The model's registered name.
    pub fn model(&self) -> &'static str {
        match self {
            ModelSpec::Amas(_) => amas::ENTRY.name,
            ModelSpec::Chobie(_) => chobie::ENTRY.name,
            ModelSpec::Cubes3d(_) => cubes3d::ENTRY.name,
            ModelSpec::Fracta(_) => fracta::ENTRY.name,
        }
    }

    /// The keys written back with every default written out, so a scenario (and its link) states
    /// all it depends on and replays the same even if a later version changes a default.
    pub fn to_body(&self) -> Map<String, Value> {
        match each_spec!(self, s => serde_json::to_value(s)) {
            Ok(Value::Object(map)) => map,
            _ => unreachable!("a model's description serialises to an object"),
        }
    }

    /// Checks the description within `limits` and each scheduled action (`disturbances[i]` in
    /// errors), without building the model.
    pub fn validate<'a>(
        &self,
        limits: &Limits,
        actions: impl IntoIterator<Item = &'a Action>,
    ) -> Result<()> {
        fn check<'a, S: Spec>(
            s: &S,
            limits: &Limits,
            actions: impl IntoIterator<Item = &'a Action>,
        ) -> Result<()> {
            let checked = s.validate(limits)?;
            for (i, action) in actions.into_iter().enumerate() {
                S::check_action(&checked, action)
                    .map_err(|e| e.within(&format!("disturbances[{i}]")))?;
            }
            Ok(())
        }
        each_spec!(self, s => check(s, limits, actions))
    }

    /// The model at step 0, built from this description (checked within `limits`) and `seed`.
    pub fn build(&self, seed: u64, limits: &Limits) -> Result<Box<dyn Model>> {
        fn build<S: Spec>(s: &S, seed: u64, limits: &Limits) -> Result<Box<dyn Model>> {
            let checked = s.validate(limits)?;
            #[cfg(test)]
            builds::count();
            Ok(S::build(checked, seed))
        }
        each_spec!(self, s => build(s, seed, limits))
    }
}

/// Reads a model's typed description from its keys, naming unknown and invalid fields.
pub fn parse<S: Spec>(body: Value, variant: fn(S) -> ModelSpec) -> Result<ModelSpec> {
    crate::error::from_value(body).map(variant)
}

/// Models built on this thread, so a test can show that loading a scenario builds it once.
#[cfg(test)]
pub mod builds {
    use std::cell::Cell;

    thread_local! {
        static BUILDS: Cell<u64> = const { Cell::new(0) };
    }

    pub(super) fn count() {
        BUILDS.with(|b| b.set(b.get() + 1));
    }

    /// Models built on this thread so far.
    pub fn so_far() -> u64 {
        BUILDS.with(Cell::get)
    }
}
