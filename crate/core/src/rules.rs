//! A scenario's rules: `rules: { slot: source }`, scripts that take a model's rule slots in place
//! of its paper's rules (`kumiki_model::slot`; docs/rules.md).
//!
//! ```json
//! "rules": { "leader": "fn leader(robot) { ... }" }
//! ```
//!
//! Each key names a slot of the scenario's model (its entry's `slots`); each value is the slot's
//! script, at most [`MAX_SOURCE_BYTES`], or null for the paper's rule (written as no key). A
//! scenario without rules writes no `rules`, so every scenario and link made before them reads,
//! writes and hashes as it did.
//!
//! The script engine (crate `kumiki-rules`) is built in with the `rules` feature: the command
//! line, the lab module and the page's second simulation module have it; the page's first-load
//! module does not, and there a scenario with rules is read (its slots and sizes checked) but
//! does not run ([`ENGINE`] says which build this is). With the engine, reading a scenario also
//! reads each script, so a syntax error is refused at its line like any other field.

#[cfg(feature = "rules")]
use std::rc::Rc;

use kumiki_model::entry::ModelEntry;
#[cfg(feature = "rules")]
use kumiki_model::slot::Script;
pub use kumiki_model::slot::{SlotInfo, MAX_SOURCE_BYTES};
use serde_json::{Map, Value};

use crate::error::{Error, Result};
use crate::models::Model;

/// The envelope's key.
pub const KEY: &str = "rules";

/// Whether this build runs scripts: false in the page's first-load module.
pub const ENGINE: bool = cfg!(feature = "rules");

/// The scripts of a scenario, by slot, in slot-name order (a model has a few slots: a list keeps
/// the page's first-load module free of another map's code).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Rules(Vec<(String, String)>);

impl Rules {
    /// Reads the `rules` section of a scenario of `entry`'s model: an object of slot names and
    /// scripts (null for the paper's rule), each script within [`MAX_SOURCE_BYTES`] and, when the
    /// engine is built in, read and checked.
    pub fn read(section: Option<Value>, entry: &ModelEntry) -> Result<Rules> {
        let entries = match section {
            None => return Ok(Rules::default()),
            Some(Value::Object(entries)) => entries,
            Some(_) => {
                return Err(Error::field(
                    KEY,
                    "expected an object of slot names and scripts, like {\"leader\": \"fn leader(robot) { ... }\"}",
                ))
            }
        };
        // A JSON object's keys come in order (serde_json's map is sorted).
        let mut rules = Vec::new();
        for (slot, value) in entries {
            let path = format!("{KEY}.{slot}");
            let info = slot_info(entry, &slot).ok_or_else(|| {
                let known: Vec<&str> = entry.slots.iter().map(|s| s.name).collect();
                let known = match known.is_empty() {
                    true => "it has none yet".to_string(),
                    false => format!("its slots: {}", known.join(", ")),
                };
                Error::field(
                    &path,
                    format!("{} has no rule slot '{slot}'; {known}", entry.name),
                )
            })?;
            let source = match value {
                Value::Null => continue,
                Value::String(source) => source,
                _ => {
                    return Err(Error::field(
                        path,
                        "expected the slot's script as text, or null for the paper's rule",
                    ))
                }
            };
            if source.len() > MAX_SOURCE_BYTES {
                return Err(Error::field(
                    path,
                    format!(
                        "{} bytes is too long; a rule's script holds at most {MAX_SOURCE_BYTES}",
                        source.len()
                    ),
                ));
            }
            #[cfg(feature = "rules")]
            kumiki_rules::check(*info, &source)?;
            #[cfg(not(feature = "rules"))]
            let _ = info;
            rules.push((slot, source));
        }
        Ok(Rules(rules))
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// The scripts by slot.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &str)> {
        self.0.iter().map(|(k, v)| (k.as_str(), v.as_str()))
    }

    /// The section as a scenario writes it.
    pub fn to_value(&self) -> Value {
        let mut entries = Map::new();
        for (slot, source) in &self.0 {
            entries.insert(slot.clone(), Value::String(source.clone()));
        }
        Value::Object(entries)
    }

    /// Puts each script in its slot of `model` (of `entry`'s model): the handles a run keeps to
    /// start each step's budget.
    pub fn install(&self, model: &mut dyn Model, entry: &ModelEntry) -> Result<Installed> {
        #[cfg(feature = "rules")]
        {
            let mut installed = Vec::new();
            for (slot, source) in &self.0 {
                let info = slot_info(entry, slot).expect("a read scenario's slots are its model's");
                let script: Rc<dyn Script> = kumiki_rules::compile(*info, source)?;
                model.install(slot, Rc::clone(&script))?;
                installed.push(script);
            }
            Ok(Installed(installed))
        }
        #[cfg(not(feature = "rules"))]
        {
            let _ = (model, entry);
            match self.0.first() {
                None => Ok(Installed),
                Some((slot, _)) => Err(Error::field(
                    format!("{KEY}.{slot}"),
                    "this build has no script engine: a scenario with rules runs in the page's rules module (kumiki_wasm_rules) or with kumiki run",
                )),
            }
        }
    }
}

/// A rule slot as the page's editor and `kumiki rules` show it: its model and its documentation,
/// with the paper's rule as a script.
#[derive(Clone, Debug, PartialEq, serde::Serialize, schemars::JsonSchema)]
pub struct SlotDoc {
    pub model: &'static str,
    pub slot: SlotInfo,
}

/// Every model's rule slots, models in gallery order.
pub fn slots() -> Vec<SlotDoc> {
    crate::models::MODELS
        .iter()
        .flat_map(|entry| {
            entry.slots.iter().map(|&slot| SlotDoc {
                model: entry.name,
                slot,
            })
        })
        .collect()
}

/// The slot of `entry`'s model named `name`.
pub fn slot_info<'a>(entry: &'a ModelEntry, name: &str) -> Option<&'a SlotInfo> {
    entry.slots.iter().find(|s| s.name == name)
}

/// The scripts a run put in its model's slots.
#[cfg(feature = "rules")]
#[derive(Clone, Default)]
pub struct Installed(Vec<Rc<dyn Script>>);

/// Without the engine, no script is ever installed.
#[cfg(not(feature = "rules"))]
#[derive(Clone, Default)]
pub struct Installed;

impl Installed {
    /// A step begins: each script's budget of operations a step starts again.
    #[inline]
    pub fn begin_step(&self) {
        #[cfg(feature = "rules")]
        for script in &self.0 {
            script.begin_step();
        }
    }
}
