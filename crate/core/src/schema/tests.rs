use super::*;

/// The published files, and the generated parts of hand-written pages, are what this build
/// derives (`kumiki schema` rewrites them).
#[test]
fn the_published_schemas_are_current() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let read = |path: &str| std::fs::read_to_string(root.join(path)).unwrap_or_default();
    let stale = |path: &str| {
        format!("{path} is stale: run 'cargo run -p kumiki-cli -- schema' and commit it")
    };
    for (path, text) in files() {
        assert!(read(&path) == text, "{}", stale(&path));
    }
    for (path, marker, part) in spliced().unwrap() {
        let page = read(path);
        assert!(
            splice(&page, marker, &part) == Some(page.clone()),
            "{}",
            stale(path)
        );
    }
}

/// Every preset states only keys its model's schema names, and every key the schema
/// requires: a scenario the core accepts is one the schema accepts, key for key.
#[test]
fn every_preset_keeps_to_its_models_schema() {
    let schema = scenario();
    for name in presets::names() {
        let doc = presets::scenario(name).unwrap().to_value();
        let model = doc["model"].as_str().unwrap();
        let def = &schema["$defs"][format!("{}Scenario", capitalised(model))];
        let properties = def["properties"].as_object().unwrap();
        for key in doc.as_object().unwrap().keys() {
            assert!(
                properties.contains_key(key),
                "{name}: {key} is not in the schema"
            );
        }
        for key in def["required"].as_array().unwrap() {
            let key = key.as_str().unwrap();
            assert!(doc.get(key).is_some(), "{name}: lacks the required {key}");
        }
        assert_eq!(properties["model"]["const"], model);
    }
}

/// Every scheduled disturbance of a preset or lesson is one of its model's kinds, with only
/// that kind's keys, and the schema names the same kinds the model reads.
#[test]
fn disturbances_keep_to_their_models_kinds() {
    let schema = scenario();
    let mut seen = 0;
    let docs = presets::names()
        .map(|n| presets::scenario(n).unwrap())
        .chain(crate::lessons::names().map(|n| crate::lessons::scenario(n).unwrap()));
    for s in docs {
        let doc = s.to_value();
        let model = doc["model"].as_str().unwrap();
        let def = &schema["$defs"][format!("{}Disturbance", capitalised(model))];
        for d in doc["disturbances"].as_array().into_iter().flatten() {
            let kind = def["oneOf"]
                .as_array()
                .unwrap()
                .iter()
                .find(|k| k["properties"]["kind"]["const"] == d["kind"])
                .unwrap_or_else(|| panic!("{model}: kind {} is not in the schema", d["kind"]));
            for key in d.as_object().unwrap().keys() {
                assert!(kind["properties"].get(key).is_some(), "{model}: {key}");
            }
            assert!(kind["additionalProperties"] == false);
            seen += 1;
        }
    }
    assert!(seen > 0, "no preset or lesson schedules a disturbance");
    // A kind the schema offers is one the model reads: each kind's minimal action is refused,
    // if at all, for what it lacks or for the state, never as an unknown kind.
    for entry in MODELS {
        let def = &schema["$defs"][format!("{}Disturbance", capitalised(entry.name))];
        for kind in def["oneOf"].as_array().unwrap() {
            let name = kind["properties"]["kind"]["const"].as_str().unwrap();
            let preset = presets::names()
                .map(|n| presets::scenario(n).unwrap())
                .find(|s| s.to_value()["model"] == entry.name)
                .unwrap();
            let mut doc = preset.to_value();
            doc["disturbances"] = json!([{ "at": 1, "kind": name }]);
            if let Err(e) = crate::scenario::Scenario::from_value(doc) {
                let e = e.to_string();
                assert!(!e.contains("not a choice"), "{}: {name}: {e}", entry.name);
            }
        }
    }
}

/// The envelope's table names exactly the keys the envelope's schema has.
#[test]
fn the_envelope_table_is_the_envelopes_keys() {
    let (exercise, compare, handin, disturbance) = (json!({}), json!({}), json!({}), json!({}));
    let mut schema = envelope("amas", "", 1, [&exercise, &compare, &handin], &disturbance);
    schema.insert(rules::KEY.into(), rules_schema(&[]));
    let mut keys: Vec<&str> = schema.keys().map(String::as_str).collect();
    let mut table: Vec<&str> = crate::scenario::ENVELOPE.iter().map(|k| k.key).collect();
    keys.sort_unstable();
    table.sort_unstable();
    assert_eq!(keys, table);
}

/// Every range the schema states is the one the check holds to (both read the model's
/// bounds): a value just outside it is refused by name, one at its edge is not refused for it.
#[test]
fn every_range_in_the_schema_is_the_one_the_check_holds_to() {
    let schema = scenario();
    let mut ranges = 0;
    for entry in MODELS {
        let def = &schema["$defs"][format!("{}Scenario", capitalised(entry.name))];
        let doc = presets::names()
            .map(|n| presets::scenario(n).unwrap())
            .find(|s| s.model() == entry.name)
            .unwrap()
            .to_value();
        for (key, property) in def["properties"].as_object().unwrap() {
            let property = match property.get("$ref").and_then(Value::as_str) {
                Some(r) => &schema["$defs"][r.trim_start_matches("#/$defs/")],
                None => property,
            };
            let integer = property["type"] == "integer"
                || property["type"]
                    .as_array()
                    .is_some_and(|t| t.contains(&json!("integer")));
            let step = if integer { 1.0 } else { 1e-9 };
            let edges = [
                ("minimum", -step, true),
                ("exclusiveMinimum", 0.0, false),
                ("maximum", step, true),
            ];
            for (edge, outside, inclusive) in edges {
                let Some(v) = property.get(edge).and_then(Value::as_f64) else {
                    continue;
                };
                let out = v + outside * v.abs().max(1.0);
                if out < 0.0 && integer || ["version", "seed", "max_steps"].contains(&key.as_str())
                {
                    continue;
                }
                let with = |value: f64| {
                    let mut d = doc.clone();
                    d[key] = match integer {
                        true => json!(value as u64),
                        false => json!(value),
                    };
                    crate::scenario::Scenario::from_value(d)
                };
                let refused = with(out).expect_err(&format!("{}.{key} = {out}", entry.name));
                assert!(
                    refused.to_string().starts_with(&format!("{key}: ")),
                    "{}.{key} = {out}: {refused}",
                    entry.name
                );
                if inclusive {
                    if let Err(e) = with(v) {
                        assert!(
                            !e.to_string().starts_with(&format!("{key}: must")),
                            "{}.{key} = {v}: {e}",
                            entry.name
                        );
                    }
                }
                ranges += 1;
            }
        }
    }
    assert!(ranges > 30, "only {ranges} ranges in the schema");
}

/// Enums are lists of constants and sizes carry the limits, so a form can offer a select
/// and bounds.
#[test]
fn choices_are_constants_and_sizes_carry_their_limits() {
    let schema = scenario();
    let consts: Vec<&str> = schema["$defs"]["Collision"]["oneOf"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["const"].as_str().unwrap())
        .collect();
    assert_eq!(consts, ["token", "relay", "blackboard"]);
    let amas = &schema["$defs"]["AmasScenario"]["properties"];
    assert_eq!(
        amas["supply_rows"]["maximum"],
        kumiki_amas::limits::LIMITS.page.supply_rows
    );
    assert_eq!(amas["name"]["maxLength"], MAX_NAME_CHARS);
    assert_eq!(amas["max_steps"]["default"], 100_000);
    assert!(amas["robots"]["description"].is_string());
}
