//! Golden state hashes and the share links of earlier releases, checked in wasm (headless Node)
//! against the same fixtures the native suite checks: equal hashes mean the native and wasm runs
//! are bit-identical.
#![cfg(target_arch = "wasm32")]

use kumiki_core::{hash, link, presets, Run};
use wasm_bindgen_test::wasm_bindgen_test;

const GOLDEN: &str = include_str!("../fixtures/golden.json");
const LINKS: &str = include_str!("../fixtures/links.json");

#[wasm_bindgen_test]
fn golden_hashes_match_in_wasm() {
    let cases: Vec<serde_json::Value> = serde_json::from_str(GOLDEN).unwrap();
    assert!(!cases.is_empty());
    for case in cases {
        let preset = case["preset"].as_str().unwrap();
        let mut scenario = presets::scenario(preset).unwrap();
        scenario.seed = case["seed"].as_u64().unwrap();
        let mut run = Run::new(scenario).unwrap();
        run.advance(case["steps"].as_u64().unwrap());
        assert_eq!(
            hash::hex(run.state_hash()),
            case["hash"].as_str().unwrap(),
            "{preset} seed {} after {} steps",
            case["seed"],
            case["steps"]
        );
    }
}

#[wasm_bindgen_test]
fn links_of_earlier_releases_open_and_run_as_they_did_in_wasm() {
    let entries: Vec<serde_json::Value> = serde_json::from_str(LINKS).unwrap();
    assert!(!entries.is_empty());
    for entry in entries {
        let preset = entry["preset"].as_str().unwrap();
        let opened = link::open(entry["link"].as_str().unwrap())
            .unwrap_or_else(|e| panic!("the {preset} link no longer opens: {e}"));
        let mut run = Run::new(opened.scenario.clone()).unwrap();
        run.advance(entry["steps"].as_u64().unwrap());
        if !opened.version_differs() {
            assert_eq!(
                hash::hex(run.state_hash()),
                entry["hash"].as_str().unwrap(),
                "the {preset} link"
            );
        }
    }
}
