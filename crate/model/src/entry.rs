//! How a model is registered: its [`ModelEntry`] (name, title, version, metrics, limits, the
//! reader of its keys, their schemas, its helper calls and its paper), and the object-safe face
//! of its description ([`AnySpec`]) that a scenario holds whatever the model.

use std::any::Any;

use serde_json::{Map, Value};

use crate::error::Result;
use crate::limits::{LimitTable, Limits};
use crate::model::{Action, MetricInfo, Model, Spec};

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
    /// Every metric the model reports, with unit and meaning; see [`MetricInfo`].
    pub metrics: &'static [MetricInfo],
    /// Its own sizes under the page's and the large limits, each described once: its
    /// [`ModelLimits`](crate::limits::ModelLimits).
    pub limits: &'static dyn LimitTable,
    /// Reads the model's keys of a scenario into its typed description: [`parse`] of its
    /// [`Spec`].
    pub parse: fn(Value) -> Result<Box<dyn AnySpec>>,
    /// The JSON Schema of those keys ([`schema_of`] its [`Spec`]).
    pub schema: SchemaOf,
    /// The JSON Schema of one of its actions (a disturbance without its `at`).
    pub disturbance: SchemaOf,
    /// Its helper calls (none for a model without any).
    pub queries: &'static [Query],
    /// Its paper's claims for the reproduction report ([`paper_of`] its `Paper`).
    pub paper: PaperOf,
}

/// A JSON Schema as a [`ModelEntry`] names it: [`schema_of`] a type. A function of the schema
/// generator in builds with the `schema` feature; nothing in the others (the page's wasm), so the
/// generator is not linked there. A model crate writes the same entry either way.
#[cfg(feature = "schema")]
pub type SchemaOf = fn(&mut schemars::SchemaGenerator) -> schemars::Schema;
#[cfg(not(feature = "schema"))]
pub type SchemaOf = ();

/// A paper as a [`ModelEntry`] names it: [`paper_of`] it. The paper in builds with the `report`
/// feature; nothing in the others, so the findings' code is not linked there.
#[cfg(feature = "report")]
pub type PaperOf = &'static crate::report::Paper;
#[cfg(not(feature = "report"))]
pub type PaperOf = ();

/// The keys of a scenario document that belong to its envelope, common to every model: the
/// others are the model's own, read by its entry's `parse`. The core's scenario reader reads these
/// (a test there holds it to this list); a model crate that reads one of its own preset files
/// leaves them out to have the model's keys.
pub const ENVELOPE: &[&str] = &[
    "version",
    "model",
    "name",
    "description",
    "seed",
    "max_steps",
    "disturbances",
    "exercise",
    "compare",
];

/// A helper call a model offers beside its runs, for editors and the CLI: deriving a target
/// description from a shape, checking one. JSON arguments, a JSON answer; errors name the
/// argument and the problem like scenario errors do.
pub struct Query {
    pub name: &'static str,
    pub description: &'static str,
    pub run: fn(&Value) -> Result<Value>,
}

/// A model's description whatever the model, as a scenario holds it: the object-safe face of
/// [`Spec`], which every `Spec` has. Its methods are the ones every build uses: a vtable keeps
/// each of them linked, so comparing and printing go through [`AnySpec::to_body`] instead of the
/// spec's own `PartialEq` and `Debug`, which the page's wasm would otherwise carry unused.
pub trait AnySpec: Send + Sync + 'static {
    /// The keys written back with every default written out.
    fn to_body(&self) -> Map<String, Value>;
    /// Checks the description within `limits` and each scheduled action (`disturbances[i]` in
    /// errors), without building the model.
    fn validate(&self, limits: &Limits, actions: &mut dyn Iterator<Item = &Action>) -> Result<()>;
    /// The model at step 0, built from this description (checked within `limits`) and `seed`.
    fn build(&self, seed: u64, limits: &Limits) -> Result<Box<dyn Model>>;
    fn clone_box(&self) -> Box<dyn AnySpec>;
    fn as_any(&self) -> &dyn Any;
}

impl<S: Spec + Send + Sync + 'static> AnySpec for S {
    fn to_body(&self) -> Map<String, Value> {
        match serde_json::to_value(self) {
            Ok(Value::Object(map)) => map,
            _ => unreachable!("a model's description serialises to an object"),
        }
    }

    fn validate(&self, limits: &Limits, actions: &mut dyn Iterator<Item = &Action>) -> Result<()> {
        let checked = Spec::validate(self, limits)?;
        for (i, action) in actions.enumerate() {
            S::check_action(&checked, action)
                .map_err(|e| e.within(&format!("disturbances[{i}]")))?;
        }
        Ok(())
    }

    fn build(&self, seed: u64, limits: &Limits) -> Result<Box<dyn Model>> {
        Ok(S::build(Spec::validate(self, limits)?, seed))
    }

    fn clone_box(&self) -> Box<dyn AnySpec> {
        Box::new(self.clone())
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// Reads a model's typed description from its keys, naming unknown and invalid fields: the
/// `parse` of its [`ModelEntry`].
pub fn parse<S: Spec + Send + Sync + 'static>(body: Value) -> Result<Box<dyn AnySpec>> {
    crate::error::from_value::<S>(body).map(|s| Box::new(s) as Box<dyn AnySpec>)
}

/// The JSON Schema of `T`, as a subschema of the generator it is given: the `schema` and
/// `disturbance` of a [`ModelEntry`].
#[cfg(feature = "schema")]
pub const fn schema_of<T: schemars::JsonSchema>() -> SchemaOf {
    fn of<T: schemars::JsonSchema>(generator: &mut schemars::SchemaGenerator) -> schemars::Schema {
        generator.subschema_for::<T>()
    }
    of::<T>
}

/// Without the `schema` feature, nothing.
#[cfg(not(feature = "schema"))]
pub const fn schema_of<T: schemars::JsonSchema>() -> SchemaOf {}

/// A model's paper: the `paper` of its [`ModelEntry`].
#[cfg(feature = "report")]
pub const fn paper_of(paper: &'static crate::report::Paper) -> PaperOf {
    paper
}

/// Without the `report` feature, nothing.
#[cfg(not(feature = "report"))]
pub const fn paper_of(_: &'static crate::report::Paper) -> PaperOf {}
