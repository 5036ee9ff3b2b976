//! Step phase 1, planning (5.1): robots plan one after another in a fresh random order; each
//! reads the field on the module under it (footnote 3) and claims the cell it wants.

use kumiki_model::slot::Stop;

use super::direction::{self, Reading, Shown, Sight, LISTED};
use super::field::Field;
use super::state::{ACTIVE_MASK, CLAIMED, CONVEYOR, FRONT, MODULE, REMOVE, SOURCE, VACANT};
use super::{Amas, Collision, Plan, NONE, UNKNOWN};

/// No cell: a neighbour off the lattice.
const OFF: usize = usize::MAX;

impl Amas {
    /// How far module `j` is from where a robot wants to go: lower is better.
    #[inline]
    pub(super) fn cost(&self, j: usize, loaded: bool) -> f32 {
        match &self.field {
            Field::Discrete {
                to_supply,
                to_front,
                ..
            } => f32::from(if loaded { to_front[j] } else { to_supply[j] }),
            Field::Continuous { p, .. } => {
                if loaded {
                    -p[j]
                } else {
                    p[j]
                }
            }
        }
    }

    /// Blackboard (4.6.2): a module is engaged when a robot has written a plan on it, or a
    /// robot stands on it that has not written a plan to leave it (or plans to come to `me`).
    pub(super) fn engaged(&self, c: usize, me: usize) -> bool {
        if self.state[c] & CLAIMED != 0 {
            return true;
        }
        let o = self.occupant[c];
        if o == NONE {
            return false;
        }
        match (self.planned[o as usize], self.plans[o as usize]) {
            (true, Plan::Move(t)) => t as usize == me,
            _ => true,
        }
    }

    pub(super) fn pick_random(&mut self, options: &[u32]) -> Option<u32> {
        match options.len() {
            0 => None,
            1 => Some(options[0]),
            n => Some(options[self.rng.index(n)]),
        }
    }

    /// The four neighbouring cells by slot (N, S, E, W, see [`direction`]), [`OFF`] off the
    /// lattice.
    #[inline]
    fn compass(&self, i: usize) -> [usize; 4] {
        let (w, x, y) = (self.w, i % self.w, i / self.w);
        let mut out = [OFF; 4];
        if y > 0 {
            out[direction::N] = i - w;
        }
        if y + 1 < self.h {
            out[direction::S] = i + w;
        }
        if x + 1 < w {
            out[direction::E] = i + 1;
        }
        if x > 0 {
            out[direction::W] = i - 1;
        }
        out
    }

    /// What the module at `i` holds about its neighbours for a robot that is `loaded`; `open`
    /// says which neighbouring modules the robot may step onto.
    #[inline]
    fn reading(&self, around: &[usize; 4], loaded: bool, open: impl Fn(usize) -> bool) -> Reading {
        let mut r = Reading {
            cost: [None; 4],
            open: [false; 4],
        };
        for (slot, &j) in around.iter().enumerate() {
            if j != OFF && self.state[j] & MODULE != 0 {
                r.cost[slot] = Some(self.cost(j, loaded));
                r.open[slot] = open(j);
            }
        }
        r
    }

    /// A random cell among the slots in `set` (bit `1 << slot`), drawn in the order Kumiki
    /// listed neighbours before model version 3.
    fn draw(&mut self, set: u8, around: &[usize; 4]) -> Option<u32> {
        let mut options = [0u32; 4];
        let mut n = 0;
        for slot in LISTED {
            if set >> slot & 1 == 1 {
                options[n] = around[slot] as u32;
                n += 1;
            }
        }
        self.pick_random(&options[..n])
    }

    /// What the module at `i` shows a robot that is `loaded` and sees `reading` (footnote 3):
    /// the paper's rule, [`direction::shown`], or a scenario's script (the slot `direction`),
    /// whose answer must name neighbouring modules.
    #[inline]
    fn show(&self, reading: &Reading, loaded: bool, giving_way: bool) -> Result<Shown, Stop> {
        if !self.direction_rule.scripted() {
            // The paper's rule straight from the reading, without the script's copy of it.
            let threshold = match giving_way {
                true => f32::NEG_INFINITY,
                false => self.p.threshold,
            };
            return Ok(direction::shown(reading, threshold, self.p.direction));
        }
        let sight = Sight::of(
            reading,
            self.p.threshold,
            self.p.direction,
            loaded,
            giving_way,
        );
        let shown = self.direction_rule.decide(&sight, None)?;
        let modules = (0..4)
            .filter(|&slot| reading.cost[slot].is_some())
            .fold(0u8, |set, slot| set | 1 << slot);
        let named = match shown {
            Shown::Toward(slot) => 1 << slot,
            Shown::Among(set) => set,
            Shown::Nowhere | Shown::NoGradient => 0,
        };
        match named & !modules {
            0 => Ok(shown),
            off => Err(Stop(format!(
                "rule 'direction' answered {}, where no module is: a robot steps only onto a neighbouring module",
                ["N", "S", "E", "W"][off.trailing_zeros() as usize]
            ))),
        }
    }

    /// The move the module under the robot shows it (footnote 3, [`Amas::show`]): towards the
    /// best neighbour, or, with no effective gradient, a random neighbouring module. On a
    /// blackboard the robot avoids engaged modules and takes the best free one.
    pub(super) fn follow(
        &mut self,
        r: usize,
        i: usize,
        loaded: bool,
        board: bool,
    ) -> Result<Plan, Stop> {
        let around = self.compass(i);
        let reading = self.reading(&around, loaded, |j| !(board && self.engaged(j, i)));
        Ok(match self.show(&reading, loaded, false)? {
            Shown::Toward(slot) => Plan::Move(around[slot] as u32),
            Shown::Among(set) => self.draw(set, &around).map_or(Plan::Wait, Plan::Move),
            Shown::Nowhere => Plan::Wait,
            Shown::NoGradient => {
                self.robots[r].lost = true;
                self.wandering += 1;
                let open = (0..4)
                    .filter(|&slot| reading.open[slot])
                    .fold(0u8, |set, slot| set | 1 << slot);
                self.draw(open, &around).map_or(Plan::Wait, Plan::Move)
            }
        })
    }

    /// A robot that gives way (4.6) steps, at its next plan, to the best module for itself that
    /// no robot stands on: it moves on if the way has cleared, or aside if it has not.
    pub(super) fn give_way(&mut self, i: usize, loaded: bool) -> Result<Option<u32>, Stop> {
        let around = self.compass(i);
        let reading = self.reading(&around, loaded, |j| self.occupant[j] == NONE);
        Ok(match self.show(&reading, loaded, true)? {
            Shown::Toward(slot) => Some(around[slot] as u32),
            Shown::Among(set) => self.draw(set, &around),
            Shown::Nowhere | Shown::NoGradient => None,
        })
    }

    /// A vacant target site among `nb`, chosen at random; on a blackboard, not one another
    /// robot has already claimed.
    pub(super) fn vacant_site(&mut self, nb: &[usize], board: bool) -> Option<u32> {
        let mut opts = [0u32; 4];
        let mut n = 0;
        for &j in nb {
            let t = self.state[j];
            if t & VACANT != 0 && !(board && t & CLAIMED != 0) {
                opts[n] = j as u32;
                n += 1;
            }
        }
        self.pick_random(&opts[..n])
    }

    /// What robot `r` wants to do this step.
    pub(super) fn decide(&mut self, r: usize) -> Result<Plan, Stop> {
        let rb = self.robots[r];
        let i = rb.cell as usize;
        let s = self.state[i];
        let board = self.p.collision == Collision::Blackboard;
        self.robots[r].lost = false;
        self.robots[r].waiting_for = NONE;
        if rb.give_way {
            self.robots[r].give_way = false;
            if let Some(c) = self.give_way(i, rb.loaded)? {
                return Ok(Plan::Move(c));
            }
        }
        if s & ACTIVE_MASK != MODULE {
            // A broken module tells the robot nothing. A loaded robot still knows the target
            // shape and its coordinates (4.1) and sees the sites next to it, so it fills a
            // vacant target site beside it; otherwise it walks at random.
            let (nb, k) = self.neighbours(i);
            if rb.loaded {
                if let Some(t) = self.vacant_site(&nb[..k], board) {
                    return Ok(Plan::Place(t));
                }
            }
            let mut walk = [0u32; 4];
            let mut n = 0;
            for &j in &nb[..k] {
                if self.state[j] & MODULE != 0 && !(board && self.engaged(j, i)) {
                    walk[n] = j as u32;
                    n += 1;
                }
            }
            self.robots[r].lost = true;
            self.wandering += 1;
            return Ok(self.pick_random(&walk[..n]).map_or(Plan::Wait, Plan::Move));
        }
        let (nb, k) = self.neighbours(i);
        if rb.loaded {
            if s & FRONT != 0 {
                if s & CONVEYOR != 0 && self.return_mode {
                    return Ok(Plan::Return);
                }
                if let Some(t) = self.vacant_site(&nb[..k], board) {
                    return Ok(Plan::Place(t));
                }
                if board {
                    return Ok(Plan::Wait);
                }
            }
            return self.follow(r, i, true, board);
        }
        if s & SOURCE != 0 {
            let mut opts = [0u32; 4];
            let mut n = 0;
            for &j in &nb[..k] {
                let t = self.state[j];
                if t & REMOVE != 0
                    && self.is_releasable(j)
                    && self.occupant[j] == NONE
                    && !(board && t & CLAIMED != 0)
                {
                    opts[n] = j as u32;
                    n += 1;
                }
            }
            if n > 0 {
                return Ok(self
                    .pick_random(&opts[..n])
                    .map_or(Plan::Wait, Plan::Remove));
            }
            if s & CONVEYOR != 0 && !self.return_mode && !self.reuse {
                return Ok(Plan::Pick);
            }
        }
        self.follow(r, i, false, board)
    }

    pub(super) fn claim(&mut self, c: usize) {
        self.state[c] |= CLAIMED;
        self.claimed.push(c as u32);
    }

    /// Every robot plans, in a fresh random order; a script that stops the run stops planning.
    pub(super) fn plan_all(&mut self) -> Result<(), Stop> {
        self.rng.shuffle(&mut self.order);
        for k in 0..self.order.len() {
            let r = self.order[k] as usize;
            self.position[r] = k as u32;
            self.planned[r] = false;
            self.status[r] = UNKNOWN;
            self.relaying[r] = false;
        }
        for k in 0..self.order.len() {
            let r = self.order[k] as usize;
            let plan = if self.robots[r].busy > 0 {
                self.robots[r].busy -= 1;
                Plan::Busy
            } else {
                self.decide(r)?
            };
            let plan = match plan {
                Plan::Move(t) | Plan::Place(t) | Plan::Remove(t) => {
                    if self.state[t as usize] & CLAIMED != 0 {
                        Plan::Blocked(t)
                    } else {
                        self.claim(t as usize);
                        plan
                    }
                }
                other => other,
            };
            self.plans[r] = plan;
            self.planned[r] = true;
        }
        Ok(())
    }
}
