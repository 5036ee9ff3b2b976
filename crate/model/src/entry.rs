//! How a model is registered: its [`ModelEntry`] (name, title, version, metrics, the reader of
//! its keys, their schemas, its helper calls and its paper), and the object-safe face of its
//! description ([`AnySpec`]) that a scenario holds whatever the model, with what checking it
//! learnt ([`Learnt`]).

use std::any::Any;
use std::sync::Arc;

use serde_json::{Map, Value};

use crate::error::Result;
use crate::limits::Limits;
use crate::model::{Action, MetricInfo, Model, Spec};

/// Reads and checks a model's keys within the limits, with the scenario's scheduled actions; see
/// [`parse`].
pub type Parse =
    fn(Value, &Limits, &mut dyn Iterator<Item = &Action>) -> Result<(Arc<dyn AnySpec>, Learnt)>;

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
    /// Reads the model's keys of a scenario into its typed description and checks it: [`parse`]
    /// of its [`Spec`].
    pub parse: Parse,
    /// The JSON Schema of those keys ([`schema_of`] its [`Spec`]).
    #[cfg(feature = "schema")]
    pub schema: fn(&mut schemars::SchemaGenerator) -> schemars::Schema,
    /// The JSON Schema of one of its actions (a disturbance without its `at`).
    #[cfg(feature = "schema")]
    pub disturbance: fn(&mut schemars::SchemaGenerator) -> schemars::Schema,
    /// Its helper calls (none for a model without any).
    pub queries: &'static [Query],
    /// Its paper's claims for the reproduction report. Left out of builds without the `report`
    /// feature (the page's wasm, which shows the report's published JSON), so the findings'
    /// code is not linked there.
    #[cfg(feature = "report")]
    pub paper: &'static crate::report::Paper,
}

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
    /// The model at step 0, built from what [`parse`] learnt checking this description: taken
    /// when `learnt` is its only copy, else copied. It checks nothing again.
    fn build(&self, learnt: Learnt, seed: u64) -> Box<dyn Model>;
    /// Checks the description again within `limits` and builds the model at step 0: for a
    /// description whose check's results went into a run already.
    fn check_and_build(&self, limits: &Limits, seed: u64) -> Result<Box<dyn Model>>;
    fn as_any(&self) -> &dyn Any;
}

/// What checking a description learnt ([`Spec::Checked`]: the lattice size, the shapes read from
/// their text), kept beside the description so that building the model does not check it again.
/// Only [`parse`] makes one, by checking; copies share it.
#[derive(Clone)]
pub struct Learnt(Arc<dyn Any + Send + Sync>);

impl<S: Spec + Send + Sync + 'static> AnySpec for S {
    fn to_body(&self) -> Map<String, Value> {
        match serde_json::to_value(self) {
            Ok(Value::Object(map)) => map,
            _ => unreachable!("a model's description serialises to an object"),
        }
    }

    fn build(&self, learnt: Learnt, seed: u64) -> Box<dyn Model> {
        let Ok(checked) = learnt.0.downcast::<S::Checked>() else {
            unreachable!("a description's check results are its own model's")
        };
        let checked = Arc::try_unwrap(checked).unwrap_or_else(|shared| (*shared).clone());
        S::build(checked, seed)
    }

    fn check_and_build(&self, limits: &Limits, seed: u64) -> Result<Box<dyn Model>> {
        crate::bounds::check(self, limits)?;
        Ok(S::build(Spec::validate(self, limits)?, seed))
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// Reads a model's typed description from its keys, naming unknown and invalid fields, and checks
/// it within `limits` with each scheduled action (`disturbances[i]` in errors), without building
/// the model: the `parse` of its [`ModelEntry`]. Gives the description and what the check learnt.
pub fn parse<S: Spec + Send + Sync + 'static>(
    body: Value,
    limits: &Limits,
    actions: &mut dyn Iterator<Item = &Action>,
) -> Result<(Arc<dyn AnySpec>, Learnt)> {
    let spec: S = crate::error::from_value(body)?;
    crate::bounds::check(&spec, limits)?;
    let checked = spec.validate(limits)?;
    for (i, action) in actions.enumerate() {
        S::check_action(&checked, action).map_err(|e| e.within(&format!("disturbances[{i}]")))?;
    }
    Ok((Arc::new(spec), Learnt(Arc::new(checked))))
}

/// The JSON Schema of `T` as a subschema of `generator`: the `schema` and `disturbance` of a
/// [`ModelEntry`].
#[cfg(feature = "schema")]
pub fn schema_of<T: schemars::JsonSchema>(
    generator: &mut schemars::SchemaGenerator,
) -> schemars::Schema {
    generator.subschema_for::<T>()
}
