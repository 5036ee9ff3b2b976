//! Step phase 1, the "OK" signals of section 4: faulty units are cut off, and the others take
//! up the description with one spare fewer per unit lost. Nothing else restarts: the algorithm
//! runs on, and the repair is launched by the differences the cut-off raises.

use super::*;

impl Fracta {
    /// Section 4: a unit that sends no "OK" at the start of a step is cut off by its neighbours.
    /// If that splits the system, the largest part carries on (the part holding the smallest
    /// unit id among equals) and the others are stranded. The goal then loses one priority
    /// level per unit lost (the description with one spare fewer, section 3.3). x and the
    /// irritation carry on from the step before: equation 2's initial state is the start's
    /// (interpretation 8), so the units whose difference the cut-off raised above their x pass
    /// equation 3 at once.
    pub(super) fn cut_off_faulty(&mut self) {
        if self.pending == 0 {
            return;
        }
        let before = self.working.len() + self.pending;
        for u in 0..self.units.len() {
            if self.units[u].status == Status::Faulty {
                let cell = self.units[u].cell;
                self.units[u].status = Status::CutOff;
                self.occ[cell as usize] = NO_UNIT;
                self.ghost[cell as usize] = code::CUT_OFF;
                self.cut_off += 1;
                self.events.push(Event {
                    cell,
                    kind: event::CUT_OFF,
                });
            }
        }
        self.pending = 0;
        let groups = self.components();
        if groups.len() > 1 {
            let keep = groups
                .iter()
                .enumerate()
                .max_by_key(|(i, g)| (g.len(), std::cmp::Reverse(*i)))
                .map(|(i, _)| i)
                .unwrap_or(0);
            for (i, g) in groups.iter().enumerate() {
                if i == keep {
                    continue;
                }
                for &u in g {
                    let cell = self.units[u as usize].cell;
                    self.units[u as usize].status = Status::Stranded;
                    self.occ[cell as usize] = NO_UNIT;
                    self.ghost[cell as usize] = code::STRANDED;
                    self.stranded += 1;
                }
            }
            self.working
                .retain(|&u| self.units[u as usize].status == Status::Working);
        }
        self.goal = self.goal.without_last_levels(before - self.working.len());
        self.refresh();
    }
}
