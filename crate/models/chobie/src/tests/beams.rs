//! The frame solver against beam theory.

use super::*;

fn mech() -> Mechanics {
    let s: spec::Spec = serde_json::from_value(json!({"world": "#\n="})).unwrap();
    Mechanics::from_spec(&s).unwrap()
}

/// A straight horizontal cantilever: a clamped robot and `n` robots beyond it.
fn cantilever(n: i32, m: &Mechanics, tip: f64, weight: bool) -> (frame::Solution, Vec<(u32, u32)>) {
    let pos: Vec<(i32, i32)> = (0..=n).map(|x| (x, 0)).collect();
    let elems = frame::elements(&pos, &|x, y| {
        (y == 0 && (0..=n).contains(&x)).then_some(x as u32)
    });
    let fixed: Vec<bool> = (0..=n).map(|x| x == 0).collect();
    let loads: Vec<[f64; 3]> = (0..=n)
        .map(|x| {
            let w = if weight { m.weight } else { 0.0 };
            [0.0, -(w + if x == n { tip } else { 0.0 }), 0.0]
        })
        .collect();
    (
        frame::solve(m, &pos, &elems, &fixed, &loads).unwrap(),
        elems,
    )
}

#[test]
fn tip_loaded_cantilever_matches_beam_theory() {
    let m = mech();
    let p = 50.0;
    for n in [1, 3, 8, 20] {
        let (sol, _) = cantilever(n, &m, p, false);
        let l = n as f64 * m.length;
        let root = sol.forces[0][1].abs();
        assert!(
            (root - p * l).abs() <= 1e-9 * p * l,
            "n = {n}: root moment {root} vs {}",
            p * l
        );
        let tip = -sol.disp[n as usize][1];
        // Timoshenko: bending P·L³/3EI plus shear P·L/(κ·G·A).
        let g = m.e / (2.0 * (1.0 + spec::POISSON));
        let theory = p * l * l * l / (3.0 * m.e * m.inertia)
            + p * l / (spec::SHEAR_COEFFICIENT * g * m.area);
        assert!(
            (tip - theory).abs() <= 1e-9 * theory,
            "n = {n}: tip {tip} vs {theory}"
        );
    }
}

#[test]
fn self_weight_root_moment_grows_with_the_square_of_the_length() {
    let m = mech();
    let root = |n| cantilever(n, &m, 0.0, true).0.forces[0][1].abs();
    for n in [5, 10, 20, 40] {
        // Exactly w·a·n(n + 1)/2 with nodal weights: ~ L² / 2 per unit length.
        let exact = m.weight * m.length * (n * (n + 1)) as f64 / 2.0;
        assert!((root(n) - exact).abs() <= 1e-9 * exact);
    }
    let ratio = root(80) / root(40);
    assert!(
        (ratio - 4.0).abs() < 0.06,
        "doubling the length multiplies the moment by {ratio}"
    );
}

#[test]
fn thickening_the_root_lowers_the_peak_stress() {
    let world = |top: &str| {
        model(
            &format!("{top}\n##########\n====......\n"),
            json!({"tip_load": 100.0}),
        )
        .peak()
    };
    let bare = world("..........");
    let thick = world("..###.....");
    // The peak moves to the end of the thickened part, one cell nearer the load.
    assert!(thick < 0.9 * bare, "bare {bare}, thickened {thick}");
}

#[test]
fn a_two_tier_cantilever_carries_the_root_moment_as_a_couple_of_its_tiers() {
    // Two tiers of n robots, the left column clamped, a load P on the lower tip.
    let m = mech();
    let (n, p) = (10, 50.0);
    let pos: Vec<(i32, i32)> = (0..=n).flat_map(|x| [(x, 0), (x, 1)]).collect();
    let at = |x: i32, y: i32| {
        ((0..=n).contains(&x) && (0..2).contains(&y)).then_some((2 * x + y) as u32)
    };
    let elems = frame::elements(&pos, &at);
    let fixed: Vec<bool> = pos.iter().map(|&(x, _)| x == 0).collect();
    let loads: Vec<[f64; 3]> = pos
        .iter()
        .map(|&(x, y)| [0.0, if (x, y) == (n, 1) { -p } else { 0.0 }, 0.0])
        .collect();
    let sol = frame::solve(&m, &pos, &elems, &fixed, &loads).unwrap();
    // The root elements of the two tiers: (0,0)-(1,0) and (0,1)-(1,1).
    let root = |y: i32| {
        let k = elems
            .iter()
            .position(|&e| e == (at(0, y).unwrap(), at(1, y).unwrap()))
            .unwrap();
        sol.forces[k]
    };
    let (top, bottom) = (root(0), root(1));
    // Statics, exact: equal and opposite axial forces, and their couple over one cell plus the
    // tiers' own end moments carry P·L.
    let l = n as f64 * m.length;
    assert!((top[0] + bottom[0]).abs() < 1e-9 * p);
    let carried = top[0].abs() * m.length + top[1].abs() + bottom[1].abs();
    assert!(
        (carried - p * l).abs() <= 1e-6 * p * l,
        "{carried} vs {}",
        p * l
    );
    // Most of it as the couple (a Vierendeel frame): the root stress is far below that of a
    // single tier, P·L·c/I.
    // Most of it as the couple (a Vierendeel frame; about 0.68 P·L here, the rest bends the
    // tiers between the verticals): the root stress is about a quarter of a single tier's.
    assert!(top[0].abs() * m.length > 0.6 * p * l);
    let peak = sol.stress.iter().copied().fold(0.0, f64::max);
    assert!(peak < 0.3 * p * l * m.fibre / m.inertia);
}
