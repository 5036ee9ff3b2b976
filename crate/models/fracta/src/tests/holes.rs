//! Holes: the cells a ring of units encloses.

use super::*;

#[test]
fn holes_count_the_cells_a_ring_encloses() {
    let ring = scenario(". # # .\n # . # .\n. # # .\n", TRIANGLE_GOAL, 1, json!({}));
    assert_eq!(Fracta::of_scenario(&ring).unwrap().holes(), 1);
    let full = scenario(TRIANGLE, TRIANGLE_GOAL, 1, json!({}));
    assert_eq!(Fracta::of_scenario(&full).unwrap().holes(), 0);
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
    let m = Fracta::of_scenario(&edge).unwrap();
    assert_eq!((m.holes(), holes_over_the_whole_lattice(&m)), (1, 1));
    let mut compared = 0;
    let mut with_holes = 0;
    for seed in 1..=40 {
        let mut s = presets::scenario("fracta-triangle10-3spares")
            .unwrap()
            .with_override("no_holes", json!(false))
            .unwrap();
        s.seed = seed;
        let mut m = Fracta::of_scenario(&s).unwrap();
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
