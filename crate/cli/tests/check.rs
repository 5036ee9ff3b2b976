//! `kumiki check` grades hand-ins from their links: a fair one, one that misses the goal, one that
//! edits a locked field, one that edits the exercise, one with a disturbance the exercise does not
//! allow, one over the exercise's budget, and one that is not a link at all; from a list of links,
//! a form's CSV export and a workbook alike; by the teacher's exercise or the class's.

use std::process::Command;

use kumiki_core::{link, presets, Scenario};
use serde_json::{json, Value};

fn kumiki(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_kumiki"))
        .args(args)
        .output()
        .expect("the kumiki binary runs")
}

/// The JSON rows a successful run printed, one per line.
fn json_rows(out: std::process::Output) -> Vec<Value> {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

fn exercise() -> Scenario {
    let mut doc = presets::scenario("amas-L").unwrap().to_value();
    doc["exercise"] = json!({
        "title": "Build the L",
        "instructions": "Choose the collision rule.",
        "locked": {"robots": 5},
        "goal": "completed and steps <= 100000"
    });
    Scenario::from_value(doc).unwrap()
}

#[test]
fn hand_ins_are_replayed_and_graded_one_row_each() {
    let teacher = exercise();
    let fair = teacher.with_override("collision", json!("relay")).unwrap();
    let short = teacher.with_override("max_steps", json!(20)).unwrap();
    let locked = teacher.with_override("robots", json!(8)).unwrap();
    let mut cheat = fair.clone();
    cheat.exercise.as_mut().unwrap().goal = "true".into();
    let links: Vec<String> = [&fair, &short, &locked, &cheat]
        .iter()
        .map(|s| format!("https://example.org/kumiki/#{}", link::encode(s)))
        .collect();
    let dir = std::env::temp_dir().join(format!("kumiki-check-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let list = dir.join("handins.txt");
    std::fs::write(
        &list,
        format!("# class 3\n{}\n\n{}\nnot-a-link\n", links[2], links[3]),
    )
    .unwrap();
    let original = link::encode(&teacher);

    let out = kumiki(&[
        "check",
        &links[0],
        &links[1],
        "--file",
        list.to_str().unwrap(),
        "--exercise",
        &format!("#{original}"),
        "--jobs",
        "2",
    ]);
    let rows = json_rows(out);
    assert_eq!(rows.len(), 5);
    assert_eq!(
        rows.iter()
            .map(|r| r["handin"].as_u64().unwrap())
            .collect::<Vec<_>>(),
        [1, 2, 3, 4, 5]
    );

    assert_eq!(rows[0]["met"], true, "{}", rows[0]);
    assert_eq!(rows[0]["changed"], json!(["collision"]));
    assert_eq!(rows[1]["met"], false);
    assert_eq!(rows[1]["completed"], false);
    assert_eq!(rows[1]["because"], "the run did not complete");
    assert_eq!(rows[2]["locked_edited"], json!(["robots: 5 → 8"]));
    assert_eq!(rows[2]["met"], false);
    assert_eq!(rows[3]["exercise_edited"], true);
    assert_eq!(rows[3]["met"], false);
    assert!(
        rows[4]["error"].as_str().unwrap().contains("not-a-link"),
        "{}",
        rows[4]
    );

    // The replayed hash is the run's own: the same link through `kumiki run`.
    let run = kumiki(&["run", &links[0]]);
    let row: Value = serde_json::from_str(String::from_utf8(run.stdout).unwrap().trim()).unwrap();
    assert_eq!(rows[0]["hash"], row["hash"]);

    let csv = kumiki(&["check", &links[2], "--format", "csv"]);
    let text = String::from_utf8(csv.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        lines[0],
        "handin,student,name,met,points,max_points,because,completed,steps,over_budget,hash,locked_edited,disturbances,changed,exercise_edited,credit,made,checks,hints,answer,error,link"
    );
    assert!(
        lines[1].starts_with("1,,amas-L,false,,,") && lines[1].contains(",robots: 5 → 8,,,false,"),
        "{}",
        lines[1]
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn check_with_nothing_to_grade_is_a_usage_error() {
    let out = kumiki(&["check"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("hand-in links"));
}

#[test]
fn lessons_are_listed_and_graded_by_name() {
    let out = kumiki(&["lessons"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let listed: Vec<&str> = text
        .lines()
        .map(|l| l.split('\t').next().unwrap())
        .collect();
    assert_eq!(listed, kumiki_core::lessons::names().collect::<Vec<_>>());
    assert!(text.lines().all(|l| l.split('\t').count() == 4), "{text}");

    let lesson = kumiki_core::lessons::scenario("lesson-chobie-forms").unwrap();
    let solved = lesson.with_override("method", json!("cautious")).unwrap();
    let handins = [&lesson, &solved].map(|s| format!("#{}", link::encode(s)));
    let out = kumiki(&[
        "check",
        &handins[0],
        &handins[1],
        "--exercise",
        "lesson-chobie-forms",
    ]);
    let rows = json_rows(out);
    assert_eq!(rows[0]["met"], false);
    assert_eq!(rows[1]["met"], true);
    assert_eq!(rows[1]["changed"], json!(["method"]));
}

#[test]
fn strict_fails_when_a_hand_in_fails_and_text_gives_one_line_a_student() {
    let teacher = exercise();
    let mut doc = teacher.to_value();
    doc["exercise"]["locked"]["target"] = doc["target"].clone();
    let locked_teacher = Scenario::from_value(doc).unwrap();
    let mut named = locked_teacher
        .with_override("collision", json!("relay"))
        .unwrap();
    named.name = "Ada".into();
    // Linus erased two cells and changed the lock to match.
    let mut doc = named.to_value();
    let shape = doc["target"].as_str().unwrap().to_string();
    let mut rows: Vec<String> = shape.lines().map(str::to_string).collect();
    let column = rows[1].find('#').unwrap();
    rows[1].replace_range(column..column + 1, ".");
    doc["target"] = json!(format!("{}\n", rows.join("\n")));
    doc["exercise"]["locked"]["target"] = doc["target"].clone();
    let mut tampered = Scenario::from_value(doc).unwrap();
    tampered.name = "Linus".into();
    let links = [&named, &tampered].map(|s| format!("#{}", link::encode(s)));
    let original = format!("#{}", link::encode(&locked_teacher));

    let out = kumiki(&["check", &links[0], "--exercise", &original, "--strict"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let rows = json_rows(out);
    // The student's name, set by Hand in, is not a change.
    assert_eq!(rows[0]["changed"], json!(["collision"]));
    assert_eq!(rows[0]["met"], true);

    let out = kumiki(&[
        "check",
        &links[0],
        &links[1],
        "--exercise",
        &original,
        "--format",
        "text",
        "--strict",
    ]);
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[0].starts_with("1. Ada: met in "), "{text}");
    assert!(
        lines[1].starts_with(&format!(
            "2. Linus: not met (not replayed: its exercise is not the class's (locked.target differs); it changed locked fields (target: 1 cell removed at ({column}, 1)))"
        )),
        "{text}"
    );
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("2 hand-ins: 1 met, 1 not met, 0 could not be graded"),
        "{err}"
    );
    assert!(err.contains("--strict"), "{err}");
}

#[test]
fn link_says_which_base_it_used() {
    let run = |envs: &[(&str, &str)], args: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_kumiki"))
            .env_remove("KUMIKI_BASE")
            .envs(envs.iter().copied())
            .args(args)
            .output()
            .unwrap();
        assert!(out.status.success());
        (
            String::from_utf8(out.stdout).unwrap(),
            String::from_utf8(out.stderr).unwrap(),
        )
    };
    let (out, err) = run(&[], &["link", "amas-L"]);
    assert!(out.starts_with("http://localhost:8080/#k1."), "{out}");
    assert!(
        err.contains("(the default; set KUMIKI_BASE or --base)"),
        "{err}"
    );
    let (out, err) = run(
        &[("KUMIKI_BASE", "https://example.org/kumiki/")],
        &["link", "amas-L"],
    );
    assert!(out.starts_with("https://example.org/kumiki/#k1."), "{out}");
    assert!(
        err.contains("https://example.org/kumiki/ (KUMIKI_BASE)"),
        "{err}"
    );
    let (out, _) = run(
        &[("KUMIKI_BASE", "https://example.org/kumiki/")],
        &["link", "amas-L", "--base", "https://school.example/k/"],
    );
    assert!(out.starts_with("https://school.example/k/#k1."), "{out}");
}

/// A scenario that compares two runs (its `compare` section) runs both: the first run's row, then
/// the second's, named with its label and equal to the run of its own scenario alone.
#[test]
fn run_prints_both_runs_of_a_comparison() {
    let lesson = kumiki_core::lessons::scenario("lesson-amas-compare").unwrap();
    let rows = json_rows(kumiki(&["run", "lesson-amas-compare"]));
    assert_eq!(rows.len(), 2);
    assert_eq!(rows[0]["scenario"], "lesson-amas-compare");
    assert_eq!(rows[1]["scenario"], "lesson-amas-compare (tokens only)");
    let alone = |s: &Scenario| {
        let mut run = kumiki_core::Run::new(s.clone()).unwrap();
        run.run_to_end();
        (run.steps(), kumiki_core::hash::hex(run.state_hash()))
    };
    let second = lesson.compared().unwrap().unwrap();
    for (row, scenario) in rows.iter().zip([&lesson, &second]) {
        let (steps, hash) = alone(scenario);
        assert_eq!(
            (
                row["steps"].as_u64().unwrap(),
                row["hash"].as_str().unwrap()
            ),
            (steps, hash.as_str())
        );
    }
    // The collision rule matters: tokens only collide more than relay.
    assert!(rows[1]["metrics"]["collisions"].as_u64() > rows[0]["metrics"]["collisions"].as_u64());
}

#[path = "../../../tests/support/xlsx.rs"]
mod xlsx;

/// The output of a check that succeeded, as text.
fn stdout(out: std::process::Output) -> String {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// A class of four, as a teacher has it in three forms: links one a line, a form's CSV export
/// with answers over several lines, and the same export as a workbook. Each grades to the same
/// rows, verdicts and points; the over-budget hand-in and the one with a click the exercise does
/// not allow are marked as such.
#[test]
fn a_form_export_a_workbook_and_a_list_of_links_grade_the_same() {
    let mut doc = presets::scenario("amas-L").unwrap().to_value();
    doc["exercise"] = json!({
        "title": "Build the L",
        "locked": {"robots": 5, "seed": 1},
        "goal": "completed and steps <= 600",
        "credit": [{"goal": "completed", "points": 5}, {"goal": "metrics.collisions < 150", "points": 2}],
        "budget": {"steps": 1000}
    });
    let teacher = Scenario::from_value(doc).unwrap();
    let named = |s: &Scenario, name: &str| s.with_override("name", json!(name)).unwrap();
    let fair = named(&teacher, "Ada");
    // Stops before the L is built: no points for completing it, two for its few collisions.
    let slow = named(
        &teacher.with_override("max_steps", json!(100)).unwrap(),
        "Grace",
    );
    let mut clicked = teacher.to_value();
    clicked["disturbances"] = json!([{"at": 25, "kind": "remove", "cells": [144]}]);
    let clicked = named(&Scenario::from_value(clicked).unwrap(), "Linus");
    let mut huge = teacher.to_value();
    huge["max_steps"] = json!(5000);
    huge["target"] = json!("##############\n".repeat(40));
    let huge = named(&Scenario::from_value(huge).unwrap(), "Hopper");
    let class = [&fair, &slow, &clicked, &huge];
    let links: Vec<String> = class
        .iter()
        .map(|s| format!("https://example.org/k/#{}", link::encode(s)))
        .collect();
    let names = ["Ada", "Grace", "Linus", "Hopper"];
    let answers = [
        "Fewer robots,\nfewer collisions.",
        "I tried \"blackboard\"",
        "One click\r\nhelped.",
        "",
    ];

    let dir = std::env::temp_dir().join(format!("kumiki-forms-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let list = dir.join("links.txt");
    std::fs::write(&list, links.join("\n")).unwrap();
    let form = dir.join("form.csv");
    let quoted = |s: &str| format!("\"{}\"", s.replace('"', "\"\""));
    let mut csv = String::from("\u{feff}Timestamp,Name,Hand-in link,Why?\r\n");
    for i in 0..4 {
        csv.push_str(&format!(
            "2026/11/28 10:1{i}:00,{},{},{}\r\n",
            names[i],
            links[i],
            quoted(answers[i])
        ));
    }
    std::fs::write(&form, csv).unwrap();
    let book = dir.join("form.xlsx");
    let mut rows = vec![vec![
        xlsx::Cell::Text("Timestamp"),
        xlsx::Cell::Text("Name"),
        xlsx::Cell::Text("Hand-in link"),
        xlsx::Cell::Text("Why?"),
    ]];
    for i in 0..4 {
        rows.push(vec![
            xlsx::Cell::Number(46_354.4 + i as f64 / 100.0),
            xlsx::Cell::Text(names[i]),
            xlsx::Cell::Text(&links[i]),
            xlsx::Cell::Text(answers[i]),
        ]);
    }
    std::fs::write(&book, xlsx::xlsx(&rows)).unwrap();

    let original = format!("#{}", link::encode(&teacher));
    let graded = |file: &std::path::Path| {
        let out = kumiki(&[
            "check",
            "--file",
            file.to_str().unwrap(),
            "--exercise",
            &original,
            "--format",
            "csv",
        ]);
        stdout(out)
    };
    let from_list = graded(&list);
    let from_form = graded(&form);
    let from_book = graded(&book);
    assert_eq!(from_form, from_book, "the CSV export and the workbook");
    // The list has no names column: the student column is empty, the rest the same.
    let without_student = |text: &str| -> Vec<String> {
        let mut reader = csv_cells(text);
        for row in &mut reader {
            row.remove(1);
        }
        reader.into_iter().map(|r| r.join("|")).collect()
    };
    assert_eq!(without_student(&from_list), without_student(&from_form));
    let table = csv_cells(&from_form);
    let head = &table[0];
    let col = |name: &str| head.iter().position(|h| h == name).unwrap();
    assert_eq!(table.len(), 5, "four hand-ins, one row each: {from_form}");
    let column = |name: &str| {
        table[1..]
            .iter()
            .map(|r| r[col(name)].as_str())
            .collect::<Vec<_>>()
    };
    assert_eq!(column("student"), names);
    assert_eq!(column("met"), ["true", "false", "false", "false"]);
    assert_eq!(column("over_budget"), ["false", "false", "false", "true"]);
    assert_eq!(column("points"), ["7", "2", "0", "0"]);
    assert_eq!(column("max_points"), ["7", "7", "7", "7"]);
    assert_eq!(
        column("disturbances")[2],
        "'remove' added at step 25 (the exercise allows none)"
    );
    assert!(column("because")[3].starts_with(
        "over budget: the exercise replays a hand-in within its step budget of 1000 steps"
    ));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Without the teacher's exercise, the class's is the one most hand-ins carry: a student who
/// re-made the exercise (unlocked the seed, changed it) fails, and the check says which exercise
/// it graded by.
#[test]
fn without_the_teachers_exercise_the_class_exercise_is_the_one_most_carry() {
    let teacher = exercise();
    let mut doc = teacher.to_value();
    doc["exercise"]["locked"] = json!({"robots": 5, "seed": 1});
    let teacher = Scenario::from_value(doc).unwrap();
    let fair = teacher.with_override("collision", json!("relay")).unwrap();
    let mut doc = teacher.to_value();
    doc["exercise"]["locked"]
        .as_object_mut()
        .unwrap()
        .remove("seed");
    doc["seed"] = json!(3);
    let remade = Scenario::from_value(doc).unwrap();
    let links = [&fair, &remade, &teacher].map(|s| format!("#{}", link::encode(s)));
    let out = kumiki(&["check", &links[0], &links[1], &links[2]]);
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert!(
        err.contains("graded by “Build the L”, which 2 of the 3 hand-ins with an exercise carry"),
        "{err}"
    );
    let rows = json_rows(out);
    assert_eq!(rows[0]["met"], true);
    assert_eq!(rows[1]["met"], false);
    assert_eq!(rows[1]["exercise_edited"], true);
    assert!(rows[1]["because"]
        .as_str()
        .unwrap()
        .starts_with("not replayed: its exercise is not the class's (locked.seed differs)"));
}

/// A file of another kind is refused with one message.
#[test]
fn a_file_that_is_no_export_is_refused_with_one_message() {
    let dir = std::env::temp_dir().join(format!("kumiki-binary-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("photo.png");
    std::fs::write(
        &file,
        [0x89, b'P', b'N', b'G', 0x0d, 0x0a, 0x1a, 0x0a, 0, 0, 0, 13],
    )
    .unwrap();
    let out = kumiki(&["check", "--file", file.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains(kumiki_core::handins::NOT_HANDINS), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A CSV's records and cells (RFC 4180), for reading the check's own CSV back.
fn csv_cells(text: &str) -> Vec<Vec<String>> {
    let mut out = vec![Vec::new()];
    let mut cell = String::new();
    let mut quoted = false;
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match (quoted, c) {
            (true, '"') if chars.peek() == Some(&'"') => {
                cell.push('"');
                chars.next();
            }
            (true, '"') => quoted = false,
            (true, c) => cell.push(c),
            (false, '"') => quoted = true,
            (false, ',') => out.last_mut().unwrap().push(std::mem::take(&mut cell)),
            (false, '\n') => {
                out.last_mut().unwrap().push(std::mem::take(&mut cell));
                out.push(Vec::new());
            }
            (false, c) => cell.push(c),
        }
    }
    out.pop();
    out
}
