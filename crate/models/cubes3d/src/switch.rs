//! The second phase of a step (section 6): each unit switches its own target when its
//! difference has stayed under the threshold long enough.

use super::{Cubes, HELD_LIT, MAX_TARGETS};

impl Cubes {
    /// The target most units are working toward (the lower index on a tie).
    pub(super) fn main_target(&self) -> usize {
        let mut count = [0usize; MAX_TARGETS];
        for &c in &self.units {
            count[self.target[c as usize] as usize] += 1;
        }
        let best = count.iter().copied().max().unwrap_or(0);
        count.iter().position(|&n| n == best).unwrap_or(0)
    }

    /// The unit at `c` moves on to target `to` (section 6): if that target asks for it and the
    /// unit sees the light, it holds still until its next switch.
    pub(super) fn switch_unit(&mut self, c: usize, to: usize) {
        self.target[c] = to as u8;
        self.stable[self.upos[c] as usize] = 0;
        self.took[self.upos[c] as usize] = self.steps;
        self.switches += 1;
        self.flags[c] &= !HELD_LIT;
        if self.targets[to].hold_lit && self.lit(c) {
            self.flags[c] |= HELD_LIT;
        }
        self.rediff(c);
        self.refresh(c);
    }

    /// The switching rule of section 6, run by every unit after each step: a unit whose D_0
    /// has stayed under its target's threshold for `stable_steps` steps moves on to the next
    /// target.
    pub(super) fn switch_targets(&mut self) {
        for k in 0..self.units.len() {
            let c = self.units[k] as usize;
            if self.diff[k] < self.targets[self.target[c] as usize].threshold {
                self.stable[k] += 1;
            } else {
                self.stable[k] = 0;
            }
            if self.stable[k] >= self.stable_steps {
                let next = (self.target[c] as usize + 1) % self.targets.len();
                self.switch_unit(c, next);
            }
        }
    }
}
