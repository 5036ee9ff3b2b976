//! Golden state hashes for fixed scenarios, checked natively here and in wasm by
//! `tests/wasm/golden.rs` against the same fixture file.
//!
//! After an intended change to a model, regenerate the fixture with
//! `KUMIKI_BLESS=1 cargo test -p kumiki-core --test golden` and say why in the commit.

use kumiki_core::{hash, presets, Run};
use serde_json::{json, Value};

const FIXTURE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../tests/fixtures/golden.json"
);

/// The cases: every preset, two seeds, after a fixed number of steps (or its end).
fn cases() -> Vec<(String, u64, u64)> {
    presets::names()
        .flat_map(|p| [(p.to_string(), 1, 150), (p.to_string(), 7, 400)])
        .collect()
}

fn hash_after(preset: &str, seed: u64, steps: u64) -> String {
    let mut scenario = presets::scenario(preset).unwrap();
    scenario.seed = seed;
    let mut run = Run::new(scenario).unwrap();
    run.advance(steps);
    hash::hex(run.state_hash())
}

#[test]
fn golden_hashes_match_natively() {
    let computed: Vec<Value> = cases()
        .into_iter()
        .map(|(preset, seed, steps)| {
            let h = hash_after(&preset, seed, steps);
            json!({"preset": preset, "seed": seed, "steps": steps, "hash": h})
        })
        .collect();
    if std::env::var_os("KUMIKI_BLESS").is_some() {
        let text = serde_json::to_string_pretty(&computed).unwrap() + "\n";
        std::fs::write(FIXTURE, text).unwrap();
        return;
    }
    let stored: Vec<Value> =
        serde_json::from_str(&std::fs::read_to_string(FIXTURE).unwrap()).unwrap();
    assert_eq!(
        stored.len(),
        computed.len(),
        "the fixture covers other presets than exist; re-bless with KUMIKI_BLESS=1"
    );
    for (want, got) in stored.iter().zip(&computed) {
        assert_eq!(
            want, got,
            "golden hash changed; if intended, re-bless with KUMIKI_BLESS=1"
        );
    }
}
