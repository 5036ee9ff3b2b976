//! Rule 4 of the pairwise motion (see [`super::motion`]): does the structure stay connected when
//! a unit is lifted out and its carrier lets go of every bond off its axis? And the positions a
//! unit can reach by moves that keep all four rules ([`Structure::reachable`]).
//!
//! A search limited to the 5×5×5 cells around the carrier settles almost every case (short
//! cycles); only when it cannot join all the released units does a search over the structure
//! run, from every released unit at once, stopping as soon as they meet or one side is
//! exhausted, so a move that would split off a small piece costs the size of that piece.

use super::motion::{Move, Structure};

/// Cells of the 5×5×5 box of the local connectivity search (bit x + 5y + 25z) with x = 0,
/// x = 4, y = 0 and y = 4: a shift along x or y must not carry a bit into the next row.
const BOX_X0: u128 = box_plane(1, 0);
const BOX_X4: u128 = box_plane(1, 4);
const BOX_Y0: u128 = box_plane(5, 0);
const BOX_Y4: u128 = box_plane(5, 4);

/// The step in box bits along each direction (in the order of [`DIRS`]).
const BOX_STEP: [i32; 6] = [1, -1, 5, -5, 25, -25];

/// The box cell `b` alone (without a 128-bit shift by a variable amount, which wasm lacks).
#[inline]
fn one(b: u32) -> u128 {
    if b < 64 {
        u128::from(1u64 << b)
    } else {
        u128::from(1u64 << (b - 64)) << 64
    }
}

const fn box_plane(stride: u32, at: u32) -> u128 {
    let mut m = 0u128;
    let mut i = 0;
    while i < 125 {
        if (i / stride) % 5 == at {
            m |= 1 << i;
        }
        i += 1;
    }
    m
}

/// Reusable buffers for the connectivity searches, and counters of how they went.
///
/// A copy (a keyframe of the run) keeps the counters and starts with empty buffers: they hold
/// nothing between checks, and are sized again on first use.
#[derive(Default)]
pub struct Scratch {
    seen: Vec<u32>,
    gen: u32,
    label: Vec<u8>,
    queues: Vec<Vec<u32>>,
    heads: Vec<usize>,
    parent: Vec<u8>,
    terminals: Vec<u32>,
    pub moves: Vec<Move>,
    /// Connectivity checks made.
    pub checks: u64,
    /// Checks the local search could not settle.
    pub searches: u64,
    /// Cells visited by those searches.
    pub search_cells: u64,
}

impl Clone for Scratch {
    fn clone(&self) -> Scratch {
        Scratch {
            checks: self.checks,
            searches: self.searches,
            search_cells: self.search_cells,
            ..Scratch::default()
        }
    }
}

impl Scratch {
    fn next_gen(&mut self, len: usize) -> u32 {
        if self.seen.len() != len {
            self.seen = vec![0; len];
            self.label = vec![0; len];
            self.gen = 0;
        }
        if self.gen == u32::MAX {
            self.seen.iter_mut().for_each(|s| *s = 0);
            self.gen = 0;
        }
        self.gen += 1;
        self.gen
    }
}

impl Structure {
    /// The reachable positions of the unit at `p` (rules 1 to 5 of [`super::motion`]), in
    /// a fixed order: carriers by direction from p, then axes, then senses. Left in `s.moves`.
    pub fn reachable(&self, p: usize, s: &mut Scratch) {
        s.moves.clear();
        if !self.plane_holds(p) {
            return;
        }
        let mut pending = [0u32; 2];
        for k in 0..6 {
            let q = self.nb(p, k);
            if !self.occupied(q) {
                continue;
            }
            // The cells around this carrier, read once for its axes.
            let mut around = None;
            let bond_axis = k / 2;
            for a in 0..3 {
                if a == bond_axis {
                    continue;
                }
                if !self.supported(q, a) {
                    continue;
                }
                let b = 3 - bond_axis - a;
                let mut n = 0;
                for f in [2 * b, 2 * b + 1] {
                    let dest = self.nb(q, f);
                    if self.wall[dest] || self.occupied(dest) || self.occupied(self.nb(p, f)) {
                        continue;
                    }
                    pending[n] = dest as u32;
                    n += 1;
                }
                if n > 0 && self.stays_connected_around(p, Some((q, a)), s, &mut around) {
                    for &dest in &pending[..n] {
                        s.moves.push(Move {
                            dest,
                            carrier: q as u32,
                            axis: a as u8,
                        });
                    }
                }
            }
        }
    }

    /// Is the edge from `x` in direction `dir` usable once `p` is lifted and, with a carrier
    /// `(q, a)`, q has let go of every bond off the axis `a`?
    #[inline]
    fn usable(
        &self,
        x: usize,
        dir: usize,
        p: usize,
        carrier: Option<(usize, usize)>,
    ) -> Option<usize> {
        let y = self.nb(x, dir);
        if y == p || !self.occupied(y) {
            return None;
        }
        if let Some((q, a)) = carrier {
            if (x == q || y == q) && dir / 2 != a {
                return None;
            }
        }
        Some(y)
    }

    /// Does the structure stay connected when the unit at `p` is lifted out and, if a carrier
    /// `(q, a)` is given, q lets go of its bonds off the axis `a`? Exact.
    ///
    /// Every piece the cut could leave holds a neighbour of p or a unit q let go of (or q itself),
    /// so the structure stays connected exactly when those "terminals" stay joined.
    pub fn stays_connected(
        &self,
        p: usize,
        carrier: Option<(usize, usize)>,
        s: &mut Scratch,
    ) -> bool {
        self.stays_connected_around(p, carrier, s, &mut None)
    }

    /// [`Structure::stays_connected`] with the occupied cells of the box around the carrier (or
    /// p) in `around` once read, for the next check around the same centre.
    fn stays_connected_around(
        &self,
        p: usize,
        carrier: Option<(usize, usize)>,
        s: &mut Scratch,
        around: &mut Option<u128>,
    ) -> bool {
        s.checks += 1;
        s.terminals.clear();
        for d in 0..6 {
            let j = self.nb(p, d);
            if self.occupied(j) {
                s.terminals.push(j as u32);
            }
        }
        if let Some((q, a)) = carrier {
            for d in 0..6 {
                let j = self.nb(q, d);
                if d / 2 != a && j != p && self.occupied(j) {
                    s.terminals.push(j as u32);
                }
            }
        }
        if s.terminals.len() <= 1 {
            return true;
        }
        let centre = carrier.map_or(p, |(q, _)| q);
        let occupied = *around.get_or_insert_with(|| self.box_around(centre));
        if self.local_join(p, carrier, occupied) {
            return true;
        }
        s.searches += 1;
        self.global_join(p, carrier, s)
    }

    /// The occupied cells of the 5×5×5 box around `centre` (bit x + 5y + 25z from its corner).
    /// Built in two 64-bit halves: wasm has no 128-bit shift by a variable amount and calls a
    /// helper for each.
    fn box_around(&self, centre: usize) -> u128 {
        let (mut lo, mut hi) = (0u64, 0u64);
        let corner = centre as isize - 2 - 2 * self.stride[2] - 2 * self.stride[4];
        for z in 0..5 {
            for y in 0..5 {
                let row = (corner + y * self.stride[2] + z * self.stride[4]) as usize;
                let base = 5 * y as u32 + 25 * z as u32;
                for x in 0..5 {
                    if self.types[row + x] != 0 {
                        let b = base + x as u32;
                        if b < 64 {
                            lo |= 1 << b;
                        } else {
                            hi |= 1 << (b - 64);
                        }
                    }
                }
            }
        }
        u128::from(lo) | (u128::from(hi) << 64)
    }

    /// Tries to join the terminals without leaving the 5×5×5 cells around the carrier (around
    /// p when there is none). Success proves the answer is yes.
    ///
    /// The box fits in the 125 low bits of a `u128`, one bit per cell (x fastest), so the search
    /// is a flood fill by whole-box shifts: a handful of word operations per layer of the search
    /// instead of a stack and a visited mark per cell. That is the same search as walking cell by
    /// cell, and much faster, in wasm especially (its engines keep no Vec pointers in registers
    /// across a loop of pushes and loads, so the walk cost about twice what it costs natively).
    fn local_join(&self, p: usize, carrier: Option<(usize, usize)>, occupied: u128) -> bool {
        // Bits are found from the centre (bit 62) by steps along the directions, with no
        // division: p is the centre or next to it, every terminal next to p or the carrier.
        let p_bit = match carrier {
            Some((q, _)) => match (0..6).find(|&d| self.nb(q, d) == p) {
                Some(d) => (62 + BOX_STEP[d]) as u32,
                None => return false,
            },
            None => 62,
        };
        let occ = occupied & !one(p_bit);
        // The carrier holds on only along its axis: take it out of the flood and let it join
        // its two axis neighbours to each other.
        let (bridge, q_bit) = match carrier {
            Some((_, a)) => {
                let step = [1u32, 5, 25][a];
                let pair = one(62 - step) | one(62 + step);
                (pair & occ, one(62))
            }
            None => (0, 0),
        };
        let open = occ & !q_bit;
        // The terminals of `stays_connected`: p's neighbours and the carrier's neighbours off
        // its axis.
        let mut want: u128 = 0;
        let mut reach: u128 = 0;
        for (d, step) in BOX_STEP.iter().enumerate() {
            if self.occupied(self.nb(p, d)) {
                want |= one((p_bit as i32 + step) as u32);
            }
        }
        if let Some((q, a)) = carrier {
            for (d, step) in BOX_STEP.iter().enumerate() {
                let j = self.nb(q, d);
                if d / 2 != a && j != p && self.occupied(j) {
                    want |= one((62 + step) as u32);
                }
            }
        }
        if want != 0 {
            reach = want & want.wrapping_neg();
        }
        loop {
            if reach & want == want {
                return true;
            }
            // The carrier spreads only to its axis neighbours (the bridge), never off the axis.
            let from = reach & !q_bit;
            let mut next = reach
                | (((from << 1) & !BOX_X0)
                    | ((from >> 1) & !BOX_X4)
                    | ((from << 5) & !BOX_Y0)
                    | ((from >> 5) & !BOX_Y4)
                    | (from << 25)
                    | (from >> 25))
                    & open;
            if next & (bridge | q_bit) != 0 {
                next |= bridge | q_bit;
            }
            if next == reach {
                return false;
            }
            reach = next;
        }
    }

    /// Breadth-first searches from every terminal at once, one cell each in turn. Two searches
    /// that touch are joined; the answer is yes when one group remains, no when a group runs out
    /// of cells first (it has explored a whole piece without meeting the others).
    fn global_join(&self, p: usize, carrier: Option<(usize, usize)>, s: &mut Scratch) -> bool {
        let k = s.terminals.len();
        let gen = s.next_gen(self.len());
        while s.queues.len() < k {
            s.queues.push(Vec::new());
        }
        s.heads.clear();
        s.heads.resize(k, 0);
        s.parent.clear();
        s.parent.extend(0..k as u8);
        for t in 0..k {
            let c = s.terminals[t] as usize;
            s.queues[t].clear();
            s.queues[t].push(c as u32);
            s.seen[c] = gen;
            s.label[c] = t as u8;
        }
        fn find(parent: &mut [u8], mut i: u8) -> u8 {
            while parent[i as usize] != i {
                let up = parent[parent[i as usize] as usize];
                parent[i as usize] = up;
                i = up;
            }
            i
        }
        let mut groups = k;
        loop {
            for t in 0..k {
                let Some(&x) = s.queues[t].get(s.heads[t]) else {
                    continue;
                };
                s.heads[t] += 1;
                s.search_cells += 1;
                let x = x as usize;
                for d in 0..6 {
                    let Some(y) = self.usable(x, d, p, carrier) else {
                        continue;
                    };
                    if s.seen[y] != gen {
                        s.seen[y] = gen;
                        s.label[y] = t as u8;
                        s.queues[t].push(y as u32);
                    } else {
                        let (r1, r2) = (
                            find(&mut s.parent, t as u8),
                            find(&mut s.parent, s.label[y]),
                        );
                        if r1 != r2 {
                            s.parent[r1 as usize] = r2;
                            groups -= 1;
                            if groups == 1 {
                                return true;
                            }
                        }
                    }
                }
            }
            // A group whose searches have all run dry has found a whole piece on its own.
            let mut alive = [false; 16];
            for t in 0..k {
                if s.heads[t] < s.queues[t].len() {
                    alive[find(&mut s.parent, t as u8) as usize] = true;
                }
            }
            for t in 0..k {
                let r = find(&mut s.parent, t as u8);
                if !alive[r as usize] {
                    return false;
                }
            }
        }
    }
}
