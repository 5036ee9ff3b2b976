//! Reachable positions and the connectivity rule.

use super::*;

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
    // The plane holds the structure: a move that would lift its last unit on the plane off it
    // is not made. A on the plane, B on top of A, C beside B on B's x axis: B may swing A up off
    // the plane, where there is no holding plane...
    let units = [[0, 0, 0], [0, 0, 1], [1, 0, 1]];
    let lifted = set(&[[0, 1, 1], [0, -1, 1]]);
    assert_eq!(reach(&structure(&units), [0, 0, 0]), lifted);
    // ...but not from a holding plane, of which A is the last unit.
    let mut held = structure(&units);
    held.hold_on_plane(O[2]);
    assert_eq!(held.on_plane, 1);
    assert!(reach(&held, [0, 0, 0]).is_empty());
    // With D beside A on the plane, the plane still holds the structure when A goes.
    let units = [[0, 0, 0], [0, 0, 1], [1, 0, 1], [1, 0, 0]];
    let mut held = structure(&units);
    held.hold_on_plane(O[2]);
    assert_eq!(held.on_plane, 2);
    let r = reach(&held, [0, 0, 0]);
    assert!(lifted.is_subset(&r), "{r:?}");
    assert_eq!(r, reach(&structure(&units), [0, 0, 0]));
    // Fixed: units touching the plane never move.
    let fixed = model(body("fixed"));
    assert!(fixed.movable.is_empty());
}
