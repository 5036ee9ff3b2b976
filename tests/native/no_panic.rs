//! No input ever panics: random text into every reader, and every preset with its keys set to
//! unexpected values (which must either load and run, or be refused with an error).

use kumiki_core::error::BRIEF_CHARS;
use kumiki_core::experiment::Experiment;
use kumiki_core::{link, presets, shape, Error, Run, Scenario};
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

/// One edit of a preset's canonical JSON: at a position (a fraction of the length), replace a
/// character, insert text, delete a span, or repeat a span several times.
#[derive(Clone, Debug)]
enum Edit {
    Replace(f64, char),
    Insert(f64, String),
    Delete(f64, usize),
    Repeat(f64, usize, usize),
}

fn edit() -> impl Strategy<Value = Edit> {
    let at = 0.0..1.0f64;
    prop_oneof![
        (
            at.clone(),
            prop::sample::select(vec![
                '9', '"', '{', '}', '[', ']', '-', 'e', '#', '.', '\n', ',', ':', '0', ' ',
                '\u{202e}'
            ])
        )
            .prop_map(|(a, c)| Edit::Replace(a, c)),
        (
            at.clone(),
            prop::sample::select(vec![
                "99999999999",
                "-1",
                "1e308",
                "0.5",
                "null",
                "\"\"",
                "[]",
                "{}",
                "\\n####",
                "#\\n",
                "\\u0000"
            ])
        )
            .prop_map(|(a, t)| Edit::Insert(a, t.to_string())),
        (at.clone(), 1usize..40).prop_map(|(a, n)| Edit::Delete(a, n)),
        (at, 1usize..12, 2usize..200).prop_map(|(a, n, k)| Edit::Repeat(a, n, k)),
    ]
}

fn apply(text: &str, edits: &[Edit]) -> String {
    let mut chars: Vec<char> = text.chars().collect();
    for e in edits {
        let pos = |a: f64, len: usize| ((a * len as f64) as usize).min(len);
        match e {
            Edit::Replace(a, c) => {
                if !chars.is_empty() {
                    let i = pos(*a, chars.len() - 1);
                    chars[i] = *c;
                }
            }
            Edit::Insert(a, t) => {
                let i = pos(*a, chars.len());
                chars.splice(i..i, t.chars());
            }
            Edit::Delete(a, n) => {
                let i = pos(*a, chars.len());
                let j = (i + n).min(chars.len());
                chars.drain(i..j);
            }
            Edit::Repeat(a, n, k) => {
                let i = pos(*a, chars.len());
                let j = (i + n).min(chars.len());
                let span: Vec<char> = chars[i..j].to_vec();
                for _ in 1..*k {
                    chars.splice(j..j, span.iter().copied());
                }
            }
        }
    }
    chars.into_iter().collect()
}

/// The fuzz run: every preset's link, edited, must open and run a few steps or be refused with
/// an error whose message is brief (under BRIEF_CHARS characters, with the field's path); nothing
/// panics. `KUMIKI_FUZZ_CASES` sets the number of cases (`npm run fuzz` runs
/// many); the count and the slowest case are printed.
#[test]
fn edited_preset_links_open_and_run_or_are_refused() {
    use proptest::test_runner::{Config, TestRunner};
    use std::time::{Duration, Instant};
    let cases: u32 = std::env::var("KUMIKI_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(300);
    let names: Vec<&str> = presets::names().collect();
    let corpus: Vec<String> = names
        .iter()
        .map(|n| presets::scenario(n).unwrap().to_json())
        .collect();
    let mut runner = TestRunner::new(Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    });
    let slowest = std::cell::RefCell::new((Duration::ZERO, String::new()));
    let (opened, refused) = (std::cell::Cell::new(0u32), std::cell::Cell::new(0u32));
    let longest = std::cell::Cell::new(0usize);
    let strategy = (0..corpus.len(), prop::collection::vec(edit(), 1..4));
    runner
        .run(&strategy, |(preset, edits)| {
            let text = apply(&corpus[preset], &edits);
            let packed = miniz_oxide::deflate::compress_to_vec(text.as_bytes(), 6);
            let link = format!(
                "#k1.{}",
                base64::Engine::encode(&base64::engine::general_purpose::URL_SAFE_NO_PAD, packed)
            );
            let start = Instant::now();
            match link::decode(&link) {
                Ok(scenario) => {
                    let mut run = Run::new(scenario).expect("a decoded scenario builds");
                    run.advance(20);
                    let _ = run.outcome();
                    opened.set(opened.get() + 1);
                }
                Err(e) => {
                    // The message is brief, and says where: the field's path when it is a field.
                    let brief = e.to_string();
                    prop_assert!(
                        brief.chars().count() < BRIEF_CHARS,
                        "{} characters: {brief}",
                        brief.chars().count()
                    );
                    if let Error::Field { path, .. } = &e {
                        // A long path keeps its ends (its middle elided).
                        let head: String = path.chars().take(30).collect();
                        prop_assert!(
                            path.is_empty()
                                || brief.starts_with(&format!("{path}: "))
                                || (path.chars().count() > 60 && brief.starts_with(&head)),
                            "the path {path} is not shown: {brief}"
                        );
                    }
                    longest.set(longest.get().max(format!("{e:#}").chars().count()));
                    refused.set(refused.get() + 1)
                }
            }
            let took = start.elapsed();
            if took > slowest.borrow().0 {
                *slowest.borrow_mut() = (took, format!("{} with {edits:?}", names[preset]));
            }
            Ok(())
        })
        .unwrap();
    let (took, case) = slowest.into_inner();
    println!(
        "fuzz: {} cases without a panic ({} opened and ran 20 steps, {} refused, every message under {BRIEF_CHARS} characters, the longest in full {}); slowest {:.1} ms: {case}",
        opened.get() + refused.get(),
        opened.get(),
        refused.get(),
        longest.get(),
        took.as_secs_f64() * 1e3
    );
}
