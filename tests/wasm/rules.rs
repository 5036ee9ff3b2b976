//! Rule slots in wasm (headless Node): every slot's paper script gives the built-in rule's hashes
//! step by step, and the hashes and stop messages the native suite wrote in
//! `tests/fixtures/rules.json` (`tests/native/rules.rs`): a scripted rule and a hostile script run
//! bit for bit as they do natively. Also through the page's handle (`Sim`) of the rules module.
#![cfg(target_arch = "wasm32")]

use kumiki_core::models::MODELS;
use kumiki_core::{hash, presets, Run, Scenario};
use serde_json::Value;
use wasm_bindgen_test::wasm_bindgen_test;

const FIXTURE: &str = include_str!("../fixtures/rules.json");

fn fixture() -> Value {
    serde_json::from_str(FIXTURE).unwrap()
}

fn scripted(preset: &str, slot: &str, source: &str) -> Scenario {
    presets::scenario(preset)
        .unwrap()
        .with_override(&format!("rules.{slot}"), source.into())
        .unwrap()
}

/// The scenario of a fixture's scripted case: its preset with its settings (`set`, its first
/// steps at least), and the script `source` in its slot when one is given.
fn case_scenario(case: &Value, source: Option<&str>) -> Scenario {
    let mut overrides: Vec<(String, Value)> = case["set"]
        .as_object()
        .unwrap()
        .iter()
        .map(|(k, v)| (k.clone(), v.clone()))
        .collect();
    if let Some(source) = source {
        let slot = case["slot"].as_str().unwrap();
        overrides.push((format!("rules.{slot}"), source.into()));
    }
    presets::scenario(case["preset"].as_str().unwrap())
        .unwrap()
        .with_overrides(&overrides)
        .unwrap()
}

fn paper(slot: &str) -> &'static str {
    MODELS
        .iter()
        .flat_map(|m| m.slots)
        .find(|s| s.name == slot)
        .unwrap()
        .paper
}

#[wasm_bindgen_test]
fn paper_scripts_give_the_built_in_hashes_step_by_step_in_wasm() {
    let cases = fixture()["scripted"].as_array().unwrap().clone();
    assert!(!cases.is_empty());
    for case in cases {
        let (preset, slot) = (
            case["preset"].as_str().unwrap(),
            case["slot"].as_str().unwrap(),
        );
        let mut builtin = Run::new(case_scenario(&case, None)).unwrap();
        let mut script = Run::new(case_scenario(&case, Some(paper(slot)))).unwrap();
        while builtin.step() {
            assert!(script.step(), "{preset}");
            assert_eq!(
                builtin.state_hash(),
                script.state_hash(),
                "{preset} at {}",
                builtin.steps()
            );
        }
        assert!(!script.step());
        assert_eq!(script.steps(), case["steps"].as_u64().unwrap(), "{preset}");
        assert_eq!(
            hash::hex(script.state_hash()),
            case["hash"].as_str().unwrap(),
            "{preset}"
        );
    }
}

#[wasm_bindgen_test]
fn hostile_scripts_stop_where_and_as_they_do_natively() {
    for case in fixture()["stopped"].as_array().unwrap() {
        let source = case["source"].as_str().unwrap();
        let scenario = scripted(case["preset"].as_str().unwrap(), "leader", source);
        let mut run = Run::new(scenario).unwrap();
        run.run_to_end();
        let name = &case["name"];
        assert_eq!(run.stopped(), case["stopped"].as_str(), "{name}");
        assert_eq!(run.steps(), case["steps"].as_u64().unwrap(), "{name}");
        assert_eq!(
            hash::hex(run.state_hash()),
            case["hash"].as_str().unwrap(),
            "{name}"
        );
    }
}

#[wasm_bindgen_test]
fn the_pages_handle_runs_a_scenario_with_rules() {
    assert!(kumiki_wasm::rules_engine());
    let case = &fixture()["scripted"][0];
    let slot = case["slot"].as_str().unwrap();
    let mut sim = kumiki_wasm::Sim::new(&case_scenario(case, Some(paper(slot))).to_json()).unwrap();
    while sim.advance(50) > 0 {}
    assert_eq!(sim.hash(), case["hash"].as_str().unwrap());
    assert_eq!(sim.stopped(), None);
    let hostile = &fixture()["stopped"][0];
    let text = scripted(
        "chobie-crawl5",
        "leader",
        hostile["source"].as_str().unwrap(),
    )
    .to_json();
    let mut sim = kumiki_wasm::Sim::new(&text).unwrap();
    while sim.advance(50) > 0 {}
    assert_eq!(sim.stopped().as_deref(), hostile["stopped"].as_str());
    assert!(sim.finished());
}
