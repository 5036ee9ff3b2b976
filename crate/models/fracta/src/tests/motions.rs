//! Motions: the fewest that repair each fault, what one motion changes, and which units equation 3
//! lets move.

use super::*;

#[test]
fn a_few_motions_repair_every_fault_position() {
    // The paper's "few steps" is what the geometry allows: with the spare in the middle of an
    // edge, 2.0 motions on average over the 10 positions; beside a corner 2.4, at most 4
    // (crate/models/fracta/README.md quotes these).
    for (spare, expected) in [
        (Spare::Edge, [1, 2, 3, 0, 3, 3, 2, 3, 2, 1]),
        (Spare::Corner, [0, 1, 3, 2, 3, 3, 2, 3, 4, 3]),
    ] {
        let fewest: Vec<Option<usize>> = [0, 1, 2, 3, 4, 6, 7, 8, 9, 10]
            .into_iter()
            .map(|unit| search::fewest_repair_motions(spare, unit, 4))
            .collect();
        assert_eq!(fewest, expected.map(Some), "{spare:?}");
    }
}

/// The summed difference of every working unit.
fn total_difference(m: &Fracta) -> i64 {
    m.working
        .iter()
        .map(|&u| i64::from(m.diff[u as usize]))
        .sum()
}

#[test]
fn a_motion_changes_the_summed_difference_only_within_two_cells_of_its_ends() {
    // What a unit weighs its directions by (interpretation 21) is computed from the units
    // within two cells of where it starts and lands; it is the change of the whole system's
    // summed difference, for every legal motion along seeded runs.
    let mut checked = 0;
    for (preset, seed) in [
        ("fracta-triangle10", 1),
        ("fracta-triangle10", 2),
        ("fracta-triangle10-3spares", 3),
        ("fracta-hexagon7", 4),
    ] {
        let mut s = presets::scenario(preset).unwrap();
        s.seed = seed;
        let mut m = Fracta::of_scenario(&s).unwrap();
        for _ in 0..30 {
            let before = total_difference(&m);
            for u in m.working.clone() {
                let cell = m.units[u as usize].cell;
                for pivot in 0..6 {
                    for turn in Turn::BOTH {
                        let Some(to) = m.legal(cell, m.mask[u as usize], pivot, turn) else {
                            continue;
                        };
                        let local = m.change_after(u, cell, to);
                        let mut n = m.clone();
                        n.occ[cell as usize] = NO_UNIT;
                        n.occ[to as usize] = u;
                        n.units[u as usize].cell = to;
                        n.refresh();
                        assert_eq!(local, total_difference(&n) - before, "{preset} seed {seed}");
                        checked += 1;
                    }
                }
            }
            m.step();
        }
    }
    assert!(checked > 500, "{checked} motions checked");
}

#[test]
fn only_irritation_moves_a_unit_that_no_direction_improves() {
    // Equation 3 activates a unit; it rolls only when one of its directions lowers the
    // difference around it, and then picks between its two by their Boltzmann weights. Units
    // whose irritation fired roll whatever the change (the deadlock needs them to).
    let (mut gated, mut free) = (0, 0);
    for seed in 1..=20 {
        let mut s = presets::scenario("fracta-triangle10").unwrap();
        s.seed = seed;
        let mut m = Fracta::of_scenario(&s).unwrap();
        while m.steps < 300 && !m.completed() {
            m.events.clear();
            m.cut_off_faulty();
            m.diffuse().unwrap();
            m.plan().unwrap();
            for plan in &m.plans {
                let (_, irritated) = *m.active.iter().find(|a| a.0 == plan.unit).unwrap();
                let cell = m.units[plan.unit as usize].cell;
                let mask = m.mask[plan.unit as usize];
                assert!(m
                    .legal(cell, mask, plan.pivot_slot as usize, plan.turn)
                    .is_some());
                let mut probe = m.clone();
                let best = (0..6)
                    .flat_map(|pivot| Turn::BOTH.map(|turn| (pivot, turn)))
                    .filter_map(|(pivot, turn)| m.legal(cell, mask, pivot, turn))
                    .map(|to| probe.change_after(plan.unit, cell, to))
                    .min()
                    .unwrap();
                if irritated {
                    free += 1;
                } else {
                    assert!(
                        best < 0,
                        "seed {seed}: equation 3 rolled a unit none of whose rolls lowers the difference ({best})"
                    );
                    gated += 1;
                }
            }
            m.commit();
            m.refresh();
            m.steps += 1;
        }
    }
    assert!(
        gated > 50 && free > 50,
        "{gated} by equation 3, {free} by irritation"
    );
}

#[test]
fn after_a_corner_fault_the_spare_moves_at_once() {
    // Fault on unit 7 (crate/models/fracta/README.md, "Beside the paper"): the spare is the only unit
    // with a roll that lowers the difference around it. The cut-off leaves x at the finished
    // triangle's 0 and raises the spare's difference, so equation 3 activates it in the
    // cut-off's own step, and the two motions the search finds are the two the run makes.
    let mut s = presets::scenario("fracta-repair-corner").unwrap();
    s.disturbances[0].action.insert("unit".into(), json!(7));
    let mut m = Fracta::of_scenario(&s).unwrap();
    m.apply(&s.disturbances[0].action).unwrap();
    m.cut_off_faulty();
    let improving = search::improving_units(&m);
    assert_eq!(improving, vec![0]);
    m.diffuse().unwrap();
    assert!(m.active.contains(&(0, false)), "{:?}", m.active);
    m.plan().unwrap();
    assert_eq!(m.plans.iter().map(|p| p.unit).collect::<Vec<_>>(), vec![0]);
    m.commit();
    m.refresh();
    m.steps += 1;
    while !m.completed() && m.steps < 50 {
        m.step();
    }
    assert!(m.completed());
    assert_eq!((m.steps, m.moves), (2, 2));
    assert_eq!(search::fewest_repair_motions(Spare::Corner, 7, 4), Some(2));
}

#[test]
fn irritation_grows_only_while_a_units_difference_stays() {
    // The fault on unit 4 leaves no motion that lowers the summed difference: only irritation
    // can move a unit. In the cut-off's own step the differences around the hole change, so
    // no unit's irritation grows; from the next step on, the units whose difference stays grow
    // theirs while x is stable (equation 4), and irritation makes the first motion.
    let mut s = presets::scenario("fracta-repair-corner").unwrap();
    s.disturbances[0].action.insert("unit".into(), json!(4));
    let mut m = Fracta::of_scenario(&s).unwrap();
    m.apply(&s.disturbances[0].action).unwrap();
    m.decide().unwrap();
    assert!(m.working.iter().any(|&u| m.diff[u as usize] > 0));
    assert!(m.working.iter().all(|&u| m.units[u as usize].irr == 0.0));
    m.act();
    let before: Vec<u32> = m.diff.clone();
    m.decide().unwrap();
    let grew: Vec<u32> = m
        .working
        .iter()
        .copied()
        .filter(|&u| m.units[u as usize].irr > 0.0)
        .collect();
    assert!(!grew.is_empty());
    assert!(grew
        .iter()
        .all(|&u| m.diff[u as usize] == before[u as usize]));
    let first = search::first_motion_after_fault(Spare::Corner, 4, 50).unwrap();
    assert!(
        first.improving.is_empty() && first.by_irritation,
        "{first:?}"
    );
}

#[test]
fn the_report_reads_what_a_repair_waits_for() {
    // The apex and the corner faults: the spare beside the hole improves, and equation 3 moves
    // it in the cut-off's own step.
    for unit in [1, 7] {
        let first = search::first_motion_after_fault(Spare::Corner, unit, 50).unwrap();
        assert!(first.improving.contains(&0), "{first:?}");
        assert!(
            first.improving_activated && !first.by_irritation && first.wait == 0,
            "{first:?}"
        );
    }
    // The traces count every step of every run, and the steps are the run's repair time.
    let trace = search::trace_repairs(Spare::Corner, 7, 1..=3, 5000).unwrap();
    let mut steps = 0;
    for seed in 1..=3 {
        let mut s = presets::scenario("fracta-repair-corner").unwrap();
        s.seed = seed;
        s.disturbances[0].action.insert("unit".into(), json!(7));
        let mut run = Run::new(s).unwrap();
        run.run_to_end();
        steps += run.outcome().metrics["repair_steps"].as_u64().unwrap();
    }
    assert_eq!((trace.runs, trace.unfinished, trace.steps), (3, 0, steps));
    assert_eq!((trace.held, trace.stuck, trace.together_worse), (0, 0, 0));
}

#[test]
fn the_assembly_from_two_lines_starts_by_equation_3_and_waited_under_version_6s_leak() {
    // At the two-line start the units with a roll that lowers the summed difference are the
    // line ends, the only movable units. With L = 0.3 the leak keeps their x below their
    // difference and equation 3 moves them at once; with version 6's L = 0.05 and the spare
    // beside a corner, their neighbours' flux lifted x above it, and the first motion waited
    // for irritation, the same in every seed.
    for spare in Spare::BOTH {
        let now = search::first_motion_of_assembly(spare, &[], 50).unwrap();
        assert_eq!(now.improving, [0, 5, 6, 10], "the line ends");
        assert!(
            now.improving_activated && !now.by_irritation && now.wait <= 1,
            "{spare:?} {now:?}"
        );
        let old = search::first_motion_of_assembly(spare, &[("L", json!(0.05))], 50).unwrap();
        match spare {
            // Version 6's dead start: every line end had difference 1.
            Spare::Corner => assert!(
                !old.improving_activated && old.by_irritation && old.wait >= 8,
                "{old:?}"
            ),
            // The ε line ends have difference 3 against these statements, and equation 3
            // moves them at once even with the smaller leak.
            Spare::Edge => assert!(
                old.improving_activated && !old.by_irritation && old.wait <= 1,
                "{old:?}"
            ),
        }
    }
}
