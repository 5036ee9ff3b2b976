//! The type graph (section 3.1): which types one motion of a neighbour links, and the distances
//! between types along those links.

use std::collections::BTreeSet;

use super::pattern::{far_steps, roll_ok, target_slot, Turn};

/// Axial offsets of the six directions (same as [`kumiki_model::lattice::Hex::AXIAL`]).
const AXIAL: [(i32, i32); 6] = kumiki_model::lattice::Hex::AXIAL;

fn axial_step((q, r): (i32, i32), d: usize) -> (i32, i32) {
    (q + AXIAL[d].0, r + AXIAL[d].1)
}

fn hex_distance((q, r): (i32, i32)) -> i32 {
    (q.abs() + r.abs() + (q + r).abs()) / 2
}

/// Every pair (pattern before, pattern after) of a unit that stays where it is while one other
/// unit makes one legal roll, enumerated over all 64 neighbourhoods of the unit.
///
/// The unit sits at the origin with neighbours `a`; the roller starts on a cell at distance 1 or
/// 2 (no other roll can touch the unit's neighbourhood) and rolls about an occupied neighbour,
/// by the model's own rule ([`roll_ok`] and a free [`far_steps`] cell). Every cell not named is
/// empty: more units could only forbid rolls, never allow new ones.
/// The roller's own before/after patterns are not pairs: where it lands decides its new type,
/// not its old one.
pub fn derive_links() -> BTreeSet<(u8, u8)> {
    let origin = (0, 0);
    let ring: Vec<(i32, i32)> = (0..6).map(|d| axial_step(origin, d)).collect();
    let mut cells: Vec<(i32, i32)> = Vec::new();
    for q in -2..=2 {
        for r in -2..=2 {
            let d = hex_distance((q, r));
            if d == 1 || d == 2 {
                cells.push((q, r));
            }
        }
    }
    let mut pairs = BTreeSet::new();
    for a in 0..64u8 {
        let mut base: BTreeSet<(i32, i32)> = BTreeSet::new();
        base.insert(origin);
        for (d, &c) in ring.iter().enumerate() {
            if a & (1 << d) != 0 {
                base.insert(c);
            }
        }
        for &p in &cells {
            let in_ring = ring.contains(&p);
            if in_ring && !base.contains(&p) {
                continue;
            }
            for pivot in 0..6 {
                let q = axial_step(p, pivot);
                if ring.contains(&q) && !base.contains(&q) {
                    continue;
                }
                let mut world = base.clone();
                world.insert(p);
                world.insert(q);
                let mask_of = |w: &BTreeSet<(i32, i32)>, c: (i32, i32)| -> u8 {
                    (0..6)
                        .filter(|&d| w.contains(&axial_step(c, d)))
                        .fold(0, |m, d| m | 1 << d)
                };
                let m = mask_of(&world, p);
                for turn in Turn::BOTH {
                    let [f1, f2] = far_steps(pivot, turn);
                    if !roll_ok(m, pivot, turn)
                        || world.contains(&axial_step(axial_step(p, f1), f2))
                    {
                        continue;
                    }
                    let t = axial_step(p, target_slot(pivot, turn));
                    let mut after = world.clone();
                    after.remove(&p);
                    after.insert(t);
                    pairs.insert((a, mask_of(&after, origin)));
                }
            }
        }
    }
    pairs
}
