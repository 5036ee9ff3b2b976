//! Tests of what a 3-D view of the cubic lattice draws.

use super::*;
use crate::camera::{dot, sub, Camera, Camera3D};
use crate::scene::{Cursor, Marks, Overlay, State};
use kumiki_model::model::{Layout, LegendEntry, Scene};

fn layout(dims: [u32; 3]) -> Layout {
    Layout {
        lattice: LatticeKind::Cubic,
        dims,
        cells: vec![
            LegendEntry::new(1, "unit", "#4080c0"),
            LegendEntry::new(2, "other", "#102030"),
        ],
        agents: Vec::new(),
        events: Vec::new(),
        fields: Vec::new(),
        tools: Vec::new(),
        cell_labels: false,
        chart: String::new(),
        goal: false,
    }
}

struct Fixture {
    layout: Layout,
    cells: Vec<u8>,
    bonds: Vec<u8>,
    overlay: Vec<f32>,
    world: Scene,
    marks: Marks,
    camera: Camera,
}

impl Fixture {
    fn new(dims: [u32; 3]) -> Fixture {
        let n = dims.iter().product::<u32>() as usize;
        Fixture {
            layout: layout(dims),
            cells: vec![0; n],
            bonds: Vec::new(),
            overlay: Vec::new(),
            world: Scene::default(),
            marks: Marks::default(),
            camera: Camera::Orbit(Camera3D::default()),
        }
    }

    fn index(&self, [x, y, z]: [u32; 3]) -> usize {
        let [w, h, _] = self.layout.dims;
        ((z * h + y) * w + x) as usize
    }

    fn set(&mut self, c: [u32; 3], code: u8) {
        let i = self.index(c);
        self.cells[i] = code;
    }

    fn model(&self) -> CubicModel {
        CubicModel::build(&self.scene())
    }

    fn scene(&self) -> SceneRef<'_> {
        SceneRef {
            layout: &self.layout,
            grid: Grid::new(LatticeKind::Cubic, self.layout.dims),
            state: State {
                cells: &self.cells,
                agents: &[],
                events: &[],
                bonds: &self.bonds,
                overlay: (!self.overlay.is_empty()).then_some(Overlay {
                    name: "field",
                    data: &self.overlay,
                    min: 0.0,
                    max: 2.0,
                }),
                world: &self.world,
            },
            camera: &self.camera,
            marks: &self.marks,
        }
    }
}

fn solid_block(dims: [u32; 3]) -> Fixture {
    let mut f = Fixture::new(dims);
    f.cells.fill(1);
    f
}

#[test]
fn a_solid_block_shows_its_shell_and_hides_the_centre() {
    let f = solid_block([3, 3, 3]);
    let m = f.model();
    assert_eq!(m.units(), 27);
    assert_eq!(m.visible.len(), 26);
    let centre = f.index([1, 1, 1]) as u32;
    assert!(m.visible.iter().all(|&u| m.unit_cell[u as usize] != centre));
    assert_eq!(m.unit_pos[13], [1, 1, 1]);
    assert_eq!(m.unit_color[0], [0x40, 0x80, 0xc0, 255]);
    assert_eq!(
        m.bounds,
        Some(Box3 {
            min: [0.0; 3],
            max: [3.0; 3]
        })
    );
}

#[test]
fn a_unit_against_the_edge_of_the_space_stays_visible() {
    // Every unit of a block that fills the space in x touches its walls.
    let f = solid_block([2, 3, 3]);
    assert_eq!(f.model().visible.len(), 18);
}

#[test]
fn bonds_follow_the_masks_and_skip_the_buried_ones() {
    let mut f = solid_block([4, 3, 3]);
    // Every unit bonded toward +x, +y and +z.
    f.bonds = vec![0b010101; f.cells.len()];
    let m = f.model();
    // All +x, +y and +z pairs of a 4×3×3 block, but the one between the two covered units
    // (1, 1, 1) and (2, 1, 1).
    let pairs = 3 * 3 * 3 + 4 * 2 * 3 + 4 * 3 * 2;
    assert_eq!(m.bonds.len(), pairs - 1);
    assert!(!m.bonds.contains(&Bond {
        mid: [2.0, 1.5, 1.5],
        axis: 0
    }));
    assert!(m.bonds.contains(&Bond {
        mid: [1.0, 1.5, 1.5],
        axis: 0
    }));
    assert_eq!(m.stats().bonds, pairs as u32 - 1);

    // Only the +z bits: no bond along x or y.
    f.bonds.fill(0b010000);
    assert!(f.model().bonds.iter().all(|b| b.axis == 2));
    // The view can hide them, and a model without masks has none.
    f.marks.bonds = false;
    assert!(f.model().bonds.is_empty());
    f.marks.bonds = true;
    f.bonds.clear();
    assert!(f.model().bonds.is_empty());
}

#[test]
fn ghost_and_highlight_keep_only_empty_cells() {
    let mut f = Fixture::new([3, 3, 3]);
    f.set([0, 0, 0], 1);
    let occupied = f.index([0, 0, 0]) as u32;
    let free = f.index([1, 0, 0]) as u32;
    f.world.ghost = vec![occupied, free, 999];
    f.marks.highlight = vec![free, occupied];
    let m = f.model();
    assert_eq!(m.ghost, vec![free]);
    assert_eq!(m.highlight, vec![free]);
    let s = m.stats();
    assert_eq!((s.ghost, s.highlight), (1, 1));
    f.marks.ghost = false;
    assert!(f.model().ghost.is_empty());
}

#[test]
fn the_plane_is_the_ground_or_a_reference_under_the_lowest_unit() {
    let mut f = Fixture::new([4, 4, 5]);
    assert_eq!(f.model().plane, None);
    f.set([1, 1, 2], 1);
    f.set([1, 1, 4], 1);
    f.set([2, 1, 3], 1);
    let m = f.model();
    assert_eq!(
        m.plane,
        Some(Plane {
            z: 2.0,
            solid: false
        })
    );
    assert!(!m.stats().ground);
    // One shadow per column, the floating column fainter.
    assert_eq!(
        m.shadows,
        vec![
            Shadow {
                x: 1,
                y: 1,
                strength: 1.0
            },
            Shadow {
                x: 2,
                y: 1,
                strength: (1.0 / (1.0 + 0.35 * 1.0)) as f32
            },
        ]
    );
    f.world.ground = Some(0);
    let m = f.model();
    assert_eq!(
        m.plane,
        Some(Plane {
            z: 0.0,
            solid: true
        })
    );
    assert!(m.stats().ground);
    assert_eq!(m.shadows[0].strength, (1.0 / (1.0 + 0.35 * 2.0)) as f32);
}

#[test]
fn the_lamp_sits_outside_the_box_along_the_light() {
    let mut f = Fixture::new([6, 6, 6]);
    f.set([2, 2, 2], 1);
    f.set([3, 2, 2], 1);
    assert_eq!(f.model().lamp, None);
    f.world.light = Some([0.0, 0.0, 2.0]);
    let m = f.model();
    let lamp = m.lamp.expect("a lamp");
    assert_eq!(lamp.dir, [0.0, 0.0, 1.0]);
    assert_eq!(lamp.size, 1.0);
    let b = m.bounds.unwrap();
    assert!(lamp.at[2] > b.max[2] + 1.0, "{lamp:?}");
    assert_eq!(&lamp.at[..2], &b.centre()[..2]);
    assert!(m.stats().light);

    // Along a slanted light it is still beyond every corner, measured along the light.
    let l = lamp_placement([0.0; 3], [4.0, 2.0, 1.0], [1.0, -1.0, 0.5], [48, 10, 10]).unwrap();
    assert_eq!(l.size, 2.0);
    let corners = (0..8).map(|k| {
        [
            4.0 * (k & 1) as f64,
            2.0 * ((k >> 1) & 1) as f64,
            (k >> 2) as f64,
        ]
    });
    for c in corners {
        assert!(dot(sub(l.at, c), l.dir) > 0.9, "{c:?}");
    }
    assert_eq!(
        lamp_placement([0.0; 3], [1.0; 3], [0.0; 3], [4, 4, 4]),
        None
    );
}

#[test]
fn the_lamp_clears_the_ghost_too() {
    let mut f = Fixture::new([8, 8, 8]);
    f.set([1, 1, 0], 1);
    f.world.light = Some([1.0, 0.0, 0.0]);
    let near = f.model().lamp.unwrap();
    f.world.ghost = vec![f.index([6, 1, 0]) as u32];
    let far = f.model().lamp.unwrap();
    assert!(far.at[0] > near.at[0] + 2.0, "{near:?} {far:?}");
}

#[test]
fn hover_lightens_and_removal_tints() {
    let mut f = Fixture::new([3, 1, 1]);
    f.set([0, 0, 0], 2);
    f.set([1, 0, 0], 2);
    f.set([2, 0, 0], 2);
    f.marks.hover = Some(0);
    f.marks.cursor = Some(Cursor {
        cell: 1,
        kind: CursorKind::Remove,
    });
    let m = f.model();
    // #102030 lifted 35 % toward white, and tinted toward red.
    assert_eq!(m.unit_color[0], [100, 110, 120, 255]);
    assert_eq!(m.unit_color[1], [158, 63, 62, 255]);
    assert_eq!(m.unit_color[2], [0x10, 0x20, 0x30, 255]);
}

#[test]
fn an_overlay_colours_finite_values_from_the_heat_map() {
    let mut f = Fixture::new([3, 1, 1]);
    f.cells.fill(1);
    f.overlay = vec![0.0, 2.0, f32::NAN];
    let m = f.model();
    assert_eq!(m.unit_color[0], [68, 1, 84, 255]);
    assert_eq!(m.unit_color[1], [253, 231, 37, 255]);
    assert_eq!(m.unit_color[2], [0x40, 0x80, 0xc0, 255]);
}

#[test]
fn the_cache_rebuilds_only_on_a_new_revision() {
    let mut f = solid_block([2, 2, 2]);
    let mut cache = ModelCache::default();
    assert!(cache.update(&f.scene(), 1));
    assert_eq!(cache.model().stats().units, 8);
    f.cells[0] = 0;
    assert!(!cache.update(&f.scene(), 1));
    assert_eq!(cache.model().stats().units, 8);
    assert!(cache.update(&f.scene(), 2));
    assert_eq!(
        cache.model().stats(),
        RenderStats {
            units: 7,
            bonds: 0,
            ghost: 0,
            highlight: 0,
            light: false,
            ground: false
        }
    );
}
