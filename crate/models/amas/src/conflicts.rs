//! Step phase 2, conflicts (4.6): which moves go ahead, module relay (4.6.1), and the
//! collision penalty of the robots that must wait.

use kumiki_model::slot::Stop;

use super::collision::{self, Conflict, Meeting, Outcome, Partner};
use super::spec::GiveWay;
use super::{
    Amas, Collision, Communication, Plan, EV_COLLISION, EV_RELAY, MOVES, NONE, STAYS, UNKNOWN,
    VISITING,
};

/// Bits of a robot's `lock` byte within a step's conflicts: on the path being followed, seen,
/// on a ring ([`Amas::mark_rings`]); on the queue being followed, its queue's answer known, and
/// that answer: it waits on a robot that gives way ([`Amas::queued_on_yielding`]).
const ON_PATH: u8 = 1;
const SEEN: u8 = 2;
const RING: u8 = 4;
const ON_QUEUE: u8 = 8;
const QUEUED: u8 = 16;
const BEHIND: u8 = 32;
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

    /// Robot `r` pays the collision penalty for wanting cell `at`, where robot `other` stood
    /// in its way or claimed the cell first; `give_way` it steps aside at its next plan.
    pub(super) fn collide(&mut self, r: usize, at: u32, other: Option<usize>, give_way: bool) {
        self.collisions += 1;
        // Appendix A.1: which kinds of robot meet, as they were when they planned (a relay
        // this step has already swapped the other's load).
        let loaded = self.robots[r].loaded;
        match other.map(|o| self.robots[o].loaded ^ self.relaying[o]) {
            Some(l) if l != loaded => self.mixed_collisions += 1,
            _ if loaded => self.loaded_collisions += 1,
            _ => self.unloaded_collisions += 1,
        }
        *self.collision_cells.entry(at).or_insert(0) += 1;
        let row = at / self.w as u32;
        if row == self.corner_row || row == self.corner_row + 1 {
            self.corner_collisions += 1;
        } else if row < self.corner_row {
            self.above_corner_collisions += 1;
        } else if row as usize >= self.supply_top {
            self.supply_collisions += 1;
        }
        self.robots[r].give_way = give_way;
        self.robots[r].waiting_for = at;
        self.robots[r].busy = self.p.penalty - 1;
        self.events.push(Event {
            cell: at,
            kind: EV_COLLISION,
        });
    }

    /// The robot that claimed cell `t` this step: it stands next to `t` (every plan takes a
    /// neighbouring cell) and its plan holds the claim.
    fn claimant(&self, t: u32, r: usize) -> Option<usize> {
        let (nb, k) = self.neighbours(t as usize);
        nb[..k].iter().find_map(|&j| {
            let q = self.occupant[j] as usize;
            let holds = q != r
                && self.occupant[j] != NONE
                && matches!(self.plans[q], Plan::Move(x) | Plan::Place(x) | Plan::Remove(x) if x == t);
            holds.then_some(q)
        })
    }

    /// The cell robot `q` wants this step, if it wants to move; where locked robots alone give
    /// way, a robot paying a collision penalty still wants the cell it collided over.
    fn wants(&self, q: usize) -> Option<u32> {
        match self.plans[q] {
            Plan::Move(x) | Plan::Blocked(x) => Some(x),
            Plan::Busy if self.p.give_way == GiveWay::Locked => {
                Some(self.robots[q].waiting_for).filter(|&x| x != NONE)
            }
            _ => None,
        }
    }

    /// Whether robot `r`, which wants the module robot `o` stands on, is locked with it: `o`
    /// wants `r`'s module (head-on), or, where only locked robots give way, `r` lies on a ring of
    /// waiting robots each wanting the next one's module ([`Amas::mark_rings`]). A robot busy
    /// relaying is in no lock.
    fn locked(&self, r: usize, o: usize) -> bool {
        let here = self.robots[r].cell;
        if self.wants(o) == Some(here) && !self.relaying[o] {
            return true;
        }
        self.p.give_way == GiveWay::Locked && self.lock[r] & RING != 0
    }

    /// The robot each robot waits on this step (`ahead`: the one on the module it wants, where
    /// it does not move and is not relaying), and which robots lie on a ring of them: every
    /// robot follows its one successor until it meets a robot already seen, once for all.
    fn mark_rings(&mut self) {
        let n = self.robots.len();
        for q in 0..n {
            let waits = self.status[q] != MOVES && !self.relaying[q];
            self.ahead[q] = match self.wants(q).filter(|_| waits) {
                Some(x) => self.occupant[x as usize],
                None => NONE,
            };
            self.lock[q] = 0;
        }
        for s in 0..n {
            self.chain.clear();
            let mut q = s as u32;
            while q != NONE && self.lock[q as usize] == 0 {
                self.lock[q as usize] = ON_PATH;
                self.chain.push(q);
                q = self.ahead[q as usize];
            }
            if q != NONE && self.lock[q as usize] == ON_PATH {
                let from = self.chain.iter().position(|&p| p == q).unwrap_or(0);
                for &p in &self.chain[from..] {
                    self.lock[p as usize] |= RING;
                }
            }
            for &p in &self.chain {
                self.lock[p as usize] = (self.lock[p as usize] & RING) | SEEN;
            }
        }
    }

    /// Token and relay rules: decides which moves go ahead, then hands modules over (relay)
    /// or charges the collision penalty to the robots that must wait.
    pub(super) fn settle_conflicts(&mut self) -> Result<(), Stop> {
        let n = self.robots.len();
        for r in 0..n {
            if matches!(self.plans[r], Plan::Move(_)) {
                self.resolve(r);
            }
        }
        if self.p.collision == Collision::Blackboard {
            return Ok(());
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
                let partner = match self.plans[o] {
                    Plan::Wait | Plan::Blocked(_) => Partner::Stays,
                    Plan::Move(_) if self.status[o] == STAYS => Partner::Stays,
                    Plan::Busy if self.robots[o].waiting_for != NONE => Partner::Penalised,
                    _ => Partner::Busy,
                };
                if collision::relays(partner, self.p.relay_with)
                    && !self.relaying[o]
                    && self.robots[r].loaded != self.robots[o].loaded
                {
                    // 4.6.1: the robot carrying the module hands it to the other.
                    self.relaying[r] = true;
                    self.relaying[o] = true;
                    self.robots[r].loaded = !self.robots[r].loaded;
                    self.robots[o].loaded = !self.robots[o].loaded;
                    self.robots[r].busy = self.p.relay_d - 1;
                    // The relay resolves the collision a penalised robot was waiting on.
                    self.robots[o].busy = self.p.relay_d - 1;
                    self.robots[o].waiting_for = NONE;
                    self.robots[o].give_way = false;
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
        if self.p.give_way == GiveWay::Locked {
            self.mark_rings();
        }
        self.find_losers();
        for k in 0..self.losers.len() {
            let (r, t, conflict) = self.losers[k];
            let r = r as usize;
            let conflict = match conflict {
                Conflict::Occupied { .. } => Conflict::Occupied {
                    ahead_gives_way: self.queued_on_yielding(t),
                },
                other => other,
            };
            self.losers[k].2 = conflict;
            let other = match self.plans[r] {
                Plan::Blocked(_) => self.claimant(t, r),
                _ => Some(self.occupant[t as usize] as usize),
            };
            let meeting = Meeting::of(conflict, self.p.give_way, self.robots[r].loaded);
            match self.collision_rule.decide(&meeting, None)? {
                Outcome::Keeps => {}
                Outcome::Waits => self.collide(r, t, other, false),
                Outcome::GivesWay => self.collide(r, t, other, true),
            }
        }
        Ok(())
    }

    /// The robots that could not do what they planned, in planning order, with the cell each
    /// wanted and why it could not have it; `yielding` marks the robots that give way: the
    /// smaller tokens of locks, and those still paying the penalty before they do.
    fn find_losers(&mut self) {
        self.losers.clear();
        for k in 0..self.robots.len() {
            let r = self.order[k] as usize;
            self.yielding[r] = self.plans[r] == Plan::Busy && self.robots[r].give_way;
            if self.relaying[r] {
                continue;
            }
            let t = match self.plans[r] {
                Plan::Blocked(t) => t,
                Plan::Move(t) if self.status[r] == STAYS => t,
                _ => continue,
            };
            let o = self.occupant[t as usize];
            let conflict = match o {
                // Lost the claim on a free cell to a larger token.
                NONE => Conflict::Claimed,
                o if self.locked(r, o as usize) => Conflict::Locked {
                    ahead_larger: self.position[o as usize] < self.position[r],
                },
                _ => Conflict::Occupied {
                    ahead_gives_way: false,
                },
            };
            self.yielding[r] = conflict == Conflict::Locked { ahead_larger: true };
            self.losers.push((r as u32, t, conflict));
        }
    }

    /// Whether the robot on cell `t` gives way as the smaller token of a lock, or waits,
    /// directly or through others, on one that does (only where locked robots alone give way).
    /// Each robot's answer is kept for the step, so every queue is walked once.
    fn queued_on_yielding(&mut self, t: u32) -> bool {
        if self.p.give_way == GiveWay::EveryLoser {
            return false;
        }
        self.chain.clear();
        let mut q = self.occupant[t as usize];
        let answer = loop {
            if q == NONE {
                break false;
            }
            let r = q as usize;
            if self.yielding[r] {
                break true;
            }
            match self.lock[r] & (QUEUED | BEHIND | ON_QUEUE) {
                0 => {}
                ON_QUEUE => break false,
                known => break known & BEHIND != 0,
            }
            self.lock[r] |= ON_QUEUE;
            self.chain.push(q);
            q = self.ahead[r];
        };
        for &p in &self.chain {
            let l = &mut self.lock[p as usize];
            *l = (*l & !ON_QUEUE) | QUEUED | if answer { BEHIND } else { 0 };
        }
        answer
    }
}
