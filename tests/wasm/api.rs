//! The exported handle as JavaScript sees it, run in headless Node.
#![cfg(target_arch = "wasm32")]

use kumiki_wasm::{
    decode_link, encode_link, fresh_seed, link_model_versions, model_query, preset_changes,
    preset_json, unpack_link, Draft, Sim,
};
use wasm_bindgen_test::wasm_bindgen_test;

#[wasm_bindgen_test]
fn sim_steps_and_reports() {
    let json = preset_json("amas-L").unwrap();
    let mut sim = Sim::new(&json).unwrap();
    let before = sim.hash();
    assert_eq!(sim.advance(10), 10);
    assert_eq!(sim.steps(), 10.0);
    assert_ne!(sim.hash(), before);
    let cells = sim.cells();
    assert!(cells.length() > 0);
    assert_eq!(sim.agents().length() % 2, 0);
    assert!(sim.field("potential").is_some());
    assert!(sim.field("no_such_field").is_none());
}

#[wasm_bindgen_test]
fn link_round_trip_in_wasm() {
    let json = preset_json("amas-L").unwrap();
    let link = encode_link(&json).unwrap();
    assert!(link.starts_with("k1."));
    assert_eq!(
        decode_link(&format!("https://x.example/kumiki/#{link}")).unwrap(),
        json
    );
    let versions = link_model_versions(&link).unwrap();
    let get = |key: &str| {
        js_sys::Reflect::get(&versions, &key.into())
            .unwrap()
            .as_f64()
    };
    // A link made now carries the running model's version.
    assert!(get("current").is_some_and(|v| v >= 1.0));
    assert_eq!(get("made_with"), get("current"));
}

#[wasm_bindgen_test]
fn bad_input_is_an_error_not_a_panic() {
    assert!(Sim::new("{").is_err());
    assert!(Sim::new(r##"{"version": 1, "model": "amas", "target": "#", "robots": 0}"##).is_err());
    assert!(decode_link("#k1.@@@").is_err());
}

#[wasm_bindgen_test]
fn clicked_actions_enter_the_scenario() {
    let mut sim = Sim::new(&preset_json("amas-L").unwrap()).unwrap();
    sim.advance(200);
    sim.apply(r#"{"kind": "remove", "count": 1}"#).unwrap();
    assert!(sim.scenario_json().contains("\"disturbances\""));
    assert!(sim.apply(r#"{"kind": "bogus"}"#).is_err());
}

#[wasm_bindgen_test]
fn cubes_scene_and_queries_in_wasm() {
    let mut sim = Sim::new(&preset_json("cubes-light").unwrap()).unwrap();
    assert_eq!(sim.advance(5), 5);
    assert!(sim.scene().is_ok());
    // The first frame carries the scene; later ones only when it changed (light and ground stay).
    let scene = |sim: &mut Sim| {
        js_sys::Reflect::get(&sim.frame(false, None, 0).unwrap(), &"scene".into()).unwrap()
    };
    assert!(!scene(&mut sim).is_null());
    sim.advance(3);
    assert!(scene(&mut sim).is_null());
    assert!(sim.field("difference").is_some());
    let out = model_query(
        "cubes3d",
        "derive",
        r###"{"shape": "##\n##\n---\n##\n##\n"}"###,
    )
    .unwrap();
    assert!(out.contains("C31[C31, C31, C31]"));
    assert!(model_query("cubes3d", "check", r#"{"type_lists": "C31[C31"}"#).is_err());
}

#[wasm_bindgen_test]
fn fracta_bonds_and_queries_in_wasm() {
    let mut sim = Sim::new(&preset_json("fracta-triangle10").unwrap()).unwrap();
    sim.advance(5);
    assert_eq!(sim.bonds().length(), sim.cells().length());
    assert!(sim.field("difference").is_some());
    let amas = Sim::new(&preset_json("amas-L").unwrap()).unwrap();
    assert_eq!(amas.bonds().length(), 0);
    let goal = model_query(
        "fracta",
        "derive",
        r###"{"shape": ". . # .\n . # # .\n. # # #\n # # # #\n"}"###,
    )
    .unwrap();
    assert_eq!(
        goal,
        r#"{"goal":"o{K, K}  K{o, K, K, s}  s{K, K, K, K, K, K}\n"}"#
    );
    assert!(model_query("fracta", "check", r#"{"goal": "o{K, K}\nK{o}"}"#).is_err());
    assert!(model_query("fracta", "no-such-query", "{}").is_err());
}

#[wasm_bindgen_test]
fn rewinding_gives_identical_hashes_and_a_click_in_the_past_forks() {
    let json = preset_json("amas-L").unwrap();
    let mut sim = Sim::new(&json).unwrap();
    let furthest = |sim: &mut Sim| {
        let frame = sim.frame(false, None, 0).unwrap();
        js_sys::Reflect::get(&frame, &"furthest".into())
            .unwrap()
            .as_f64()
            .unwrap()
    };
    let mut hashes = vec![sim.hash()];
    for _ in 0..120 {
        sim.advance(1);
        hashes.push(sim.hash());
    }
    assert_eq!(furthest(&mut sim), 120.0);
    for back in [0usize, 7, 64, 119] {
        sim.seek(back as f64);
        assert_eq!(sim.steps(), back as f64);
        assert_eq!(sim.hash(), hashes[back], "back at {back}");
    }
    sim.seek(30.0);
    sim.advance(90);
    assert_eq!(sim.hash(), hashes[120], "forward again");
    assert_eq!(furthest(&mut sim), 120.0);

    sim.seek(100.0);
    sim.apply(r#"{"kind": "remove", "count": 2}"#).unwrap();
    assert_eq!(
        furthest(&mut sim),
        100.0,
        "the fork ends the timeline at the click"
    );
    assert!(sim.scenario_json().contains("\"at\": 100"));
    sim.advance(20);
    assert_ne!(sim.hash(), hashes[120], "the fork runs differently");
}

#[wasm_bindgen_test]
fn fresh_seeds_come_from_crypto_and_fit_a_scenario() {
    let a = fresh_seed().unwrap();
    let b = fresh_seed().unwrap();
    assert_ne!(a, b, "two draws of 53 bits");
    for seed in [a, b] {
        assert!((0.0..=9_007_199_254_740_991.0).contains(&seed) && seed.fract() == 0.0);
    }
}

#[wasm_bindgen_test]
fn large_scenarios_are_measured_and_packed_without_building() {
    let field =
        |v: &wasm_bindgen::JsValue, key: &str| js_sys::Reflect::get(v, &key.into()).unwrap();
    let json = preset_json("amas-L").unwrap();
    let mut draft = Draft::new(f64::from(1 << 18));
    let small = draft.open(&json, false).unwrap();
    assert_eq!(field(&small, "large_cells").as_f64(), Some(0.0));
    assert_eq!(field(&small, "text").as_string(), Some(json.clone()));
    let big = draft
        .edit_all(r#"{"target": {"rect": [2048, 2040]}}"#)
        .unwrap();
    assert_eq!(field(&big, "large_cells").as_f64(), Some(2048.0 * 2040.0));
    assert!(field(&big, "problem").is_null());
    // The large one is the worker's to check: until it ran, the scenario in view is the first.
    let link = draft.link(None).unwrap();
    assert_eq!(link, encode_link(&json).unwrap());
    let unpacked = unpack_link(&link).unwrap();
    let scenario = js_sys::Reflect::get(&unpacked, &"scenario".into())
        .unwrap()
        .as_string()
        .unwrap();
    assert_eq!(scenario, json);
}

#[wasm_bindgen_test]
fn an_edited_preset_says_what_changed_unless_too_large_to_read_on_the_pages_thread() {
    let limit = f64::from(1 << 18);
    let edited = |set: &str| {
        let mut doc: serde_json::Value =
            serde_json::from_str(&preset_json("amas-L").unwrap()).unwrap();
        let set: serde_json::Value = serde_json::from_str(set).unwrap();
        for (k, v) in set.as_object().unwrap() {
            doc[k] = v.clone();
        }
        doc.to_string()
    };
    let changes = preset_changes(&edited(r#"{"robots": 3}"#), limit).unwrap();
    assert_eq!(
        serde_wasm_bindgen::from_value::<Vec<String>>(changes).unwrap(),
        ["robots: 5 → 3"]
    );
    // Its worker reads a large one; a name no preset has is no edited preset.
    let large = edited(r#"{"target": {"rect": [4096, 4088]}}"#);
    assert!(preset_changes(&large, limit).unwrap().is_null());
    assert!(
        preset_changes(&edited(r#"{"name": "mine", "robots": 3}"#), limit)
            .unwrap()
            .is_null()
    );
}

#[wasm_bindgen_test]
fn an_edit_runs_from_the_scenario_the_draft_checked() {
    let field =
        |v: &wasm_bindgen::JsValue, key: &str| js_sys::Reflect::get(v, &key.into()).unwrap();
    let mut draft = Draft::new(f64::from(1 << 18));
    assert!(field(
        &draft.open(&preset_json("amas-L").unwrap(), false).unwrap(),
        "problem"
    )
    .is_null());
    let edited = draft.edit_all(r#"{"seed": 7, "robots": 6}"#).unwrap();
    let text = field(&edited, "text").as_string().unwrap();
    let mut started = Sim::start(&mut draft).unwrap();
    let mut read = Sim::new(&text).unwrap();
    assert_eq!(started.scenario_json(), text);
    started.advance(50);
    read.advance(50);
    assert_eq!(
        started.hash(),
        read.hash(),
        "the run started from the draft is the run of its text"
    );
    // The draft holds the scenario the run keeps: a click recorded in the run is in the next edit.
    started.apply(r#"{"kind": "remove", "count": 1}"#).unwrap();
    draft.ran(&started);
    let next = draft.edit_all(r#"{"seed": 8}"#).unwrap();
    assert!(field(&next, "text")
        .as_string()
        .unwrap()
        .contains("\"at\": 50"));
}
