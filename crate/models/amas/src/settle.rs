//! The structure's roles after each step: growth front and supply of every module, the
//! connection rule of disassembly (6.2, 6.3), stage switching (6.4), and the values new modules
//! take.

use std::collections::{HashSet, VecDeque};

use super::field::{Field, FAR};
use super::state::{self, BROKEN, CONVEYOR, FRONT, MODULE, REMOVE, SOURCE, VACANT};
use super::Amas;

impl Amas {
    /// Recomputes the growth-front and supply roles of cell `i` from its neighbours.
    pub(super) fn refresh(&mut self, i: usize) {
        let s = self.state[i];
        let new = if s & MODULE == 0 {
            s & !(FRONT | SOURCE)
        } else {
            let (nb, k) = self.neighbours(i);
            let mut front = false;
            let mut source = false;
            for &j in &nb[..k] {
                let t = self.state[j];
                front |= t & VACANT != 0;
                source |= t & REMOVE != 0 && self.is_releasable(j);
            }
            // A robot cannot remove the module it stands on: a module that may go now is not
            // itself supply.
            source &= !self.is_releasable(i);
            if s & CONVEYOR != 0 {
                if self.return_mode {
                    front = true;
                } else {
                    source |= !self.reuse;
                }
            }
            (s & !(FRONT | SOURCE))
                | if front { FRONT } else { 0 }
                | if source { SOURCE } else { 0 }
        };
        self.state[i] = new;
        self.display[i] = state::display(new);
    }

    #[inline]
    pub(super) fn is_releasable(&self, i: usize) -> bool {
        self.releasable[i / 64] >> (i % 64) & 1 == 1
    }

    /// Section 6.2 with 6.3: the neighbours of a module to be removed become supply while the
    /// connection rule lets that module go.
    pub(super) fn update_releasable(&mut self) {
        if self.to_remove == 0 && self.releasable.iter().all(|&b| b == 0) {
            return;
        }
        let mut changed = Vec::new();
        for i in 0..self.supply_top * self.w {
            let want = self.state[i] & REMOVE != 0 && self.removable(i);
            if want != self.is_releasable(i) {
                self.releasable[i / 64] ^= 1 << (i % 64);
                changed.push(i);
            }
        }
        for i in changed {
            self.refresh_around(i);
        }
        let reuse = self.releasable.iter().any(|&b| b != 0);
        if reuse != self.reuse {
            self.reuse = reuse;
            for i in self.supply_top * self.w..self.state.len() {
                self.refresh(i);
            }
        }
    }

    pub(super) fn refresh_around(&mut self, i: usize) {
        self.refresh(i);
        let (nb, k) = self.neighbours(i);
        for &j in &nb[..k] {
            self.refresh(j);
        }
    }

    /// The value a module takes when it appears or its role changes: what its first update
    /// would give from its neighbours' current values. A broken module keeps its value.
    pub(super) fn init_value(&mut self, i: usize) {
        let s = self.state[i];
        if s & BROKEN != 0 {
            return;
        }
        let on = s & MODULE != 0;
        let (nb, k) = self.neighbours(i);
        match &mut self.field {
            Field::Discrete {
                to_supply,
                to_front,
                ..
            } => {
                if !on {
                    to_supply[i] = FAR;
                    to_front[i] = FAR;
                    return;
                }
                let ms = nb[..k].iter().map(|&j| to_supply[j]).min().unwrap_or(FAR);
                let mf = nb[..k].iter().map(|&j| to_front[j]).min().unwrap_or(FAR);
                to_supply[i] = if s & SOURCE != 0 {
                    0
                } else {
                    ms.saturating_add(1)
                };
                to_front[i] = if s & FRONT != 0 {
                    0
                } else {
                    mf.saturating_add(1)
                };
            }
            Field::Continuous { p, .. } => {
                p[i] = if !on || (s & SOURCE != 0 && s & FRONT == 0) {
                    0.0
                } else if s & FRONT != 0 {
                    1.0
                } else {
                    let mut sum = 0.0f32;
                    let mut cnt = 0.0f32;
                    for &j in &nb[..k] {
                        if self.state[j] & MODULE != 0 {
                            sum += p[j];
                            cnt += 1.0;
                        }
                    }
                    if cnt > 0.0 {
                        sum / cnt
                    } else {
                        0.0
                    }
                };
            }
        }
    }

    /// Stage switching (section 6.4) and the supply taking modules back when the target is
    /// full but modules are still to be removed.
    pub(super) fn settle(&mut self) {
        while self.vacant == 0 && self.to_remove == 0 && self.stage + 1 < self.stages.len() {
            self.stage += 1;
            let above = self.supply_top * self.w;
            for i in 0..above {
                let inside = self.stages[self.stage][i / 64] >> (i % 64) & 1 == 1;
                let s = self.state[i];
                self.state[i] = if s & MODULE != 0 {
                    if inside {
                        s & !REMOVE
                    } else {
                        s | REMOVE
                    }
                } else if inside {
                    VACANT
                } else {
                    0
                };
            }
            self.recount();
            self.dirty = true;
            for i in 0..self.state.len() {
                self.refresh(i);
            }
        }
        let back = self.vacant == 0 && self.to_remove > 0;
        if back != self.return_mode {
            self.return_mode = back;
            for i in self.supply_top * self.w..self.state.len() {
                self.refresh(i);
            }
        }
        if self.dirty {
            self.dirty = false;
            self.update_releasable();
        }
    }

    /// Section 6.3: a module with one connection is removable; with two to four, only when all
    /// its neighbours stay connected without it. The neighbours first look for each other
    /// around the module (its eight surrounding cells), then through the whole structure.
    pub(super) fn removable(&self, c: usize) -> bool {
        let (nb, k) = self.neighbours(c);
        let mut mods = [0usize; 4];
        let mut m = 0;
        for &j in &nb[..k] {
            if self.state[j] & MODULE != 0 {
                mods[m] = j;
                m += 1;
            }
        }
        if m <= 1 {
            return true;
        }
        // The ring E, NE, N, NW, W, SW, S, SE; even positions are the four neighbours.
        let (x, y) = ((c % self.w) as i64, (c / self.w) as i64);
        let ring: [(i64, i64); 8] = [
            (1, 0),
            (1, -1),
            (0, -1),
            (-1, -1),
            (-1, 0),
            (-1, 1),
            (0, 1),
            (1, 1),
        ];
        let here = |(dx, dy): (i64, i64)| {
            let (nx, ny) = (x + dx, y + dy);
            nx >= 0
                && ny >= 0
                && (nx as usize) < self.w
                && (ny as usize) < self.h
                && self.state[ny as usize * self.w + nx as usize] & MODULE != 0
        };
        let filled: [bool; 8] = std::array::from_fn(|q| here(ring[q]));
        if filled.iter().all(|&f| f) {
            return true;
        }
        // Count runs of filled ring cells that hold a neighbour.
        let start = (0..8).find(|&q| !filled[q]).unwrap_or(0);
        let mut runs = 0;
        let mut in_run = false;
        let mut run_has = false;
        for step in 1..=8 {
            let q = (start + step) % 8;
            if filled[q] {
                if !in_run {
                    in_run = true;
                    run_has = false;
                }
                run_has |= q % 2 == 0;
            } else if in_run {
                in_run = false;
                if run_has {
                    runs += 1;
                }
            }
        }
        if in_run && run_has {
            runs += 1;
        }
        if runs <= 1 {
            return true;
        }
        // Through the structure: search from one neighbour until the others are found.
        let mut seen: HashSet<usize> = HashSet::new();
        let mut queue = VecDeque::new();
        seen.insert(c);
        seen.insert(mods[0]);
        queue.push_back(mods[0]);
        let mut missing = m - 1;
        while let Some(i) = queue.pop_front() {
            let (nb, k) = self.neighbours(i);
            for &j in &nb[..k] {
                if self.state[j] & MODULE != 0 && seen.insert(j) {
                    if mods[1..m].contains(&j) {
                        missing -= 1;
                        if missing == 0 {
                            return true;
                        }
                    }
                    queue.push_back(j);
                }
            }
        }
        false
    }

    /// The fraction of the current target that is built.
    pub(super) fn built_fraction(&self) -> f64 {
        if self.target_cells == 0 {
            1.0
        } else {
            (self.target_cells - self.vacant) as f64 / self.target_cells as f64
        }
    }
}
