//! Where lattice cells are in the view's world space, and which cell a point falls in: the one
//! place the page's drawing, picking, editors and annotations take lattice geometry from. The
//! numbering and the neighbour order are the core's ([`kumiki_model::lattice`]); this adds the
//! drawing units: square cells are unit squares at integer corners, hex rows are sqrt(3)/2 apart
//! with odd rows shifted half a cell right (pointy-top hexagons of radius 1/sqrt(3)).

use kumiki_model::lattice::{Coord, Cubic, Hex, Lattice, LatticeKind, Square};

/// Vertical distance between hex rows.
pub const HEX_ROW: f64 = 0.866_025_403_784_438_6;
/// Centre-to-corner radius of a hex cell.
pub const HEX_RADIUS: f64 = 0.577_350_269_189_625_8;

/// An axis-aligned rectangle in world units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    pub x0: f64,
    pub y0: f64,
    pub x1: f64,
    pub y1: f64,
}

/// A lattice of a kind and size: what geometry needs to know.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Grid {
    pub kind: LatticeKind,
    pub dims: [u32; 3],
}

impl Grid {
    pub fn new(kind: LatticeKind, dims: [u32; 3]) -> Grid {
        Grid { kind, dims }
    }

    pub fn len(&self) -> usize {
        self.dims.iter().map(|&d| d as usize).product()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// A cell index's (x, y, z); z is 0 on the planar lattices.
    pub fn coord(&self, i: usize) -> [u32; 3] {
        let [w, h, _] = self.dims.map(|d| d.max(1) as usize);
        [(i % w) as u32, ((i / w) % h) as u32, (i / (w * h)) as u32]
    }

    /// Centre of a planar cell in world units.
    pub fn centre(&self, i: usize) -> [f64; 2] {
        let [x, y, _] = self.coord(i);
        cell_centre(self.kind, x, y)
    }

    /// The world rectangle the whole planar lattice covers.
    pub fn bounds(&self) -> Bounds {
        let [w, h, _] = self.dims.map(f64::from);
        match self.kind {
            LatticeKind::Hex => Bounds {
                x0: 0.0,
                y0: 0.0,
                x1: w + 0.5,
                y1: (h - 1.0) * HEX_ROW + 2.0 * HEX_RADIUS,
            },
            _ => Bounds {
                x0: 0.0,
                y0: 0.0,
                x1: w,
                y1: h,
            },
        }
    }

    /// The planar cell under a world point, if it is on the lattice.
    pub fn cell_at(&self, wx: f64, wy: f64) -> Option<usize> {
        let (x, y) = match self.kind {
            LatticeKind::Hex => {
                // Pointy-top axial coordinates of the point, rounded to the nearest hex.
                let r = (wy - HEX_RADIUS) / HEX_ROW;
                let q = (wx - 0.5) - r / 2.0;
                let s = -q - r;
                let (mut rq, mut rr, rs) = (q.round(), r.round(), s.round());
                let (dq, dr, ds) = ((rq - q).abs(), (rr - r).abs(), (rs - s).abs());
                if dq > dr && dq > ds {
                    rq = -rr - rs;
                } else if dr > ds {
                    rr = -rq - rs;
                }
                let c = Hex::from_axial(rq as i32, rr as i32);
                (c.x, c.y)
            }
            _ => (wx.floor() as i32, wy.floor() as i32),
        };
        let [w, h, _] = self.dims;
        (x >= 0 && y >= 0 && (x as u32) < w && (y as u32) < h)
            .then(|| y as usize * w as usize + x as usize)
    }

    /// Neighbours of a cell in the core's direction order, `None` where the neighbour would be
    /// off the lattice.
    pub fn neighbours(&self, i: usize) -> Vec<Option<usize>> {
        let [w, h, d] = self.dims;
        match self.kind {
            LatticeKind::Square => around(&Square::new(w, h), i),
            LatticeKind::Hex => around(&Hex::new(w, h), i),
            LatticeKind::Cubic => around(&Cubic::new(w, h, d), i),
        }
    }

    /// World bounds of the non-empty planar cells, two cells wider all round, or `None` when
    /// every cell is empty: what a fitted view frames. A row's cells share their height and lie
    /// in order along it, so only each row's first and last non-empty cells are placed: the view
    /// asks this at every frame it draws, and a filled 4096² lattice has 16 M cells.
    pub fn content_bounds(&self, cells: &[u8]) -> Option<Bounds> {
        let mut b = Bounds {
            x0: f64::INFINITY,
            y0: f64::INFINITY,
            x1: f64::NEG_INFINITY,
            y1: f64::NEG_INFINITY,
        };
        let width = self.dims[0].max(1) as usize;
        for (row, line) in cells.chunks(width).enumerate() {
            let Some(first) = line.iter().position(|&c| c != 0) else {
                continue;
            };
            let last = line.iter().rposition(|&c| c != 0).unwrap_or(first);
            for x in [first, last] {
                let [cx, cy] = self.centre(row * width + x);
                b.x0 = b.x0.min(cx);
                b.x1 = b.x1.max(cx);
                b.y0 = b.y0.min(cy);
                b.y1 = b.y1.max(cy);
            }
        }
        if b.x1 < b.x0 {
            return None;
        }
        let pad = 2.0
            + if self.kind == LatticeKind::Hex {
                HEX_RADIUS
            } else {
                0.5
            };
        Some(Bounds {
            x0: b.x0 - pad,
            y0: b.y0 - pad,
            x1: b.x1 + pad,
            y1: b.y1 + pad,
        })
    }
}

fn around<L: Lattice>(lattice: &L, i: usize) -> Vec<Option<usize>> {
    (0..L::DIRECTIONS)
        .map(|d| lattice.neighbour(i, d))
        .collect()
}

/// Centre of planar cell (x, y) in world units.
pub fn cell_centre(kind: LatticeKind, x: u32, y: u32) -> [f64; 2] {
    match kind {
        LatticeKind::Hex => {
            let (cx, cy) = Hex::centre(Coord::xy(x as i32, y as i32));
            [cx + 0.5, cy + HEX_RADIUS]
        }
        _ => [f64::from(x) + 0.5, f64::from(y) + 0.5],
    }
}

/// Corners of a pointy-top hexagon of radius `r` around a centre, clockwise from the upper right.
pub fn hex_corners(cx: f64, cy: f64, r: f64) -> [[f64; 2]; 6] {
    std::array::from_fn(|k| {
        let a = (60.0 * k as f64 - 30.0).to_radians();
        [cx + r * a.cos(), cy + r * a.sin()]
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_cell_centre_picks_its_own_cell() {
        for kind in [LatticeKind::Square, LatticeKind::Hex] {
            let g = Grid::new(kind, [7, 5, 1]);
            for i in 0..g.len() {
                let [x, y] = g.centre(i);
                assert_eq!(g.cell_at(x, y), Some(i), "{kind:?} cell {i}");
                // Inside the cell, near each corner, still the same cell.
                let r = if kind == LatticeKind::Hex {
                    HEX_RADIUS * 0.8
                } else {
                    0.45
                };
                for [cx, cy] in hex_corners(x, y, r) {
                    if kind == LatticeKind::Hex {
                        assert_eq!(
                            g.cell_at(cx, cy),
                            Some(i),
                            "{kind:?} cell {i} near ({cx}, {cy})"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn points_off_the_lattice_pick_nothing() {
        let g = Grid::new(LatticeKind::Square, [4, 3, 1]);
        assert_eq!(g.cell_at(-0.1, 1.0), None);
        assert_eq!(g.cell_at(4.0, 1.0), None);
        assert_eq!(g.cell_at(1.0, 3.0), None);
        let h = Grid::new(LatticeKind::Hex, [4, 3, 1]);
        assert_eq!(h.cell_at(-0.2, 0.5), None);
    }

    #[test]
    fn hex_neighbours_touch_and_follow_the_core_order() {
        let g = Grid::new(LatticeKind::Hex, [6, 6, 1]);
        let i = 3 * 6 + 2;
        let [x, y] = g.centre(i);
        let around = g.neighbours(i);
        assert_eq!(around.len(), 6);
        for (d, j) in around.iter().enumerate() {
            let [nx, ny] = g.centre(j.unwrap());
            assert!(
                ((nx - x).hypot(ny - y) - 1.0).abs() < 1e-9,
                "direction {d} is one cell away"
            );
            // Direction d points 60·d degrees counter-clockwise from east (y grows downward).
            let angle = (-(ny - y)).atan2(nx - x).to_degrees().rem_euclid(360.0);
            assert!(
                (angle - 60.0 * d as f64).abs() < 1e-6,
                "direction {d} at {angle}"
            );
        }
        assert_eq!(
            Grid::new(LatticeKind::Square, [3, 3, 1]).neighbours(0),
            vec![Some(1), None, None, Some(3)]
        );
    }

    #[test]
    fn content_bounds_pad_the_occupied_cells() {
        let g = Grid::new(LatticeKind::Square, [5, 5, 1]);
        let mut cells = vec![0u8; 25];
        assert_eq!(g.content_bounds(&cells), None);
        cells[2 * 5 + 3] = 1;
        assert_eq!(
            g.content_bounds(&cells),
            Some(Bounds {
                x0: 1.0,
                y0: 0.0,
                x1: 6.0,
                y1: 5.0
            })
        );
    }

    #[test]
    fn content_bounds_are_those_of_every_occupied_cell() {
        // The rows' ends give the bounds that placing every occupied cell gives, on both planar
        // lattices (odd hex rows are shifted) and for cells scattered by a fixed pattern.
        for kind in [LatticeKind::Square, LatticeKind::Hex] {
            let g = Grid::new(kind, [7, 6, 1]);
            for seed in 1..40u32 {
                let cells: Vec<u8> = (0..42u32)
                    .map(|i| u8::from((i * 7 + seed * 13) % (seed % 5 + 2) == 0 && i % seed != 3))
                    .collect();
                let mut want: Option<Bounds> = None;
                for i in (0..cells.len()).filter(|&i| cells[i] != 0) {
                    let [cx, cy] = g.centre(i);
                    let b = want.get_or_insert(Bounds {
                        x0: cx,
                        y0: cy,
                        x1: cx,
                        y1: cy,
                    });
                    *b = Bounds {
                        x0: b.x0.min(cx),
                        y0: b.y0.min(cy),
                        x1: b.x1.max(cx),
                        y1: b.y1.max(cy),
                    };
                }
                let pad = 2.0
                    + if kind == LatticeKind::Hex {
                        HEX_RADIUS
                    } else {
                        0.5
                    };
                let want = want.map(|b| Bounds {
                    x0: b.x0 - pad,
                    y0: b.y0 - pad,
                    x1: b.x1 + pad,
                    y1: b.y1 + pad,
                });
                assert_eq!(g.content_bounds(&cells), want, "{kind:?} {seed}");
            }
        }
    }
}
