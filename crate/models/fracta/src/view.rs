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
    /// The box is copied into a grid of its own with a blocked ring round it, so the flood steps
    /// by fixed offsets (one set for even rows, one for odd) with no bounds check and no
    /// division: it was a fifth to a quarter of a step when it mapped every neighbour back from
    /// its lattice index.
    pub(super) fn holes(&self) -> u64 {
        let w = self.lattice.w;
        let (mut x0, mut y0, mut x1, mut y1) = (u32::MAX, u32::MAX, 0, 0);
        for (u, unit) in self.units.iter().enumerate() {
            if self.occ.get(unit.cell as usize) == Some(&(u as u32)) {
                let (x, y) = (unit.cell % w, unit.cell / w);
                (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
            }
        }
        if x0 > x1 {
            return 0;
        }
        let (bx0, by0) = (x0.saturating_sub(1), y0.saturating_sub(1));
        let bx1 = (x1 + 1).min(w - 1);
        let by1 = (y1 + 1).min(self.lattice.h - 1);
        let (bw, bh) = ((bx1 - bx0 + 1) as usize, (by1 - by0 + 1) as usize);
        // The box at (1, 1) of a grid one cell wider on every side; the ring stays blocked.
        let gw = bw + 2;
        let mut grid = vec![BLOCKED; gw * (bh + 2)];
        for r in 0..bh {
            let start = (by0 as usize + r) * w as usize + bx0 as usize;
            let row = &mut grid[(r + 1) * gw + 1..][..bw];
            for (g, &o) in row.iter_mut().zip(&self.occ[start..start + bw]) {
                if o == NO_UNIT {
                    *g = ENCLOSED;
                }
            }
        }
        // The six neighbours of a cell on an even and on an odd lattice row: the grid offset, and
        // whether the neighbour's row has the other parity.
        let offsets = [0, 1].map(|parity| {
            let c = Coord::xy(2, 2 + parity);
            [0, 1, 2, 3, 4, 5].map(|dir| {
                let n = self.lattice.step(c, dir);
                let offset = (n.y - c.y) as isize * gw as isize + (n.x - c.x) as isize;
                (offset, (n.y - c.y).unsigned_abs() as usize & 1)
            })
        });
        // Stack entries: a grid index times two plus its lattice row's parity.
        let mut stack: Vec<usize> = Vec::new();
        for r in 0..bh {
            let parity = (by0 as usize + r) & 1;
            let border_row = r == 0 || r == bh - 1;
            for c in 0..bw {
                let k = (r + 1) * gw + c + 1;
                if (border_row || c == 0 || c == bw - 1) && grid[k] == ENCLOSED {
                    grid[k] = OUTSIDE;
                    stack.push(k << 1 | parity);
                }
            }
        }
        while let Some(entry) = stack.pop() {
            let (k, parity) = (entry >> 1, entry & 1);
            for &(offset, flip) in &offsets[parity] {
                let j = k.wrapping_add_signed(offset);
                if grid[j] == ENCLOSED {
                    grid[j] = OUTSIDE;
                    stack.push(j << 1 | (parity ^ flip));
                }
            }
        }
        // The box's cells beyond the units' box lie on its border, seeded when empty: what is
        // still enclosed lies within the units' box.
        grid.iter().filter(|&&g| g == ENCLOSED).count() as u64
    }
}

/// Cells of the holes' grid: a unit or the ring round the box, an empty cell not (yet) reached
/// from the box's border, an empty cell reached from it.
const BLOCKED: u8 = 0;
const ENCLOSED: u8 = 1;
const OUTSIDE: u8 = 2;
