//! The structure on the cubic lattice and the pairwise motion of sections 2 and 3.2.
//!
//! A move of unit P (at p) is made by a neighbour Q (the carrier, at q = p - e): Q turns its body
//! a quarter turn about an axis `a` perpendicular to the bond e, holding on to a support unit on
//! that axis (at q + a or q - a), and P swings from q + e to q + f, where f is perpendicular to
//! both e and a. The move is allowed when
//! 1. Q has a support on the axis;
//! 2. the destination q + f is empty and inside the space;
//! 3. the swing hits no unit: the cell p + f, the corner P sweeps through, is empty;
//! 4. nothing else is carried and the structure stays connected: P lets go of every other bond,
//!    Q lets go of every bond not on the axis except the one to P, and every unit must still be
//!    held by the rest of the structure during the swing (so also after it);
//! 5. on a holding ground plane, the structure stays fixed to it: a unit other than P still
//!    touches it.
//!
//! Rule 4 is checked exactly, in [`super::connect`], which also lists the positions a unit can
//! reach by such moves.

use std::sync::Arc;

use super::types::TYPE_OF_MASK;

/// Empty cells around the space: units stay this far from the edge of the cell buffer, so
/// neighbour arithmetic two cells out never leaves it.
pub const PAD: u32 = 2;

/// Unit vectors of the six directions.
pub const DIRS: [[i32; 3]; 6] = [
    [1, 0, 0],
    [-1, 0, 0],
    [0, 1, 0],
    [0, -1, 0],
    [0, 0, 1],
    [0, 0, -1],
];

/// A reachable position: the destination cell, the carrier and the axis it turns about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Move {
    pub dest: u32,
    pub carrier: u32,
    pub axis: u8,
}

/// Units on a padded cubic lattice. A cell holds a unit exactly when its type code is not 0 (in a
/// connected structure of two or more units every unit has a neighbour, so a type).
#[derive(Clone, Debug)]
pub struct Structure {
    pub dims: [u32; 3],
    pub stride: [isize; 6],
    /// Connection type code per cell, 0 where there is no unit.
    pub types: Vec<u8>,
    /// Cells no unit may occupy: the padding, and what lies below a ground plane. Fixed from
    /// the start, so shared by every copy (keyframe) of the structure.
    pub wall: Arc<[bool]>,
    /// A ground plane that holds the units touching it, under the layer z = this: it is a
    /// support on the vertical axis of every unit in that layer. Set with [`Structure::hold_on_plane`].
    pub plane: Option<i32>,
    /// Units in the layer on the plane (0 without one).
    pub on_plane: u32,
}

impl Structure {
    /// An empty structure; cells outside `lo..hi` (per axis) are walls.
    pub fn new(dims: [u32; 3], lo: [u32; 3], hi: [u32; 3]) -> Structure {
        let [w, h, d] = dims;
        let (wi, hi_) = (w as isize, h as isize);
        let len = (w * h * d) as usize;
        let mut wall = vec![true; len];
        for z in lo[2]..hi[2] {
            for y in lo[1]..hi[1] {
                for x in lo[0]..hi[0] {
                    wall[((z * h + y) * w + x) as usize] = false;
                }
            }
        }
        Structure {
            dims,
            stride: [1, -1, wi, -wi, wi * hi_, -wi * hi_],
            types: vec![0; len],
            wall: wall.into(),
            plane: None,
            on_plane: 0,
        }
    }

    /// A ground plane under the layer `z` holds the units touching it from now on.
    pub fn hold_on_plane(&mut self, z: i32) {
        self.plane = Some(z);
        self.on_plane = (0..self.len())
            .filter(|&i| self.occupied(i) && self.in_plane_layer(i))
            .count() as u32;
    }

    /// Is the cell `i` in the layer on a holding plane?
    #[inline]
    pub fn in_plane_layer(&self, i: usize) -> bool {
        let layer = self.dims[0] as usize * self.dims[1] as usize;
        self.plane == Some((i / layer) as i32)
    }

    /// Keeps the count of units on the plane as the unit at `i` arrives (+1) or leaves (-1).
    fn count_on_plane(&mut self, i: usize, arrives: bool) {
        if self.plane.is_some() && self.in_plane_layer(i) {
            if arrives {
                self.on_plane += 1;
            } else {
                self.on_plane -= 1;
            }
        }
    }

    pub fn len(&self) -> usize {
        self.types.len()
    }

    pub fn is_empty(&self) -> bool {
        self.types.is_empty()
    }

    pub fn coord(&self, i: usize) -> [i32; 3] {
        let [w, h, _] = self.dims;
        let (w, h) = (w as usize, h as usize);
        [(i % w) as i32, ((i / w) % h) as i32, (i / (w * h)) as i32]
    }

    pub fn index(&self, c: [i32; 3]) -> Option<usize> {
        let [w, h, d] = self.dims;
        if c.iter().any(|&v| v < 0) || c[0] >= w as i32 || c[1] >= h as i32 || c[2] >= d as i32 {
            return None;
        }
        Some(((c[2] as u32 * h + c[1] as u32) * w + c[0] as u32) as usize)
    }

    /// The cell next to `i` in direction `dir`. Only for cells at least one cell from the edge.
    #[inline]
    pub fn nb(&self, i: usize, dir: usize) -> usize {
        (i as isize + self.stride[dir]) as usize
    }

    #[inline]
    pub fn occupied(&self, i: usize) -> bool {
        self.types[i] != 0
    }

    /// The occupied faces of the cell `i`.
    pub fn mask(&self, i: usize) -> u8 {
        let mut m = 0;
        for d in 0..6 {
            if self.occupied(self.nb(i, d)) {
                m |= 1 << d;
            }
        }
        m
    }

    /// Places units (cells not yet typed) and types everything. For construction only.
    pub fn place(&mut self, cells: &[usize]) {
        for &c in cells {
            self.types[c] = u8::MAX;
            self.count_on_plane(c, true);
        }
        for &c in cells {
            self.types[c] = TYPE_OF_MASK[self.mask(c) as usize];
        }
    }

    /// Types of the unit at `i` and of its neighbours, sorted by decreasing code, padded with 0.
    pub fn profile(&self, i: usize) -> [u8; 7] {
        let mut out = [0u8; 7];
        out[0] = self.types[i];
        let mut n = 1;
        for d in 0..6 {
            let j = self.nb(i, d);
            if self.occupied(j) {
                out[n] = self.types[j];
                n += 1;
            }
        }
        sort_desc(&mut out[1..]);
        out
    }

    /// [`Structure::profile`] of the unit as it would be after moving from `from` to `to`.
    pub fn profile_after(&self, from: usize, to: usize) -> [u8; 7] {
        let occ = |x: usize| x == to || (x != from && self.types[x] != 0);
        let mask = |x: usize| {
            let mut m = 0u8;
            for d in 0..6 {
                if occ(self.nb(x, d)) {
                    m |= 1 << d;
                }
            }
            m
        };
        let mut out = [0u8; 7];
        out[0] = TYPE_OF_MASK[mask(to) as usize];
        let mut n = 1;
        for d in 0..6 {
            let j = self.nb(to, d);
            if occ(j) {
                out[n] = TYPE_OF_MASK[mask(j) as usize];
                n += 1;
            }
        }
        sort_desc(&mut out[1..]);
        out
    }

    /// Moves the unit at `from` to the empty cell `to` (which must touch another unit) and
    /// retypes the cells around both.
    pub fn relocate(&mut self, from: usize, to: usize) {
        self.count_on_plane(from, false);
        self.count_on_plane(to, true);
        self.types[from] = 0;
        self.types[to] = u8::MAX;
        self.retype_around(to);
        self.retype_around(from);
    }

    /// Adds a unit at the empty cell `at`.
    pub fn add(&mut self, at: usize) {
        self.count_on_plane(at, true);
        self.types[at] = u8::MAX;
        self.retype_around(at);
    }

    /// Removes the unit at `at`.
    pub fn remove(&mut self, at: usize) {
        self.count_on_plane(at, false);
        self.types[at] = 0;
        self.retype_around(at);
    }

    fn retype_around(&mut self, c: usize) {
        if self.occupied(c) {
            self.types[c] = TYPE_OF_MASK[self.mask(c) as usize];
        }
        for d in 0..6 {
            let j = self.nb(c, d);
            if self.occupied(j) {
                self.types[j] = TYPE_OF_MASK[self.mask(j) as usize];
            }
        }
    }

    /// Rule 5: with a holding plane, does a unit other than the one at `p` still touch it? (A
    /// carrier on the plane that turns about a horizontal axis lets go of the plane, but its
    /// support on that axis lies on the plane too and holds on.) Without a plane there is
    /// nothing to hold.
    pub fn plane_holds(&self, p: usize) -> bool {
        self.plane.is_none() || self.on_plane > u32::from(self.in_plane_layer(p))
    }

    /// Has the unit at `q` a support on the axis `a`: a unit, or a holding ground plane?
    pub fn supported(&self, q: usize, a: usize) -> bool {
        self.occupied(self.nb(q, 2 * a))
            || self.occupied(self.nb(q, 2 * a + 1))
            || (a == 2 && self.plane == Some(self.coord(q)[2]))
    }

    /// Every unit, in cell order.
    pub fn units(&self) -> Vec<usize> {
        (0..self.len()).filter(|&i| self.occupied(i)).collect()
    }

    /// Whether all units form one piece (a full search; for construction and tests).
    pub fn connected(&self) -> bool {
        let units = self.units();
        let Some(&first) = units.first() else {
            return true;
        };
        let mut seen = vec![false; self.len()];
        seen[first] = true;
        let mut stack = vec![first];
        let mut n = 1;
        while let Some(x) = stack.pop() {
            for d in 0..6 {
                let y = self.nb(x, d);
                if self.occupied(y) && !seen[y] {
                    seen[y] = true;
                    n += 1;
                    stack.push(y);
                }
            }
        }
        n == units.len()
    }
}

/// Sorts a few codes in decreasing order (insertion sort; at most six).
fn sort_desc(v: &mut [u8]) {
    for i in 1..v.len() {
        let mut j = i;
        while j > 0 && v[j - 1] < v[j] {
            v.swap(j - 1, j);
            j -= 1;
        }
    }
}
