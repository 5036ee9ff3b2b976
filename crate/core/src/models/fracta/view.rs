//! Figures the outputs read from the state: the mean difference and the enclosed holes.

use super::*;

impl Fracta {
    pub(super) fn mean_difference(&self) -> f64 {
        if self.working.is_empty() {
            return 0.0;
        }
        let sum: u64 = self
            .working
            .iter()
            .map(|&u| u64::from(self.diff[u as usize]))
            .sum();
        sum as f64 / self.working.len() as f64
    }

    /// Empty cells enclosed by units: not reachable from the lattice's edge through empty cells.
    /// A ring of units round such a cell cannot open (its units are not movable) and no unit can
    /// roll into it, so a goal without holes is then out of reach for good.
    pub(super) fn holes(&self) -> u64 {
        let n = self.occ.len();
        let mut outside = vec![false; n];
        let mut queue: VecDeque<u32> = VecDeque::new();
        for (i, out) in outside.iter_mut().enumerate() {
            if self.nbr[i].contains(&NO_UNIT) && self.occ[i] == NO_UNIT {
                *out = true;
                queue.push_back(i as u32);
            }
        }
        while let Some(i) = queue.pop_front() {
            for &j in &self.nbr[i as usize] {
                if j != NO_UNIT && !outside[j as usize] && self.occ[j as usize] == NO_UNIT {
                    outside[j as usize] = true;
                    queue.push_back(j);
                }
            }
        }
        (0..n)
            .filter(|&i| self.occ[i] == NO_UNIT && !outside[i])
            .count() as u64
    }
}
