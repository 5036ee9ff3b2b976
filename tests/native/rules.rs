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

/// The equivalence runs are held to their first steps, as the golden hashes are: a script
/// asked of hundreds of units a step is slow in a debug build. Every CHOBIE II preset ends
/// sooner.
const MAX_STEPS: u64 = 300;

/// Settings a slot's paper script is also held to, beside its model's presets as they are: the
/// two selection rules of cubes3d that no preset uses (every one uses the MRF), with "no motion"
/// among random selection's options and without it (model version 4 and before), on one target
/// and two, with the light's priority on positions and on units; and AMAS's L with every loser
/// giving way (its links made before model version 3), and the L and figure 24's continuous
/// field with each robot drawing among equally good neighbours (footnote 3's other reading).
const VARIANTS: [(&str, &str); 10] = [
    ("cubes-cube8-zigzag", r#"{"selection": "random"}"#),
    (
        "cubes-cube8-zigzag",
        r#"{"selection": "random", "random_stays": false}"#,
    ),
    ("cubes-cube8-zigzag", r#"{"selection": "steepest"}"#),
    ("cubes-box12-ladder", r#"{"selection": "steepest"}"#),
    ("cubes-box16-movers", r#"{"selection": "random"}"#),
    ("cubes-light", r#"{"selection": "steepest"}"#),
    (
        "cubes-light",
        r#"{"selection": "random", "priority": "units"}"#,
    ),
    ("amas-L", r#"{"give_way": "every_loser"}"#),
    ("amas-L", r#"{"direction": "robot"}"#),
    ("amas-fig24", r#"{"direction": "robot"}"#),
];

/// Every (preset, settings) of `entry`'s model whose run asks `slot`: its presets, then its
/// variants, each held to [`MAX_STEPS`].
fn cases(model: &str, slot: &str) -> Vec<(&'static str, Value)> {
    let held = |preset: &str, mut set: Value| {
        let max = presets::scenario(preset).unwrap().max_steps;
        set["max_steps"] = json!(max.min(MAX_STEPS));
        set
    };
    let plain = presets::names().map(|p| (p, held(p, json!({}))));
    let varied = VARIANTS
        .iter()
        .map(|&(p, set)| (p, held(p, serde_json::from_str(set).unwrap())));
    plain
        .chain(varied)
        .filter(|(p, _)| presets::scenario(p).unwrap().model() == model)
        .filter(|(p, set)| asks(p, set, slot))
        .collect()
}

/// The scenario `preset` with the settings `set`.
fn with_settings(preset: &str, set: &Value) -> Scenario {
    let overrides: Vec<(String, Value)> = set
        .as_object()
        .unwrap()
        .iter()
        .map(|(k, v)| (k.clone(), v.clone()))
        .collect();
    presets::scenario(preset)
        .unwrap()
        .with_overrides(&overrides)
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

/// Whether `preset` with the settings `set` asks slot `slot` in its run: a script that throws
/// stops it if so.
fn asks(preset: &str, set: &Value, slot: &str) -> bool {
    let source = format!("fn {slot}(x) {{ throw \"asked\" }}");
    let scenario = with_settings(preset, set)
        .with_override(&format!("rules.{slot}"), source.into())
        .unwrap();
    let mut run = Run::new(scenario).unwrap();
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
            for (preset, set) in cases(entry.name, slot.name) {
                let scenario = with_settings(preset, &set)
                    .with_override(&format!("rules.{}", slot.name), slot.paper.into())
                    .unwrap();
                let mut run = Run::new(scenario).unwrap();
                run.run_to_end();
                scripted.push(json!({"preset": preset, "set": set, "slot": slot.name, "steps": run.steps(), "hash": run.outcome().hash}));
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
            let cases = cases(entry.name, slot.name);
            assert!(
                !cases.is_empty(),
                "{}.{}: no preset asks it",
                entry.name,
                slot.name
            );
            for (preset, set) in cases {
                let builtin = with_settings(preset, &set);
                let script = builtin
                    .with_override(&format!("rules.{}", slot.name), slot.paper.into())
                    .unwrap();
                let steps = same_hashes_step_by_step(
                    Run::new(builtin).unwrap(),
                    Run::new(script).unwrap(),
                    &format!("{preset} {set} with the paper's {} script", slot.name),
                );
                checked.push(format!("{preset}:{}:{steps}", slot.name));
            }
        }
    }
    // CHOBIE II's election asks `leader` in every preset but the one whose robots only adapt
    // (figure 14: construction off, so the three rules never elect).
    let of = |prefix: &str| -> Vec<String> {
        let mut names: Vec<String> = checked
            .iter()
            .filter_map(|c| c.strip_prefix(prefix))
            .map(|c| c.split(':').next().unwrap().to_string())
            .collect();
        names.sort();
        names.dedup();
        names
    };
    let chobie = of("chobie-");
    assert_eq!(
        chobie,
        [
            "bridge", "crawl3", "crawl5", "crawl7", "crawl9", "fig13", "form-a", "form-b",
            "form-c", "form-d"
        ],
        "{checked:?}"
    );
    assert!(!asks("chobie-load5", &json!({}), "leader"));
    // Every cubes3d and fracta preset asks its model's slots, and the cubes3d variants too.
    let count = |model: &str| {
        presets::names()
            .filter(|p| presets::scenario(p).unwrap().model() == model)
            .count()
    };
    assert_eq!(of("cubes-").len(), count("cubes3d"), "{checked:?}");
    let select = checked.iter().filter(|c| c.contains(":select:")).count();
    let variants = |prefix: &str| {
        VARIANTS
            .iter()
            .filter(|(p, _)| p.starts_with(prefix))
            .count()
    };
    assert_eq!(select, count("cubes3d") + variants("cubes-"), "{checked:?}");
    // AMAS asks `direction` in every preset (every robot reads its module at every plan), and
    // `collision` wherever robots collide in their first steps: not in the square, whose 28
    // robots build their columns in lockstep, nor in figures 25 and 26's squares.
    let amas = |slot: &str| -> Vec<String> {
        let mut names: Vec<String> = checked
            .iter()
            .filter(|c| c.starts_with("amas-") && c.contains(&format!(":{slot}:")))
            .map(|c| c["amas-".len()..].split(':').next().unwrap().to_string())
            .collect();
        let all = names.len();
        names.sort();
        names.dedup();
        assert_eq!(all, names.len() + variants("amas-"), "{slot}: {checked:?}");
        names
    };
    assert_eq!(amas("direction").len(), count("amas"), "{checked:?}");
    assert_eq!(
        amas("collision"),
        ["L", "T", "bridge-single", "bridge-staged", "fig24"],
        "{checked:?}"
    );
    for slot in ["activation", "roll"] {
        let asked = checked
            .iter()
            .filter(|c| c.contains(&format!(":{slot}:")))
            .count();
        assert_eq!(asked, count("fracta"), "{slot}: {checked:?}");
    }
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
        "rules.select: amas has no rule slot 'select'; its slots: direction, collision"
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
fn a_direction_off_the_structure_stops_the_run_naming_the_rule_and_the_way() {
    // A robot steps only onto a neighbouring module: "always north" runs until a robot's
    // module has none to its north.
    let mut run = Run::new(scripted_scenario(
        "amas-L",
        "direction",
        "fn direction(robot) { \"N\" }",
    ))
    .unwrap();
    run.run_to_end();
    assert_eq!(
        run.stopped(),
        Some("rule 'direction' answered N, where no module is: a robot steps only onto a neighbouring module")
    );
    // "wait" is an answer too: robots only pick and place where they stand, and never wander.
    let mut still = Run::new(scripted_scenario(
        "amas-L",
        "direction",
        "fn direction(robot) { \"wait\" }",
    ))
    .unwrap();
    still.advance(50);
    let mut paper = Run::new(presets::scenario("amas-L").unwrap()).unwrap();
    paper.advance(50);
    assert_eq!(still.stopped(), None);
    assert_eq!(still.outcome().metrics["wandering"], json!(0));
    let placed = |run: &Run| run.outcome().metrics["placed"].as_u64().unwrap();
    assert!(
        placed(&still) < placed(&paper),
        "{} against {}",
        placed(&still),
        placed(&paper)
    );
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

/// The paper's script of `model`'s slot `slot`.
fn paper_of(model: &str, slot: &str) -> &'static str {
    let entry = models::entry(model).unwrap();
    entry.slots.iter().find(|s| s.name == slot).unwrap().paper
}

#[test]
fn one_of_the_papers_three_selection_rules_taken_whatever_the_scenario_names() {
    // The paper's script with its own `select` renamed, and one that always descends steepest:
    // on a scenario that names the MRF, the run of the built-in steepest descent.
    let paper = paper_of("cubes3d", "select");
    let steepest = paper.replace("fn select(unit)", "fn named(unit)")
        + "\nfn select(unit) { steepest_descent(unit) }\n";
    let held = |s: Scenario| s.with_override("max_steps", json!(300)).unwrap();
    let mut mine = Run::new(held(scripted_scenario(
        "cubes-cube8-zigzag",
        "select",
        &steepest,
    )))
    .unwrap();
    let builtin = presets::scenario("cubes-cube8-zigzag")
        .unwrap()
        .with_override("selection", json!("steepest"))
        .unwrap();
    let mut theirs = Run::new(held(builtin)).unwrap();
    mine.run_to_end();
    theirs.run_to_end();
    assert_eq!(mine.outcome().hash, theirs.outcome().hash);
    // Steepest descent is stuck in the zigzag; the MRF forms the cube.
    assert_eq!(mine.outcome().metrics["completed"], json!(0));
    let mut mrf = Run::new(presets::scenario("cubes-cube8-zigzag").unwrap()).unwrap();
    mrf.run_to_end();
    assert_eq!(mrf.outcome().metrics["completed"], json!(1));
}

#[test]
fn an_answer_outside_the_slots_choices_stops_the_run_naming_them() {
    let stopped = |preset: &str, slot: &str, source: &str| {
        let mut run = Run::new(scripted_scenario(preset, slot, source)).unwrap();
        run.run_to_end();
        run.stopped().expect("stopped").to_string()
    };
    let select = stopped(
        "cubes-cube8-zigzag",
        "select",
        "fn select(unit) { unit.options.len() }",
    );
    assert!(
        select.starts_with("rule 'select' answered ")
            && select.contains("; it must answer an index of its "),
        "{select}"
    );
    assert_eq!(
        stopped("cubes-cube8-zigzag", "select", "fn select(unit) { -1 }"),
        "rule 'select' answered -1; it must answer the index of the chosen option in options (an integer from 0); choosing the option with stay true is \"no motion\""
    );
    let roll = stopped("fracta-triangle10", "roll", "fn roll(unit) { 2 }");
    assert!(
        roll.starts_with("rule 'roll' answered 2; it must answer () or an index of its "),
        "{roll}"
    );
    assert_eq!(
        stopped("fracta-triangle10", "activation", "fn activation(unit) { 1 }"),
        "rule 'activation' answered 1; it must answer true (the unit is active and plans a roll) or false"
    );
    // Fracta's activation decides without chance: a draw stops the run.
    let draw = stopped(
        "fracta-triangle10",
        "activation",
        "fn activation(unit) { random() < 0.5 }",
    );
    assert!(draw.contains("draws no random numbers"), "{draw}");
}

#[test]
fn an_activation_without_irritation_leaves_the_deadlock_irritation_dissolves() {
    // Equation 3 alone: in the text's deadlock (figure 4) no unit moves, where the paper's rule
    // with condition 5 moves units out of it (section 3.2.5).
    let eq3 = "fn activation(unit) { unit.threshold * unit.x < to_float(unit.difference) }";
    let held = |s: Scenario| s.with_override("max_steps", json!(500)).unwrap();
    let mut paper = Run::new(held(presets::scenario("fracta-deadlock").unwrap())).unwrap();
    let mut mine = Run::new(held(scripted_scenario(
        "fracta-deadlock",
        "activation",
        eq3,
    )))
    .unwrap();
    paper.run_to_end();
    mine.run_to_end();
    assert_eq!(mine.outcome().metrics["moves"], json!(0));
    assert!(paper.outcome().metrics["moves"].as_u64().unwrap() > 0);
}
