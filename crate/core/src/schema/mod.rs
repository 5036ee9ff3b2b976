//! JSON Schemas of scenarios and experiments, published in `docs/schema/` (`kumiki schema`) so
//! editors can check scenario files, and read by the page to build its parameter form.
//!
//! Each model's keys are derived (schemars) from the very types serde reads them into: their doc
//! comments become descriptions, their enums `oneOf` lists of constants, and their ranges come
//! from the same constants and [`Limits::PAGE`] that validation applies. The envelope and the
//! experiment file are read by hand-written code (`scenario/`, `experiment.rs`), so their part
//! is written here from the same constants; a test reads every key it names.

use schemars::generate::SchemaSettings;
use serde_json::{json, Map, Value};

use crate::compare::Compare;
use crate::design;
use crate::exercise::{Exercise, MAX_GOAL_CHARS};
use crate::experiment::MAX_JOBS;
use crate::models::MODELS;
use crate::presets;
use crate::rules;
use crate::scenario::{FORMAT_VERSION, MAX_DESCRIPTION_CHARS, MAX_NAME_CHARS, MAX_SEED, MAX_STEPS};

mod pages;
pub use kumiki_model::typescript::{declarations, typescript};

/// Where the published schemas live, relative to the repository root.
pub const DIR: &str = "docs/schema";
/// The scenario schema's file name; the experiment schema refers to it by this name.
pub const SCENARIO_FILE: &str = "scenario.schema.json";
pub const EXPERIMENT_FILE: &str = "experiment.schema.json";

/// The schema of a scenario document: one object per model (`oneOf`, told apart by `model`),
/// each the envelope keys plus the model's own.
pub fn scenario() -> Value {
    let mut generator = SchemaSettings::draft2020_12().into_generator();
    let exercise = generator.subschema_for::<Exercise>().to_value();
    let compare = generator.subschema_for::<Compare>().to_value();
    let handin = generator
        .subschema_for::<crate::handin::Handin>()
        .to_value();
    let specs: Vec<(Value, Value)> = MODELS
        .iter()
        .map(|m| {
            let spec = (m.schema)(&mut generator).to_value();
            (spec, (m.disturbance)(&mut generator).to_value())
        })
        .collect();
    let mut defs: Map<String, Value> = generator.take_definitions(true).into_iter().collect();
    let mut one_of = Vec::new();
    for (entry, (spec, disturbance)) in MODELS.iter().zip(specs) {
        scheduled(&mut defs, &def_name(&disturbance));
        let name = def_name(&spec);
        let Some(Value::Object(mut body)) = defs.remove(&name) else {
            unreachable!("a model's description is an object schema named {name}")
        };
        let mut properties = envelope(
            entry.name,
            entry.title,
            entry.default_max_steps,
            [&exercise, &compare, &handin],
            &disturbance,
        );
        properties.insert(rules::KEY.into(), rules_schema(entry.slots));
        if let Some(Value::Object(own)) = body.remove("properties") {
            properties.extend(own);
        }
        let mut required = vec![json!("version"), json!("model")];
        if let Some(Value::Array(own)) = body.remove("required") {
            required.extend(own);
        }
        let id = format!("{}Scenario", capitalised(entry.name));
        defs.insert(
            id.clone(),
            json!({
                "title": entry.title,
                "type": "object",
                "properties": properties,
                "required": required,
                "additionalProperties": false,
            }),
        );
        one_of.push(json!({ "$ref": format!("#/$defs/{id}") }));
    }
    json!({
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": SCENARIO_FILE,
        "title": "Kumiki scenario",
        "description": "One versioned JSON document that fully determines a run: the envelope keys, common to every model, and the model's own keys (crate/models/<model>/README.md). docs/scenario-format.md gives the size limits.",
        "type": "object",
        "oneOf": one_of,
        "$defs": defs,
    })
}

/// The envelope keys of model `model`'s scenarios.
fn envelope(
    model: &str,
    title: &str,
    default_max_steps: u64,
    [exercise, compare, handin]: [&Value; 3],
    disturbance: &Value,
) -> Map<String, Value> {
    let properties = json!({
        "version": {
            "description": "The scenario format version; older versions are migrated when read.",
            "type": "integer", "minimum": 1, "maximum": FORMAT_VERSION,
        },
        "model": { "description": title, "const": model },
        "name": {
            "description": "The scenario's name, shown as its title.",
            "type": "string", "maxLength": MAX_NAME_CHARS, "default": "",
        },
        "description": {
            "description": "What the scenario shows.",
            "type": "string", "maxLength": MAX_DESCRIPTION_CHARS, "default": "",
        },
        "seed": {
            "description": "The seed of every random choice of the run.",
            "type": "integer", "minimum": 0, "maximum": MAX_SEED, "default": 1,
        },
        "max_steps": {
            "description": "The run stops after this many steps if its goal is not reached first.",
            "type": "integer", "minimum": 1, "maximum": MAX_STEPS, "default": default_max_steps,
        },
        "disturbances": {
            "description": "Actions applied during the run (recorded clicks included): `at` is the step after which it applies; the other keys are the model's action, given in its documentation.",
            "type": "array",
            "items": disturbance,
        },
        "exercise": exercise,
        "compare": compare,
        "handin": handin,
    });
    match properties {
        Value::Object(map) => map,
        _ => unreachable!(),
    }
}

/// The envelope's `rules` of a model with `slots`: a script (or null, the paper's rule) for each
/// slot, and no other key.
fn rules_schema(slots: &[rules::SlotInfo]) -> Value {
    let properties: Map<String, Value> = slots
        .iter()
        .map(|slot| {
            let about = format!(
                "{}. {} The script defines fn {}(input), which answers {}. null: the paper's rule.",
                slot.title, slot.about, slot.name, slot.output
            );
            let node = json!({
                "description": about,
                "type": ["string", "null"],
                "maxLength": rules::MAX_SOURCE_BYTES,
            });
            (slot.name.to_string(), node)
        })
        .collect();
    json!({
        "description": "Scripts in the model's rule slots, in place of the paper's rules (docs/rules.md): each slot's script, or null for the paper's rule.",
        "type": "object",
        "properties": properties,
        "additionalProperties": false,
    })
}

/// The schema of an experiment file (docs/experiments.md).
pub fn experiment() -> Value {
    let presets: Vec<&str> = presets::names().collect();
    json!({
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": EXPERIMENT_FILE,
        "title": "Kumiki experiment",
        "description": "Scenarios × a grid of overrides × seeds, one row per run (docs/experiments.md).",
        "type": "object",
        "properties": {
            "version": { "description": "The experiment format version.", "const": 1 },
            "name": { "description": "The experiment's name.", "type": "string", "minLength": 1 },
            "title": { "type": "string" },
            "description": { "type": "string" },
            "scenarios": {
                "description": "Preset names or whole scenarios.",
                "type": "array",
                "minItems": 1,
                "items": {
                    "oneOf": [
                        { "description": "A built-in scenario.", "enum": presets },
                        { "$ref": SCENARIO_FILE },
                    ],
                },
            },
            "grid": {
                "description": "Dotted scenario paths and the values each takes, listed or as a range; every combination runs.",
                "type": "object",
                "additionalProperties": {
                    "oneOf": [
                        { "description": "The values, listed.", "type": "array", "minItems": 1 },
                        {
                            "description": "start, start + step, ... up to end (included when a whole number of steps reaches it).",
                            "type": "object",
                            "properties": {
                                "start": { "type": "number" },
                                "step": { "type": "number", "exclusiveMinimum": 0 },
                                "end": { "type": "number" },
                            },
                            "required": ["start", "step", "end"],
                            "additionalProperties": false,
                        },
                    ],
                },
            },
            "sample": {
                "description": "Parameter points drawn from ranges, each run with every grid combination: `latin` (a Latin hypercube, every stratum of each range once) or `random`, from `seed`.",
                "type": "object",
                "properties": {
                    "method": { "enum": ["latin", "random"], "default": "latin" },
                    "count": { "type": "integer", "minimum": 1, "maximum": design::MAX_POINTS },
                    "seed": { "type": "integer", "minimum": 0, "default": 1 },
                    "ranges": {
                        "description": "Dotted scenario paths and the range each is drawn from; `integer` draws whole numbers from min to max inclusive.",
                        "type": "object",
                        "minProperties": 1,
                        "additionalProperties": {
                            "type": "object",
                            "properties": {
                                "min": { "type": "number" },
                                "max": { "type": "number" },
                                "integer": { "type": "boolean", "default": false },
                            },
                            "required": ["min", "max"],
                            "additionalProperties": false,
                        },
                    },
                },
                "required": ["count", "ranges"],
                "additionalProperties": false,
            },
            "stop": {
                "description": "A condition in the goal language (completed, steps, metrics.NAME, scenario.PATH; and, or, not, comparisons, arithmetic), checked after every step: a run stops at the first step where it holds.",
                "type": "string",
                "maxLength": MAX_GOAL_CHARS,
            },
            "set": {
                "description": "Overrides applied to every run: dotted scenario paths and their values.",
                "type": "object",
            },
            "seeds": {
                "description": "A count N (seeds 1 to N) or a list of seeds.",
                "oneOf": [
                    { "type": "integer", "minimum": 1, "maximum": MAX_JOBS },
                    {
                        "type": "array",
                        "minItems": 1,
                        "items": { "type": "integer", "minimum": 0, "maximum": MAX_SEED },
                    },
                ],
                "default": 1,
            },
            "trace": {
                "description": "Metrics sampled every `every` steps during each run.",
                "type": "object",
                "properties": {
                    "every": { "type": "integer", "minimum": 1, "default": 1 },
                    "metrics": { "type": "array", "minItems": 1, "items": { "type": "string" } },
                },
                "required": ["metrics"],
                "additionalProperties": false,
            },
            "plot": { "description": "How the rows are drawn: one plot specification or a list (docs/experiments.md), checked when the experiment is read." },
        },
        "required": ["version", "name", "scenarios"],
        "additionalProperties": false,
    })
}

/// Makes the definition `name` of a model's action (a tagged enum: `oneOf` one object per kind)
/// that of a scheduled action: each kind gains `at`, the step after which it applies. Its other
/// keys lose their defaults: an action is kept as written, never filled in.
fn scheduled(defs: &mut Map<String, Value>, name: &str) {
    let Some(Value::Array(kinds)) = defs.get_mut(name).and_then(|d| d.get_mut("oneOf")) else {
        unreachable!("a model's action {name} is an enum tagged by kind")
    };
    for kind in kinds {
        let Some(Value::Object(properties)) = kind.get_mut("properties") else {
            unreachable!("each kind of {name} is an object")
        };
        for property in properties.values_mut() {
            if let Value::Object(p) = property {
                p.remove("default");
            }
        }
        properties.insert(
            "at".into(),
            json!({
                "description": "The step after which it applies.",
                "type": "integer", "minimum": 0, "maximum": MAX_STEPS,
            }),
        );
        if let Some(Value::Array(required)) = kind.get_mut("required") {
            required.insert(0, json!("at"));
        }
    }
}

/// The name of the definition a `{"$ref": "#/$defs/NAME"}` schema points to.
fn def_name(reference: &Value) -> String {
    reference["$ref"]
        .as_str()
        .and_then(|r| r.strip_prefix("#/$defs/"))
        .expect("a model's description is referenced, not inlined")
        .to_string()
}

fn capitalised(name: &str) -> String {
    let mut chars = name.chars();
    chars
        .next()
        .map(|c| c.to_uppercase().chain(chars).collect())
        .unwrap_or_default()
}

/// Where the TypeScript types generated from the scenario schema live, from the repository root.
pub const TYPESCRIPT_FILE: &str = "web/scenario.gen.ts";
/// Where the TypeScript types of the records the core hands the page live (see [`contract`]).
pub const CONTRACT_FILE: &str = "web/contract.gen.ts";
/// The page's copy of the scenario schema, which its form reads (the page takes no runtime data
/// from `docs/`).
pub const PAGE_SCHEMA_FILE: &str = "web/scenario.schema.gen.json";

/// Where the generated table of every model's metrics lives, from the repository root.
pub const METRICS_FILE: &str = "docs/metrics.md";

/// The published files, as paths from the repository root, and their text: the schemas (pretty
/// JSON with a final newline), the TypeScript types of the scenario schema and those of the
/// records that cross from Rust to the page, and the metric tables.
pub fn files() -> Vec<(String, String)> {
    let pretty = |v: &Value| serde_json::to_string_pretty(v).expect("a schema serialises") + "\n";
    let scenario = scenario();
    vec![
        (format!("{DIR}/{SCENARIO_FILE}"), pretty(&scenario)),
        (PAGE_SCHEMA_FILE.to_string(), pretty(&scenario)),
        (format!("{DIR}/{EXPERIMENT_FILE}"), pretty(&experiment())),
        (TYPESCRIPT_FILE.to_string(), typescript(&scenario)),
        (CONTRACT_FILE.to_string(), contract_typescript()),
        (METRICS_FILE.to_string(), crate::models::metrics_markdown()),
    ]
}

/// The schema of every record the core hands the page through the wasm glue (serde-wasm-bindgen
/// or JSON text), so that their TypeScript types are generated from them and a change of one in
/// Rust is a type error in the page, not a silent mismatch: a run's layout, scene, frame,
/// metrics and inspected facts, an exercise's check and a graded hand-in, the scenario in view's proposals and
/// comparison, links unpacked, shapes read, the lists of presets, lessons, metrics and
/// experiments, an experiment's rows and figures, and the reproduction report's sections and a
/// claim recomputed.
pub fn contract() -> Value {
    use kumiki_model::model::{Facts, MetricInfo, MetricValues};
    let mut generator = SchemaSettings::draft2020_12().into_generator();
    generator.subschema_for::<crate::models::Layout>();
    generator.subschema_for::<crate::models::Scene>();
    generator.subschema_for::<crate::playback::Frame>();
    generator.subschema_for::<MetricValues>();
    generator.subschema_for::<MetricInfo>();
    generator.subschema_for::<Facts>();
    generator.subschema_for::<crate::exercise::Check>();
    generator.subschema_for::<crate::exercise::Verdict>();
    generator.subschema_for::<crate::grading::Graded>();
    generator.subschema_for::<crate::grading::table::Row>();
    generator.subschema_for::<crate::grading::ClassExercise>();
    #[cfg(feature = "sheets")]
    generator.subschema_for::<crate::handins::Handin>();
    generator.subschema_for::<crate::scenario::EnvelopeKey>();
    generator.subschema_for::<crate::draft::Proposal>();
    generator.subschema_for::<crate::draft::Comparison>();
    generator.subschema_for::<crate::link::Unpacked>();
    generator.subschema_for::<crate::link::Versions>();
    generator.subschema_for::<crate::shape::Cells>();
    generator.subschema_for::<crate::lessons::LessonInfo>();
    generator.subschema_for::<crate::presets::PresetInfo>();
    generator.subschema_for::<crate::experiment::ExperimentInfo>();
    generator.subschema_for::<crate::experiment::Row>();
    generator.subschema_for::<crate::plot::figure::Figure>();
    generator.subschema_for::<crate::reproduce::Section>();
    generator.subschema_for::<crate::reproduce::Finding>();
    generator.subschema_for::<crate::rules::SlotDoc>();
    let defs: Map<String, Value> = generator.take_definitions(true).into_iter().collect();
    json!({ "$defs": defs })
}

/// TypeScript declarations of [`contract`], and the tables of the core the page goes by.
pub fn contract_typescript() -> String {
    let mut out = String::from(
        "// Generated by `kumiki schema` from the Rust types the core hands the page: do not edit.\n",
    );
    out.push_str(&declarations(&contract()));
    let envelope = serde_json::to_string(crate::scenario::ENVELOPE).expect("a table serialises");
    out.push_str(&format!(
        "\n/** The envelope's keys, in the order a form shows them (kumiki_model::entry::ENVELOPE). */\nexport const ENVELOPE: EnvelopeKey[] = {envelope};\n"
    ));
    out
}

/// Generated parts of hand-written pages: the page's path from the repository root, the marker
/// that bounds the part (`<!-- NAME:begin -->` ... `<!-- NAME:end -->`) and the part's text: the
/// limits table, the README's table of models and the teachers' guide's table of lessons.
pub fn spliced() -> crate::error::Result<Vec<(&'static str, &'static str, String)>> {
    Ok(vec![
        (
            "docs/scenario-format.md",
            "limits",
            crate::models::limits_markdown(),
        ),
        ("README.md", "models", pages::models_markdown()?),
        ("docs/teaching.md", "lessons", crate::lessons::markdown()?),
        ("docs/teaching.md", "guide", crate::guide::markdown()?),
    ])
}

/// `doc` with the text between `marker`'s begin and end comments replaced by `part`, or `None`
/// when the page lacks either comment.
pub fn splice(doc: &str, marker: &str, part: &str) -> Option<String> {
    let begin = format!("<!-- {marker}:begin -->\n");
    let end = format!("<!-- {marker}:end -->");
    let from = doc.find(&begin)? + begin.len();
    let to = from + doc[from..].find(&end)?;
    Some(format!("{}{part}{}", &doc[..from], &doc[to..]))
}

#[cfg(test)]
mod tests;
