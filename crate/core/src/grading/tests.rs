use super::*;
use crate::playback::Playback;
use crate::{lessons, presets, Run, Scenario};
use serde_json::json;

/// The L as the issue's page ran it (AMAS before model version 3): standing on its foot, each
/// robot drawing among equal neighbours and every collision loser giving way. The issue's figures
/// ("Goal met at step 190") are of that run; the tests keep them rather than follow the model.
fn amas_l() -> Value {
    let mut doc = presets::scenario("amas-L").unwrap().to_value();
    doc["target"] = json!("####..........\n".repeat(8) + "##############\n".repeat(4).as_str());
    as_in_the_issue(doc)
}

/// `doc` with AMAS's readings before model version 3.
fn as_in_the_issue(mut doc: Value) -> Value {
    doc["direction"] = json!("robot");
    doc["give_way"] = json!("every_loser");
    doc
}

/// A scenario of preset `preset` (the L as the issue ran it for `amas-L`) with the exercise
/// `exercise`, read as a link would be.
fn with_exercise(preset: &str, exercise: Value) -> Scenario {
    let mut doc = match preset {
        "amas-L" => amas_l(),
        _ => presets::scenario(preset).unwrap().to_value(),
    };
    doc["exercise"] = exercise;
    Scenario::from_value(doc).unwrap()
}

/// `scenario` with `disturbance` added, as a hand-in made without the page's lock would carry it
/// (a link edited by hand, or made before disturbances could be locked).
fn disturbed(scenario: &Scenario, disturbance: Value) -> Scenario {
    let mut doc = scenario.to_value();
    doc["disturbances"] = json!([disturbance]);
    Scenario::from_value(doc).unwrap()
}

fn no_clock() -> f64 {
    unreachable!("no time budget: the clock is not read")
}

/// Whether the goal alone (without the exercise's rules) is met by the run of `scenario`.
fn goal_alone(scenario: &Scenario) -> (bool, u64) {
    let mut run = Run::new(scenario.clone()).unwrap();
    run.run_to_end();
    let o = run.outcome();
    let doc = scenario.to_value();
    let check = scenario.exercise.as_ref().unwrap().goal().check(&Outcome {
        completed: o.completed,
        steps: o.steps,
        metrics: &o.metrics,
        scenario: &doc,
    });
    (check.met, o.steps)
}

/// A click at step `at` in the page's Playback of `scenario`.
fn click(scenario: &Scenario, at: u64, action: Value) -> crate::error::Result<Scenario> {
    let mut p = Playback::new(Run::new(scenario.clone()).unwrap());
    p.advance(at, &mut || 0.0);
    let Value::Object(action) = action else {
        unreachable!()
    };
    p.apply(action)?;
    Ok(p.run().scenario().clone())
}

/// The issue's first case: with the shape, the seed and the collision rule locked, one "Remove
/// module" click at step 25 met `completed and steps <= 200 and metrics.collisions < 20` ("Goal
/// met at step 190"), in the page and with `kumiki check --exercise`.
#[test]
fn a_remove_click_that_would_meet_the_goal_is_refused_and_fails_the_hand_in() {
    let teacher = with_exercise(
        "amas-L",
        json!({
            "title": "Faster with fewer collisions",
            "locked": {"target": amas_l()["target"], "seed": 1, "collision": "token"},
            "goal": "completed and steps <= 200 and metrics.collisions < 20"
        }),
    );
    let remove = json!({"kind": "remove", "cells": [144]});
    // The page refuses the click where it is made, with the reason.
    let refused = click(&teacher, 25, remove.clone()).unwrap_err().to_string();
    assert_eq!(
        refused,
        "Remove module (5.4) is locked by the exercise: it allows no 'remove' disturbance"
    );
    // A hand-in carrying it anyway: the click alone would meet the goal...
    let mut at = remove.clone();
    at["at"] = json!(25);
    let handin = disturbed(&teacher, at);
    assert_eq!(goal_alone(&handin), (true, 190), "the click meets the goal");
    // ...but the page's verdict, the grade and kumiki check (this same grade) fail it by name.
    let mut run = Run::new(handin.clone()).unwrap();
    run.run_to_end();
    let v = verdict(&run).unwrap();
    assert!(!v.met);
    assert!(v
        .because
        .contains("'remove' added at step 25 (the exercise allows none)"));
    let g = grade(handin, &Teacher::given(&teacher).unwrap(), &mut no_clock).unwrap();
    assert!(!g.met);
    assert_eq!(
        g.disturbances,
        vec!["'remove' added at step 25 (the exercise allows none)"]
    );
    assert_eq!(
        g.because,
        "not replayed: it has disturbances the exercise does not allow ('remove' added at step 25 (the exercise allows none))"
    );
}

/// A teacher may allow some: "remove at most 1 module".
#[test]
fn an_allowed_click_is_taken_and_graded_and_one_more_is_refused() {
    let teacher = with_exercise(
        "amas-L",
        json!({"title": "t", "goal": "completed and steps <= 200", "disturbances": {"remove": 1}}),
    );
    let once = click(&teacher, 25, json!({"kind": "remove", "cells": [144]})).unwrap();
    assert_eq!(once.disturbances.len(), 1);
    let g = grade(
        once.clone(),
        &Teacher::given(&teacher).unwrap(),
        &mut no_clock,
    )
    .unwrap();
    assert!(g.met && g.steps == 190, "{}", g.because);
    let twice = click(&once, 30, json!({"kind": "remove", "cells": [115]}))
        .unwrap_err()
        .to_string();
    assert_eq!(
        twice,
        "Remove module (5.4) is locked by the exercise: it allows one 'remove' disturbance, and it is used"
    );
}

/// The issue's second case: one "Mark to be removed" click met lesson-amas-heatmap with its
/// target unchanged.
#[test]
fn a_mark_to_be_removed_click_no_longer_meets_the_heatmap_lesson() {
    let lesson = Scenario::from_value(as_in_the_issue(
        lessons::scenario("lesson-amas-heatmap").unwrap().to_value(),
    ))
    .unwrap();
    let dismantle = json!({"kind": "dismantle", "cells": [115]});
    assert_eq!(
        click(&lesson, 40, dismantle.clone())
            .unwrap_err()
            .to_string(),
        "Mark to be removed (6.2) is locked by the exercise: it allows no 'dismantle' disturbance"
    );
    let mut at = dismantle;
    at["at"] = json!(40);
    let handin = disturbed(&lesson, at);
    assert!(
        goal_alone(&handin).0,
        "the click alone meets the lesson's goal"
    );
    let g = grade(handin, &Teacher::given(&lesson).unwrap(), &mut no_clock).unwrap();
    assert!(!g.met);
    assert_eq!(
        g.disturbances,
        vec!["'dismantle' added at step 40 (the exercise allows none)"]
    );
}

/// The issue's third case: "Add target cell" changed a locked target.
#[test]
fn an_add_target_cell_click_is_refused_where_the_target_is_locked() {
    let target = amas_l()["target"].clone();
    let teacher = with_exercise(
        "amas-L",
        json!({"title": "t", "locked": {"target": target}, "goal": "completed"}),
    );
    let extend = json!({"kind": "extend", "cells": [100]});
    assert_eq!(
        click(&teacher, 25, extend.clone()).unwrap_err().to_string(),
        "Add target cell is locked by the exercise: it allows no 'extend' disturbance"
    );
    let mut at = extend;
    at["at"] = json!(25);
    let g = grade(
        disturbed(&teacher, at),
        &Teacher::given(&teacher).unwrap(),
        &mut no_clock,
    )
    .unwrap();
    assert!(!g.met);
    assert_eq!(
        g.disturbances,
        vec!["'extend' added at step 25 (the exercise allows none)"]
    );
}

/// An exercise made before disturbances could be locked keeps the disturbances of the scenario
/// it is read with: fracta-repair's scheduled fault is the teacher's, not the student's.
#[test]
fn an_old_exercise_keeps_its_scenarios_disturbances_and_its_link_opens() {
    let teacher = with_exercise("fracta-repair", json!({"title": "t", "goal": "completed"}));
    let e = teacher.exercise.as_ref().unwrap();
    assert_eq!(e.kept().len(), teacher.disturbances.len());
    assert!(!e.kept().is_empty());
    let link = crate::link::encode(&teacher);
    let back = crate::link::decode(&link).unwrap();
    assert_eq!(back.exercise, teacher.exercise);
    let g = grade(back, &Teacher::given(&teacher).unwrap(), &mut no_clock).unwrap();
    assert!(g.disturbances.is_empty() && g.met, "{}", g.because);
    // Leaving the teacher's fault out is a change the exercise does not allow.
    let mut doc = teacher.to_value();
    doc.as_object_mut().unwrap().remove("disturbances");
    let g = grade(
        Scenario::from_value(doc).unwrap(),
        &Teacher::given(&teacher).unwrap(),
        &mut no_clock,
    )
    .unwrap();
    assert!(!g.met);
    assert!(g.disturbances[0]
        .starts_with("the exercise's own disturbances were left out or changed (fault at step"));
}

#[test]
fn grading_replays_the_hand_in_and_reports_what_changed() {
    let teacher = with_exercise(
        "amas-L",
        json!({"title": "Build it", "locked": {"robots": 5}, "goal": "completed and steps <= 100000"}),
    );
    let class = Teacher::given(&teacher).unwrap();
    let fair = teacher.with_override("collision", json!("relay")).unwrap();
    let g = grade(fair.clone(), &class, &mut no_clock).unwrap();
    assert!(g.met, "{}", g.because);
    assert!(g.completed && g.steps > 0 && g.hash.len() == 16);
    assert_eq!(g.changed, vec!["collision"]);
    assert!(g.locked_edited.is_empty() && !g.exercise_edited && !g.over_budget);
    let mut run = Run::new(fair.clone()).unwrap();
    run.run_to_end();
    assert_eq!(
        g.hash,
        run.outcome().hash,
        "the same run as replaying the link"
    );

    let tampered = teacher.with_override("robots", json!(9)).unwrap();
    let g = grade(tampered, &class, &mut no_clock).unwrap();
    assert_eq!(g.locked_edited, vec!["robots: 5 → 9"]);
    assert!(!g.met && g.hash.is_empty());
    assert_eq!(
        g.because,
        "not replayed: it changed locked fields (robots: 5 → 9)"
    );
}

/// "Make an exercise…" on the student's page replaced the locks: untick the seed, change it,
/// "Goal met", hand in. Graded without the teacher's exercise, the class's is the one most
/// hand-ins carry, and the re-authored one fails, saying so.
#[test]
fn the_class_exercise_is_taken_from_the_hand_ins_and_a_re_authored_one_fails() {
    let teacher = with_exercise(
        "amas-L",
        json!({"title": "t", "locked": {"seed": 1}, "goal": "completed"}),
    );
    let fair = teacher.with_override("robots", json!(4)).unwrap();
    let mut doc = teacher.to_value();
    doc["exercise"]["locked"]
        .as_object_mut()
        .unwrap()
        .remove("seed");
    doc["seed"] = json!(7);
    let cheat = Scenario::from_value(doc).unwrap();
    let docs = [&fair, &teacher, &cheat].map(|s| s.to_value());
    let class = Teacher::from_handins(docs).unwrap();
    assert_eq!(class.source(), &Source::Handins { carried: 2, of: 3 });
    assert_eq!(
        class.describe(),
        "“t”, which 2 of the 3 hand-ins with an exercise carry (none was given)"
    );
    // One fair hand-in and one re-authored: neither exercise is the class's, the teacher's is asked for.
    let tie = Teacher::from_handins([&cheat, &fair].map(|s| s.to_value()));
    assert_eq!(
        tie.unwrap_err().to_string(),
        "exercise: the hand-ins carry 2 different exercises equally often (1 each), so none is the class's: give the teacher's exercise (its link or a lesson's name)"
    );
    let g = grade(cheat, &class, &mut no_clock).unwrap();
    assert!(!g.met && g.exercise_edited);
    assert_eq!(
        g.because,
        "not replayed: its exercise is not the class's (locked.seed differs); it changed locked fields (seed: 1 → 7)"
    );
    assert!(grade(fair, &class, &mut no_clock).unwrap().met);
    let none = Teacher::from_handins([amas_l()]);
    assert!(none
        .unwrap_err()
        .to_string()
        .contains("none of the hand-ins carries an exercise"));
    // A teacher travels to a grading worker as JSON and grades the same.
    let back = Teacher::from_json(&class.to_json()).unwrap();
    assert_eq!(back, class);
}

#[test]
fn a_hand_in_over_its_budget_is_stopped_and_marked() {
    let by_steps = with_exercise(
        "amas-L",
        json!({"title": "t", "goal": "completed", "budget": {"steps": 100},
               "credit": [{"goal": "completed", "points": 5}]}),
    );
    let g = grade(
        by_steps.clone(),
        &Teacher::given(&by_steps).unwrap(),
        &mut no_clock,
    )
    .unwrap();
    assert!(g.over_budget && !g.met && g.steps == 100);
    assert_eq!((g.points, g.max_points), (Some(0), Some(5)));
    assert_eq!(
        g.because,
        "over budget: the exercise replays a hand-in within its step budget of 100 steps, and this run had not ended at step 100"
    );
    // A clock that moves a second each time it is read: a budget of 2.5 s stops it early.
    let by_time = with_exercise(
        "amas-L",
        json!({"title": "t", "goal": "completed", "budget": {"seconds": 2.5}}),
    );
    let mut now = 0.0;
    let mut clock = || {
        now += 1.0;
        now
    };
    let g = grade(
        by_time.clone(),
        &Teacher::given(&by_time).unwrap(),
        &mut clock,
    )
    .unwrap();
    assert!(g.over_budget && g.steps > 0 && g.steps < 209, "{g:?}");
    assert!(g.because.contains("its time budget of 2.5 s"));
    // Within the budget, the run is judged as usual.
    let enough = with_exercise(
        "amas-L",
        json!({"title": "t", "goal": "completed", "budget": {"steps": 209}}),
    );
    let g = grade(
        enough.clone(),
        &Teacher::given(&enough).unwrap(),
        &mut no_clock,
    )
    .unwrap();
    assert!(g.met && !g.over_budget && g.steps == 209);
}

#[test]
fn the_grade_gives_points_for_each_part_and_carries_the_hand_ins_record() {
    let teacher = with_exercise(
        "amas-L",
        json!({"title": "t", "goal": "completed and steps <= 200",
               "credit": [
                   {"goal": "completed", "points": 5},
                   {"goal": "steps < 300", "points": 3},
                   {"goal": "metrics.collisions < 5", "points": 2}
               ],
               "question": "Why?"}),
    );
    let mut doc = teacher.to_value();
    doc["name"] = json!("Ada");
    doc["handin"] =
        json!({"made": "2026-11-28T10:15:00Z", "checks": 4, "hints": 2, "answer": "Because."});
    let g = grade(
        Scenario::from_value(doc).unwrap(),
        &Teacher::given(&teacher).unwrap(),
        &mut no_clock,
    )
    .unwrap();
    assert!(!g.met, "209 steps");
    assert_eq!((g.points, g.max_points), (Some(8), Some(10)));
    assert_eq!(
        g.summary(),
        format!("Ada: not met ({}), 8 of 10 points", g.because)
    );
    assert_eq!(g.record.as_ref().unwrap().answer, "Because.");
    assert_eq!(
        g.goal_metrics.keys().collect::<Vec<_>>(),
        vec!["collisions"]
    );
}

#[test]
fn an_edit_may_not_change_a_locked_field_the_exercise_or_the_disturbances() {
    let current = json!({"seed": 1, "robots": 5, "target": "##\n",
        "exercise": {"title": "t", "goal": "completed", "locked": {"seed": 1, "target": "##\n", "disturbances": []}}});
    let mut next = current.clone();
    next["robots"] = json!(6);
    assert_eq!(locked_problem(&current, &next), None);
    next["seed"] = json!(9);
    next["target"] = json!("#.\n");
    assert_eq!(
        locked_problem(&current, &next).unwrap(),
        "locked by the exercise, which keeps the teacher's value (seed: 1 → 9, target: 1 cell removed at (1, 0))"
    );
    let mut clicked = current.clone();
    clicked["disturbances"] = json!([{"at": 3, "kind": "remove", "cells": [0]}]);
    assert_eq!(
        locked_problem(&current, &clicked).unwrap(),
        "locked by the exercise, which keeps the teacher's value ('remove' added at step 3 (the exercise allows none))"
    );
    // An edit of a scenario that already carries one (a link edited by hand) is not held back by
    // it.
    let mut later = clicked.clone();
    later["robots"] = json!(4);
    assert_eq!(locked_problem(&clicked, &later), None);
    let float = json!({"tip_load": 200.0, "exercise": {"title": "t", "goal": "completed", "locked": {"tip_load": 200}}});
    assert_eq!(locked_problem(&float, &float), None);
    let mut unlocked = current.clone();
    unlocked["exercise"]["locked"] = json!({});
    assert!(locked_problem(&current, &unlocked)
        .unwrap()
        .starts_with("the exercise itself cannot be changed"));
    assert_eq!(
        locked_problem(&json!({"seed": 1}), &json!({"seed": 2})),
        None
    );
}

#[test]
fn the_grade_table_is_one_csv_for_the_cli_and_the_page() {
    let teacher = with_exercise(
        "amas-L",
        json!({"title": "t", "goal": "completed", "credit": [{"goal": "metrics.collisions < 20", "points": 2}]}),
    );
    let class = Teacher::given(&teacher).unwrap();
    let mut doc = teacher.to_value();
    doc["name"] = json!("=HYPERLINK(\"x\")");
    doc["handin"] = json!({"made": "2026-11-28T10:15:00Z", "checks": 3, "answer": "Two, lines"});
    let g = grade(Scenario::from_value(doc).unwrap(), &class, &mut no_clock).unwrap();
    let rows = [
        table::Row {
            handin: 1,
            student: "Ada, L.".into(),
            link: Some("#k1.x".into()),
            graded: Graded::from(g),
        },
        table::Row {
            handin: 2,
            student: String::new(),
            link: None,
            graded: Graded::Failed {
                error: "holds no Kumiki link (line 3 of the file): Grace".into(),
            },
        },
    ];
    // The row's number and the hand-in's record are two keys of the row's JSON.
    let json = serde_json::to_value(&rows[0]).unwrap();
    assert_eq!(json["handin"], 1);
    assert_eq!(json["record"]["checks"], 3);
    let back: table::Row = serde_json::from_value(json).unwrap();
    assert_eq!(
        back.graded.grade().unwrap().record,
        rows[0].graded.grade().unwrap().record
    );
    let csv = table::csv(&rows, &class);
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(
        lines[0],
        "handin,student,name,met,points,max_points,because,completed,steps,over_budget,hash,locked_edited,disturbances,changed,exercise_edited,credit,made,checks,hints,answer,metrics.collisions,error,link"
    );
    assert!(
        lines[1].starts_with("1,\"Ada, L.\",\"'=HYPERLINK(\"\"x\"\")\",true,2,2,"),
        "{}",
        lines[1]
    );
    assert!(
        lines[1].ends_with(",2026-11-28T10:15:00Z,3,0,\"Two, lines\",9,,#k1.x"),
        "{}",
        lines[1]
    );
    assert_eq!(
        lines[2],
        "2,,,false,,,,,,,,,,,,,,,,,,holds no Kumiki link (line 3 of the file): Grace,"
    );
    assert!(lines[1].split(',').count() >= 23);
}

/// Hand-ins of an exercise made before disturbances could be locked carry no list of the
/// teacher's: graded from the links, it is the one most of them have, so the click of the first
/// hand-in is not taken for the teacher's.
#[test]
fn old_hand_ins_graded_from_their_links_take_the_teachers_disturbances_from_most_of_them() {
    let old = |disturbances: Value| {
        let mut doc = amas_l();
        doc["exercise"] =
            json!({"title": "t", "locked": {"seed": 1}, "goal": "completed and steps <= 200"});
        if !disturbances.is_null() {
            doc["disturbances"] = disturbances;
        }
        doc
    };
    let clicked = old(json!([{"at": 25, "kind": "remove", "cells": [144]}]));
    let docs = [clicked.clone(), old(Value::Null), old(Value::Null)];
    let class = Teacher::from_handins(docs).unwrap();
    assert!(class.exercise().kept().is_empty());
    let g = grade(
        Scenario::from_value(clicked).unwrap(),
        &class,
        &mut no_clock,
    )
    .unwrap();
    assert!(!g.met && !g.exercise_edited);
    assert_eq!(
        g.disturbances,
        vec!["'remove' added at step 25 (the exercise allows none)"]
    );
}
