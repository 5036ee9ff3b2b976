//! `kumiki rules`, `kumiki run --rule` and a link with rules: the paper's script prints the
//! built-in's hash, a hostile one stops with its message, and `kumiki check` fails a hand-in
//! whose rule a cap stopped.

use std::process::Command;

use kumiki_core::models;
use kumiki_core::{link, presets};
use serde_json::{json, Value};

fn kumiki(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_kumiki"))
        .args(args)
        .output()
        .expect("the kumiki binary runs")
}

fn stdout(out: &std::process::Output) -> String {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout.clone()).unwrap()
}

fn row(out: &std::process::Output) -> Value {
    serde_json::from_str(stdout(out).trim()).unwrap()
}

/// A file holding `text`, removed when dropped.
struct Temp(std::path::PathBuf);

impl Temp {
    fn new(name: &str, text: &str) -> Temp {
        let path = std::env::temp_dir().join(format!("kumiki-rules-{}-{name}", std::process::id()));
        std::fs::write(&path, text).unwrap();
        Temp(path)
    }

    fn arg(&self, slot: &str) -> String {
        format!("{slot}={}", self.0.display())
    }
}

impl Drop for Temp {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

#[test]
fn rules_lists_the_slots_and_prints_the_papers_script() {
    let list = stdout(&kumiki(&["rules"]));
    assert!(
        list.starts_with("amas direction\tAMAS: the direction a module shows its robot (footnote 3)\namas collision\tAMAS: what a robot does after a collision"),
        "{list}"
    );
    assert!(
        list.contains("\nchobie leader\tCHOBIE II: who leads"),
        "{list}"
    );
    assert_eq!(list.lines().count(), 6, "{list}");
    let paper = models::entry("chobie").unwrap().slots[0].paper;
    assert_eq!(stdout(&kumiki(&["rules", "chobie", "leader"])), paper);
    let out = kumiki(&["rules", "chobie", "lead"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("its slots: leader"));
}

#[test]
fn run_with_the_papers_script_prints_the_built_in_hash_and_a_link_carries_a_rule() {
    let paper = Temp::new(
        "paper.rhai",
        models::entry("chobie").unwrap().slots[0].paper,
    );
    let builtin = row(&kumiki(&["run", "chobie-crawl5"]));
    let scripted = row(&kumiki(&[
        "run",
        "chobie-crawl5",
        "--rule",
        &paper.arg("leader"),
    ]));
    assert_eq!(scripted["hash"], builtin["hash"]);
    assert_eq!(scripted.get("stopped"), None);
    // A link with a rule of one's own runs it: the robots on the lower tier never lead.
    let mine = "fn leader(robot) { if robot.first.up && robot.second.right { \"top_right\" } else { () } }";
    let scenario = presets::scenario("chobie-crawl5")
        .unwrap()
        .with_override("rules.leader", mine.into())
        .unwrap();
    let mut run = kumiki_core::Run::new(scenario.clone()).unwrap();
    run.run_to_end();
    let linked = row(&kumiki(&["run", &link::encode(&scenario)]));
    assert_eq!(linked["hash"], json!(run.outcome().hash));
    assert_ne!(linked["hash"], builtin["hash"]);
}

#[test]
fn a_hostile_rule_stops_the_run_with_its_message_and_fails_a_hand_in() {
    let endless = Temp::new("loop.rhai", "fn leader(robot) {\n  loop { }\n}");
    let out = kumiki(&["run", "chobie-crawl5", "--rule", &endless.arg("leader")]);
    let stopped = row(&out)["stopped"].as_str().unwrap().to_string();
    assert_eq!(
        stopped,
        "rule 'leader' stopped at line 2, column 3: more than 100000 operations in one call (the cap per call)"
    );
    assert!(String::from_utf8_lossy(&out.stderr).contains(&stopped));
    // A hand-in whose rule loops is graded, not met, the stop its reason.
    let mut doc = presets::scenario("chobie-crawl5").unwrap().to_value();
    doc["exercise"] =
        json!({"title": "Crawl", "instructions": "Write rule 3.", "goal": "steps <= 300"});
    doc["rules"] = json!({"leader": "fn leader(robot) {\n  loop { }\n}"});
    let handin = kumiki_core::Scenario::from_value(doc).unwrap();
    let graded = row(&kumiki(&["check", &link::encode(&handin)]));
    assert_eq!(graded["met"], json!(false));
    assert_eq!(
        graded["because"],
        json!(format!("a rule's script stopped the run: {stopped}"))
    );
    // A script that does not parse is refused by name and line.
    let broken = Temp::new("broken.rhai", "fn leader(robot) {\n  robot.first.up +\n}");
    let out = kumiki(&["run", "chobie-crawl5", "--rule", &broken.arg("leader")]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        String::from_utf8_lossy(&out.stderr).trim(),
        "kumiki: rules.leader: line 3, column 1: Unexpected '}'"
    );
}
