//! No input ever panics: random text into every reader, and every preset with its keys set to
//! unexpected values (which must either load and run, or be refused with an error).

use kumiki_core::experiment::Experiment;
use kumiki_core::{link, presets, shape, Run, Scenario};
use proptest::prelude::*;
use serde_json::{json, Value};

fn odd_value() -> impl Strategy<Value = Value> {
    prop_oneof![
        Just(Value::Null),
        any::<bool>().prop_map(Value::from),
        any::<i64>().prop_map(Value::from),
        any::<f64>()
            .prop_filter("JSON has no NaN or infinity", |f| f.is_finite())
            .prop_map(|f| json!(f)),
        prop_oneof![
            Just(0u64),
            Just(1),
            Just(2),
            Just(7),
            Just(1 << 20),
            Just(u64::MAX)
        ]
        .prop_map(Value::from),
        ".{0,12}".prop_map(Value::from),
        "[#. \n-]{0,40}".prop_map(Value::from),
        Just(json!([])),
        Just(json!({})),
        Just(json!({"rect": [3, 2]})),
        Just(json!({"rect": [100000, 100000]})),
        Just(json!([{"at": 1, "kind": "remove", "count": 1}])),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn readers_refuse_garbage_without_panicking(text in "\\PC{0,200}") {
        let _ = Scenario::from_json(&text);
        let _ = link::decode(&text);
        let _ = link::decode(&format!("#k1.{text}"));
        let _ = Experiment::from_json(&text);
        let _ = shape::parse_square(&text);
        let _ = shape::parse_hex(&text);
        let _ = shape::parse_cubic(&text);
    }

    #[test]
    fn presets_with_odd_values_load_and_run_or_are_refused(
        preset in 0usize..64,
        key in 0usize..64,
        value in odd_value(),
    ) {
        let names: Vec<&str> = presets::names().collect();
        let name = names[preset % names.len()];
        let mut doc = presets::scenario(name).unwrap().to_value();
        let keys: Vec<String> = doc.as_object().unwrap().keys().cloned().collect();
        let key = &keys[key % keys.len()];
        doc[key.as_str()] = value;
        if let Ok(scenario) = Scenario::from_value(doc) {
            let mut run = Run::new(scenario).unwrap();
            run.advance(30);
            let _ = run.outcome();
        }
    }
}
