//! Step phase 3: which motions are legal (section 3.1 and section 4's no-e rule) and which
//! one each active unit plans (section 3.2.4).

use kumiki_model::slot::{Slot, Stop};

use super::roll::{Candidate, Roll, Rolls, Senses};
use super::*;

/// The largest empty region, in cells, a motion is checked not to enclose.
const HOLE_REACH: usize = 7;

impl Fracta {
    /// Where the unit on `cell` with neighbours `mask` ends when it rolls about slot `pivot`, if
    /// it may. One 60° roll is legal by the rule of [`pattern::roll_ok`], with every swept cell
    /// inside the lattice and the far swept cell free (collision avoidance). With `avoid_e` the
    /// unit does not stop as an `e` (section 4): while the cell it reached touches no unit but
    /// the pivot, it rolls on about the same pivot, each 60° legal in the same way, and the
    /// motion is impossible if it would come round to where it started.
    pub(super) fn legal(&self, cell: u32, mask: u8, pivot: usize, turn: Turn) -> Option<u32> {
        let (mut at, mut mask, mut pivot) = (cell, mask, pivot);
        for _ in 0..5 {
            let target = self.roll_once(at, mask, pivot, turn)?;
            if !self.p.avoid_e {
                return self.leaves_no_hole(cell, target);
            }
            // Bonds at the target once the unit has left its starting cell.
            let there = self.ring_without(target, cell);
            if there.count_ones() >= 2 {
                return self.leaves_no_hole(cell, target);
            }
            // Seen from the target, the pivot sits one slot back against the turn.
            (at, mask, pivot) = (target, there, turn.back(pivot));
        }
        None
    }

    /// `Some(to)` unless the unit moving from `from` to `to` would enclose empty cells (with
    /// `no_holes`): the cell it leaves or an empty cell beside the one it reaches would then
    /// belong to an empty region of at most [`HOLE_REACH`] cells that does not reach the
    /// lattice's edge. No rule can open such a ring again (its units are never movable), so
    /// the low-level control does not close one. Larger regions count as open, as a unit's
    /// map of its surroundings is local.
    fn leaves_no_hole(&self, from: u32, to: u32) -> Option<u32> {
        if !self.p.no_holes {
            return Some(to);
        }
        let empty = |c: u32| c != to && (c == from || self.occ[c as usize] == NO_UNIT);
        let enclosed = |seed: u32| {
            let mut region = [NO_UNIT; HOLE_REACH];
            region[0] = seed;
            let (mut len, mut next) = (1, 0);
            while next < len {
                for &j in &self.nbr[region[next] as usize] {
                    if j == NO_UNIT {
                        return false;
                    }
                    if empty(j) && !region[..len].contains(&j) {
                        if len == HOLE_REACH {
                            return false;
                        }
                        region[len] = j;
                        len += 1;
                    }
                }
                next += 1;
            }
            true
        };
        let beside = self.nbr[to as usize]
            .iter()
            .any(|&c| c != NO_UNIT && empty(c) && enclosed(c));
        if beside || enclosed(from) {
            None
        } else {
            Some(to)
        }
    }

    /// The cell one legal 60° roll about slot `pivot` takes the unit on `at` (neighbours `mask`)
    /// to.
    pub(super) fn roll_once(&self, at: u32, mask: u8, pivot: usize, turn: Turn) -> Option<u32> {
        if !pattern::roll_ok(mask, pivot, turn) {
            return None;
        }
        let nb = &self.nbr[at as usize];
        if swept_slots(pivot, turn).iter().any(|&s| nb[s] == NO_UNIT) {
            return None;
        }
        let target = nb[target_slot(pivot, turn)];
        let [_, beyond] = far_steps(pivot, turn);
        let far = self.nbr[target as usize][beyond];
        if far == NO_UNIT || self.occ[far as usize] != NO_UNIT {
            return None;
        }
        Some(target)
    }

    /// How much the motion of unit `u` from `from` to `to` changes the summed difference of
    /// the working units: the change of those whose statement it changes. The bonds change for
    /// the mover and the units beside either end (their types may change), and the neighbour
    /// types change only for the units beside a unit whose type changed; every other unit,
    /// within two cells of the ends or farther, keeps its statement and its difference. This
    /// is the change of the whole system's summed difference, computed from what the units
    /// around the mover know.
    pub(super) fn change_after(&mut self, u: u32, from: u32, to: u32) -> i64 {
        let t = types();
        self.occ[from as usize] = NO_UNIT;
        self.occ[to as usize] = u;
        // The units whose bonds change (working or faulty: a faulty unit is still a
        // neighbour), with their type after the motion.
        let mut bonds = [(NO_UNIT, 0u8); 13];
        let mut n = 0;
        bonds[n] = (u, t.of(self.ring(to)));
        n += 1;
        for end in [from, to] {
            for &c in &self.nbr[end as usize] {
                if c == NO_UNIT {
                    continue;
                }
                let v = self.occ[c as usize];
                if v != NO_UNIT && !bonds[..n].iter().any(|b| b.0 == v) {
                    bonds[n] = (v, t.of(self.ring(c)));
                    n += 1;
                }
            }
        }
        let bonds = &bonds[..n];
        let class_of = |v: u32| {
            bonds
                .iter()
                .find(|b| b.0 == v)
                .map_or(self.class[v as usize], |b| b.1)
        };
        // The working units whose statement can change: those whose bonds change, and those
        // beside a unit whose type changed.
        let mut touched = std::mem::take(&mut self.touched);
        touched.clear();
        for &(v, class) in bonds {
            if self.units[v as usize].status == Status::Working && !touched.contains(&v) {
                touched.push(v);
            }
            if class == self.class[v as usize] {
                continue;
            }
            let cell = if v == u {
                to
            } else {
                self.units[v as usize].cell
            };
            for &c in &self.nbr[cell as usize] {
                if c == NO_UNIT {
                    continue;
                }
                let w = self.occ[c as usize];
                if w != NO_UNIT
                    && self.units[w as usize].status == Status::Working
                    && !touched.contains(&w)
                {
                    touched.push(w);
                }
            }
        }
        let mut change = 0i64;
        let mut nb = [0u8; 6];
        for &v in &touched {
            let cell = if v == u {
                to
            } else {
                self.units[v as usize].cell
            };
            let mut k = 0;
            for &c in &self.nbr[cell as usize] {
                if c != NO_UNIT && self.occ[c as usize] != NO_UNIT {
                    nb[k] = class_of(self.occ[c as usize]);
                    k += 1;
                }
            }
            nb[..k].sort_unstable();
            let after = self
                .goal
                .difference(&t.dist, class_of(v), &nb[..k], self.p.priorities)
                .difference;
            change += i64::from(after) - i64::from(self.diff[v as usize]);
        }
        self.occ[to as usize] = NO_UNIT;
        self.occ[from as usize] = u;
        self.touched = touched;
        change
    }

    /// Section 3.2.4: each active unit that has a legal roll picks one, or stays, by the slot
    /// `roll` (`roll.rs`). The paper's rule: clockwise or counter-clockwise, the direction that
    /// leaves the smaller difference around it being the likelier (Boltzmann weights at
    /// `temperature` of the change [`Self::change_after`]); a unit that equation 3 activated
    /// moves only when one of its directions lowers that difference (section 3.2 (iii): "it
    /// moves towards the direction to make it smaller"); a unit whose irritation fired moves
    /// whatever the change (condition 5 dissolves deadlocks, where no motion lowers it). A
    /// script in the slot that stops ends the phase where it stopped.
    pub(super) fn plan(&mut self) -> Result<(), Stop> {
        self.plans.clear();
        for k in 0..self.active.len() {
            let (u, irritated) = self.active[k];
            let cell = self.units[u as usize].cell;
            let mask = self.mask[u as usize];
            let mut plans = [Plan {
                unit: u,
                pivot: 0,
                pivot_slot: 0,
                turn: Turn::Ccw,
            }; 2];
            let mut options = Rolls::NONE;
            for pivot in 0..6 {
                for turn in Turn::BOTH {
                    if let Some(target) = self.legal(cell, mask, pivot, turn) {
                        let change = self.change_after(u, cell, target);
                        let n = options.as_slice().len();
                        if n < 2 {
                            let pivot_cell = self.nbr[cell as usize][pivot];
                            plans[n] = Plan {
                                unit: u,
                                pivot: self.occ[pivot_cell as usize],
                                pivot_slot: pivot as u8,
                                turn,
                            };
                            options.push(Candidate {
                                turn,
                                pivot: pivot as u8,
                                change,
                            });
                        }
                    }
                }
            }
            let n = options.as_slice().len();
            if n == 0 {
                continue;
            }
            let unit = Senses {
                options,
                irritated,
                temperature: self.p.temperature,
            };
            match self.roll.decide(&unit, Some(&mut self.rng))? {
                None => {}
                Some(i) if i < n => self.plans.push(plans[i]),
                Some(i) => {
                    return Err(Stop(format!(
                        "rule '{}' answered {i}; it must answer () or an index of its {n} rolls (0 to {})",
                        Roll::INFO.name,
                        n - 1
                    )))
                }
            }
        }
        Ok(())
    }
}
