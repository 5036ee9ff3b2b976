//! How a model is registered: its [`ModelEntry`] (name, title, version, metrics, limits, the
//! reader of its keys, their schemas and its helper calls), and the object-safe face
//! of its description ([`AnySpec`]) that a scenario holds whatever the model, with what checking
//! it learnt ([`Learnt`]).

use std::any::Any;
use std::sync::Arc;

use serde_json::{Map, Value};

use crate::error::Result;
use crate::limits::{LimitTable, Limits};
use crate::model::{Action, MetricInfo, Model, Spec};
use crate::slot::SlotInfo;

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
    /// Its own sizes under the page's and the large limits, each described once: its
    /// [`ModelLimits`](crate::limits::ModelLimits).
    pub limits: &'static dyn LimitTable,
    /// Reads the model's keys of a scenario into its typed description and checks it: [`parse`]
    /// of its [`Spec`].
    pub parse: Parse,
    /// The JSON Schema of those keys ([`schema_of`] its [`Spec`]).
    pub schema: SchemaOf,
    /// The JSON Schema of one of its actions (a disturbance without its `at`).
    pub disturbance: SchemaOf,
    /// Its helper calls (none for a model without any).
    pub queries: &'static [Query],
    /// Its rule slots: the decisions a scenario's `rules` may give to a script (none for a
    /// model without any); see [`crate::slot`].
    pub slots: &'static [SlotInfo],
    /// The settings a link made with an earlier behaviour version pins, so that it replays as
    /// it did where a change of behaviour came behind a new setting (none for most models).
    pub pins: &'static [Pin],
}

/// A setting that links made with an earlier behaviour version of the model pin: a link made
/// with a version below `before` that does not set `key` opens with `key` set to `value`, the
/// behaviour it was made with, instead of the setting's default.
pub struct Pin {
    pub before: u32,
    pub key: &'static str,
    pub value: PinValue,
}

/// The value a [`Pin`] sets: a choice's name or a switch. Typed rather than JSON text, so the
/// page's module opens a pinned link without linking a JSON text parser.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PinValue {
    Choice(&'static str),
    Switch(bool),
}

impl PinValue {
    fn to_value(self) -> Value {
        match self {
            PinValue::Choice(name) => Value::String(name.into()),
            PinValue::Switch(on) => Value::Bool(on),
        }
    }
}

impl ModelEntry {
    /// Sets in the scenario document `doc` of a link made with behaviour version `made_with`
    /// the settings that version pins and the link does not set.
    pub fn pin(&self, made_with: u32, doc: &mut Map<String, Value>) {
        for pin in self.pins.iter().filter(|p| made_with < p.before) {
            if !doc.contains_key(pin.key) {
                doc.insert(pin.key.into(), pin.value.to_value());
            }
        }
    }
}

/// A JSON Schema as a [`ModelEntry`] names it: [`schema_of`] a type. A function of the schema
/// generator in builds with the `schema` feature; nothing in the others (the page's wasm), so the
/// generator is not linked there. A model crate writes the same entry either way.
#[cfg(feature = "schema")]
pub type SchemaOf = fn(&mut schemars::SchemaGenerator) -> schemars::Schema;
#[cfg(not(feature = "schema"))]
pub type SchemaOf = ();

/// What a key of the envelope is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Role {
    /// The format's version and the model: what kind of scenario it is.
    Format,
    /// The name and the description: they describe the scenario and change no run.
    Text,
    /// A setting of the run: a second run may vary it.
    Setting,
    /// A section of its own: the scheduled disturbances, an exercise, a comparison, a hand-in's
    /// record.
    Section,
}

/// One key of the envelope, the keys every model's scenario has beside its own.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, schemars::JsonSchema)]
pub struct EnvelopeKey {
    pub key: &'static str,
    pub role: Role,
}

/// The keys of a scenario document that belong to its envelope, common to every model, in the
/// order a form shows them: the others are the model's own, read by its entry's `parse`. The one
/// list the core's scenario reader, the comparison's check and the page (`ENVELOPE` in
/// web/contract.gen.ts) go by; tests in the core hold the scenarios' and the schema's envelope to
/// it. A model crate that reads one of its own preset files leaves them out to have the model's
/// keys.
pub const ENVELOPE: &[EnvelopeKey] = &[
    EnvelopeKey::new("version", Role::Format),
    EnvelopeKey::new("model", Role::Format),
    EnvelopeKey::new("name", Role::Text),
    EnvelopeKey::new("description", Role::Text),
    EnvelopeKey::new("max_steps", Role::Setting),
    EnvelopeKey::new("seed", Role::Setting),
    EnvelopeKey::new("rules", Role::Setting),
    EnvelopeKey::new("disturbances", Role::Section),
    EnvelopeKey::new("exercise", Role::Section),
    EnvelopeKey::new("compare", Role::Section),
    EnvelopeKey::new("handin", Role::Section),
];

impl EnvelopeKey {
    const fn new(key: &'static str, role: Role) -> EnvelopeKey {
        EnvelopeKey { key, role }
    }
}

/// The role of `key` when it is an envelope key.
pub fn envelope_role(key: &str) -> Option<Role> {
    ENVELOPE.iter().find(|k| k.key == key).map(|k| k.role)
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
