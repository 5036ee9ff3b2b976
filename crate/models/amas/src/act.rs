//! Step phase 3, acting: moves, picks, removals, placements and returns take effect.

use super::state::{CLAIMED, MODULE, REMOVE, VACANT};
use super::{Amas, Plan, MOVES, NONE};

impl Amas {
    /// The direction of a move from cell `a` to its neighbour `b`: 0 right, 1 up, 2 left,
    /// 3 down.
    pub(super) fn heading_to(&self, a: u32, b: u32) -> u8 {
        let w = self.w as u32;
        if b == a + 1 {
            0
        } else if b + w == a {
            1
        } else if b + 1 == a {
            2
        } else {
            3
        }
    }

    pub(super) fn act_all(&mut self) {
        let n = self.robots.len();
        let moves =
            |m: &Amas, r: usize| matches!(m.plans[r], Plan::Move(_)) && m.status[r] == MOVES;
        for r in 0..n {
            if moves(self, r) {
                self.occupant[self.robots[r].cell as usize] = NONE;
            }
        }
        for r in 0..n {
            if let Plan::Move(t) = self.plans[r] {
                if self.status[r] == MOVES {
                    let heading = self.heading_to(self.robots[r].cell, t);
                    let turn = if heading == self.robots[r].heading {
                        0
                    } else {
                        self.p.turn_d
                    };
                    self.occupant[t as usize] = r as u32;
                    self.robots[r].cell = t;
                    self.robots[r].heading = heading;
                    self.robots[r].top = self.robots[r].top.min(t / self.w as u32);
                    self.robots[r].busy = self.p.move_d - 1 + turn;
                }
            }
        }
        for k in 0..n {
            let r = self.order[k] as usize;
            if self.relaying[r] {
                continue;
            }
            match self.plans[r] {
                Plan::Pick => {
                    self.robots[r].loaded = true;
                    self.robots[r].busy = self.p.pick_d - 1;
                    self.picked += 1;
                }
                Plan::Remove(t) => {
                    let t = t as usize;
                    if self.state[t] & REMOVE != 0 && self.occupant[t] == NONE && self.removable(t)
                    {
                        self.take(t);
                        self.robots[r].loaded = true;
                        self.robots[r].busy = self.p.pick_d - 1;
                        self.dismantled += 1;
                    }
                }
                Plan::Place(t) => {
                    let t = t as usize;
                    if self.state[t] & VACANT != 0 {
                        self.put(t);
                        self.robots[r].placed_past_corner |= t / self.w <= self.corner_row as usize;
                        self.robots[r].loaded = false;
                        self.robots[r].busy = self.p.place_d - 1;
                        self.placed += 1;
                    }
                }
                Plan::Return => {
                    self.robots[r].loaded = false;
                    self.robots[r].busy = self.p.place_d - 1;
                    self.returned += 1;
                }
                _ => {}
            }
        }
        for &c in &self.claimed {
            self.state[c as usize] &= !CLAIMED;
        }
        self.claimed.clear();
    }

    /// A module is placed at vacant target cell `t`.
    pub(super) fn put(&mut self, t: usize) {
        self.state[t] = (self.state[t] & !VACANT) | MODULE;
        self.vacant -= 1;
        self.dirty = true;
        self.refresh_around(t);
        self.init_value(t);
        self.top = self.top.min(t / self.w);
    }

    /// The module to be removed at `t` is taken away.
    pub(super) fn take(&mut self, t: usize) {
        self.state[t] &= CLAIMED;
        self.to_remove -= 1;
        self.dirty = true;
        self.refresh_around(t);
        self.init_value(t);
    }
}
