//! Share links: round trips for every preset and lesson, clear errors for damaged links, and the links of
//! earlier releases in `tests/fixtures/links.json`, which must keep opening.

use kumiki_core::experiment::PROGRAM_VERSION;
use kumiki_core::{hash, lessons, link, models, presets, Error, Run, Scenario};
use serde_json::{json, Value};

const FIXTURE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../tests/fixtures/links.json"
);
/// Steps run from each fixture link before its state hash is taken.
const STEPS: u64 = 150;

/// Every built-in scenario, presets and lessons, with its name.
fn builtins() -> impl Iterator<Item = (&'static str, Scenario)> {
    presets::names()
        .map(|n| (n, presets::scenario(n).unwrap()))
        .chain(lessons::names().map(|n| (n, lessons::scenario(n).unwrap())))
}

fn hash_after(scenario: kumiki_core::Scenario, steps: u64) -> String {
    let mut run = Run::new(scenario).unwrap();
    run.advance(steps);
    hash::hex(run.state_hash())
}

/// Links never rot: every link in the fixture opens, and while its model's behaviour version is
/// the one it was made with, it runs to the state hash it gave when it was made. A model whose
/// behaviour changed on purpose raises its `model_version` (in its `ModelEntry`); its old links
/// must then still open and run.
///
/// `KUMIKI_BLESS=1 cargo test -p kumiki-core --test links` adds a link, made by this program, for
/// each preset or lesson the fixture lacks (a lesson's entry names it under "preset" too). It never rewrites an entry: the fixture is a record of links
/// that are out in the world.
#[test]
fn links_of_earlier_releases_open_and_run_as_they_did() {
    let mut stored: Vec<Value> = match std::fs::read_to_string(FIXTURE) {
        Ok(text) => serde_json::from_str(&text).unwrap(),
        Err(_) => Vec::new(),
    };
    let has = |stored: &[Value], name: &str| stored.iter().any(|e| e["preset"] == name);
    if std::env::var_os("KUMIKI_BLESS").is_some() {
        for (name, scenario) in builtins() {
            if has(&stored, name) {
                continue;
            }
            let model = models::entry(scenario.model()).unwrap();
            stored.push(json!({
                "preset": name,
                "made_by": PROGRAM_VERSION,
                "model": model.name,
                "model_version": model.model_version,
                "link": link::encode(&scenario),
                "steps": STEPS,
                "hash": hash_after(scenario, STEPS),
            }));
        }
        let text = serde_json::to_string_pretty(&stored).unwrap() + "\n";
        std::fs::write(FIXTURE, text).unwrap();
        return;
    }
    for (name, _) in builtins() {
        assert!(
            has(&stored, name),
            "{name} has no link in tests/fixtures/links.json; add one with KUMIKI_BLESS=1 cargo test -p kumiki-core --test links"
        );
    }
    for entry in &stored {
        let preset = entry["preset"].as_str().unwrap();
        let made_by = entry["made_by"].as_str().unwrap();
        let text = entry["link"].as_str().unwrap();
        let opened = link::open(text)
            .unwrap_or_else(|e| panic!("the {preset} link made by {made_by} no longer opens: {e}"));
        assert_eq!(
            u64::from(opened.made_with),
            entry["model_version"].as_u64().unwrap(),
            "the {preset} link carries another model version than the fixture recorded"
        );
        let steps = entry["steps"].as_u64().unwrap();
        let hash = hash_after(opened.scenario.clone(), steps);
        if !opened.version_differs() {
            assert_eq!(
                hash,
                entry["hash"].as_str().unwrap(),
                "the {preset} link made by {made_by} runs differently, yet {} is still at model version {}: if its behaviour changed on purpose, raise model_version in its ModelEntry",
                opened.scenario.model(),
                opened.current
            );
        }
    }
}

#[test]
fn a_link_says_which_model_version_made_it() {
    let scenario = presets::scenario("fracta-hexagon7").unwrap();
    let current = models::entry("fracta").unwrap().model_version;
    let opened = link::open(&link::encode(&scenario)).unwrap();
    assert_eq!((opened.made_with, opened.current), (current, current));
    assert!(!opened.version_differs());
    assert_eq!(opened.scenario, scenario);

    // A link of another version (and one from before versions were recorded, which counts as
    // version 1) opens with the same scenario and says so.
    let pack = |doc: &Value| {
        use base64::Engine as _;
        let packed = miniz_oxide::deflate::compress_to_vec(doc.to_string().as_bytes(), 9);
        format!(
            "{}{}",
            link::PREFIX,
            base64::engine::general_purpose::URL_SAFE_NO_PAD.encode(packed)
        )
    };
    let mut doc = scenario.to_value();
    doc[link::MODEL_VERSION_KEY] = json!(current + 1);
    let newer = link::open(&pack(&doc)).unwrap();
    assert_eq!(newer.made_with, current + 1);
    assert!(newer.version_differs());
    assert_eq!(newer.scenario, scenario);
    let unversioned = link::open(&pack(&scenario.to_value())).unwrap();
    assert_eq!(unversioned.made_with, 1);
    assert_eq!(unversioned.scenario, scenario);
    doc[link::MODEL_VERSION_KEY] = json!("one");
    let err = link::open(&pack(&doc)).unwrap_err().to_string();
    assert!(err.starts_with("model_version: "), "{err}");
}

#[test]
fn every_preset_and_lesson_survives_a_link_round_trip() {
    for (name, scenario) in builtins() {
        let encoded = link::encode(&scenario);
        assert!(encoded.starts_with(link::PREFIX));
        assert!(encoded[3..]
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b'_'));
        for form in [
            encoded.clone(),
            format!("#{encoded}"),
            format!("https://example.org/sub/path/index.html?x=1#{encoded}"),
        ] {
            assert_eq!(link::decode(&form).unwrap(), scenario, "{name} via {form}");
        }
    }
}

/// The page encodes the scenario it already validated from its JSON, and reads a large link's
/// size before the worker validates it: both must agree with the checked paths.
#[test]
fn unchecked_packing_and_unpacking_match_the_checked_paths() {
    for name in presets::names() {
        let scenario = presets::scenario(name).unwrap();
        let doc: Value = serde_json::from_str(&scenario.to_json_pretty()).unwrap();
        let encoded = link::pack(doc.clone());
        assert_eq!(encoded, link::encode(&scenario), "{name}");
        let (unpacked, made_with) = link::unpack(&encoded).unwrap();
        assert_eq!(unpacked, doc, "{name}");
        assert_eq!(
            made_with,
            models::entry(scenario.model()).unwrap().model_version
        );
    }
}

#[test]
fn damaged_links_are_errors_that_say_so() {
    let good = link::encode(&presets::scenario("amas-L").unwrap());
    let cases = [
        ("", "starts with"),
        ("#hello", "starts with"),
        ("#k9.abcdef", "another Kumiki version"),
        (
            "#k1.***",
            "damaged: it holds '*', which no Kumiki link has (character 1",
        ),
        ("#k1.ab%20", "'%'"),
        (&good[..good.len() / 2], "damaged"),
    ];
    for (input, expect) in cases {
        let err = link::decode(input).unwrap_err();
        assert!(matches!(err, Error::Link(_)), "{input}: {err}");
        assert!(err.to_string().contains(expect), "{input}: {err}");
        assert!(
            !err.to_string().contains("Invalid symbol"),
            "{input}: {err}"
        );
    }
}

#[test]
fn a_link_to_an_invalid_scenario_names_the_field() {
    use base64::Engine as _;
    let json = r###"{"version":1,"model":"amas","target":"##","robots":0}"###;
    let packed = miniz_oxide::deflate::compress_to_vec(json.as_bytes(), 6);
    let payload = format!(
        "k1.{}",
        base64::engine::general_purpose::URL_SAFE_NO_PAD.encode(packed)
    );
    let err = link::decode(&payload).unwrap_err().to_string();
    assert!(err.starts_with("robots:"), "{err}");
}

#[test]
fn decompression_bombs_are_refused() {
    use base64::Engine as _;
    let huge = vec![b' '; link::MAX_SCENARIO_BYTES + 10];
    let packed = miniz_oxide::deflate::compress_to_vec(&huge, 9);
    let payload = format!(
        "k1.{}",
        base64::engine::general_purpose::URL_SAFE_NO_PAD.encode(packed)
    );
    assert!(link::decode(&payload)
        .unwrap_err()
        .to_string()
        .contains("larger than"));
}

#[test]
fn canonical_scenarios_state_every_default() {
    // fracta-triangle10's file leaves K, L, G and I_th at their defaults; the canonical form, and
    // so every link, writes them out.
    let s = presets::scenario("fracta-triangle10").unwrap();
    for key in ["K", "L", "G", "I_th"] {
        assert!(
            s.body().contains_key(key),
            "{key} missing from the canonical scenario"
        );
    }
    // Reading the canonical form again changes nothing.
    let again = kumiki_core::Scenario::from_json(&s.to_json()).unwrap();
    assert_eq!(again, s);
}

const EXPERIMENT_FIXTURE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../tests/fixtures/experiment-links.json"
);

/// Experiment links (`#x1.…`) never rot either: each link in `tests/fixtures/experiment-links.json`
/// opens, as the page opens it (unpacked, then read and checked like a file), to the experiment it
/// was made from, with the same runs. `KUMIKI_BLESS=1 cargo test -p kumiki-core --test links` adds
/// a link for each built-in experiment the fixture lacks, and never rewrites an entry.
#[test]
fn experiment_links_of_earlier_releases_open() {
    use kumiki_core::experiment::Experiment;
    let mut stored: Vec<Value> = match std::fs::read_to_string(EXPERIMENT_FIXTURE) {
        Ok(text) => serde_json::from_str(&text).unwrap(),
        Err(_) => Vec::new(),
    };
    let has = |stored: &[Value], name: &str| stored.iter().any(|e| e["experiment"] == name);
    let names: Vec<&str> = presets::experiment_names().collect();
    if std::env::var_os("KUMIKI_BLESS").is_some() {
        for name in &names {
            if has(&stored, name) {
                continue;
            }
            let e = Experiment::named_or_json(name).unwrap();
            stored.push(json!({
                "experiment": name,
                "made_by": PROGRAM_VERSION,
                "link": format!("#{}", link::pack_experiment(&e.definition)),
                "runs": e.jobs().len(),
            }));
        }
        let text = serde_json::to_string_pretty(&stored).unwrap() + "\n";
        std::fs::write(EXPERIMENT_FIXTURE, text).unwrap();
        return;
    }
    for name in &names {
        assert!(
            has(&stored, name),
            "{name} has no link in tests/fixtures/experiment-links.json; add one with KUMIKI_BLESS=1 cargo test -p kumiki-core --test links"
        );
    }
    for entry in &stored {
        let name = entry["experiment"].as_str().unwrap();
        let made_by = entry["made_by"].as_str().unwrap();
        let json = link::unpack_experiment(entry["link"].as_str().unwrap()).unwrap_or_else(|e| {
            panic!("the {name} experiment link made by {made_by} no longer opens: {e}")
        });
        let e = Experiment::from_json(&json).unwrap_or_else(|e| {
            panic!("the {name} experiment link made by {made_by} is no longer read: {e}")
        });
        assert_eq!(e.name, name);
        assert_eq!(
            e.jobs().len() as u64,
            entry["runs"].as_u64().unwrap(),
            "the {name} experiment link made by {made_by} holds other runs than it did"
        );
    }
}
