//! Cameras: pan and zoom for the planar lattices ([`Camera2D`]), an orbit camera for the cubic
//! one ([`Camera3D`], in `orbit.rs`, with the matrices WebGL needs, projection for Canvas 2D and
//! annotations, and picking by ray), and the view's choice between them ([`Camera`]). The vector
//! arithmetic they and the 3-D renderers share is in `vector.rs`.

use crate::geometry::{Bounds, Grid};
use kumiki_model::lattice::LatticeKind;

mod orbit;
mod vector;

pub use orbit::{Camera3D, Hit};
pub use vector::{cross, dot, multiply, norm, normalize, sub, Mat4, V3};

/// The planar camera: the world point at the view's centre and pixels per world unit.
#[derive(Clone, Debug, PartialEq)]
pub struct Camera2D {
    pub cx: f64,
    pub cy: f64,
    pub scale: f64,
    pub width: f64,
    pub height: f64,
}

impl Default for Camera2D {
    fn default() -> Self {
        Camera2D {
            cx: 0.0,
            cy: 0.0,
            scale: 10.0,
            width: 1.0,
            height: 1.0,
        }
    }
}

impl Camera2D {
    pub fn fit(&mut self, b: Bounds) {
        let bw = (b.x1 - b.x0).max(1e-6);
        let bh = (b.y1 - b.y0).max(1e-6);
        self.scale = ((self.width / bw).min(self.height / bh) * 0.94).max(0.05);
        self.cx = (b.x0 + b.x1) / 2.0;
        self.cy = (b.y0 + b.y1) / 2.0;
    }

    pub fn to_screen(&self, wx: f64, wy: f64) -> [f64; 2] {
        [
            (wx - self.cx) * self.scale + self.width / 2.0,
            (wy - self.cy) * self.scale + self.height / 2.0,
        ]
    }

    pub fn to_world(&self, sx: f64, sy: f64) -> [f64; 2] {
        [
            (sx - self.width / 2.0) / self.scale + self.cx,
            (sy - self.height / 2.0) / self.scale + self.cy,
        ]
    }

    pub fn pan(&mut self, dx: f64, dy: f64) {
        self.cx -= dx / self.scale;
        self.cy -= dy / self.scale;
    }

    /// Zooms by `factor`, keeping the world point under (sx, sy) where it is on screen.
    pub fn zoom(&mut self, factor: f64, sx: f64, sy: f64) {
        let [wx, wy] = self.to_world(sx, sy);
        self.scale = (self.scale * factor).clamp(0.02, 400.0);
        let [nx, ny] = self.to_world(sx, sy);
        self.cx += wx - nx;
        self.cy += wy - ny;
    }

    /// The world rectangle in view.
    pub fn visible(&self) -> Bounds {
        let [x0, y0] = self.to_world(0.0, 0.0);
        let [x1, y1] = self.to_world(self.width, self.height);
        Bounds { x0, y0, x1, y1 }
    }

    /// Whether the world rectangle `b` is wholly in view.
    pub fn shows(&self, b: Bounds) -> bool {
        let v = self.visible();
        let eps = 1e-9;
        b.x0 >= v.x0 - eps && b.y0 >= v.y0 - eps && b.x1 <= v.x1 + eps && b.y1 <= v.y1 + eps
    }

    /// The cell under a screen point.
    pub fn pick(&self, grid: &Grid, sx: f64, sy: f64) -> Option<usize> {
        let [wx, wy] = self.to_world(sx, sy);
        grid.cell_at(wx, wy)
    }

    /// The range of planar cells (x0..=x1, y0..=y1) that can be on screen, one cell wider all
    /// round, or `None` when none can.
    pub fn visible_cells(&self, grid: &Grid) -> Option<[u32; 4]> {
        let v = self.visible();
        let row = if grid.kind == LatticeKind::Hex {
            crate::geometry::HEX_ROW
        } else {
            1.0
        };
        let [w, h, _] = grid.dims.map(f64::from);
        let x0 = (v.x0.floor() - 1.0).max(0.0);
        let x1 = v.x1.ceil().min(w - 1.0);
        let y0 = ((v.y0 / row).floor() - 1.0).max(0.0);
        let y1 = (v.y1 / row).ceil().min(h - 1.0);
        (x1 >= x0 && y1 >= y0).then_some([x0 as u32, x1 as u32, y0 as u32, y1 as u32])
    }
}

/// What is under the pointer: a cell (or none), its code, and in 3-D the face hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, schemars::JsonSchema)]
pub struct Picked {
    /// The cell, or -1 off the lattice.
    pub cell: i64,
    /// The cell's code in the frame drawn (0: empty).
    pub code: u8,
    /// In 3-D, the face hit.
    pub hit: Option<Hit>,
}

/// Either camera, as the view holds it: the planar one for square and hex lattices, the orbit
/// one for the cubic lattice.
#[derive(Clone, Debug, PartialEq)]
pub enum Camera {
    Planar(Camera2D),
    Orbit(Camera3D),
}

impl Camera {
    /// The camera that suits a lattice, framing all of it.
    pub fn for_grid(grid: &Grid, width: f64, height: f64) -> Camera {
        let mut c = if grid.kind == LatticeKind::Cubic {
            Camera::Orbit(Camera3D {
                width,
                height,
                ..Camera3D::default()
            })
        } else {
            Camera::Planar(Camera2D {
                width,
                height,
                ..Camera2D::default()
            })
        };
        c.fit_lattice(grid);
        c
    }

    pub fn fit_lattice(&mut self, grid: &Grid) {
        match self {
            Camera::Planar(c) => c.fit(grid.bounds()),
            Camera::Orbit(c) => c.fit(grid.dims),
        }
    }

    pub fn size(&self) -> [f64; 2] {
        match self {
            Camera::Planar(c) => [c.width, c.height],
            Camera::Orbit(c) => [c.width, c.height],
        }
    }

    /// A new size in CSS pixels (the view keeps a planar camera's centre; see `View::resize`).
    pub fn set_size(&mut self, width: f64, height: f64) {
        match self {
            Camera::Planar(c) => {
                c.width = width;
                c.height = height;
            }
            Camera::Orbit(c) => {
                c.width = width;
                c.height = height;
            }
        }
    }

    /// A drag: an orbit drag turns a 3-D camera; otherwise either camera pans.
    pub fn drag(&mut self, dx: f64, dy: f64, orbit: bool) {
        match self {
            Camera::Orbit(c) if orbit => c.orbit(dx, dy),
            Camera::Orbit(c) => c.pan(dx, dy),
            Camera::Planar(c) => c.pan(dx, dy),
        }
    }

    /// Zooms about a screen point (the planar camera keeps it fixed; the orbit camera dollies).
    pub fn zoom(&mut self, factor: f64, sx: f64, sy: f64) {
        match self {
            Camera::Planar(c) => c.zoom(factor, sx, sy),
            Camera::Orbit(c) => c.zoom(factor),
        }
    }
}

/// The box around the occupied cells of a cubic lattice and any extra cells (a ghost), in world
/// units, or `None` when there are none: what a 3-D camera frames.
pub fn occupied_box(dims: [u32; 3], cells: &[u8], extra: &[u32]) -> Option<(V3, V3)> {
    let grid = Grid::new(LatticeKind::Cubic, dims);
    let mut min = [f64::INFINITY; 3];
    let mut max = [f64::NEG_INFINITY; 3];
    let occupied = cells
        .iter()
        .enumerate()
        .filter(|(_, &c)| c != 0)
        .map(|(i, _)| i);
    for i in occupied.chain(extra.iter().map(|&i| i as usize)) {
        let c = grid.coord(i).map(f64::from);
        for a in 0..3 {
            min[a] = min[a].min(c[a]);
            max[a] = max[a].max(c[a] + 1.0);
        }
    }
    (min[0] <= max[0]).then_some((min, max))
}

#[cfg(test)]
mod tests {
    use super::orbit::YAW;
    use super::*;

    #[test]
    fn planar_zoom_keeps_the_point_under_the_pointer() {
        let mut c = Camera2D {
            width: 400.0,
            height: 300.0,
            ..Camera2D::default()
        };
        let before = c.to_world(120.0, 80.0);
        c.zoom(1.7, 120.0, 80.0);
        let after = c.to_world(120.0, 80.0);
        assert!((before[0] - after[0]).abs() < 1e-9 && (before[1] - after[1]).abs() < 1e-9);
        let [sx, sy] = c.to_screen(after[0], after[1]);
        assert!((sx - 120.0).abs() < 1e-9 && (sy - 80.0).abs() < 1e-9);
    }

    #[test]
    fn a_fitted_camera_shows_its_box_and_not_a_box_grown_past_it() {
        let mut c = Camera2D {
            width: 400.0,
            height: 300.0,
            ..Camera2D::default()
        };
        let b = Bounds {
            x0: -2.5,
            y0: -2.5,
            x1: 22.5,
            y1: 6.5,
        };
        c.fit(b);
        assert!(c.shows(b));
        // One more cell on the right, as a bridge grows: out of view until framed again.
        let grown = Bounds { x1: 23.5, ..b };
        assert!(!c.shows(grown));
        c.fit(grown);
        assert!(c.shows(grown) && c.shows(b));
    }

    #[test]
    fn a_planar_camera_pans_on_either_drag_and_an_orbit_camera_turns_on_an_orbit_drag() {
        let mut c = Camera::Planar(Camera2D {
            width: 800.0,
            height: 600.0,
            ..Camera2D::default()
        });
        c.drag(20.0, -10.0, true);
        c.drag(20.0, -10.0, false);
        let Camera::Planar(p) = &c else {
            panic!("planar")
        };
        assert_eq!((p.cx, p.cy), (-4.0, 2.0));
        let mut o = Camera::Orbit(Camera3D {
            width: 800.0,
            height: 600.0,
            ..Camera3D::default()
        });
        o.drag(50.0, 0.0, true);
        let Camera::Orbit(turned) = o.clone() else {
            panic!("orbit")
        };
        assert!((turned.yaw - (YAW - 0.4)).abs() < 1e-12);
        o.drag(50.0, 0.0, false);
        o.zoom(2.0, 10.0, 10.0);
        let Camera::Orbit(moved) = o else {
            panic!("orbit")
        };
        assert_ne!(moved.target, turned.target, "a pan drag moves the target");
        assert_eq!(moved.yaw, turned.yaw, "and does not turn");
        assert!((moved.distance - 10.0).abs() < 1e-12, "zoom dollies");
    }

    #[test]
    fn a_fitted_lattice_is_all_in_view() {
        let grid = Grid::new(LatticeKind::Hex, [30, 10, 1]);
        let c = Camera::for_grid(&grid, 640.0, 480.0);
        let Camera::Planar(c) = c else {
            panic!("planar")
        };
        let (v, b) = (c.visible(), grid.bounds());
        assert!(v.x0 <= b.x0 && v.y0 <= b.y0 && v.x1 >= b.x1 && v.y1 >= b.y1);
    }

    #[test]
    fn the_ray_through_a_projected_point_goes_back_through_it() {
        let mut c = Camera3D {
            width: 640.0,
            height: 400.0,
            ..Camera3D::default()
        };
        c.fit([8, 6, 4]);
        c.orbit(37.0, -12.0);
        let p = [2.5, 3.5, 1.5];
        let [sx, sy, depth] = c.project(p).unwrap();
        let (o, d) = c.ray(sx, sy);
        let back: V3 = std::array::from_fn(|a| {
            o[a] + d[a] * depth / dot(d, normalize(sub(c.target, c.eye())))
        });
        assert!(norm(sub(back, p)) < 1e-6, "{back:?}");
    }

    #[test]
    fn picking_finds_the_nearest_unit_and_the_cell_in_front() {
        let dims = [4, 4, 4];
        let mut c = Camera3D {
            width: 500.0,
            height: 500.0,
            ..Camera3D::default()
        };
        c.fit(dims);
        let mut cells = [0u8; 64];
        let centre = (4 + 1) * 4 + 1;
        cells[centre] = 1;
        let [sx, sy, _] = c.project([1.5, 1.5, 1.5]).unwrap();
        let hit = c.pick(dims, |i| cells[i] != 0, sx, sy).unwrap();
        assert_eq!(hit.cell as usize, centre);
        assert!(hit.front >= 0 && hit.front as usize != centre);
        assert_eq!(c.pick(dims, |_| false, sx, sy), None);
    }

    #[test]
    fn the_view_matrix_puts_the_target_straight_ahead() {
        let c = Camera3D {
            width: 300.0,
            height: 300.0,
            target: [1.0, 2.0, 3.0],
            ..Camera3D::default()
        };
        let m = c.view_projection();
        let t = [1.0f32, 2.0, 3.0, 1.0];
        let clip: [f32; 4] = std::array::from_fn(|row| (0..4).map(|k| m[k * 4 + row] * t[k]).sum());
        assert!((clip[0] / clip[3]).abs() < 1e-5 && (clip[1] / clip[3]).abs() < 1e-5);
        assert_eq!(
            occupied_box([2, 2, 2], &[0, 0, 0, 1, 0, 0, 0, 0], &[]),
            Some(([1.0, 1.0, 0.0], [2.0, 2.0, 1.0]))
        );
    }
}
