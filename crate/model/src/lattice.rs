//! The three lattices, each behind the same neighbourhood API ([`Lattice`]).
//!
//! Cells are numbered row by row from the top-left (and layer by layer from the ground for the
//! cubic lattice); [`Lattice::index`] and [`Lattice::coord`] are the only place that layout is
//! written down. Directions are numbered so that rotations are index arithmetic:
//! - square: 0 east (+x), 1 north (-y), 2 west, 3 south (+y), counter-clockwise;
//! - hex: 0 east, 1 north-east, 2 north-west, 3 west, 4 south-west, 5 south-east,
//!   counter-clockwise in steps of 60 degrees, so `(d + 1) % 6` is a 60 degree turn;
//! - cubic: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z (up), 5 -z, so `d ^ 1` is the opposite face.

use serde::{Deserialize, Serialize};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum LatticeKind {
    Square,
    Hex,
    Cubic,
}

/// A cell position. `z` is 0 on the planar lattices.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct Coord {
    pub x: i32,
    pub y: i32,
    pub z: i32,
}

impl Coord {
    pub const fn new(x: i32, y: i32, z: i32) -> Self {
        Coord { x, y, z }
    }
    pub const fn xy(x: i32, y: i32) -> Self {
        Coord { x, y, z: 0 }
    }
}

/// One neighbourhood API for every lattice.
pub trait Lattice {
    /// Number of neighbour directions (4, 6 or 6).
    const DIRECTIONS: usize;

    fn kind(&self) -> LatticeKind;
    /// Width, height and depth in cells (depth 1 on planar lattices).
    fn dims(&self) -> [u32; 3];
    fn len(&self) -> usize {
        let [w, h, d] = self.dims();
        w as usize * h as usize * d as usize
    }
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    fn contains(&self, c: Coord) -> bool {
        let [w, h, d] = self.dims();
        c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x < w as i32 && c.y < h as i32 && c.z < d as i32
    }
    fn index(&self, c: Coord) -> Option<usize> {
        if !self.contains(c) {
            return None;
        }
        let [w, h, _] = self.dims();
        Some((c.z as usize * h as usize + c.y as usize) * w as usize + c.x as usize)
    }
    fn coord(&self, i: usize) -> Coord {
        let [w, h, _] = self.dims();
        let (w, h) = (w as usize, h as usize);
        Coord::new((i % w) as i32, ((i / w) % h) as i32, (i / (w * h)) as i32)
    }
    /// The coordinate one step from `c` in direction `dir`, whether or not it is inside.
    fn step(&self, c: Coord, dir: usize) -> Coord;
    /// The neighbouring cell index in direction `dir`, if it is inside the lattice.
    fn neighbour(&self, i: usize, dir: usize) -> Option<usize> {
        self.index(self.step(self.coord(i), dir))
    }
    /// Every neighbouring cell inside the lattice, in direction order.
    fn neighbours(&self, i: usize) -> impl Iterator<Item = usize> + '_ {
        (0..Self::DIRECTIONS).filter_map(move |d| self.neighbour(i, d))
    }
    fn opposite(dir: usize) -> usize;
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Square {
    pub w: u32,
    pub h: u32,
}

impl Square {
    pub const DX: [i32; 4] = [1, 0, -1, 0];
    pub const DY: [i32; 4] = [0, -1, 0, 1];
    pub fn new(w: u32, h: u32) -> Self {
        Square { w, h }
    }
}

impl Lattice for Square {
    const DIRECTIONS: usize = 4;
    #[inline]
    fn kind(&self) -> LatticeKind {
        LatticeKind::Square
    }
    #[inline]
    fn dims(&self) -> [u32; 3] {
        [self.w, self.h, 1]
    }
    #[inline]
    fn step(&self, c: Coord, dir: usize) -> Coord {
        Coord::new(c.x + Self::DX[dir], c.y + Self::DY[dir], c.z)
    }
    #[inline]
    fn opposite(dir: usize) -> usize {
        (dir + 2) % 4
    }
}

/// A hexagonal lattice in "odd-r" offset layout: odd rows sit half a cell to the right, rows run
/// top to bottom. The geometry depends on row parity, so a shape moved by an odd number of rows
/// must be re-laid through [`Hex::to_axial`] and [`Hex::from_axial`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Hex {
    pub w: u32,
    pub h: u32,
}

impl Hex {
    /// Axial (q, r) offsets of the six directions, r pointing down.
    pub const AXIAL: [(i32, i32); 6] = [(1, 0), (1, -1), (0, -1), (-1, 0), (-1, 1), (0, 1)];

    pub fn new(w: u32, h: u32) -> Self {
        Hex { w, h }
    }

    /// Offset (x, y) to axial (q, r).
    #[inline]
    pub fn to_axial(c: Coord) -> (i32, i32) {
        (c.x - (c.y - (c.y & 1)) / 2, c.y)
    }

    /// Axial (q, r) to offset (x, y).
    #[inline]
    pub fn from_axial(q: i32, r: i32) -> Coord {
        Coord::xy(q + (r - (r & 1)) / 2, r)
    }

    /// Centre of a cell in drawing units (cell width 1, row spacing sqrt(3)/2).
    #[inline]
    pub fn centre(c: Coord) -> (f64, f64) {
        let x = c.x as f64 + if c.y & 1 == 1 { 0.5 } else { 0.0 };
        (x, c.y as f64 * 0.866_025_403_784_438_6)
    }
}

impl Lattice for Hex {
    const DIRECTIONS: usize = 6;
    #[inline]
    fn kind(&self) -> LatticeKind {
        LatticeKind::Hex
    }
    #[inline]
    fn dims(&self) -> [u32; 3] {
        [self.w, self.h, 1]
    }
    #[inline]
    fn step(&self, c: Coord, dir: usize) -> Coord {
        let (q, r) = Hex::to_axial(c);
        let (dq, dr) = Self::AXIAL[dir];
        Hex::from_axial(q + dq, r + dr)
    }
    #[inline]
    fn opposite(dir: usize) -> usize {
        (dir + 3) % 6
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cubic {
    pub w: u32,
    pub h: u32,
    pub d: u32,
}

impl Cubic {
    pub const DIRS: [(i32, i32, i32); 6] = [
        (1, 0, 0),
        (-1, 0, 0),
        (0, 1, 0),
        (0, -1, 0),
        (0, 0, 1),
        (0, 0, -1),
    ];
    pub fn new(w: u32, h: u32, d: u32) -> Self {
        Cubic { w, h, d }
    }
}

impl Lattice for Cubic {
    const DIRECTIONS: usize = 6;
    #[inline]
    fn kind(&self) -> LatticeKind {
        LatticeKind::Cubic
    }
    #[inline]
    fn dims(&self) -> [u32; 3] {
        [self.w, self.h, self.d]
    }
    #[inline]
    fn step(&self, c: Coord, dir: usize) -> Coord {
        let (dx, dy, dz) = Self::DIRS[dir];
        Coord::new(c.x + dx, c.y + dy, c.z + dz)
    }
    #[inline]
    fn opposite(dir: usize) -> usize {
        dir ^ 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn symmetric<L: Lattice>(l: &L) {
        for i in 0..l.len() {
            assert_eq!(l.index(l.coord(i)), Some(i));
            for d in 0..L::DIRECTIONS {
                if let Some(j) = l.neighbour(i, d) {
                    assert_eq!(l.neighbour(j, L::opposite(d)), Some(i), "cell {i} dir {d}");
                }
            }
        }
    }

    #[test]
    fn neighbourhoods_are_symmetric() {
        symmetric(&Square::new(5, 4));
        symmetric(&Hex::new(6, 5));
        symmetric(&Cubic::new(3, 4, 5));
    }

    #[test]
    fn interior_degrees() {
        assert_eq!(Square::new(3, 3).neighbours(4).count(), 4);
        assert_eq!(Square::new(3, 3).neighbours(0).count(), 2);
        let hex = Hex::new(5, 5);
        for y in 1..4 {
            let i = hex.index(Coord::xy(2, y)).unwrap();
            assert_eq!(hex.neighbours(i).count(), 6);
        }
        let cube = Cubic::new(3, 3, 3);
        assert_eq!(cube.neighbours(13).count(), 6);
        assert_eq!(cube.neighbours(0).count(), 3);
    }

    #[test]
    fn hex_neighbours_are_at_unit_distance() {
        let hex = Hex::new(8, 8);
        for y in 1..7 {
            for x in 1..7 {
                let c = Coord::xy(x, y);
                let (cx, cy) = Hex::centre(c);
                for d in 0..6 {
                    let (nx, ny) = Hex::centre(hex.step(c, d));
                    let dist = ((nx - cx).powi(2) + (ny - cy).powi(2)).sqrt();
                    assert!((dist - 1.0).abs() < 1e-9, "{c:?} dir {d}");
                }
            }
        }
    }

    #[test]
    fn hex_directions_turn_counter_clockwise() {
        let hex = Hex::new(8, 8);
        let c = Coord::xy(3, 3);
        let (cx, cy) = Hex::centre(c);
        let angle = |d: usize| {
            let (x, y) = Hex::centre(hex.step(c, d));
            // y points down on screen; flip it so counter-clockwise is positive.
            (-(y - cy)).atan2(x - cx).to_degrees()
        };
        for d in 0..6 {
            let a = angle(d).rem_euclid(360.0);
            assert!((a - 60.0 * d as f64).abs() < 1e-6, "dir {d} at {a}");
        }
    }

    #[test]
    fn axial_round_trip() {
        for y in -5..5 {
            for x in -5..5 {
                let c = Coord::xy(x, y);
                let (q, r) = Hex::to_axial(c);
                assert_eq!(Hex::from_axial(q, r), c);
            }
        }
    }
}
