//! The shapes in which every unit matches a statement (the run's end) and those in which every
//! movable unit does (figure 4's deadlock), over every 11-cell polyhex: an exhaustive check
//! that the triangle with its spare is the only fixed point of its description, for the spare
//! beside a corner and in the middle of an edge.

use super::*;

/// The six axial neighbour offsets in cyclic order, so that bit d of a mask and bit d + 1 are
/// adjacent slots, as in the model's directions (a type is the same under every rotation and
/// reflection, so where the cycle starts does not matter).
const AXIAL: [(i32, i32); 6] = [(1, 0), (1, -1), (0, -1), (-1, 0), (-1, 1), (0, 1)];

/// What [`each_polyhex`] hands each polyhex to: its cells (axial) and an occupancy test.
type Visit<'a> = &'a mut dyn FnMut(&[(i32, i32)], &dyn Fn(i32, i32) -> bool);

/// Every fixed polyhex of `n` cells, each handed once to `visit` with an occupancy test, by
/// Redelmeier's method: the first cell is the lowest in (r, q) order, and cells are added only
/// above it or to its right in its row.
struct Polyhexes<'a> {
    n: usize,
    side: i32,
    /// Cells tried in this branch or a parent one (Redelmeier's "seen").
    seen: Vec<bool>,
    /// Cells of the polyhex being grown.
    occupied: Vec<bool>,
    cells: Vec<(i32, i32)>,
    /// The untried cells: those of a parent branch after the one it took, then the new ones.
    untried: Vec<(i32, i32)>,
    visit: Visit<'a>,
}

impl Polyhexes<'_> {
    fn index(&self, (q, r): (i32, i32)) -> usize {
        ((r + self.side) * (2 * self.side + 1) + q + self.side) as usize
    }

    fn grow(&mut self, from: usize) {
        let end = self.untried.len();
        for k in from..end {
            let c = self.untried[k];
            let i = self.index(c);
            self.cells.push(c);
            self.occupied[i] = true;
            if self.cells.len() == self.n {
                let (occupied, side) = (&self.occupied, self.side);
                let at = |q: i32, r: i32| {
                    q.abs() <= side
                        && r.abs() <= side
                        && occupied[((r + side) * (2 * side + 1) + q + side) as usize]
                };
                (self.visit)(&self.cells, &at);
            } else {
                for (dq, dr) in AXIAL {
                    let nb = (c.0 + dq, c.1 + dr);
                    let j = self.index(nb);
                    if (nb.1 > 0 || (nb.1 == 0 && nb.0 >= 0)) && !self.seen[j] {
                        self.seen[j] = true;
                        self.untried.push(nb);
                    }
                }
                self.grow(k + 1);
                for a in end..self.untried.len() {
                    let j = self.index(self.untried[a]);
                    self.seen[j] = false;
                }
                self.untried.truncate(end);
            }
            self.cells.pop();
            self.occupied[i] = false;
        }
    }
}

/// Calls `visit` for every fixed polyhex of `n` cells; returns how many there are.
fn each_polyhex(n: usize, visit: Visit<'_>) -> u64 {
    let side = n as i32;
    let cells = ((2 * side + 1) * (2 * side + 1)) as usize;
    let mut count = 0u64;
    let mut counting = |c: &[(i32, i32)], at: &dyn Fn(i32, i32) -> bool| {
        count += 1;
        visit(c, at);
    };
    let mut p = Polyhexes {
        n,
        side,
        seen: vec![false; cells],
        occupied: vec![false; cells],
        cells: Vec::new(),
        untried: vec![(0, 0)],
        visit: &mut counting,
    };
    let origin = p.index((0, 0));
    p.seen[origin] = true;
    p.grow(0);
    count
}

#[test]
fn the_enumeration_counts_the_fixed_polyhexes() {
    // OEIS A001207: fixed hexagonal polyominoes with n cells.
    let known = [1, 3, 11, 44, 186, 814, 3652, 16689];
    for (n, &want) in known.iter().enumerate() {
        assert_eq!(each_polyhex(n + 1, &mut |_, _| {}), want, "n = {}", n + 1);
    }
}

/// The type of the unit on each of `cells`.
fn classes(cells: &[(i32, i32)], at: &dyn Fn(i32, i32) -> bool) -> Vec<u8> {
    let t = types();
    cells
        .iter()
        .map(|&(q, r)| {
            let mask = AXIAL
                .iter()
                .enumerate()
                .filter(|(_, (dq, dr))| at(q + dq, r + dr))
                .fold(0u8, |m, (d, _)| m | 1 << d);
            t.of(mask)
        })
        .collect()
}

/// Whether the unit on each of `cells` (of types `own`) matches a statement of `goal` exactly.
fn matches(goal: &Goal, cells: &[(i32, i32)], own: &[u8]) -> Vec<bool> {
    let t = types();
    let class_at = |c: (i32, i32)| cells.iter().position(|&d| d == c).map(|k| own[k]);
    cells
        .iter()
        .zip(own)
        .map(|(&c, &class)| {
            let mut nb: Vec<u8> = AXIAL
                .iter()
                .filter_map(|(dq, dr)| class_at((c.0 + dq, c.1 + dr)))
                .collect();
            nb.sort_unstable();
            goal.difference(&t.dist, class, &nb, Priorities::Pooled)
                .difference
                == 0
        })
        .collect()
}

/// Whether the polyhex encloses an empty cell (a region that does not reach beyond its box).
fn enclosed(cells: &[(i32, i32)], at: &dyn Fn(i32, i32) -> bool) -> bool {
    let (q0, q1) = (
        cells.iter().map(|c| c.0).min().unwrap() - 1,
        cells.iter().map(|c| c.0).max().unwrap() + 1,
    );
    let (r0, r1) = (
        cells.iter().map(|c| c.1).min().unwrap() - 1,
        cells.iter().map(|c| c.1).max().unwrap() + 1,
    );
    let inside = |(q, r): (i32, i32)| q >= q0 && q <= q1 && r >= r0 && r <= r1;
    let mut seen = BTreeSet::from([(q0, r0)]);
    let mut stack = vec![(q0, r0)];
    while let Some((q, r)) = stack.pop() {
        for (dq, dr) in AXIAL {
            let n = (q + dq, r + dr);
            if inside(n) && !at(n.0, n.1) && seen.insert(n) {
                stack.push(n);
            }
        }
    }
    let empty = ((q1 - q0 + 1) * (r1 - r0 + 1)) as usize - cells.len();
    seen.len() < empty
}

/// Axial cells in a normal form shared by every rotation, reflection and translation.
pub(super) fn normal_form(cells: &[(i32, i32)]) -> Vec<(i32, i32)> {
    let normal = |cs: &[(i32, i32)]| -> Vec<(i32, i32)> {
        let q0 = cs.iter().map(|c| c.0).min().unwrap_or(0);
        let r0 = cs.iter().map(|c| c.1).min().unwrap_or(0);
        let mut out: Vec<(i32, i32)> = cs.iter().map(|&(q, r)| (q - q0, r - r0)).collect();
        out.sort_unstable();
        out
    };
    let mut best: Option<Vec<(i32, i32)>> = None;
    let mut cur = cells.to_vec();
    for _ in 0..2 {
        for _ in 0..6 {
            let n = normal(&cur);
            if best.as_ref().is_none_or(|b| n < *b) {
                best = Some(n);
            }
            cur = cur.iter().map(|&(q, r)| (-r, q + r)).collect();
        }
        cur = cur.iter().map(|&(q, r)| (q + r, -r)).collect();
    }
    best.unwrap_or_default()
}

/// A preset's start shape in the normal form.
fn preset_shape(name: &str) -> Vec<(i32, i32)> {
    let m = Fracta::of_scenario(&presets::scenario(name).unwrap()).unwrap();
    let cells: Vec<(i32, i32)> = m
        .working
        .iter()
        .map(|&u| Hex::to_axial(m.lattice.coord(m.units[u as usize].cell as usize)))
        .collect();
    normal_form(&cells)
}

fn goal_of(name: &str) -> Goal {
    let s = presets::scenario(name).unwrap();
    Goal::parse(s.body()["goal"].as_str().unwrap()).unwrap()
}

#[test]
fn each_spares_description_has_one_fixed_point_of_eleven_units() {
    // The run's end is a shape in which every unit matches a statement exactly: over every
    // 11-cell polyhex, the only one for either reading of the spare's place is the triangle
    // with its spare. Figure 4's deadlock is a shape without an enclosed cell in which every
    // movable unit, and not every unit, does.
    let t = types();
    let readings = [("fracta-repair-corner", 1), ("fracta-repair", 3)];
    let goals: Vec<(Goal, Vec<bool>)> = readings
        .iter()
        .map(|r| {
            let goal = goal_of(r.0);
            let mut own = vec![false; CLASSES];
            for s in goal.statements() {
                own[s.unit as usize] = true;
            }
            (goal, own)
        })
        .collect();
    let mut ends: Vec<BTreeSet<Vec<(i32, i32)>>> = vec![BTreeSet::new(); goals.len()];
    let mut stuck: Vec<BTreeSet<Vec<(i32, i32)>>> = vec![BTreeSet::new(); goals.len()];
    let total = each_polyhex(11, &mut |cells, at| {
        let own = classes(cells, at);
        let movable = |c: &u8| t.info[*c as usize].movable;
        for (k, (goal, types_of)) in goals.iter().enumerate() {
            if !own
                .iter()
                .filter(|c| movable(c))
                .all(|&c| types_of[c as usize])
            {
                continue;
            }
            let m = matches(goal, cells, &own);
            if own.iter().zip(&m).any(|(c, &zero)| movable(c) && !zero) {
                continue;
            }
            if m.iter().all(|&zero| zero) {
                ends[k].insert(normal_form(cells));
            } else if own.iter().any(movable) && !enclosed(cells, at) {
                stuck[k].insert(normal_form(cells));
            }
        }
    });
    assert_eq!(total, 1_716_033);
    for (k, &(done, deadlocks)) in readings.iter().enumerate() {
        assert_eq!(
            ends[k].iter().collect::<Vec<_>>(),
            vec![&preset_shape(done)],
            "{done}"
        );
        assert_eq!(stuck[k].len(), deadlocks, "{done}");
        assert!(
            stuck[k].contains(&preset_shape("fracta-deadlock")),
            "{done}"
        );
    }
}

#[test]
fn with_the_spare_in_the_middle_of_an_edge_some_deadlocks_cycle_by_symmetry() {
    // From figure 4's deadlock, a run that does not reach the goal ends in another deadlock
    // of the middle-of-an-edge description: every movable unit matches a statement, and the
    // shape is the same turned half round, so symmetric units' irritation fires together and
    // their rolls mirror each other (crate/models/fracta/README.md, "Beside the paper").
    let t = types();
    let mut cycling = 0;
    for seed in 1..=10 {
        let mut s = presets::scenario("fracta-deadlock").unwrap();
        s.seed = seed;
        let mut m = Fracta::of_scenario(&s).unwrap();
        while !m.completed() && m.steps < 2000 {
            m.step();
        }
        if m.completed() {
            continue;
        }
        cycling += 1;
        let cells: Vec<(i32, i32)> = m
            .working
            .iter()
            .map(|&u| Hex::to_axial(m.lattice.coord(m.units[u as usize].cell as usize)))
            .collect();
        let turned: Vec<(i32, i32)> = cells.iter().map(|&(q, r)| (-q, -r)).collect();
        assert_eq!(translated(&cells), translated(&turned));
        assert!(m.working.iter().all(|&u| {
            m.diff[u as usize] == 0 || !t.info[m.class[u as usize] as usize].movable
        }));
    }
    assert!(cycling > 0);
}

/// Axial cells moved so that their smallest q and r are 0, sorted.
fn translated(cells: &[(i32, i32)]) -> Vec<(i32, i32)> {
    let q0 = cells.iter().map(|c| c.0).min().unwrap_or(0);
    let r0 = cells.iter().map(|c| c.1).min().unwrap_or(0);
    let mut out: Vec<(i32, i32)> = cells.iter().map(|&(q, r)| (q - q0, r - r0)).collect();
    out.sort_unstable();
    out
}
