//! Golden state hashes, checked in wasm (headless Node) against the same fixture the native suite
//! checks: equal hashes mean the native and wasm runs are bit-identical.
#![cfg(target_arch = "wasm32")]

use kumiki_core::{hash, presets, Run};
use wasm_bindgen_test::wasm_bindgen_test;

const GOLDEN: &str = include_str!("../fixtures/golden.json");

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
