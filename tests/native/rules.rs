//! Rule slots natively: every slot's paper script replays the built-in rule step by step on every
//! preset that asks the slot, and a scenario's `rules` read, written, shared, swept, compared and
//! stopped like every other key. `tests/wasm/rules.rs` checks the same runs in wasm against the
//! fixture written here (`tests/fixtures/rules.json`: the scripted runs' hashes, and what each
//! hostile script stops with, where, and the state it leaves).
//!
//! After an intended change, regenerate the fixture with
//! `KUMIKI_BLESS=1 cargo test -p kumiki-core --test rules` and say why in the commit.

use kumiki_core::experiment::Experiment;
use kumiki_core::models::{self, MODELS};
use kumiki_core::{hash, link, presets, Run, Scenario};
use serde_json::{json, Value};

/// The scenario `preset` with `source` in slot `slot`.
fn scripted_scenario(preset: &str, slot: &str, source: &str) -> Scenario {
    presets::scenario(preset)
        .unwrap()
        .with_override(&format!("rules.{slot}"), source.into())
        .unwrap()
}

/// Steps both runs together, comparing their state hashes after every step; the steps taken.
fn same_hashes_step_by_step(mut builtin: Run, mut script: Run, what: &str) -> u64 {
    assert_eq!(
        builtin.state_hash(),
        script.state_hash(),
        "{what}: at step 0"
    );
    loop {
        let (a, b) = (builtin.step(), script.step());
        assert_eq!(
            a,
            b,
            "{what}: one run ended before the other, at {}",
            builtin.steps()
        );
        assert_eq!(
            hash::hex(builtin.state_hash()),
            hash::hex(script.state_hash()),
            "{what}: hashes part at step {}",
            builtin.steps()
        );
        if !a {
            assert_eq!(script.stopped(), None, "{what}");
            assert_eq!(builtin.outcome(), script.outcome(), "{what}");
            return builtin.steps();
        }
    }
}

/// Whether `preset` asks slot `slot` in its run: a script that throws stops it if so.
fn asks(preset: &str, slot: &str) -> bool {
    let mut run = Run::new(scripted_scenario(
        preset,
        slot,
        &format!("fn {slot}(x) {{ throw \"asked\" }}"),
    ))
    .unwrap();
    run.run_to_end();
    run.stopped().is_some()
}

const FIXTURE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../tests/fixtures/rules.json"
);

/// Scripts that must be stopped, in CHOBIE II's slot: (what, preset, script). The last throws what
/// the portable maths give, formatted: its message must be the same in wasm.
const STOPPED: [(&str, &str, &str); 6] = [
    ("endless loop", "chobie-crawl5", "fn leader(robot) {\n  loop { }\n}"),
    (
        "deep recursion",
        "chobie-crawl5",
        "fn deeper(n) { deeper(n + 1) }\nfn leader(robot) { deeper(0) }",
    ),
    (
        "huge array",
        "chobie-crawl5",
        "fn leader(robot) {\n  let a = [1];\n  loop { a += a; }\n}",
    ),
    (
        "huge string",
        "chobie-crawl5",
        "fn leader(robot) {\n  let s = \"robot\";\n  loop { s += s; }\n}",
    ),
    (
        "just under the cap per call, robot after robot",
        "chobie-bridge",
        "fn leader(robot) {\n  let i = 0;\n  while i < 16000 { i += 1; }\n  ()\n}",
    ),
    (
        "maths",
        "chobie-crawl5",
        "fn leader(robot) {\n  throw [0.1 + 0.2, exp(1.0), ln(3.0), pow(2.0, 0.5), ln_1p(1e-10), sqrt(2.0), 1.0 / 3.0 * 1e-7, 2.5e300 * 1e8, `${exp(-0.5)}`];\n}",
    ),
];

/// The fixture as this build computes it: every slot's paper script on every preset that asks
/// it (its steps and final hash, the built-in's), and the stopped scripts' messages and states.
fn fixture() -> Value {
    let mut scripted = Vec::new();
    for entry in MODELS {
        for slot in entry.slots {
            for preset in presets::names() {
                if presets::scenario(preset).unwrap().model() != entry.name
                    || !asks(preset, slot.name)
                {
                    continue;
                }
                let mut run = Run::new(scripted_scenario(preset, slot.name, slot.paper)).unwrap();
                run.run_to_end();
                scripted.push(json!({"preset": preset, "slot": slot.name, "steps": run.steps(), "hash": run.outcome().hash}));
            }
        }
    }
    let stopped: Vec<Value> = STOPPED
        .iter()
        .map(|(name, preset, source)| {
            let mut run = Run::new(scripted_scenario(preset, "leader", source)).unwrap();
            run.run_to_end();
            json!({"name": name, "preset": preset, "slot": "leader", "source": source,
                   "stopped": run.stopped(), "steps": run.steps(), "hash": run.outcome().hash})
        })
        .collect();
    json!({"scripted": scripted, "stopped": stopped})
}

#[test]
fn the_rules_fixture_is_what_this_build_computes() {
    let computed = fixture();
    if std::env::var_os("KUMIKI_BLESS").is_some() {
        let text = serde_json::to_string_pretty(&computed).unwrap() + "\n";
        std::fs::write(FIXTURE, text).unwrap();
        return;
    }
    let stored: Value = serde_json::from_str(&std::fs::read_to_string(FIXTURE).unwrap()).unwrap();
    assert_eq!(stored, computed, "re-bless with KUMIKI_BLESS=1 if intended");
    for case in computed["stopped"].as_array().unwrap() {
        assert!(case["stopped"].is_string(), "{case}");
    }
}

#[test]
fn every_slots_paper_script_gives_the_built_in_rules_hashes_on_every_preset_that_asks_it() {
    let mut checked = Vec::new();
    for entry in MODELS {
        for slot in entry.slots {
            let presets: Vec<&str> = presets::names()
                .filter(|p| presets::scenario(p).unwrap().model() == entry.name)
                .filter(|p| asks(p, slot.name))
                .collect();
            assert!(
                !presets.is_empty(),
                "{}.{}: no preset asks it",
                entry.name,
                slot.name
            );
            for preset in presets {
                let script = scripted_scenario(preset, slot.name, slot.paper);
                let steps = same_hashes_step_by_step(
                    Run::new(presets::scenario(preset).unwrap()).unwrap(),
                    Run::new(script).unwrap(),
                    &format!("{preset} with the paper's {} script", slot.name),
                );
                checked.push(format!("{preset}:{steps}"));
            }
        }
    }
    // CHOBIE II's election asks `leader` in every preset but the one whose robots only adapt
    // (figure 14: construction off, so the three rules never elect).
    let chobie: Vec<&str> = checked
        .iter()
        .filter_map(|c| c.strip_prefix("chobie-"))
        .map(|c| c.split(':').next().unwrap())
        .collect();
    assert_eq!(
        chobie,
        [
            "bridge", "crawl3", "crawl5", "crawl7", "crawl9", "fig13", "form-a", "form-b",
            "form-c", "form-d"
        ],
        "{checked:?}"
    );
    assert!(!asks("chobie-load5", "leader"));
}

/// Rule 3 for robots that heard from top only: the robots on the lower tier never lead, and the
/// crawl stops after its first two forms.
const TOP_ONLY: &str = r#"
fn leader(robot) {
    if !robot.first.up { return (); }
    if robot.second.right { "top_right" } else if robot.second.left { "top_left" } else { () }
}"#;

#[test]
fn a_users_rule_changes_the_run_and_its_link_replays_it() {
    let scenario = scripted_scenario("chobie-crawl5", "leader", TOP_ONLY);
    let mut run = Run::new(scenario.clone()).unwrap();
    run.run_to_end();
    let mut paper = Run::new(presets::scenario("chobie-crawl5").unwrap()).unwrap();
    paper.run_to_end();
    assert_ne!(run.outcome().hash, paper.outcome().hash);
    assert_eq!(run.outcome().metrics["transformations"], json!(2));
    // The link holds the script, and opens to the same run.
    let opened = link::open(&link::encode(&scenario)).unwrap().scenario;
    assert_eq!(opened, scenario);
    let mut again = Run::new(opened).unwrap();
    again.run_to_end();
    assert_eq!(again.outcome(), run.outcome());
}

#[test]
fn rules_read_write_and_refuse_by_name() {
    let paper = models::entry("chobie").unwrap().slots[0].paper;
    let s = scripted_scenario("chobie-crawl3", "leader", paper);
    let doc = s.to_value();
    assert_eq!(doc["rules"], json!({"leader": paper}));
    assert_eq!(Scenario::from_value(doc.clone()).unwrap(), s);
    // Null is the paper's rule: no key, the same scenario as the preset, byte for byte.
    let plain = s.with_override("rules.leader", Value::Null).unwrap();
    assert_eq!(
        plain.to_json(),
        presets::scenario("chobie-crawl3").unwrap().to_json()
    );
    assert!(plain.to_value().get("rules").is_none());
    let refused = |path: &str, value: Value| {
        presets::scenario("chobie-crawl3")
            .unwrap()
            .with_override(path, value)
            .unwrap_err()
            .to_string()
    };
    assert_eq!(
        refused("rules.lead", json!("fn lead(x) { () }")),
        "rules.lead: chobie has no rule slot 'lead'; its slots: leader"
    );
    assert_eq!(
        refused("rules", json!(["x"])),
        "rules: expected an object of slot names and scripts, like {\"leader\": \"fn leader(robot) { ... }\"}"
    );
    assert_eq!(
        refused("rules.leader", json!(3)),
        "rules.leader: expected the slot's script as text, or null for the paper's rule"
    );
    let mega = format!("fn leader(r) {{ () }}\n//{}", "x".repeat(1 << 20));
    assert_eq!(
        refused("rules.leader", mega.clone().into()),
        format!(
            "rules.leader: {} bytes is too long; a rule's script holds at most 16384",
            mega.len()
        )
    );
    assert_eq!(
        refused(
            "rules.leader",
            json!("fn leader(robot) {\n  robot.first.up +\n}")
        ),
        "rules.leader: line 3, column 1: Unexpected '}'"
    );
    let amas = presets::scenario("amas-L")
        .unwrap()
        .with_override("rules.select", json!("fn select(x) { x }"))
        .unwrap_err()
        .to_string();
    assert_eq!(
        amas,
        "rules.select: amas has no rule slot 'select'; it has none yet"
    );
}

#[test]
fn a_hostile_script_stops_the_run_with_the_rule_the_line_and_the_cap() {
    let cases = [
        (
            "fn leader(robot) {\n  loop { }\n}",
            "at line 2",
            "(the cap per call)",
        ),
        (
            "fn deeper(n) { deeper(n + 1) }\nfn leader(robot) { deeper(0) }",
            "at line 1",
            "(the cap on call depth)",
        ),
        (
            "fn leader(robot) {\n  let a = [1];\n  loop { a += a; }\n}",
            "at line 3",
            "(the cap on array size)",
        ),
        (
            "fn leader(robot) {\n  let s = \"robot\";\n  loop { s += s; }\n}",
            "at line 3",
            "(the cap on string size)",
        ),
    ];
    for (source, line, cap) in cases {
        let mut run = Run::new(scripted_scenario("chobie-crawl5", "leader", source)).unwrap();
        run.run_to_end();
        let stopped = run.stopped().expect("stopped").to_string();
        assert!(
            stopped.starts_with(&format!("rule 'leader' stopped {line}")),
            "{stopped}"
        );
        assert!(stopped.ends_with(cap), "{stopped}");
        // The first step stopped it; the run takes no more.
        assert_eq!(run.steps(), 1);
        assert!(!run.step());
        assert_eq!(run.outcome().stopped.as_deref(), Some(stopped.as_str()));
    }
}

#[test]
fn an_experiment_sweeps_rules_and_a_comparison_sets_one_to_the_papers() {
    let paper = models::entry("chobie").unwrap().slots[0].paper;
    let nobody = "fn leader(robot) { () }";
    let experiment = Experiment::from_value(json!({
        "version": 1, "name": "leaders",
        "scenarios": ["chobie-crawl5"],
        "grid": { "rules.leader": [null, paper, nobody] },
    }))
    .unwrap();
    let rows: Vec<_> = experiment
        .jobs()
        .iter()
        .map(|j| experiment.run_job(j).unwrap())
        .collect();
    assert_eq!(rows.len(), 3);
    assert_eq!(
        rows[0].hash, rows[1].hash,
        "the paper's script is the built-in"
    );
    assert_ne!(rows[0].hash, rows[2].hash);
    assert_eq!(rows[2].metrics["transformations"], json!(0));
    assert_eq!(rows[2].params["rules.leader"], json!(nobody));
    // "The paper's rule against mine": the second run sets the slot back to null.
    let mine = scripted_scenario("chobie-crawl5", "leader", nobody)
        .with_override(
            "compare",
            json!({"path": "rules.leader", "value": null, "label": "the paper's rule", "base_label": "mine"}),
        )
        .unwrap();
    let second = mine.compared().unwrap().unwrap();
    assert_eq!(
        second.to_json(),
        presets::scenario("chobie-crawl5").unwrap().to_json()
    );
}
