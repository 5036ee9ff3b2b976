//! The contract between a model and the rest of Kumiki: the [`Model`] trait a model implements,
//! the [`Spec`] trait of its typed scenario description, the records a renderer reads
//! ([`Layout`], [`Scene`], [`Agent`], [`Event`]), its metrics and actions, and the
//! [`ModelEntry`] that registers it.
//!
//! A model owns its state and its [`Rng`](crate::rng::Rng); the run drives it. Everything a
//! renderer needs is described once by [`Layout`] and then read each frame as flat buffers
//! ([`Model::cells`], [`Model::field`]) plus small lists ([`Model::agents`], [`Model::events`]).

use std::borrow::Cow;
use std::rc::Rc;

use schemars::JsonSchema;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

use crate::bounds::Bounded;
use crate::error::Result;
use crate::hash::StateHasher;
use crate::lattice::LatticeKind;
use crate::limits::Limits;
use crate::slot::Script;

/// Named metric values, sorted by name. Counts are integers, ratios floats.
pub type Metrics = Map<String, Value>;

/// The JSON Schema of [`Model::inspect`]'s answer as it crosses to the page: a few facts about one
/// cell by name, whatever the model says (each model's inspector plugin reads its own).
#[derive(JsonSchema)]
pub struct Facts(pub std::collections::BTreeMap<String, Value>);

/// The JSON Schema of [`Metrics`] as they cross to the page and into rows: each value a
/// [`Metric`] in its JSON form (the Rust type is a JSON map, which says no more).
#[derive(JsonSchema)]
#[schemars(rename = "Metrics")]
pub struct MetricValues(pub std::collections::BTreeMap<String, Metric>);

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

/// A metric's JSON form ([`Metric::to_json`]): a number, a flag, or null when missing.
impl JsonSchema for Metric {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "Metric".into()
    }

    fn json_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
        schemars::json_schema!({
            "description": "A metric's value: a count or a measure, a flag, or null when it is missing (not defined yet, or not finite).",
            "type": ["number", "boolean", "null"],
        })
    }
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

/// One metric a model reports: its name, its unit and what it means in a plain sentence. Each
/// model lists its own next to its code (`<model>/metrics.rs`), registered in its [`ModelEntry`](crate::entry::ModelEntry);
/// the page (explanations on hover, units in exports), the CLI (`kumiki metrics`) and the docs
/// (docs/metrics.md) all read this one table.
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Eq, JsonSchema)]
pub struct MetricInfo {
    pub name: &'static str,
    /// What one of it measures: `steps`, `count`, `fraction` (0 to 1), `flag`, `MPa`, ...
    pub unit: &'static str,
    /// One sentence, for a reader who has not read the paper.
    pub about: &'static str,
    /// Where the page shows it: among the few that matter first, with the others, or only in its
    /// debug view.
    pub shown: Shown,
}

/// Where the page shows a metric.
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Eq, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Shown {
    /// One of the few that matter most for the model's scenarios: on the first screen.
    Key,
    /// With the others, a click away.
    More,
    /// An internal counter of the implementation (work done, not a finding): only with `?debug`.
    Debug,
}

impl MetricInfo {
    pub const fn new(name: &'static str, unit: &'static str, about: &'static str) -> Self {
        MetricInfo {
            name,
            unit,
            about,
            shown: Shown::More,
        }
    }

    /// One of the few that matter most: the page shows it first.
    pub const fn key(self) -> Self {
        MetricInfo {
            shown: Shown::Key,
            ..self
        }
    }

    /// An internal counter: the page shows it only in its debug view.
    pub const fn internal(self) -> Self {
        MetricInfo {
            shown: Shown::Debug,
            ..self
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
    /// A cell code's shape drawn over its cells in every view, a field's heat map included, so
    /// that a state (an overload, a failure) stays visible whatever the view shows.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mark: Option<CellMark>,
}

/// The shape that marks the cells of a code: a ring or a cross, in the code's colour.
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum CellMark {
    Ring,
    Cross,
}

impl LegendEntry {
    pub fn new(code: u8, name: &str, color: &str) -> Self {
        LegendEntry {
            code,
            name: name.into(),
            color: color.into(),
            mark: None,
        }
    }

    /// The same entry, its cells marked with `mark` in every view.
    pub fn marked(self, mark: CellMark) -> Self {
        LegendEntry {
            mark: Some(mark),
            ..self
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

/// A copy of a model in the middle of its run, for keyframes (the core's timeline). Every
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
    /// A few facts about one cell, for the page's inspector ([`Facts`] as it crosses).
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
    /// Puts `script` in the rule slot named `slot` (one of its entry's
    /// [`slots`](crate::entry::ModelEntry::slots)) in place of the paper's rule. A model without
    /// slots keeps this default, which refuses.
    fn install(&mut self, slot: &str, _script: Rc<dyn Script>) -> Result<()> {
        Err(crate::Error::field(
            format!("rules.{slot}"),
            "this model has no rule slot of that name",
        ))
    }
    /// Why the run stopped before its end (a rule's script went past a cap or failed), if it
    /// did: a stopped model takes no more steps.
    fn stopped(&self) -> Option<&str> {
        None
    }
}

/// A model's typed scenario description: its keys read, every default filled in, and checked
/// by [`Spec::validate`] before any model state is allocated.
pub trait Spec:
    Bounded + Serialize + DeserializeOwned + Clone + std::fmt::Debug + PartialEq
{
    /// What validation learns that building and action checks need (the lattice size, the
    /// shapes read from their text), so neither reads or checks the description again. A
    /// scenario keeps it beside the description, and its copies share it.
    type Checked: Clone + Send + Sync + 'static;
    /// Checks every field, naming the field and the rule, without building the model; every
    /// size is computed from the text and held to `limits` before anything of that size is
    /// allocated. Its [`Bounded::BOUNDS`] are checked before, whoever reads it.
    fn validate(&self, limits: &Limits) -> Result<Self::Checked>;
    /// Checks the form of an action (its kind, its fields, cells inside the lattice), whatever
    /// the state; the same check [`Model::check_action`] makes.
    fn check_action(checked: &Self::Checked, action: &Action) -> Result<()>;
    /// The model at step 0.
    fn build(checked: Self::Checked, seed: u64) -> Box<dyn Model>;
}
