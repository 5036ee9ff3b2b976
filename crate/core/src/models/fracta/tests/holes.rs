//! Holes, and the fewest motions that repair a fault.

use super::*;

#[test]
fn holes_count_the_cells_a_ring_encloses() {
    let ring = scenario(". # # .\n # . # .\n. # # .\n", TRIANGLE_GOAL, 1, json!({}));
    assert_eq!(Fracta::new(&ring).unwrap().holes(), 1);
    let full = scenario(TRIANGLE, TRIANGLE_GOAL, 1, json!({}));
    assert_eq!(Fracta::new(&full).unwrap().holes(), 0);
}

/// The plain definition `holes` must agree with: empty cells that no path of empty cells joins
/// to the lattice's edge, flooded over the whole lattice.
fn holes_over_the_whole_lattice(m: &Fracta) -> u64 {
    let n = m.occ.len();
    let mut outside = vec![false; n];
    let mut queue: VecDeque<u32> = (0..n as u32)
        .filter(|&i| m.nbr[i as usize].contains(&NO_UNIT) && m.occ[i as usize] == NO_UNIT)
        .collect();
    for &i in &queue {
        outside[i as usize] = true;
    }
    while let Some(i) = queue.pop_front() {
        for &j in &m.nbr[i as usize] {
            if j != NO_UNIT && !outside[j as usize] && m.occ[j as usize] == NO_UNIT {
                outside[j as usize] = true;
                queue.push_back(j);
            }
        }
    }
    (0..n)
        .filter(|&i| m.occ[i] == NO_UNIT && !outside[i])
        .count() as u64
}

#[test]
fn holes_searched_in_the_units_box_equal_holes_over_the_whole_lattice() {
    let edge = scenario(". # #\n # . #\n. # #\n", TRIANGLE_GOAL, 1, json!({}));
    let m = Fracta::new(&edge).unwrap();
    assert_eq!((m.holes(), holes_over_the_whole_lattice(&m)), (1, 1));
    let mut compared = 0;
    let mut with_holes = 0;
    for seed in 1..=40 {
        let mut s = presets::scenario("fracta-triangle10")
            .unwrap()
            .with_override("no_holes", json!(false))
            .unwrap();
        s.seed = seed;
        let mut m = Fracta::new(&s).unwrap();
        while m.steps < 600 && !m.completed() {
            m.step();
            let holes = m.holes();
            assert_eq!(
                holes,
                holes_over_the_whole_lattice(&m),
                "seed {seed}, step {}",
                m.steps
            );
            compared += 1;
            with_holes += usize::from(holes > 0);
        }
    }
    assert!(
        compared > 1000 && with_holes > 0,
        "{compared} steps, {with_holes} with holes"
    );
}

/// The fewest motions (one unit's motion each, in turn) that take the 10 units left after a
/// fault on `unit` of fracta-repair to the triangle, searched breadth first up to `limit`.
fn fewest_motions(unit: u64, limit: usize) -> Option<usize> {
    let mut s = presets::scenario("fracta-repair").unwrap();
    s.disturbances[0].action.insert("unit".into(), json!(unit));
    let mut m = Fracta::new(&s).unwrap();
    m.apply(&s.disturbances[0].action).unwrap();
    m.cut_off_faulty();
    let key = |m: &Fracta| {
        let mut cells: Vec<u32> = m
            .working
            .iter()
            .map(|&u| m.units[u as usize].cell)
            .collect();
        cells.sort_unstable();
        cells
    };
    let mut seen = BTreeSet::from([key(&m)]);
    let mut layer = vec![m];
    for depth in 0..=limit {
        if layer.iter().any(Fracta::completed) {
            return Some(depth);
        }
        let mut next = Vec::new();
        for m in &layer {
            for &u in &m.working {
                let cell = m.units[u as usize].cell;
                for pivot in 0..6 {
                    for turn in Turn::BOTH {
                        let Some(to) = m.legal(cell, m.mask[u as usize], pivot, turn) else {
                            continue;
                        };
                        let mut n = m.clone();
                        n.occ[cell as usize] = NO_UNIT;
                        n.occ[to as usize] = u;
                        n.units[u as usize].cell = to;
                        n.refresh();
                        if seen.insert(key(&n)) {
                            next.push(n);
                        }
                    }
                }
            }
        }
        layer = next;
    }
    None
}

#[test]
fn a_few_motions_repair_every_fault_position() {
    // The paper's "few steps" is what the geometry allows: 2.4 motions on average over the 10
    // positions, at most 4 (docs/models/fracta.md quotes these).
    let fewest: Vec<Option<usize>> = [0, 1, 2, 3, 4, 6, 7, 8, 9, 10]
        .into_iter()
        .map(|unit| fewest_motions(unit, 4))
        .collect();
    let expected = [0, 1, 3, 2, 3, 3, 2, 3, 4, 3].map(Some);
    assert_eq!(fewest, expected);
}
