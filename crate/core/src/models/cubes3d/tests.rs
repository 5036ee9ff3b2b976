use std::collections::BTreeSet;

use super::motion::{Move, Scratch, Structure, DIRS, PAD};
use super::typelist::{self, TypeList};
use super::types::{self, TYPE_OF_MASK};
use super::*;
use crate::presets;
use crate::run::Run;

type C = [i32; 3];

/// Where the origin of the test structures lies in their space.
const O: C = [5, 5, 5];

fn scenario(body: Value) -> Result<Scenario> {
    let mut doc = json!({"version": 1, "model": "cubes3d", "name": "t", "max_steps": 3000});
    for (k, v) in body.as_object().unwrap() {
        doc[k] = v.clone();
    }
    Scenario::from_value(doc)
}

fn model(body: Value) -> Cubes {
    Cubes::new(&scenario(body).unwrap()).unwrap()
}

fn add(a: C, b: C) -> C {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// A structure in a 14-cell cube of space, units given relative to (5, 5, 5).
fn structure(units: &[C]) -> Structure {
    let mut st = Structure::new([14; 3], [PAD; 3], [14 - PAD; 3]);
    let cells: Vec<usize> = units
        .iter()
        .map(|&u| st.index(add(u, O)).unwrap())
        .collect();
    st.place(&cells);
    st
}

fn rel(st: &Structure, cell: u32) -> C {
    let c = st.coord(cell as usize);
    [c[0] - 5, c[1] - 5, c[2] - 5]
}

fn reach(st: &Structure, unit: C) -> BTreeSet<C> {
    let mut s = Scratch::default();
    st.reachable(st.index(add(unit, O)).unwrap(), &mut s);
    s.moves.iter().map(|m| rel(st, m.dest)).collect()
}

fn set(cs: &[C]) -> BTreeSet<C> {
    cs.iter().copied().collect()
}

// ---------------------------------------------------------------- descriptions and type-lists

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

// ---------------------------------------------------------------- reachable positions

#[test]
fn figure_4_a_c1_unit_has_at_most_two_reachable_positions() {
    // P on top of its carrier Q, Q held by a support S on the x axis: Q turns about x, P lands
    // beside Q on either side along y.
    let st = structure(&[[0, 0, 1], [0, 0, 0], [1, 0, 0]]);
    assert_eq!(reach(&st, [0, 0, 1]), set(&[[0, 1, 0], [0, -1, 0]]));
    // With a support on both perpendicular axes two of the four candidates are the supports.
    let st = structure(&[[0, 0, 1], [0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]);
    assert_eq!(reach(&st, [0, 0, 1]), set(&[[0, -1, 0], [-1, 0, 0]]));
    // No support on an axis perpendicular to the bond: no move (a straight line is frozen).
    let st = structure(&[[0, 0, 2], [0, 0, 1], [0, 0, 0]]);
    assert!(reach(&st, [0, 0, 2]).is_empty());
    let st = structure(&[[0, 0, 0], [1, 0, 0]]);
    assert!(reach(&st, [0, 0, 0]).is_empty());
}

fn figure_2() -> Structure {
    // Plane A of four units at z = 0; Y on top of Z = (0, 0, 0); X on top of (1, 0, 0).
    structure(&[
        [0, 0, 0],
        [1, 0, 0],
        [0, 1, 0],
        [1, 1, 0],
        [1, 0, 1],
        [0, 0, 1],
    ])
}

#[test]
fn figure_2_the_pairwise_motion_and_its_exceptions() {
    let st = figure_2();
    // Y (C21) is carried by X turning about the vertical axis b-b onto (1, 1, 1), as in the
    // figure; or by X the other way, or by Z sideways.
    let y = reach(&st, [0, 0, 1]);
    assert!(y.contains(&[1, 1, 1]));
    assert_eq!(y, set(&[[1, 1, 1], [1, -1, 1], [0, -1, 0], [-1, 0, 0]]));
    // X (C21) cannot move upward: its pivot Y has no unit on the axis of that rotation.
    let x = reach(&st, [1, 0, 1]);
    assert!(!x.contains(&[0, 0, 2]));
    assert_eq!(x, set(&[[0, 1, 1], [0, -1, 1], [1, -1, 0], [2, 0, 0]]));
    assert_eq!(st.types[st.index([6, 5, 6]).unwrap()], types::C21);
    assert_eq!(st.types[st.index([5, 5, 6]).unwrap()], types::C21);
}

#[test]
fn the_swing_may_hit_no_unit_and_carry_nothing() {
    // Figure 4's case with a unit in the corner P sweeps through toward +y.
    let st = structure(&[
        [0, 0, 1],
        [0, 0, 0],
        [1, 0, 0],
        [0, 1, 1],
        [1, 1, 1],
        [1, 0, 1],
    ]);
    assert!(!reach(&st, [0, 0, 1]).contains(&[0, 1, 0]));
    // The carrier Q = (0,0,0) would have to let go of W = (0,-1,0), which hangs on Q alone:
    // W would be carried along (or fall), so Q may not turn about x.
    let st = structure(&[[0, 0, 1], [0, 0, 0], [1, 0, 0], [0, -1, 0]]);
    let r = reach(&st, [0, 0, 1]);
    assert!(!r.contains(&[0, 1, 0]), "{r:?}");
    // Once W is also held by the support's side, the move is allowed.
    let st = structure(&[[0, 0, 1], [0, 0, 0], [1, 0, 0], [0, -1, 0], [1, -1, 0]]);
    assert!(reach(&st, [0, 0, 1]).contains(&[0, 1, 0]));
}

/// The pairwise motion written out directly on coordinates, with a full search for
/// connectivity: the reference the fast version is checked against.
fn brute_reach(units: &BTreeSet<C>, p: C, walls: impl Fn(C) -> bool) -> BTreeSet<C> {
    let mut out = BTreeSet::new();
    for e in DIRS {
        let q = [p[0] - e[0], p[1] - e[1], p[2] - e[2]];
        if !units.contains(&q) {
            continue;
        }
        for axis in 0..3 {
            if e[axis] != 0 {
                continue;
            }
            let mut av = [0; 3];
            av[axis] = 1;
            let neg = [-av[0], -av[1], -av[2]];
            if !units.contains(&add(q, av)) && !units.contains(&add(q, neg)) {
                continue;
            }
            for f in DIRS {
                if f[axis] != 0 || (0..3).any(|k| f[k] != 0 && e[k] != 0) {
                    continue;
                }
                let dest = add(q, f);
                if walls(dest) || units.contains(&dest) || units.contains(&add(p, f)) {
                    continue;
                }
                // Graph without p; q keeps only its bonds along the axis.
                let rest: BTreeSet<C> = units.iter().copied().filter(|&u| u != p).collect();
                let bonded = |a: C, b: C| {
                    let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
                    if a == q || b == q {
                        d[axis] != 0
                    } else {
                        true
                    }
                };
                let start = *rest.iter().next().unwrap();
                let mut seen = BTreeSet::from([start]);
                let mut stack = vec![start];
                while let Some(x) = stack.pop() {
                    for d in DIRS {
                        let y = add(x, d);
                        if rest.contains(&y) && bonded(x, y) && seen.insert(y) {
                            stack.push(y);
                        }
                    }
                }
                if seen.len() == rest.len() {
                    out.insert(dest);
                }
            }
        }
    }
    out
}

/// A random connected structure of `n` units grown from the origin, with holes likely when
/// `sparse`.
fn random_units(rng: &mut Rng, n: usize, span: i32, sparse: bool) -> BTreeSet<C> {
    let mut units = BTreeSet::from([[0, 0, 0]]);
    while units.len() < n {
        let list: Vec<C> = units.iter().copied().collect();
        let from = list[rng.index(list.len())];
        let d = DIRS[rng.index(6)];
        let c = add(from, d);
        if c.iter().any(|v| v.abs() > span) || units.contains(&c) {
            continue;
        }
        if sparse {
            let around = DIRS.iter().filter(|&&d| units.contains(&add(c, d))).count();
            if around > 1 && rng.chance(0.7) {
                continue;
            }
        }
        units.insert(c);
    }
    units
}

#[test]
fn reachable_positions_match_the_brute_force_reference() {
    let mut rng = Rng::new(11);
    let mut searches = 0;
    let mut compared = 0;
    for round in 0..160 {
        let n = 3 + rng.index(30);
        let units = random_units(&mut rng, n, 3, round % 2 == 0);
        let list: Vec<C> = units.iter().copied().collect();
        let st = structure(&list);
        let mut s = Scratch::default();
        for &p in &list {
            let cell = st.index(add(p, O)).unwrap();
            st.reachable(cell, &mut s);
            let fast: Vec<C> = s.moves.iter().map(|m| rel(&st, m.dest)).collect();
            let fast_set: BTreeSet<C> = fast.iter().copied().collect();
            assert_eq!(fast.len(), fast_set.len(), "a destination listed twice");
            let walls = |c: C| st.index(add(c, O)).is_none_or(|i| st.wall[i]);
            assert_eq!(
                fast_set,
                brute_reach(&units, p, walls),
                "unit {p:?} in {list:?}"
            );
            for m in &s.moves {
                check_move_geometry(&st, cell, m);
            }
            compared += 1;
        }
        searches += s.searches;
    }
    assert!(compared > 1000);
    assert!(searches > 0, "the non-local search was never exercised");
}

fn check_move_geometry(st: &Structure, p: usize, m: &Move) {
    let (pc, qc, dc) = (
        st.coord(p),
        st.coord(m.carrier as usize),
        st.coord(m.dest as usize),
    );
    let dist = |a: C, b: C| (0..3).map(|k| (a[k] - b[k]).abs()).sum::<i32>();
    assert_eq!(dist(pc, qc), 1);
    assert_eq!(dist(dc, qc), 1);
    assert_eq!(dist(pc, dc), 2, "destinations lie in the two-neighbourhood");
    let a = m.axis as usize;
    assert!(
        pc[a] == qc[a] && dc[a] == qc[a],
        "the swing is perpendicular to the axis"
    );
}

#[test]
fn connectivity_check_matches_a_full_search_on_rings_and_trees() {
    // Rings (every unit on one long cycle) and trees (every inner unit a cut) are where the
    // local search fails and the global one must be right.
    let mut rng = Rng::new(3);
    let mut shapes: Vec<Vec<C>> = Vec::new();
    for side in 2..7 {
        let mut ring = Vec::new();
        for x in 0..=side {
            ring.push([x - 3, -3, 0]);
            ring.push([x - 3, side - 3, 0]);
        }
        for y in 1..side {
            ring.push([-3, y - 3, 0]);
            ring.push([side - 3, y - 3, 0]);
        }
        shapes.push(ring);
    }
    for _ in 0..40 {
        shapes.push(random_units(&mut rng, 25, 3, true).into_iter().collect());
    }
    let mut s = Scratch::default();
    for list in &shapes {
        let st = structure(list);
        let units: BTreeSet<C> = list.iter().copied().collect();
        for &p in list {
            let pc = st.index(add(p, O)).unwrap();
            // Lifting p alone.
            let expect = !brute_split(&units, p, None);
            assert_eq!(
                st.stays_connected(pc, None, &mut s),
                expect,
                "{p:?} in {list:?}"
            );
            // With every neighbour as carrier and every axis.
            for d in 0..6 {
                let q = st.nb(pc, d);
                if !st.occupied(q) {
                    continue;
                }
                for a in 0..3 {
                    if a == d / 2 {
                        continue;
                    }
                    let fast = st.stays_connected(pc, Some((q, a)), &mut s);
                    let slow = !brute_split(&units, p, Some((rel(&st, q as u32), a)));
                    assert_eq!(
                        fast,
                        slow,
                        "p {p:?} q {:?} axis {a} in {list:?}",
                        rel(&st, q as u32)
                    );
                }
            }
        }
    }
    assert!(s.searches > 100);
}

/// Does lifting p (and, with a carrier q, cutting q's bonds off axis `a`) split the units?
fn brute_split(units: &BTreeSet<C>, p: C, carrier: Option<(C, usize)>) -> bool {
    let rest: Vec<C> = units.iter().copied().filter(|&u| u != p).collect();
    let start = rest[0];
    let mut seen = BTreeSet::from([start]);
    let mut stack = vec![start];
    while let Some(x) = stack.pop() {
        for d in DIRS {
            let y = add(x, d);
            let cut = carrier.is_some_and(|(q, axis)| (x == q || y == q) && d[axis] == 0);
            if y != p && units.contains(&y) && !cut && seen.insert(y) {
                stack.push(y);
            }
        }
    }
    seen.len() != rest.len()
}

#[test]
fn a_holding_plane_is_a_support() {
    let body = |ground: &str| {
        json!({"shape": "##\n", "ground": ground, "margin": 2,
               "targets": [{"type_lists": "C21[C21, C21]"}]})
    };
    let floor = model(body("floor"));
    let anchor = model(body("anchor"));
    let p = floor.units[0] as usize;
    assert!(floor.reach_report(p).is_empty());
    // Its neighbour turns about the vertical axis, held by the plane: P slides around it.
    let r = anchor.reach_report(p);
    assert_eq!(r.len(), 2);
    for (dest, _) in r {
        assert_eq!(
            anchor.st.coord(dest as usize)[2],
            PAD as i32,
            "stays on the plane"
        );
    }
    // Fixed: units touching the plane never move.
    let fixed = model(body("fixed"));
    assert!(fixed.movable.is_empty());
}

// ---------------------------------------------------------------- runs

/// Everything the incremental bookkeeping maintains, recomputed from scratch.
fn check_invariants(m: &Cubes) {
    let occupied: Vec<usize> = m.st.units();
    assert_eq!(
        occupied.len(),
        m.units.len(),
        "units lost, created or stacked"
    );
    let mut listed: Vec<usize> = m.units.iter().map(|&u| u as usize).collect();
    listed.sort_unstable();
    assert_eq!(
        listed, occupied,
        "two units share a cell or a unit is missing"
    );
    for (k, &u) in m.units.iter().enumerate() {
        assert_eq!(m.upos[u as usize], k as u32);
    }
    assert!(m.st.connected(), "the structure came apart");
    let mut zero = 0;
    for &c in &occupied {
        assert!(!m.st.wall[c]);
        assert_eq!(m.st.types[c], TYPE_OF_MASK[m.st.mask(c) as usize]);
        let prof = m.st.profile(c);
        let d = m.difference(m.target[c], &prof);
        assert_eq!(m.diff[c].to_bits(), d.to_bits(), "stale difference at {c}");
        // D is zero exactly when the unit's type-list is one of the target's.
        let matches = m.targets[m.target[c] as usize].lists.contains(&prof);
        assert_eq!(d == 0.0, matches, "cell {c}: D = {d}");
        zero += usize::from(d == 0.0);
        assert_eq!(m.mpos[c] != u32::MAX, m.eligible(c));
    }
    assert_eq!(zero, m.zero);
    assert_eq!(
        m.movable.len(),
        occupied.iter().filter(|&&c| m.eligible(c)).count()
    );
}

fn run_checked(m: &mut Cubes, steps: usize) {
    check_invariants(m);
    for _ in 0..steps {
        m.step();
        check_invariants(m);
    }
}

#[test]
fn invariants_hold_on_every_step_of_random_runs() {
    for (i, sel) in ["mrf", "random", "steepest"].iter().enumerate() {
        for preset in ["cubes-cube8-zigzag", "cubes-box12-ladder", "cubes-light"] {
            let mut s = presets::scenario(preset).unwrap();
            s.seed = 40 + i as u64;
            let s = s.with_override("selection", json!(sel)).unwrap();
            let mut m = Cubes::new(&s).unwrap();
            run_checked(&mut m, 250);
        }
    }
    // Random blobs, several movers per step, every type movable, tight walls.
    let mut rng = Rng::new(8);
    for round in 0..6 {
        let units = random_units(&mut rng, 20 + round * 4, 2, round % 2 == 1);
        let mut text = String::new();
        for z in -2..=2 {
            if z > -2 {
                text.push_str("---\n");
            }
            for y in -2..=2 {
                for x in -2..=2 {
                    text.push(if units.contains(&[x, y, z]) { '#' } else { '.' });
                }
                text.push('\n');
            }
        }
        let selection = ["random", "mrf"][round % 2];
        let mut m = model(json!({
            "seed": round, "shape": text, "margin": 1 + round % 3,
            "movers": 1 + round % 3, "mover_distance": 1 + round,
            "movable": ["C1", "C20", "C21", "C30", "C31", "C40", "C41", "C5"],
            "selection": selection,
            "targets": [{"shape": "###\n###\n---\n###\n###\n"}]
        }));
        run_checked(&mut m, 300);
    }
}

#[test]
fn disturbances_keep_the_books_straight() {
    let mut m = Cubes::new(&presets::scenario("cubes-box12-ladder").unwrap()).unwrap();
    let act = |kind: &str, cell: usize| -> Action {
        json!({"kind": kind, "cells": [cell]})
            .as_object()
            .cloned()
            .unwrap()
    };
    for _ in 0..20 {
        m.step();
    }
    // An end unit of the ladder can go; then add it back beside another unit.
    let victim = *m
        .units
        .iter()
        .find(|&&c| {
            let mut s = Scratch::default();
            m.st.stays_connected(c as usize, None, &mut s)
        })
        .unwrap() as usize;
    m.apply(&act("remove", victim)).unwrap();
    check_invariants(&m);
    assert_eq!(m.units.len(), 11);
    assert!(
        m.apply(&act("remove", victim)).is_err(),
        "no unit there any more"
    );
    let spot = (0..m.st.len())
        .find(|&c| !m.st.wall[c] && !m.st.occupied(c) && m.st.mask(c) != 0)
        .unwrap();
    m.apply(&act("add", spot)).unwrap();
    check_invariants(&m);
    assert!(m.apply(&act("add", spot)).is_err());
    let lonely = (0..m.st.len())
        .find(|&c| !m.st.wall[c] && m.st.mask(c) == 0 && !m.st.occupied(c))
        .unwrap();
    assert!(m
        .apply(&act("add", lonely))
        .unwrap_err()
        .to_string()
        .contains("touches no unit"));
    // Hold a movable unit: it leaves the movable set; release it again.
    let held = m.movable[0] as usize;
    m.apply(&act("hold", held)).unwrap();
    assert!(!m.eligible(held));
    check_invariants(&m);
    run_checked(&mut m, 100);
    assert!(m.check_action(&act("explode", 1)).is_err());
    assert!(m.check_action(&act("remove", usize::MAX >> 8)).is_err());
    let switch = json!({"kind": "switch"}).as_object().cloned().unwrap();
    assert!(m.check_action(&switch).is_err(), "one target only");
    // A cut unit of a chain may not be removed.
    let mut chain = model(json!({"shape": "###\n", "targets": [{"type_lists": "C1[C1]"}]}));
    let middle = (0..chain.st.len())
        .find(|&c| chain.st.types[c] == types::C20)
        .unwrap();
    let err = chain.apply(&act("remove", middle)).unwrap_err().to_string();
    assert!(err.contains("split"), "{err}");
}

#[test]
fn a_run_stops_when_every_unit_matches_and_is_deterministic() {
    let s = presets::scenario("cubes-cube8-zigzag").unwrap();
    let mut a = Run::new(s.clone()).unwrap();
    a.run_to_end();
    let mut b = Run::new(s).unwrap();
    b.run_to_end();
    assert_eq!(a.outcome(), b.outcome());
    let out = a.outcome();
    if out.completed {
        assert_eq!(out.metrics["mean_difference"], json!(0.0));
        assert_eq!(out.metrics["completed"], json!(1));
        assert!(out.steps < 5000);
    }
    let mut other = presets::scenario("cubes-cube8-zigzag").unwrap();
    other.seed = 2;
    let mut c = Run::new(other).unwrap();
    c.run_to_end();
    assert_ne!(c.outcome().hash, a.outcome().hash);
}

#[test]
fn the_mrf_rule_beats_its_baselines_on_the_cube() {
    // Qualitative check of section 5 (not a number from the paper): over a few seeds, MRF
    // reaches a lower mean difference after 1500 steps than the random and steepest rules.
    let mean_after = |sel: &str| -> f64 {
        (1..=6)
            .map(|seed| {
                let mut s = presets::scenario("cubes-cube8-zigzag")
                    .unwrap()
                    .with_override("selection", json!(sel))
                    .unwrap()
                    .with_override("max_steps", json!(1500))
                    .unwrap();
                s.seed = seed;
                let mut r = Run::new(s).unwrap();
                r.run_to_end();
                r.outcome().metrics["mean_difference"].as_f64().unwrap()
            })
            .sum::<f64>()
            / 6.0
    };
    let (mrf, random, steepest) = (
        mean_after("mrf"),
        mean_after("random"),
        mean_after("steepest"),
    );
    assert!(mrf < random && mrf < steepest, "{mrf} {random} {steepest}");
}

#[test]
fn light_switches_targets_and_holds_the_lit_units() {
    let s = presets::scenario("cubes-light").unwrap();
    let mut m = Cubes::new(&s).unwrap();
    assert_eq!(m.metrics()["displacement"], json!(0.0));
    let lit: Vec<usize> = m
        .units
        .iter()
        .map(|&c| c as usize)
        .filter(|&c| m.lit(c))
        .collect();
    assert_eq!(lit.len(), 4, "the cube's face toward the light");
    // Each unit switches on its own D_0, after it has stayed under the threshold for 30
    // steps.
    while m.switches == 0 && m.steps < 1000 {
        m.step();
        assert!(m.steps >= 30 || m.switches == 0);
    }
    assert!(
        m.switches > 0,
        "units of the cube stay under their threshold"
    );
    for &c in &m.units {
        let c = c as usize;
        if m.target[c] == 1 {
            assert_eq!(m.stable[c], 0);
        }
    }
    // The units that switched to the ladder and see the light are held.
    for &c in &m.units {
        let c = c as usize;
        assert_eq!(
            m.flags[c] & HELD_LIT != 0,
            m.target[c] == 1 && m.lit(c),
            "cell {c}"
        );
        if m.target[c] == 1 && m.lit(c) {
            assert!(!m.eligible(c));
        }
    }
    check_invariants(&m);
    // A switch by click moves every unit on from the target most units hold.
    if m.main_target() == 0 {
        m.apply(&json!({"kind": "switch"}).as_object().cloned().unwrap())
            .unwrap();
    }
    assert!(m.units.iter().all(|&c| m.target[c as usize] == 1));
    m.apply(&json!({"kind": "switch"}).as_object().cloned().unwrap())
        .unwrap();
    assert!(m.units.iter().all(|&c| m.target[c as usize] == 0));
    assert!(m.units.iter().all(|&c| m.flags[c as usize] & HELD_LIT == 0));
    check_invariants(&m);
}

#[test]
fn scene_and_layout_describe_the_view() {
    let m = Cubes::new(&presets::scenario("cubes-light").unwrap()).unwrap();
    let scene = m.scene();
    assert_eq!(scene.light, Some([1.0, 0.0, 0.0]));
    assert_eq!(scene.ground, Some(PAD));
    assert_eq!(scene.ghost.len(), 8);
    let layout = m.layout();
    assert_eq!(layout.cells.len(), 9);
    assert_eq!(layout.cells[0].name, "C1");
    let n = m.st.len();
    assert_eq!(m.cells().len(), n);
    for f in &layout.fields {
        assert_eq!(m.field(&f.name).unwrap().len(), n, "{}", f.name);
    }
    // The inspector lists the reachable positions as cell indices.
    let p = m.movable[0] as usize;
    let info = m.inspect(p);
    assert_eq!(info["unit"], json!(true));
    let listed: Vec<u64> = info["reachable"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_u64().unwrap())
        .collect();
    let expect: Vec<u64> = m.reach_report(p).iter().map(|r| u64::from(r.0)).collect();
    assert_eq!(listed, expect);
    assert_eq!(info["type_list"], json!("C31[C31, C31, C31]"));
    assert!(m.inspect(usize::MAX).is_empty());
}

#[test]
fn scenarios_with_bad_values_are_errors_that_name_the_field() {
    let base = || json!({"shape": "##\n", "targets": [{"type_lists": "C1[C1]"}]});
    let cases = [
        ("w", json!(0.0), "w"),
        ("a", json!(-1.0), "a"),
        ("c", json!(0), "c"),
        ("selection", json!("greedy"), "selection"),
        ("light", json!("up"), "light"),
        ("ground", json!("lava"), "ground"),
        ("movable", json!(["C1", "C9"]), "movable[1]"),
        ("margin", json!(1000), "margin"),
        ("movers", json!(0), "movers"),
        ("stable_steps", json!(0), "stable_steps"),
        ("shape", json!("#.#\n"), "shape"),
        ("shape", json!("#\n"), "shape"),
        ("shape", json!(""), "shape"),
        ("targets", json!([]), "targets"),
        ("targets", json!([{}]), "targets[0]"),
        ("targets", json!([{"shape": "#x\n"}]), "targets[0].shape"),
        (
            "targets",
            json!([{"type_lists": "C1[C1]", "hold_lit": true}]),
            "targets[0].hold_lit",
        ),
        ("bogus", json!(1), "bogus"),
    ];
    for (key, value, path) in cases {
        let mut body = base();
        body[key] = value;
        let err = scenario(body).unwrap_err().to_string();
        assert!(err.starts_with(&format!("{path}:")), "{key}: {err}");
    }
    // A space too large is refused before anything is allocated.
    let mut body = base();
    body["shape"] = json!("#".repeat(600));
    assert!(scenario(body)
        .unwrap_err()
        .to_string()
        .contains("exceeds the limit"));
}

#[test]
fn queries_derive_and_check_descriptions() {
    let out = models::query(
        "cubes3d",
        "derive",
        &json!({"shape": "##\n##\n---\n##\n##\n"}),
    )
    .unwrap();
    assert_eq!(out["type_lists"], json!("C31[C31, C31, C31]\n"));
    assert_eq!(out["units"], json!(8));
    let out = models::query(
        "cubes3d",
        "derive",
        &json!({"units": [[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1],[0,0,2],[1,0,2],[0,1,2],[1,1,2]]}),
    )
    .unwrap();
    assert_eq!(
        out["type_lists"],
        json!("C31[C41, C31, C31]\nC41[C41, C41, C31, C31]\n")
    );
    let err = models::query("cubes3d", "check", &json!({"type_lists": "C31[C31]"})).unwrap_err();
    assert!(err.to_string().starts_with("type_lists: line 1"), "{err}");
    assert!(models::query("cubes3d", "nope", &json!({})).is_err());
    assert!(models::query("amas", "derive", &json!({})).is_err());
    assert!(models::query("cubes3d", "derive", &json!({"units": "x"})).is_err());
}

#[test]
fn derived_descriptions_hold_for_the_shape_they_came_from() {
    // A structure placed in its own target shape has D = 0 everywhere: it is complete.
    for shape in [
        "###\n#.#\n###\n---\n#..\n...\n...\n",
        "####\n####\n",
        "##\n##\n---\n#.\n..\n",
    ] {
        let m = model(json!({"shape": shape, "targets": [{"shape": shape}]}));
        assert!(m.completed(), "{shape}");
        let lists = typelist::describe_grid(&shape::parse_cubic(shape).unwrap()).unwrap();
        let padded: Vec<[u8; 7]> = lists.iter().map(TypeList::padded).collect();
        assert_eq!(padded, m.targets[0].lists);
    }
}

#[test]
fn the_box_preset_has_the_self_repair_papers_goal_and_movable_types() {
    // Equation 6 of "Experiment of self-repairing modular machine", as printed.
    let eq6 = typelist::parse("C31{C31, C31, C41} C41{C31, C31, C41, C41}").unwrap();
    let m = Cubes::new(&presets::scenario("cubes-box12-ladder").unwrap()).unwrap();
    let padded: Vec<[u8; 7]> = eq6.iter().map(TypeList::padded).collect();
    assert_eq!(m.targets[0].lists, padded);
    let movable = (1u16 << types::C1) | (1u16 << types::C21) | (1u16 << types::C31);
    assert_eq!(m.movable_types, movable);
}

#[test]
fn steepest_descent_takes_the_least_difference_of_all_units() {
    let mut m = model(json!({
        "shape": "######\n######\n", "selection": "steepest",
        "targets": [{"type_lists": "C31[C41, C31, C31]\nC41[C41, C41, C31, C31]"}]
    }));
    let mut least = f64::INFINITY;
    for &u in &m.movable.clone() {
        for r in m.reach_report(u as usize) {
            least = least.min(r.1);
        }
    }
    let before = m.moves;
    m.step();
    assert_eq!(
        m.moves,
        before + 1,
        "steepest descent moves even when it raises D"
    );
    let moved = m.events.iter().find(|e| e.kind == ARRIVED).unwrap().cell as usize;
    assert_eq!(m.diff[moved], least);
}
