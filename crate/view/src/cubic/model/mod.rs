//! What a 3-D view of the cubic lattice draws, worked out once per revision for both renderers:
//! the units with their colours (legend or overlay), the bonds between adjacent units, the ghost
//! cells not already occupied, the plane under the structure with the units' shadows on it, the
//! lamp of a light source, and the marks (hover, reachable cells, an editing cursor).

use crate::camera::{norm, V3};
use crate::geometry::Grid;
use crate::palette::{heat_table, legend_table, Rgba};
use crate::scene::{CursorKind, RenderStats, SceneRef};
use kumiki_model::lattice::LatticeKind;

/// Colour of a unit under the pointer: lightened this far toward white.
const HOVER_LIFT: f64 = 0.35;
/// A unit marked for removal: tinted red.
const REMOVE_TINT: [f64; 3] = [235.0, 80.0, 70.0];

/// Colours both renderers draw the scene's extras in: the ghost, reachable cells, the add
/// cursor, and the lamp with its arrow.
pub const GHOST_COLOR: &str = "#bfe3ff";
pub const REACH_COLOR: &str = "#f0b429";
pub const ADD_COLOR: &str = "#3ddc84";
pub const LAMP_COLOR: &str = "#ffd166";
pub const ARROW_COLOR: &str = "#ffc23d";

/// A bond between face-adjacent units: its midpoint and its axis (0 x, 1 y, 2 z).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bond {
    pub mid: [f32; 3],
    pub axis: u8,
}

/// An axis-aligned box in world units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Box3 {
    pub min: V3,
    pub max: V3,
}

impl Box3 {
    pub fn centre(&self) -> V3 {
        std::array::from_fn(|a| (self.min[a] + self.max[a]) / 2.0)
    }

    /// Grows the box to hold cell `c`.
    fn include(&mut self, c: [u32; 3]) {
        for (a, v) in c.map(f64::from).into_iter().enumerate() {
            self.min[a] = self.min[a].min(v);
            self.max[a] = self.max[a].max(v + 1.0);
        }
    }

    fn of_cell(c: [u32; 3]) -> Box3 {
        let min = c.map(f64::from);
        Box3 {
            min,
            max: min.map(|v| v + 1.0),
        }
    }
}

/// The plane drawn under the structure: the model's ground (solid), or a reference just under
/// the lowest unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    pub z: f64,
    pub solid: bool,
}

/// A shadow square on the plane under a column of units, fainter the higher the column's lowest
/// unit floats. The strength is kept in single precision, as the renderers have always read it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shadow {
    pub x: u32,
    pub y: u32,
    pub strength: f32,
}

/// The lamp of a light source: where it stands, the unit direction toward the source and a size
/// that follows the space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lamp {
    pub at: V3,
    pub dir: V3,
    pub size: f64,
}

/// Everything a 3-D frame draws apart from the camera-dependent work.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CubicModel {
    pub dims: [u32; 3],
    /// Per unit, in cell order: its cell's (x, y, z), colour and cell index.
    pub unit_pos: Vec<[u32; 3]>,
    pub unit_color: Vec<Rgba>,
    pub unit_cell: Vec<u32>,
    /// The units that can be seen, not covered on all six faces (indices into the unit arrays).
    pub visible: Vec<u32>,
    pub bonds: Vec<Bond>,
    /// Ghost cells that hold no unit.
    pub ghost: Vec<u32>,
    /// Reachable (highlighted) cells that hold no unit.
    pub highlight: Vec<u32>,
    /// The box around the units, `None` with none.
    pub bounds: Option<Box3>,
    pub plane: Option<Plane>,
    /// One per column of units, in the order the columns are first met in cell order.
    pub shadows: Vec<Shadow>,
    pub lamp: Option<Lamp>,
}

impl CubicModel {
    /// Works out what `scene` shows.
    pub fn build(scene: &SceneRef) -> CubicModel {
        let dims = scene.grid.dims;
        let [w, h, d] = dims.map(|v| v as usize);
        let grid = scene.grid;
        let cells = scene.state.cells;
        let world = scene.state.world;
        let marks = scene.marks;
        let palette = legend_table(&scene.layout.cells);
        let heat = heat_table();
        let overlay = scene.state.overlay;
        let span = overlay.map_or(1.0, |o| (f64::from(o.max) - f64::from(o.min)).max(1e-9));
        let hover = marks.hover;
        let removing = marks
            .cursor
            .filter(|c| c.kind == CursorKind::Remove)
            .map(|c| c.cell);

        // A unit covered on all six faces cannot be seen: a solid block draws only its shell.
        // A neighbour past the end of the buffer counts as occupied.
        let layer = w * h;
        let full = |j: usize| cells.get(j) != Some(&0);
        let covered = |i: usize, [x, y, z]: [u32; 3]| {
            let (x, y, z) = (x as usize, y as usize, z as usize);
            x > 0
                && x + 1 < w
                && y > 0
                && y + 1 < h
                && z > 0
                && z + 1 < d
                && full(i - 1)
                && full(i + 1)
                && full(i - w)
                && full(i + w)
                && full(i - layer)
                && full(i + layer)
        };

        let n = cells.iter().filter(|&&c| c != 0).count();
        let mut m = CubicModel {
            dims,
            unit_pos: Vec::with_capacity(n),
            unit_color: Vec::with_capacity(n),
            unit_cell: Vec::with_capacity(n),
            ..CubicModel::default()
        };
        for (i, &code) in cells.iter().enumerate() {
            if code == 0 {
                continue;
            }
            let c = grid.coord(i);
            let k = m.unit_pos.len() as u32;
            if !covered(i, c) {
                m.visible.push(k);
            }
            match &mut m.bounds {
                Some(b) => b.include(c),
                None => m.bounds = Some(Box3::of_cell(c)),
            }
            let value = overlay.and_then(|o| o.data.get(i).map(|&v| (o, f64::from(v))));
            let at = match value {
                Some((o, v)) if v.is_finite() => {
                    let t = ((v - f64::from(o.min)) / span).clamp(0.0, 1.0);
                    Some((t * 255.0).round() as usize * 4)
                }
                _ => None,
            };
            let src = match at {
                Some(at) => &heat[at..at + 4],
                None => &palette[usize::from(code) * 4..usize::from(code) * 4 + 4],
            };
            let mut rgba: Rgba = [src[0], src[1], src[2], src[3]];
            let cell = Some(i as u32);
            if cell == removing {
                for (ch, tint) in rgba.iter_mut().zip(REMOVE_TINT) {
                    *ch = (f64::from(*ch) * 0.35 + tint * 0.65).round() as u8;
                }
            } else if cell == hover {
                for ch in &mut rgba[..3] {
                    let v = f64::from(*ch);
                    *ch = (v + (255.0 - v) * HOVER_LIFT).round() as u8;
                }
            }
            m.unit_pos.push(c);
            m.unit_color.push(rgba);
            m.unit_cell.push(i as u32);
        }

        // Bonds, from the model's bond masks: each unit with its +x, +y and +z neighbours (bits
        // 0, 2 and 4 of the mask, the lattice's direction order).
        let masks = scene.state.bonds;
        if !masks.is_empty() && marks.bonds {
            let stride = [1, w, layer];
            for (&cell, &c) in m.unit_cell.iter().zip(&m.unit_pos) {
                let i = cell as usize;
                let mask = masks.get(i).copied().unwrap_or(0);
                let inner = covered(i, c);
                for a in 0..3 {
                    if c[a] + 1 >= dims[a] || mask & (1 << (2 * a)) == 0 {
                        continue;
                    }
                    let mut next = c;
                    next[a] += 1;
                    // A bond between two covered units is buried in the structure.
                    if inner && covered(i + stride[a], next) {
                        continue;
                    }
                    let mut mid = c.map(|v| v as f32 + 0.5);
                    mid[a] += 0.5;
                    m.bonds.push(Bond { mid, axis: a as u8 });
                }
            }
        }

        let empty = |&i: &u32| cells.get(i as usize) == Some(&0);
        if marks.ghost {
            m.ghost = world.ghost.iter().copied().filter(empty).collect();
        }
        m.highlight = marks.highlight.iter().copied().filter(empty).collect();

        // The plane: the model's ground, else a reference grid under the lowest unit.
        m.plane = match (world.ground, m.bounds) {
            (Some(z), _) => Some(Plane {
                z: f64::from(z),
                solid: true,
            }),
            (None, Some(b)) => Some(Plane {
                z: b.min[2],
                solid: false,
            }),
            (None, None) => None,
        };

        // Shadows: one square per column of units, fainter the higher its lowest unit floats.
        if let Some(plane) = m.plane {
            let mut lowest: Vec<Option<u32>> = vec![None; layer];
            let mut columns = Vec::new();
            for &[x, y, z] in &m.unit_pos {
                let col = y as usize * w + x as usize;
                match &mut lowest[col] {
                    Some(low) => *low = (*low).min(z),
                    slot => {
                        *slot = Some(z);
                        columns.push(col);
                    }
                }
            }
            m.shadows = columns
                .into_iter()
                .map(|col| {
                    let z = lowest[col].map_or(0.0, f64::from);
                    let lift = (z - plane.z).max(0.0);
                    Shadow {
                        x: (col % w) as u32,
                        y: (col / w) as u32,
                        strength: (1.0 / (1.0 + 0.35 * lift)) as f32,
                    }
                })
                .collect();
        }

        // The lamp stands clear of the units and of the ghost.
        if let Some(light) = world.light {
            let mut around = m.bounds;
            for &i in &m.ghost {
                let c = grid.coord(i as usize);
                match &mut around {
                    Some(b) => b.include(c),
                    None => around = Some(Box3::of_cell(c)),
                }
            }
            let b = around.unwrap_or(Box3 {
                min: [0.0; 3],
                max: dims.map(f64::from),
            });
            m.lamp = lamp_placement(b.min, b.max, light, dims);
        }
        m
    }

    pub fn units(&self) -> usize {
        self.unit_pos.len()
    }

    /// A cell's (x, y, z).
    pub fn coord(&self, cell: u32) -> [u32; 3] {
        Grid::new(LatticeKind::Cubic, self.dims).coord(cell as usize)
    }

    /// What this model draws, for the page and its tests.
    pub fn stats(&self) -> RenderStats {
        RenderStats {
            units: self.units() as u32,
            bonds: self.bonds.len() as u32,
            ghost: self.ghost.len() as u32,
            highlight: self.highlight.len() as u32,
            light: self.lamp.is_some(),
            ground: self.plane.is_some_and(|p| p.solid),
        }
    }
}

/// The lamp of a light source in direction `dir`, beyond the box `min`..`max` by an arrow's
/// length, or `None` when `dir` has no length. Its size follows the space (`dims`), not the
/// structure, so it does not jump when the structure changes.
pub fn lamp_placement(min: V3, max: V3, dir: [f32; 3], dims: [u32; 3]) -> Option<Lamp> {
    let dir = dir.map(f64::from);
    let len = norm(dir);
    if len.is_nan() || len <= 0.0 {
        return None;
    }
    let d = dir.map(|v| v / len);
    let centre = Box3 { min, max }.centre();
    let largest = dims.into_iter().max().map_or(0.0, f64::from);
    let size = (largest / 24.0).clamp(1.0, 4.0);
    // Half the box's extent along the light, then a gap, the arrow and the lamp itself.
    let half = (0..3).map(|a| d[a].abs() * (max[a] - min[a])).sum::<f64>() / 2.0;
    let reach = half + 0.9 + 2.4 * size;
    Some(Lamp {
        at: std::array::from_fn(|a| centre[a] + d[a] * reach),
        dir: d,
        size,
    })
}

/// The model of the last revision drawn, rebuilt only when the revision changes.
#[derive(Clone, Debug, Default)]
pub struct ModelCache {
    revision: Option<u64>,
    model: CubicModel,
}

impl ModelCache {
    /// Rebuilds the model when `revision` is not the one it was built for; true when it did.
    pub fn update(&mut self, scene: &SceneRef, revision: u64) -> bool {
        if self.revision == Some(revision) {
            return false;
        }
        self.model = CubicModel::build(scene);
        self.revision = Some(revision);
        true
    }

    pub fn model(&self) -> &CubicModel {
        &self.model
    }
}

#[cfg(test)]
mod tests;
