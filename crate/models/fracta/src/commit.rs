//! Step phase 4: the planned rolls carried out one by one, conflicts cancelled.

use super::*;

impl Fracta {
    /// Carries out the planned rolls one by one in a random order. A roll goes ahead only if,
    /// in the configuration left by the rolls before it, it is still legal and neither its unit
    /// nor its pivot has already taken part in a roll this step; otherwise it is cancelled (a
    /// conflict) and the unit waits.
    pub(super) fn commit(&mut self) {
        let stamp = self.steps;
        let mut plans = std::mem::take(&mut self.plans);
        self.rng.shuffle(&mut plans);
        for plan in &plans {
            let u = plan.unit;
            let cell = self.units[u as usize].cell;
            let pivot_cell = self.nbr[cell as usize][plan.pivot_slot as usize];
            let ok = pivot_cell != NO_UNIT
                && self.busy[u as usize] != stamp
                && self.busy[plan.pivot as usize] != stamp
                && self.occ[pivot_cell as usize] == plan.pivot;
            let target = if ok {
                let mask = self.ring(cell);
                self.legal(cell, mask, plan.pivot_slot as usize, plan.turn)
            } else {
                None
            };
            match target {
                Some(to) => {
                    self.occ[cell as usize] = NO_UNIT;
                    self.occ[to as usize] = u;
                    self.ghost[to as usize] = code::EMPTY;
                    self.units[u as usize].cell = to;
                    self.busy[u as usize] = stamp;
                    self.busy[plan.pivot as usize] = stamp;
                    self.moves += 1;
                    self.events.push(Event {
                        cell: to,
                        kind: event::MOVED,
                    });
                }
                None => {
                    self.conflicts += 1;
                    self.events.push(Event {
                        cell,
                        kind: event::CONFLICT,
                    });
                }
            }
        }
        self.plans = plans;
    }
}
