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
        let theory = p * l * l * l / (3.0 * m.e * m.inertia);
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
