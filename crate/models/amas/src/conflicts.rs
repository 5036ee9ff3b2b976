//! Step phase 2, conflicts (4.6): which moves go ahead, module relay (4.6.1), and the
//! collision penalty of the robots that must wait.

use super::{
    Amas, Collision, Communication, Plan, EV_COLLISION, EV_RELAY, MOVES, NONE, STAYS, UNKNOWN,
    VISITING,
};
use kumiki_model::model::Event;

impl Amas {
    /// Token and relay: whether robot `r`'s move goes ahead, following the robots ahead of it.
    /// A move onto a module whose robot stays, or around a cycle (two robots meeting head-on),
    /// does not.
    pub(super) fn resolve(&mut self, r: usize) {
        if self.status[r] != UNKNOWN {
            return;
        }
        if self.p.communication == Communication::Radius2 {
            self.status[r] = if self.moves_locally(r) { MOVES } else { STAYS };
            return;
        }
        self.chain.clear();
        let mut cur = r;
        let result = loop {
            self.status[cur] = VISITING;
            self.chain.push(cur as u32);
            let Plan::Move(t) = self.plans[cur] else {
                break STAYS;
            };
            let o = self.occupant[t as usize];
            if o == NONE {
                break MOVES;
            }
            let o = o as usize;
            match self.status[o] {
                MOVES => break MOVES,
                STAYS | VISITING => break STAYS,
                _ => {
                    if matches!(self.plans[o], Plan::Move(_)) {
                        cur = o;
                    } else {
                        self.status[o] = STAYS;
                        break STAYS;
                    }
                }
            }
        };
        for &q in &self.chain {
            self.status[q as usize] = result;
        }
    }

    /// Appendix A.1 (2): with radius-2 communication robot `r` sees the robot on its target
    /// and that robot's target, no further. It moves onto a free module, or follows a robot
    /// that moves onto a free module (claims are exclusive, so that robot surely moves).
    pub(super) fn moves_locally(&self, r: usize) -> bool {
        let Plan::Move(t) = self.plans[r] else {
            return false;
        };
        match self.occupant[t as usize] {
            NONE => true,
            o => match self.plans[o as usize] {
                Plan::Move(t2) => self.occupant[t2 as usize] == NONE,
                _ => false,
            },
        }
    }

    pub(super) fn collide(&mut self, r: usize, at: u32) {
        self.collisions += 1;
        *self.collision_cells.entry(at).or_insert(0) += 1;
        let row = at / self.w as u32;
        if row == self.corner_row || row == self.corner_row + 1 {
            self.corner_collisions += 1;
        } else if row < self.corner_row {
            self.above_corner_collisions += 1;
        } else if row as usize >= self.supply_top {
            self.supply_collisions += 1;
        }
        self.robots[r].give_way = true;
        self.robots[r].busy = self.p.penalty - 1;
        self.events.push(Event {
            cell: at,
            kind: EV_COLLISION,
        });
    }

    /// Token and relay rules: decides which moves go ahead, then hands modules over (relay)
    /// or charges the collision penalty to the robots that must wait.
    pub(super) fn settle_conflicts(&mut self) {
        let n = self.robots.len();
        for r in 0..n {
            if matches!(self.plans[r], Plan::Move(_)) {
                self.resolve(r);
            }
        }
        if self.p.collision == Collision::Blackboard {
            return;
        }
        if self.p.collision == Collision::Relay {
            for k in 0..n {
                let r = self.order[k] as usize;
                let Plan::Move(t) = self.plans[r] else {
                    continue;
                };
                let o = self.occupant[t as usize];
                if self.status[r] != STAYS || self.relaying[r] || o == NONE {
                    continue;
                }
                let o = o as usize;
                let o_idle = match self.plans[o] {
                    Plan::Wait | Plan::Blocked(_) => true,
                    Plan::Move(_) => self.status[o] == STAYS,
                    _ => false,
                };
                if o_idle && !self.relaying[o] && self.robots[r].loaded != self.robots[o].loaded {
                    // 4.6.1: the robot carrying the module hands it to the other.
                    self.relaying[r] = true;
                    self.relaying[o] = true;
                    self.robots[r].loaded = !self.robots[r].loaded;
                    self.robots[o].loaded = !self.robots[o].loaded;
                    self.robots[r].busy = self.p.relay_d - 1;
                    self.robots[o].busy = self.p.relay_d - 1;
                    self.relays += 1;
                    // At the corner: the handing robot stands on the corner row or the row
                    // below it.
                    let row = self.robots[r].cell / self.w as u32;
                    if row == self.corner_row || row == self.corner_row + 1 {
                        self.corner_relays += 1;
                    }
                    self.events.push(Event {
                        cell: t,
                        kind: EV_RELAY,
                    });
                }
            }
        }
        for k in 0..n {
            let r = self.order[k] as usize;
            if self.relaying[r] {
                continue;
            }
            let t = match self.plans[r] {
                Plan::Blocked(t) => t,
                Plan::Move(t) if self.status[r] == STAYS => t,
                _ => continue,
            };
            let o = self.occupant[t as usize];
            if o == NONE {
                // Lost the claim on a free module to a larger token.
                self.collide(r, t);
                continue;
            }
            let o = o as usize;
            let here = self.robots[r].cell;
            // Head-on: the robot ahead wants this robot's module.
            let head_on = matches!(self.plans[o], Plan::Move(x) | Plan::Blocked(x) if x == here)
                && !self.relaying[o];
            if head_on && self.position[o] > self.position[r] {
                // The larger token keeps its priority and waits for the other to step aside.
                continue;
            }
            self.collide(r, t);
        }
    }
}
