//! Descriptions and type-lists.

use super::*;

#[test]
fn the_cube_and_the_box_have_the_papers_descriptions() {
    let cube = shape::parse_cubic("##\n##\n---\n##\n##\n").unwrap();
    assert_eq!(
        typelist::to_text(&typelist::describe_grid(&cube).unwrap()),
        "C31[C31, C31, C31]\n"
    );
    // Equation 3 (and equation 6 of the self-repair paper): the 2×2×3 box, in any orientation.
    for text in [
        "##\n##\n---\n##\n##\n---\n##\n##\n",
        "###\n###\n---\n###\n###\n",
        "##\n##\n##\n---\n##\n##\n##\n",
    ] {
        let g = shape::parse_cubic(text).unwrap();
        assert_eq!(
            typelist::to_text(&typelist::describe_grid(&g).unwrap()),
            "C31[C41, C31, C31]\nC41[C41, C41, C31, C31]\n",
            "{text}"
        );
    }
    // Every unit of the 2×2×2 cube has type C31 and the 2×2×3 box C31 corners, C41 middles.
    let st = structure(&[
        [0, 0, 0],
        [1, 0, 0],
        [0, 1, 0],
        [1, 1, 0],
        [0, 0, 1],
        [1, 0, 1],
        [0, 1, 1],
        [1, 1, 1],
    ]);
    assert!(st.units().iter().all(|&c| st.types[c] == types::C31));
}

#[test]
fn the_2x4_ladder_and_a_lone_unit() {
    let g = shape::parse_cubic("####\n####\n").unwrap();
    assert_eq!(
        typelist::to_text(&typelist::describe_grid(&g).unwrap()),
        "C21[C30, C21]\nC30[C30, C30, C21]\n"
    );
    let err = typelist::describe(&[(0, 0, 0), (5, 5, 5)])
        .unwrap_err()
        .to_string();
    assert!(err.contains("touches no other unit"), "{err}");
}

#[test]
fn type_lists_parse_in_any_order_and_bracket_style() {
    let a = typelist::parse("C31[C41, C31, C31]\nC41[C41, C41, C31, C31]").unwrap();
    // Equation 6 of the self-repair paper: braces, increasing order, both on one line.
    let b = typelist::parse("  C31{C31, C31, C41} C41{C31, C31, C41, C41}\n\n").unwrap();
    let c = typelist::parse("c41[c31,c31,c41,c41]; C31[C31,C41,C31], C31[C31, C31, C41]").unwrap();
    assert_eq!(a, b);
    assert_eq!(a, c);
    assert_eq!(a.len(), 2);
    assert_eq!(a[0].to_string(), "C31[C41, C31, C31]");
    assert_eq!(
        typelist::parse("C6[C1,C20,C21,C30,C31,C5]").unwrap()[0].to_string(),
        "C6[C5, C31, C30, C21, C20, C1]"
    );
}

fn parse_err(text: &str) -> String {
    typelist::parse(text).unwrap_err().to_string()
}

#[test]
fn malformed_type_lists_name_the_line_and_the_problem() {
    let e = parse_err("C31[C31, C31, C31]\nC42[C31]");
    assert!(
        e.contains("line 2, column 1") && e.contains("unknown connection type 'C42'"),
        "{e}"
    );
    assert!(e.contains("known: C1, C20, C21"), "{e}");
    let e = parse_err("C31[C31, C31, C31, C31]");
    assert!(
        e.contains("line 1") && e.contains("C31 has valence 3") && e.contains("names 4"),
        "{e}"
    );
    let e = parse_err("C1[]");
    assert!(
        e.contains("C1 has valence 1, so it needs 1 neighbour,") && e.contains("names 0"),
        "{e}"
    );
    let e = parse_err("\n\nC31[C31, C31, C31");
    assert!(
        e.contains("line 3, column 4") && e.contains("never closed"),
        "{e}"
    );
    let e = parse_err("C31[C31, C31, C31]]");
    assert!(
        e.contains("line 1, column 19") && e.contains("no matching opening"),
        "{e}"
    );
    let e = parse_err("C31[C31, C31, C31}");
    assert!(e.contains("does not match the '['"), "{e}");
    let e = parse_err("C31[C31, [C31], C31]");
    assert!(e.contains("do not nest"), "{e}");
    let e = parse_err("C31 C31, C31, C31]");
    assert!(e.contains("expected '[' after C31"), "{e}");
    let e = parse_err("C31");
    assert!(e.contains("needs its neighbours in brackets"), "{e}");
    let e = parse_err("[C31]");
    assert!(e.contains("needs a connection type before it"), "{e}");
    let e = parse_err("C31[C31, , C31]");
    assert!(
        e.contains("column 10") && e.contains("expected a connection type"),
        "{e}"
    );
    let e = parse_err("C31[C31, C31, C31,]");
    assert!(e.contains("missing after ','"), "{e}");
    let e = parse_err("C31[C31 C31, C31]");
    assert!(e.contains("expected ',' or ']'"), "{e}");
    for empty in ["", "   \n\n ;, "] {
        assert!(parse_err(empty).contains("no type-lists"));
    }
    // Inside a scenario the error carries the field's path.
    let err = scenario(json!({
        "shape": "##\n",
        "targets": [{"type_lists": "C1[C1]"}, {"type_lists": "C1[C1]\nC2[C1]"}]
    }))
    .unwrap_err()
    .to_string();
    assert!(
        err.starts_with("targets[1].type_lists: line 2, column 1: unknown connection type 'C2'"),
        "{err}"
    );
}

#[test]
fn parsing_never_panics_on_junk() {
    let mut rng = Rng::new(5);
    let alphabet: Vec<char> = "C0123456[]{},; \n\tx#é".chars().collect();
    for _ in 0..3000 {
        let len = rng.index(40);
        let text: String = (0..len)
            .map(|_| alphabet[rng.index(alphabet.len())])
            .collect();
        if let Ok(lists) = typelist::parse(&text) {
            for l in lists {
                assert_eq!(
                    l.neighbours.len(),
                    usize::from(types::VALENCE[l.unit as usize])
                );
                // The canonical text parses back to itself.
                assert_eq!(typelist::parse(&l.to_string()).unwrap(), vec![l]);
            }
        }
    }
}

#[test]
fn difference_follows_equations_4_to_6() {
    // One target list; the unit is a C30 with neighbours C31, C21 against C31[C41, C31, C31].
    let t = typelist::diff_table(2.0);
    assert_eq!(t[types::C30 as usize][types::C31 as usize], 1.0);
    assert_eq!(t[types::C21 as usize][types::C41 as usize], 4.0);
    assert_eq!(t[0][types::C5 as usize], 10.0);
    let m = model(json!({
        "shape": "##\n", "w": 3.0, "a": 2.0,
        "targets": [{"type_lists": "C31[C41, C31, C31]"}]
    }));
    let prof = [types::C30, types::C31, types::C21, 0, 0, 0, 0];
    // W·diff(C31, C30) + diff(C41, C31) + diff(C31, C21) + diff(C31, blank)
    // = 3·1 + 2·1 + 2·1 + 2·3 = 13.
    assert_eq!(m.difference(0, &prof), 13.0);
    let exact = [types::C31, types::C41, types::C31, types::C31, 0, 0, 0];
    assert_eq!(m.difference(0, &exact), 0.0);
}
