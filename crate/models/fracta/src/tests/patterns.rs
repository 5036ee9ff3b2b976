//! Pattern types, their letters, rolling and the type graph.

use super::*;

#[test]
fn every_pattern_has_exactly_one_type_and_symmetry_keeps_it() {
    let t = types();
    assert_eq!(t.info.len(), CLASSES);
    assert_eq!(t.of(0), NONE_CLASS);
    let mut used = BTreeSet::new();
    for m in 1..64u8 {
        let c = t.of(m);
        assert!((1..CLASSES as u8).contains(&c), "mask {m:06b} has no type");
        used.insert(c);
        for image in images(m) {
            assert_eq!(t.of(image), c, "{m:06b} and its image {image:06b}");
        }
        assert_eq!(t.of(rotate(m, 1)), c);
        assert_eq!(t.of(reflect(m)), c);
        assert_eq!(t.info[c as usize].bonds as u32, m.count_ones());
    }
    assert_eq!(used.len(), 12, "the paper counts 12 connection types");
    // Two masks share a type exactly when a symmetry maps one onto the other.
    for a in 1..64u8 {
        for b in 1..64u8 {
            assert_eq!(t.of(a) == t.of(b), images(a).contains(&b));
        }
    }
    // Rotations are turns of 60° counter-clockwise: bit d moves to d + 1.
    assert_eq!(rotate(0b000001, 1), 0b000010);
    assert_eq!(rotate(0b100000, 1), 0b000001);
    assert_eq!(reflect(0b000010), 0b100000);
    assert_eq!(canonical(0b110000), 0b000011);
}

const NONE_CLASS: u8 = types::NONE;

#[test]
fn the_papers_letters_name_the_shapes_its_text_describes() {
    let t = types();
    // e: one bond. o: the triangle's corners, two neighbours side by side. K: the triangle's
    // edge units, four side by side. s: the centre, six. ε: three side by side (movable).
    assert_eq!(t.name(t.of(mask_of(&[2]))), "e");
    assert_eq!(t.name(t.of(mask_of(&[4, 5]))), "o");
    assert_eq!(t.name(t.of(mask_of(&[0, 1, 2]))), "ε");
    assert_eq!(t.name(t.of(mask_of(&[4, 5, 0, 1]))), "K");
    assert_eq!(t.name(t.of(63)), "s");
    let names: BTreeSet<&str> = t.info.iter().map(|i| i.name).collect();
    assert_eq!(names.len(), CLASSES, "names are distinct");
    let ascii: BTreeSet<&str> = t.info.iter().map(|i| i.ascii).collect();
    assert_eq!(ascii.len(), CLASSES, "ASCII spellings are distinct");
    for (c, info) in t.info.iter().enumerate().skip(1) {
        assert_eq!(t.parse(info.name), Some(c as u8));
        assert_eq!(t.parse(info.ascii), Some(c as u8));
        assert_eq!(t.parse(&info.ascii.to_ascii_uppercase()), Some(c as u8));
    }
    assert_eq!(t.parse("none"), None);
    let paper: Vec<&str> = t.info.iter().filter(|i| i.paper).map(|i| i.name).collect();
    assert_eq!(paper, ["e", "o", "ε", "K", "s"]);
}

#[test]
fn movable_types_are_e_o_and_epsilon() {
    // Section 3.1: "A unit with connection type e, o, or ε is movable."
    let t = types();
    let movable: Vec<&str> = t
        .info
        .iter()
        .filter(|i| i.movable)
        .map(|i| i.name)
        .collect();
    assert_eq!(movable, ["e", "o", "ε"]);
    // A movable unit has exactly two rolls: clockwise and counter-clockwise.
    for m in 1..64u8 {
        let rolls: usize = (0..6)
            .map(|p| {
                Turn::BOTH
                    .iter()
                    .filter(|&&tu| pattern::roll_ok(m, p, tu))
                    .count()
            })
            .sum();
        let expect = if t.info[t.of(m) as usize].movable {
            2
        } else {
            0
        };
        assert_eq!(rolls, expect, "mask {m:06b}");
    }
}

/// Pointy-top hexagon of inradius 1/2 around a centre.
fn hexagon(cx: f64, cy: f64) -> Vec<(f64, f64)> {
    let r = 1.0 / 3f64.sqrt();
    (0..6)
        .map(|k| {
            let a = (30.0 + 60.0 * k as f64).to_radians();
            (cx + r * a.cos(), cy + r * a.sin())
        })
        .collect()
}

/// Separating-axis test for convex polygons, ignoring contact along edges (`gap`).
fn overlap(a: &[(f64, f64)], b: &[(f64, f64)], gap: f64) -> bool {
    for poly in [a, b] {
        for i in 0..poly.len() {
            let (x1, y1) = poly[i];
            let (x2, y2) = poly[(i + 1) % poly.len()];
            let (nx, ny) = (y2 - y1, x1 - x2);
            let len = (nx * nx + ny * ny).sqrt();
            let project = |p: &[(f64, f64)]| {
                p.iter()
                    .map(|&(x, y)| (x * nx + y * ny) / len)
                    .fold((f64::MAX, f64::MIN), |(lo, hi), v| (lo.min(v), hi.max(v)))
            };
            let (alo, ahi) = project(a);
            let (blo, bhi) = project(b);
            if ahi <= blo + gap || bhi <= alo + gap {
                return false;
            }
        }
    }
    true
}

#[test]
fn rolling_sweeps_exactly_the_cells_the_rule_keeps_free() {
    // A unit rolls about the vertex it shares with the pivot and the target cell; the cells its
    // hexagon passes over must be the three of `swept_slots`, whatever the pivot and turn.
    let lattice = Hex::new(12, 12);
    for start in [Coord::xy(5, 5), Coord::xy(5, 6)] {
        let p = lattice.index(start).unwrap();
        let (px, py) = Hex::centre(start);
        for pivot in 0..6 {
            for turn in Turn::BOTH {
                let q = Hex::centre(lattice.coord(lattice.neighbour(p, pivot).unwrap()));
                let target = lattice.neighbour(p, target_slot(pivot, turn)).unwrap();
                let tc = Hex::centre(lattice.coord(target));
                let w = ((px + q.0 + tc.0) / 3.0, (py + q.1 + tc.1) / 3.0);
                let rot = |(x, y): (f64, f64), a: f64| {
                    let (s, c) = a.sin_cos();
                    let (dx, dy) = (x - w.0, y - w.1);
                    (w.0 + c * dx - s * dy, w.1 + s * dx + c * dy)
                };
                // The sense of rotation that carries the unit onto the target.
                let sign = [1.0, -1.0]
                    .into_iter()
                    .find(|&sg: &f64| {
                        let (x, y) = rot((px, py), sg * 120f64.to_radians());
                        (x - tc.0).abs() < 1e-9 && (y - tc.1).abs() < 1e-9
                    })
                    .expect("a 120° turn about the shared vertex lands on the target");
                let mut swept = BTreeSet::new();
                for k in 1..=240 {
                    let a = sign * (120.0 * k as f64 / 240.0).to_radians();
                    let moving: Vec<(f64, f64)> =
                        hexagon(px, py).into_iter().map(|v| rot(v, a)).collect();
                    for c in 0..lattice.len() {
                        if c == p {
                            continue;
                        }
                        let cc = lattice.coord(c);
                        let (cx, cy) = Hex::centre(cc);
                        if ((cx - px).powi(2) + (cy - py).powi(2)).sqrt() > 3.5 {
                            continue;
                        }
                        if overlap(&moving, &hexagon(cx, cy), 1e-6) {
                            swept.insert(c);
                        }
                    }
                }
                let mut expect: BTreeSet<usize> = swept_slots(pivot, turn)
                    .iter()
                    .map(|&s| lattice.neighbour(p, s).unwrap())
                    .collect();
                let [a, b] = pattern::far_steps(pivot, turn);
                expect.insert(
                    lattice
                        .neighbour(lattice.neighbour(p, a).unwrap(), b)
                        .unwrap(),
                );
                assert_eq!(swept, expect, "start {start:?} pivot {pivot} {turn:?}");
            }
        }
    }
}

#[test]
fn the_type_graph_links_one_bond_gained_lost_or_shifted() {
    let t = types();
    // What one roll of a neighbour can do to a unit that stays: gain a bond, lose one, or have
    // one slide 60° to a free slot. Computed here by bit arithmetic, independently of the
    // geometric enumeration the model uses.
    let mut expect = BTreeSet::new();
    for a in 0..64u8 {
        for d in 0..6 {
            let b = a ^ (1 << d);
            expect.insert((t.of(a).min(t.of(b)), t.of(a).max(t.of(b))));
            if a & (1 << d) != 0 {
                for e in [(d + 1) % 6, (d + 5) % 6] {
                    if a & (1 << e) == 0 {
                        let b = (a & !(1 << d)) | 1 << e;
                        expect.insert((t.of(a).min(t.of(b)), t.of(a).max(t.of(b))));
                    }
                }
            }
        }
    }
    expect.retain(|(a, b)| a != b);
    assert_eq!(t.links, expect);
    for a in 0..CLASSES {
        for b in 0..CLASSES {
            assert_eq!(t.dist[a][b], t.dist[b][a]);
            assert!(t.dist[a][b] < u8::MAX, "{a} and {b} are not connected");
            assert_eq!(t.dist[a][b] == 0, a == b);
        }
        // A missing neighbour is a unit with no bonds: as far from a type as its bond count.
        assert_eq!(t.dist[0][a], t.info[a].bonds);
    }
    let d = |a: &str, b: &str| t.dist[class_named(a) as usize][class_named(b) as usize];
    assert_eq!(d("e", "s"), 5);
    assert_eq!(d("o", "v"), 1);
    assert_eq!(d("o", "i"), 2);
    assert_eq!(d("o", "K"), 2);
    assert_eq!(d("eps", "K"), 1);
}
