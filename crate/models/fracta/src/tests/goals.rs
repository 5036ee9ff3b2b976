//! Goal statements: derivation, parsing, realisability and the difference.

use super::*;

#[test]
fn the_triangles_statements_are_the_papers() {
    let tri = shape::parse_hex(TRIANGLE).unwrap();
    let goal = derive(std::slice::from_ref(&tri)).unwrap();
    let texts: Vec<String> = goal.statements().iter().map(Statement::text).collect();
    // Section 3.2.1: K{o, K, K, s}, with the corners o and the centre s it names.
    assert_eq!(texts, ["o{K, K}", "K{o, K, K, s}", "s{K, K, K, K, K, K}"]);
    // The neighbour types are sorted by bond count, as the paper sorts them.
    assert_eq!(goal.text(), TRIANGLE_GOAL);
    // The presets use exactly these as their first priority.
    let preset = presets::scenario("fracta-triangle10").unwrap();
    let g = Goal::parse(preset.body()["goal"].as_str().unwrap()).unwrap();
    let first: Vec<String> = g
        .statements()
        .iter()
        .filter(|s| s.priority == 1)
        .map(Statement::text)
        .collect();
    assert_eq!(first, texts);
    // The spare gives the second priority, derived, not written by hand: in the middle of an
    // edge (the same statements for each of the three edges) and beside a corner.
    for edge in [
        ". . # .\n . # # #\n. # # #\n # # # #\n",
        ". . # .\n # # # .\n. # # #\n # # # #\n",
        ". . # .\n . # # .\n. # # #\n # # # #\n. . # .\n",
    ] {
        let spare = shape::parse_hex(edge).unwrap();
        assert_eq!(derive(&[tri.clone(), spare]).unwrap().text(), g.text());
    }
    let corner = presets::scenario("fracta-triangle10-corner").unwrap();
    let spare = shape::parse_hex(". # # .\n . # # .\n. # # #\n # # # #\n").unwrap();
    assert_eq!(
        derive(&[tri, spare]).unwrap().text(),
        Goal::parse(corner.body()["goal"].as_str().unwrap())
            .unwrap()
            .text()
    );
}

#[test]
fn statements_parse_in_any_spelling_and_order() {
    let a = Goal::parse("K{o, K, K, s}").unwrap();
    let b = Goal::parse("k{S,k,O,K}").unwrap();
    assert_eq!(a.text(), b.text());
    let c = Goal::parse("# corners\n  eps{o, K, c} ; o{eps,c}\n\n2: lambda{e, k, K} # a comment")
        .unwrap();
    assert_eq!(c.text(), "o{ε, c}  ε{o, K, c}\n2: λ{e, K, K}\n");
    assert_eq!(Goal::parse(&c.text()).unwrap().text(), c.text());
    // A repeat keeps its first priority.
    let d = Goal::parse("2: o{K, K}\no{K, K}").unwrap();
    assert_eq!(d.statements().len(), 1);
    assert_eq!(d.statements()[0].priority, 1);
}

#[test]
fn malformed_statements_name_the_line_and_the_problem() {
    let err = |text: &str| Goal::parse(text).unwrap_err();
    let cases: &[(&str, &[&str])] = &[
        ("", &["no statements"]),
        ("  # only a comment\n", &["no statements"]),
        ("o{K, K}\nK{o, K, K}", &["line 2", "4 bonds", "not 3"]),
        (
            "Q{o}",
            &["line 1", "'Q' is not a connection type", "known: e, o"],
        ),
        ("o{K, K}\n\nK{0, K, K, s}", &["line 3", "'0'", "not zero"]),
        ("K{o, K, K, s", &["line 1", "missing '}'"]),
        ("K{o, K, K, s o{K, K}", &["line 1", "missing '}'"]),
        ("{K, K}", &["starts with its unit's type"]),
        ("o{K,,K}", &["empty name"]),
        ("o{}", &["lists no neighbours", "2"]),
        ("0: o{K, K}", &["priority '0'", "from 1 to 9"]),
        ("12: o{K, K}", &["priority '12'"]),
        ("2 o{K, K}", &["expected a priority"]),
        ("3:", &["followed by no statement"]),
        ("o{K, K} junk", &["found 'junk'"]),
        ("s{e, e, e, e, e, e}", &["cannot occur"]),
        ("o K{K, K}", &["expected a statement"]),
    ];
    for (text, needles) in cases {
        let e = err(text);
        for n in *needles {
            assert!(e.contains(n), "{text:?} gave {e:?}, expected {n:?}");
        }
    }
    let huge = "o{K, K}\n".repeat(10_000);
    assert!(err(&huge).contains("limit"));
    // Through a scenario the error carries the field name.
    let doc = json!({"version": 1, "model": "fracta", "start": "# #", "goal": "o{K, K}\nK{x}"});
    let e = Scenario::from_value(doc).unwrap_err().to_string();
    assert!(e.starts_with("goal: line 2:"), "{e}");
}

#[test]
fn realisability_follows_the_lattice() {
    let t = types();
    let st = |s: &str| Goal::parse(s).map(|g| g.statements()[0].clone());
    // Every statement found in a real shape is realisable.
    for shape in [
        TRIANGLE,
        "# # # # # #\n # # # # #\n",
        ". # # .\n # # # .\n. # # .\n",
    ] {
        let g = derive(&[shape::parse_hex(shape).unwrap()]).unwrap();
        for s in g.statements() {
            assert!(realisable(t, s.unit, &s.neighbours), "{}", s.text());
        }
    }
    // An o's two neighbours touch each other, so neither can be an e.
    assert!(st("o{e, e}").is_err());
    assert!(st("o{e, K}").is_err());
    assert!(st("i{e, e}").is_ok());
}

#[test]
fn difference_pairs_sorted_neighbours_and_pads_with_none() {
    let t = types();
    let g = Goal::parse("K{o, K, K, s}").unwrap();
    let (o, k, s, e) = (
        class_named("o"),
        class_named("K"),
        class_named("s"),
        class_named("e"),
    );
    let diff = |own: u8, nb: &[u8]| {
        g.difference(&t.dist, own, nb, Priorities::Pooled)
            .difference
    };
    assert_eq!(diff(k, &[o, k, k, s]), 0);
    // One neighbour one link away.
    assert_eq!(
        diff(k, &[o, k, s, s]),
        u32::from(t.dist[k as usize][s as usize])
    );
    // An ε missing its fourth neighbour: d(ε, K) + d(none, o) for the padded first place.
    let eps = class_named("eps");
    assert_eq!(
        diff(eps, &[k, k, s]),
        u32::from(t.dist[eps as usize][k as usize]) + u32::from(t.info[o as usize].bonds)
    );
    // The closest statement wins; exact matches of any priority give 0.
    let two = Goal::parse("K{o, K, K, s}\n2: e{i}").unwrap();
    let (i, v) = (class_named("i"), class_named("v"));
    let d = |own: u8, nb: &[u8], mode| two.difference(&t.dist, own, nb, mode);
    assert_eq!(d(e, &[i], Priorities::Guided).difference, 0);
    assert_eq!(d(e, &[v], Priorities::Pooled).difference, 1);
    assert!(d(e, &[v], Priorities::Guided).difference > 1);
    assert_eq!(d(e, &[v], Priorities::Penalty).difference, 2);
    // e{K} cannot occur: every bond of a K has a bonded slot beside it, an e has none.
    assert!(Goal::parse("e{K}").is_err());
}

#[test]
fn a_completed_goal_has_zero_difference_and_stays_still() {
    for (start, goal) in [
        (TRIANGLE, TRIANGLE_GOAL),
        (
            ". . # .\n . # # #\n. # # #\n # # # #\n",
            presets::scenario("fracta-triangle10").unwrap().body()["goal"]
                .as_str()
                .unwrap(),
        ),
        (
            ". # # .\n . # # .\n. # # #\n # # # #\n",
            presets::scenario("fracta-triangle10-corner")
                .unwrap()
                .body()["goal"]
                .as_str()
                .unwrap(),
        ),
        (
            ". # # .\n # # # .\n. # # .\n",
            "ε{ε, ε, s}  s{ε, ε, ε, ε, ε, ε}",
        ),
    ] {
        let s = scenario(start, goal, 3, json!({}));
        let mut m = Fracta::of_scenario(&s).unwrap();
        assert!(m.completed());
        assert!(m.working.iter().all(|&u| m.diff[u as usize] == 0));
        let cells: Vec<u32> = m.units.iter().map(|u| u.cell).collect();
        for _ in 0..300 {
            m.step();
            assert!(m.completed());
        }
        assert_eq!(m.moves, 0);
        assert_eq!(m.units.iter().map(|u| u.cell).collect::<Vec<_>>(), cells);
    }
}
