//! The per-cell books every phase reads and keeps: each unit's difference D_0 (equation 4), the
//! set of units that may move, and moving a unit with everything that travels with it.

use super::spec::Ground;
use super::types::CODES;
use super::{Cubes, ARRIVED, HELD_LIT, HELD_USER, LEFT};
use kumiki_model::model::Event;

impl Cubes {
    /// Equation 4 for a unit whose type and sorted neighbour types are `prof`, against target
    /// `target`: the least weighted difference over its type-lists.
    pub(super) fn difference(&self, target: u8, prof: &[u8; 7]) -> f64 {
        let mut best = f64::INFINITY;
        for l in &self.targets[target as usize].lists {
            let mut s = self.w * self.table[l[0] as usize][prof[0] as usize];
            for n in 1..7 {
                s += self.table[l[n] as usize][prof[n] as usize];
            }
            if s < best {
                best = s;
            }
        }
        best
    }

    pub(super) fn z(&self, i: usize) -> i32 {
        let [w, h, _] = self.st.dims;
        (i / (w as usize * h as usize)) as i32
    }

    /// Fixed to the ground plane (section 6).
    pub(super) fn fixed(&self, i: usize) -> bool {
        self.ground == Ground::Fixed && self.z(i) == self.floor_z
    }

    /// May the unit at `i` be chosen to move?
    pub(super) fn eligible(&self, i: usize) -> bool {
        let t = self.st.types[i];
        t != 0
            && self.movable_types & (1 << t) != 0
            && self.flags[i] & (HELD_LIT | HELD_USER) == 0
            && !self.fixed(i)
    }

    /// Brings the unit at `i` into or out of the movable set.
    pub(super) fn refresh(&mut self, i: usize) {
        let want = self.eligible(i);
        let have = self.mpos[i] != u32::MAX;
        if want && !have {
            self.mpos[i] = self.movable.len() as u32;
            self.movable.push(i as u32);
        } else if !want && have {
            let k = self.mpos[i] as usize;
            let last = *self.movable.last().expect("the set holds i");
            self.movable.swap_remove(k);
            if last as usize != i {
                self.mpos[last as usize] = k as u32;
            }
            self.mpos[i] = u32::MAX;
        }
    }

    /// Recomputes D_0 of the unit at `i`, keeping the count of zeros.
    pub(super) fn rediff(&mut self, i: usize) {
        if !self.st.occupied(i) {
            return;
        }
        let new = self.difference(self.target[i], &self.st.profile(i));
        let k = self.upos[i] as usize;
        let old = self.diff[k];
        if old == 0.0 && new != 0.0 {
            self.zero -= 1;
        } else if old != 0.0 && new == 0.0 {
            self.zero += 1;
        }
        self.diff[k] = new;
    }

    /// D_0 of the unit at `i`.
    pub(super) fn d0(&self, i: usize) -> f64 {
        self.diff[self.upos[i] as usize]
    }

    pub(super) fn recompute_all(&mut self) {
        for k in 0..self.units.len() {
            let c = self.units[k] as usize;
            self.rediff(c);
            self.refresh(c);
        }
    }

    /// Bookkeeping after the units at or next to `cells` changed: D_0 within distance 2 (their
    /// own type or a neighbour's may have changed), membership within distance 1.
    pub(super) fn after_change(&mut self, cells: &[usize]) {
        for &c in cells {
            for k in 0..self.near2.len() {
                let x = (c as isize + self.near2[k]) as usize;
                self.rediff(x);
            }
        }
        for &c in cells {
            self.refresh(c);
            for d in 0..6 {
                let x = self.st.nb(c, d);
                self.refresh(x);
            }
        }
    }

    /// Takes the unit at `i` out of the books before it leaves its cell.
    pub(super) fn vacate(&mut self, i: usize) {
        let k = self.upos[i] as usize;
        if self.diff[k] == 0.0 {
            self.zero -= 1;
        }
        self.flags[i] = 0;
        self.target[i] = 0;
        self.upos[i] = u32::MAX;
        self.units.swap_remove(k);
        self.diff.swap_remove(k);
        self.stable.swap_remove(k);
        self.took.swap_remove(k);
        if k < self.units.len() {
            self.upos[self.units[k] as usize] = k as u32;
        }
    }

    pub(super) fn do_move(&mut self, from: usize, to: usize) {
        let flags = self.flags[from];
        let target = self.target[from];
        let k = self.upos[from];
        // Moving keeps the unit's place in the list (and its D_0 and count of stable steps with
        // it), so sums over units keep their order.
        if self.diff[k as usize] == 0.0 {
            self.zero -= 1;
        }
        self.diff[k as usize] = f64::NAN;
        self.flags[from] = 0;
        self.target[from] = 0;
        self.upos[from] = u32::MAX;
        self.units[k as usize] = to as u32;
        self.upos[to] = k;
        self.flags[to] = flags;
        self.target[to] = target;
        self.st.relocate(from, to);
        self.after_change(&[from, to]);
        self.moves += 1;
        if self.light.is_some() {
            let (a, b) = (self.along_light(from), self.along_light(to));
            self.moves_toward += u64::from(b > a);
            self.moves_away += u64::from(b < a);
        }
        self.events.push(Event {
            cell: to as u32,
            kind: ARRIVED,
        });
        self.events.push(Event {
            cell: from as u32,
            kind: LEFT,
        });
    }

    /// The sum of the units' D_0 in the order of `units`, read for the chart every step. When
    /// every D_0 is a whole number ([`whole_diffs`]) every partial sum is exact, so eight lanes
    /// added apart give the very same number as one chain of additions, in a fraction of the
    /// time: a chain of 1000 dependent additions was a tenth of a step of cubes-block1000.
    pub(super) fn total_difference(&self) -> f64 {
        if !self.whole_diffs || self.diff.len() < LANES {
            return self.diff.iter().sum();
        }
        let chunks = self.diff.chunks_exact(LANES);
        let rest: f64 = chunks.remainder().iter().sum();
        let lanes = chunks.fold([0.0; LANES], |mut acc, chunk| {
            for (a, d) in acc.iter_mut().zip(chunk) {
                *a += d;
            }
            acc
        });
        lanes.iter().sum::<f64>() + rest
    }
}

pub(super) const LANES: usize = 8;

/// Whether every D_0 a unit can have is a whole number with every sum of them exact: each entry
/// of the difference `table`, and each times `w` (the unit's own term), whole and at most 2^20,
/// so a D_0 (seven terms) is below 2^23 and a sum over fewer than 2^30 units below 2^53.
pub(super) fn whole_diffs(table: &[[f64; CODES]; CODES], w: f64) -> bool {
    let whole = |v: f64| v.fract() == 0.0 && v.abs() <= f64::from(1 << 20);
    table.iter().flatten().all(|&t| whole(t) && whole(w * t))
}
