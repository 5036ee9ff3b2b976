//! Building the L, the bounds on the step count and the gradient fields.

use super::*;

#[test]
fn builds_the_l_shape_with_every_field_and_rule() {
    for field in ["continuous", "discrete"] {
        for collision in ["token", "relay", "blackboard"] {
            let mut m = model(json!({"field": field, "collision": collision, "robots": 4}));
            run_to_end(&mut m, 20000);
            assert!(m.completed(), "{field} {collision}: {:?}", m.metrics());
            assert_eq!(m.placed, 18);
            assert_eq!(m.metrics()["built"], json!(1.0));
        }
    }
}

#[test]
fn total_steps_never_below_either_bound() {
    let t = "######\n######\n..##..\n..##..\n..##..\n";
    for target in [L, t] {
        for field in ["continuous", "discrete"] {
            for collision in ["token", "relay", "blackboard"] {
                for (seed, robots) in [(1, 1), (2, 2), (3, 5)] {
                    let mut s = scenario(json!({
                        "target": target, "field": field, "collision": collision,
                        "robots": robots, "seed": seed
                    }));
                    s.seed = seed;
                    let mut run = Run::new(s).unwrap();
                    run.run_to_end();
                    let m = run.outcome().metrics;
                    let total = m["total_steps"].as_u64().unwrap();
                    let lower = m["lower_bound"].as_u64().unwrap();
                    let path = m["path_bound"].as_u64().unwrap();
                    assert!(run.model().completed(), "{m:?}");
                    assert!(path >= lower, "{m:?}");
                    assert!(total >= path, "{field} {collision}: {m:?}");
                }
            }
        }
    }
}

#[test]
fn footnote_bound_is_as_written() {
    // One column of 3 above the supply, 2 robots: 2·(1+2+3) − 2·3.
    let m = model(json!({"target": "#\n#\n#\n", "robots": 1}));
    assert_eq!(m.lower_bound, 12 - 3);
    // The T's arms are further through the shape than straight down.
    let m = model(json!({"target": "###\n.#.\n", "robots": 1}));
    assert_eq!(m.lower_bound, 2 * (1 + 2 + 2 + 2) - 2);
    assert_eq!(m.path_bound, 2 * (1 + 2 + 3 + 3) - 3);
}

/// Breadth-first distances through communicating modules from the cells `source` accepts.
fn bfs(m: &Amas, source: impl Fn(u8) -> bool) -> Vec<u16> {
    let mut d = vec![FAR; m.state.len()];
    let mut q = VecDeque::new();
    for (i, di) in d.iter_mut().enumerate() {
        let s = m.state[i];
        if s & MODULE != 0 && source(s) {
            *di = 0;
            q.push_back(i);
        }
    }
    while let Some(i) = q.pop_front() {
        let (nb, k) = m.neighbours(i);
        for &j in &nb[..k] {
            if m.state[j] & MODULE != 0 && d[j] == FAR {
                d[j] = d[i] + 1;
                q.push_back(j);
            }
        }
    }
    d
}

#[test]
fn discrete_field_converges_to_breadth_first_distance() {
    for seed in 1..4 {
        let mut m = model(json!({"field": "discrete", "seed": seed, "field_updates_per_step": 1}));
        for _ in 0..25 {
            m.step();
        }
        for _ in 0..m.state.len() {
            m.field.update(&m.state, m.w, m.top);
        }
        let Field::Discrete {
            to_supply,
            to_front,
            ..
        } = &m.field
        else {
            unreachable!()
        };
        assert_eq!(to_supply, &bfs(&m, |s| s & SOURCE != 0));
        assert_eq!(to_front, &bfs(&m, |s| s & FRONT != 0));
    }
}

#[test]
fn continuous_field_on_a_strip_converges_to_the_linear_profile() {
    // A strip of 9 modules on one supply module; the top one is the growth front.
    let target = "#\n".repeat(10);
    let initial = "#\n".repeat(9);
    let mut m = model(json!({"target": target, "initial": initial, "robots": 1}));
    for _ in 0..5000 {
        m.field.update(&m.state, m.w, m.top);
    }
    let Field::Continuous { p, .. } = &m.field else {
        unreachable!()
    };
    // Row 10 is the supply (0), row 1 the growth front (1).
    for (y, &v) in p.iter().enumerate().skip(1) {
        let want = (10 - y) as f32 / 9.0;
        assert!((v - want).abs() < 1e-4, "row {y}: {v} vs {want}");
    }
    assert_eq!(p[10], 0.0);
    assert!(p[0] == 0.0 && m.state[0] & VACANT != 0);
}

#[test]
fn continuous_field_leaks_nothing_at_completed_edges() {
    // A wide block: at the steady state every row holds one value (no flux sideways).
    let target = "#####\n".repeat(6);
    let initial = "#####\n".repeat(5);
    let mut m = model(json!({"target": target, "initial": initial, "robots": 1}));
    for _ in 0..3000 {
        m.field.update(&m.state, m.w, m.top);
    }
    let Field::Continuous { p, .. } = &m.field else {
        unreachable!()
    };
    for y in 1..7 {
        let row = &p[y * 5..y * 5 + 5];
        assert!(
            row.iter().all(|&v| (v - row[0]).abs() < 1e-5),
            "row {y}: {row:?}"
        );
    }
}
