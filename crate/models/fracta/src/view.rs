//! Figures the outputs read from the state: the mean difference and the enclosed holes.

use super::*;
use kumiki_model::lattice::Coord;

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
    ///
    /// Metrics are read after every step (the page charts every step), so the flood stays inside
    /// the units' bounding box grown by one cell. A neighbour differs by at most one in each offset
    /// coordinate, so a path from the box to the edge crosses the box's border, whose cells lie
    /// outside the units' box or on the lattice's edge: the empty ones are the flood's seeds.
    pub(super) fn holes(&self) -> u64 {
        let (mut x0, mut y0, mut x1, mut y1) = (i32::MAX, i32::MAX, i32::MIN, i32::MIN);
        for (u, unit) in self.units.iter().enumerate() {
            if self.occ.get(unit.cell as usize) == Some(&(u as u32)) {
                let c = self.lattice.coord(unit.cell as usize);
                (x0, y0, x1, y1) = (x0.min(c.x), y0.min(c.y), x1.max(c.x), y1.max(c.y));
            }
        }
        if x0 > x1 {
            return 0;
        }
        let (bx0, by0) = ((x0 - 1).max(0), (y0 - 1).max(0));
        let bx1 = (x1 + 1).min(self.lattice.w as i32 - 1);
        let by1 = (y1 + 1).min(self.lattice.h as i32 - 1);
        let bw = (bx1 - bx0 + 1) as usize;
        let local = |cell: u32| -> Option<usize> {
            let c = self.lattice.coord(cell as usize);
            ((bx0..=bx1).contains(&c.x) && (by0..=by1).contains(&c.y))
                .then(|| (c.y - by0) as usize * bw + (c.x - bx0) as usize)
        };
        let mut outside = vec![false; bw * (by1 - by0 + 1) as usize];
        let mut queue: VecDeque<u32> = VecDeque::new();
        for y in by0..=by1 {
            for x in bx0..=bx1 {
                let cell = self
                    .lattice
                    .index(Coord::xy(x, y))
                    .expect("inside the lattice") as u32;
                let border = x == bx0 || x == bx1 || y == by0 || y == by1;
                if self.occ[cell as usize] == NO_UNIT
                    && (border || self.nbr[cell as usize].contains(&NO_UNIT))
                {
                    outside[(y - by0) as usize * bw + (x - bx0) as usize] = true;
                    queue.push_back(cell);
                }
            }
        }
        while let Some(i) = queue.pop_front() {
            for &j in &self.nbr[i as usize] {
                if j == NO_UNIT || self.occ[j as usize] != NO_UNIT {
                    continue;
                }
                if let Some(k) = local(j) {
                    if !outside[k] {
                        outside[k] = true;
                        queue.push_back(j);
                    }
                }
            }
        }
        let mut holes = 0;
        for y in y0..=y1 {
            for x in x0..=x1 {
                let cell = self
                    .lattice
                    .index(Coord::xy(x, y))
                    .expect("inside the lattice");
                let k = (y - by0) as usize * bw + (x - bx0) as usize;
                if self.occ[cell] == NO_UNIT && !outside[k] {
                    holes += 1;
                }
            }
        }
        holes
    }
}
