//! Line motion, leader election in each crawl form and the crawl cycle.

use super::*;

#[test]
fn a_line_moves_whole_and_needs_something_to_slide_against() {
    // A robot on top of a tier of two, on the terrain's left end, beside a gap.
    let m = model("...\n#..\n##.\n==.\n", json!({}));
    let b = &m.body;
    let top = b.robot_at(0, 1);
    // Half a line may not move: the tier's left robot alone would leave its neighbour head-on.
    let half = Drive {
        robots: vec![b.robot_at(0, 2)],
        dir: RIGHT,
    };
    assert_eq!(b.check(&[half]), Err(Refusal::Blocked));
    let lone = Drive {
        robots: vec![b.robot_at(1, 2)],
        dir: RIGHT,
    };
    assert_eq!(b.check(&[lone]), Err(Refusal::HeadOn));
    // The top robot slides right over the tier.
    assert!(b
        .check(&[Drive {
            robots: vec![top],
            dir: RIGHT
        }])
        .is_ok());
    // Moving up it would leave everything: nothing keeps it attached.
    assert_eq!(
        b.check(&[Drive {
            robots: b.line(top, UP),
            dir: UP
        }]),
        Err(Refusal::Disconnected)
    );
    // The whole structure lifted has nothing fixed to push against.
    let all = [
        Drive {
            robots: b.line(b.robot_at(0, 2), UP),
            dir: UP,
        },
        Drive {
            robots: b.line(b.robot_at(1, 2), UP),
            dir: UP,
        },
    ];
    assert_eq!(b.check(&all), Err(Refusal::NoPartner));
    // Two orders that send one robot two ways conflict.
    let two = [
        Drive {
            robots: vec![top],
            dir: RIGHT,
        },
        Drive {
            robots: vec![top],
            dir: DOWN,
        },
    ];
    assert_eq!(b.check(&two), Err(Refusal::Conflict));
}

#[test]
fn exactly_one_leader_in_each_crawl_form() {
    let expected = [
        Kind::TopRight,
        Kind::TopLeft,
        Kind::BottomLeft,
        Kind::BottomRight,
    ];
    for n in [3, 5, 7, 9, 21] {
        for form in 1..=4 {
            let m = model(&crawl(n, form), json!({}));
            let leaders = election::three_rule(&m.body, &mut Comm::default());
            assert_eq!(leaders.len(), 1, "n = {n}, form {form}");
            assert_eq!(
                leaders[0].kind,
                expected[form as usize - 1],
                "n = {n}, form {form}"
            );
        }
    }
}

#[test]
fn a_crawl_cycle_moves_the_structure_one_cell() {
    for n in [3, 5, 7, 9] {
        let mut m = model(&crawl(n, 1), json!({}));
        let start = m.body.pos.clone();
        for cycle in 1..=3 {
            for _ in 0..4 {
                step_checked(&mut m);
                assert_eq!(m.last.leaders.len(), 1);
            }
            assert!((m.distance() - cycle as f64).abs() < 1e-12, "n = {n}");
            // Form 1 again, shifted: the same set of cells moved right by `cycle`.
            let mut a: Vec<_> = start.iter().map(|&(x, y)| (x + cycle, y)).collect();
            let mut b = m.body.pos.clone();
            a.sort();
            b.sort();
            assert_eq!(a, b, "n = {n}");
        }
        assert_eq!(
            m.totals.slots,
            12 * 7,
            "seven slots per transformation whatever n"
        );
    }
}

const FORM_B: &str = "..............\n#######.......\n==============\n";
const FORM_C: &str = "..............\n####..........\n####..........\n==============\n";
const FORM_D: &str = "..............\n.##...........\n#####.........\n==============\n";

#[test]
fn forms_b_and_c_elect_nobody_and_the_fallbacks_recover() {
    for form in [FORM_B, FORM_C] {
        let m = model(form, json!({}));
        assert!(election::three_rule(&m.body, &mut Comm::default()).is_empty());
        let mut first = model(form, json!({}));
        first.step();
        assert_eq!(first.totals.transformations, 0);
        assert_eq!(first.totals.election_failures, 1);
        let mut spent = Vec::new();
        for method in ["trial_and_error", "cautious"] {
            let mut m = model(form, json!({"method": method}));
            step_checked(&mut m);
            assert_eq!(m.last.leaders.len(), 1, "{method}");
            spent.push(m.totals.slots);
            for _ in 0..5 {
                step_checked(&mut m);
            }
            assert!(m.distance() >= 2.0, "{method}: {}", m.distance());
        }
        assert!(
            spent[1] < spent[0],
            "cautious spends fewer slots: {spent:?}"
        );
    }
}

#[test]
fn form_d_elects_several_and_the_priority_sequence_resolves_them() {
    let m = model(FORM_D, json!({}));
    let leaders = election::three_rule(&m.body, &mut Comm::default());
    let mut kinds: Vec<Kind> = leaders.iter().map(|e| e.kind).collect();
    kinds.dedup();
    assert!(kinds.len() >= 2, "{leaders:?}");
    let mut plain = model(FORM_D, json!({}));
    plain.step();
    assert_eq!(
        plain.totals.transformations, 0,
        "conflicting orders: nothing moves"
    );
    let mut with = model(FORM_D, json!({"priority": true}));
    for _ in 0..16 {
        step_checked(&mut with);
        assert_eq!(
            with.last
                .leaders
                .iter()
                .map(|e| e.kind)
                .collect::<std::collections::BTreeSet<_>>()
                .len(),
            1
        );
    }
    assert!(with.distance() >= 3.0);
    assert_eq!(PRIORITY[0], Kind::TopLeft);
}

#[test]
fn the_permanent_leader_sends_more_as_the_structure_grows() {
    let per = |n, leader: &str| {
        let mut m = model(&crawl(n, 1), json!({"leader": leader}));
        for _ in 0..8 {
            step_checked(&mut m);
        }
        (m.totals.slots as f64 / 8.0, m.distance())
    };
    let (t3, d3) = per(3, "temporary");
    let (t21, d21) = per(21, "temporary");
    let (p3, _) = per(3, "permanent");
    let (p21, e21) = per(21, "permanent");
    assert_eq!(t3, t21);
    assert_eq!((d3, d21, e21), (2.0, 2.0, 2.0));
    assert!(p21 > 3.0 * p3, "{p3} → {p21}");
}

#[test]
fn in_form_b_the_only_transformation_is_the_whole_row_sliding_on_the_base() {
    // Interpretation 7: the second algorithm drives the lone row along the base because no other
    // move exists. Lifting or lowering any run of its robots leaves them touching the rest by an
    // edge only, and part of the row cannot slide without parting face-on from the rest.
    let preset = kumiki_core::presets::scenario("chobie-form-b").unwrap();
    let m = Chobie::new(&preset).unwrap();
    let b = &m.body;
    let n = b.len() as u32;
    let row: Vec<u32> = {
        let mut r: Vec<u32> = (0..n).collect();
        r.sort_by_key(|&i| b.pos[i as usize].0);
        r
    };
    let mut feasible = Vec::new();
    for from in 0..row.len() {
        for to in from + 1..=row.len() {
            let run = &row[from..to];
            for dir in [RIGHT, UP, super::motion::LEFT, DOWN] {
                let drives: Vec<Drive> = if dir == RIGHT || dir == super::motion::LEFT {
                    vec![Drive {
                        robots: run.to_vec(),
                        dir,
                    }]
                } else {
                    run.iter()
                        .map(|&r| Drive {
                            robots: vec![r],
                            dir,
                        })
                        .collect()
                };
                if b.check(&drives).is_ok() {
                    feasible.push((from, to, dir));
                }
            }
        }
    }
    // (Left, the row would leave the world: it starts at its left edge.)
    assert_eq!(feasible, vec![(0, row.len(), RIGHT)]);
}
