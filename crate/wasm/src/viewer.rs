//! The lattice view for the page: [`Viewer`] draws a [`Sim`] in place from the worker (or a
//! shape from an editor on the main thread), and [`LatticeGeometry`] answers the page's geometry
//! questions. The drawing itself lives in `kumiki_view`.

use crate::{to_js, Sim};
use kumiki_core::lattice::LatticeKind;
use kumiki_core::models::{Layout, Scene};
use kumiki_view::camera::{Camera, Picked};
use kumiki_view::geometry::{hex_corners, Grid, HEX_RADIUS, HEX_ROW};
use kumiki_view::palette::range;
use kumiki_view::scene::{Marks, Overlay, State};
use kumiki_view::view::{Kind, View};
use wasm_bindgen::prelude::*;
use web_sys::{ImageBitmap, OffscreenCanvas};

#[wasm_bindgen]
extern "C" {
    /// `performance.now()`, in the page and in workers alike.
    #[wasm_bindgen(js_namespace = performance, js_name = now)]
    fn performance_now() -> f64;
}

/// A view on an OffscreenCanvas: camera, marks and renderer (see `kumiki_view::view::View`).
#[wasm_bindgen]
pub struct Viewer {
    view: View,
    /// The overlay's finite range in the last frame drawn, for the page's legend.
    overlay_range: Option<(f32, f32)>,
}

/// A lattice by the name scenarios and layouts use ("square", "hex", "cubic").
fn lattice(name: &str) -> Result<LatticeKind, JsError> {
    use serde::de::{value::Error, Deserialize, IntoDeserializer};
    LatticeKind::deserialize(IntoDeserializer::<Error>::into_deserializer(name))
        .map_err(|e| JsError::new(&format!("lattice: {e}")))
}

#[wasm_bindgen]
impl Viewer {
    /// Draws on `canvas` with WebGL2 unless `prefer` is "canvas2d" or WebGL2 is unavailable;
    /// annotations go on `annotations`.
    #[wasm_bindgen(constructor)]
    pub fn new(
        canvas: OffscreenCanvas,
        annotations: Option<OffscreenCanvas>,
        prefer: &str,
    ) -> Result<Viewer, JsValue> {
        let prefer = (prefer == "canvas2d").then_some(Kind::Canvas2d);
        let mut view = View::new(canvas, annotations, prefer)?;
        view.set_clock(performance_now);
        Ok(Viewer {
            view,
            overlay_range: None,
        })
    }

    /// "webgl2" or "canvas2d".
    pub fn kind(&self) -> String {
        self.view.kind().name().into()
    }

    /// The run's layout, from the simulation.
    pub fn set_layout_of(&mut self, sim: &Sim) -> Result<(), JsValue> {
        self.view.set_layout(sim.run().model().layout(), true)
    }

    /// A layout given by the page (an editor's own lattice); the camera stays where the editor
    /// put it.
    pub fn set_layout(&mut self, layout: JsValue) -> Result<(), JsValue> {
        let layout: Layout = serde_wasm_bindgen::from_value(layout)?;
        self.view.set_layout(layout, false)
    }

    /// The run's state changed: the next draw uploads it.
    pub fn state_changed(&mut self) {
        self.view.state_changed();
    }

    /// The page's marks (hover, selection, highlights, cursor, view options).
    pub fn set_marks(&mut self, marks: JsValue) -> Result<(), JsValue> {
        self.view
            .set_marks(serde_wasm_bindgen::from_value::<Marks>(marks)?);
        Ok(())
    }

    pub fn resize(&mut self, css_width: f64, css_height: f64, dpr: f64) {
        self.view.resize(css_width, css_height, dpr);
    }

    /// A drag by (dx, dy) CSS pixels: an orbit drag turns a 3-D view; otherwise it pans.
    pub fn drag(&mut self, dx: f64, dy: f64, orbit: bool) {
        self.view.camera_mut().drag(dx, dy, orbit);
        self.view.hold();
    }

    /// Zooms by `factor` about a screen point.
    pub fn zoom(&mut self, factor: f64, sx: f64, sy: f64) {
        self.view.camera_mut().zoom(factor, sx, sy);
        self.view.hold();
    }

    /// Frames what is on the lattice at the next draw, and follows it from then on (until a
    /// drag or a zoom).
    pub fn fit(&mut self) {
        self.view.request_fit();
    }

    /// Looks at a world box from the current direction (3-D only).
    pub fn fit_box(&mut self, min: &[f64], max: &[f64], margin: f64) {
        if let (Camera::Orbit(c), [a, b, c0], [d, e, f]) = (self.view.camera_mut(), min, max) {
            c.fit_box([*a, *b, *c0], [*d, *e, *f], margin);
        }
        self.view.cancel_fit();
    }

    /// Moves a 3-D camera's target by a world offset (an editor's grid grew on one side).
    pub fn shift_target(&mut self, dx: f64, dy: f64, dz: f64) {
        if let Camera::Orbit(c) = self.view.camera_mut() {
            c.target[0] += dx;
            c.target[1] += dy;
            c.target[2] += dz;
        }
    }

    /// Back to the default 3-D viewing direction.
    pub fn reset_orientation(&mut self) {
        if let Camera::Orbit(c) = self.view.camera_mut() {
            c.reset_orientation();
        }
    }

    /// The 3-D camera's turn about the vertical, in radians (0 for a planar view).
    pub fn yaw(&self) -> f64 {
        match self.view.camera() {
            Camera::Orbit(c) => c.yaw,
            Camera::Planar(_) => 0.0,
        }
    }

    /// Pixels per cell of a planar view (0 in 3-D).
    pub fn scale(&self) -> f64 {
        match self.view.camera() {
            Camera::Planar(c) => c.scale,
            Camera::Orbit(_) => 0.0,
        }
    }

    /// Where the ray through a screen point meets the plane at height z, or undefined.
    pub fn hit_plane_z(&self, sx: f64, sy: f64, z: f64) -> Option<Vec<f64>> {
        match self.view.camera() {
            Camera::Orbit(c) => c.hit_plane_z(sx, sy, z).map(|p| p.to_vec()),
            Camera::Planar(_) => None,
        }
    }

    /// Draws the simulation as it stands, with `overlay` as a heat map when given; a view that
    /// follows the content frames it again when it grew out of sight. Returns what a 3-D frame
    /// drew (null for a planar one).
    pub fn draw_sim(&mut self, sim: &Sim, overlay: Option<String>) -> Result<JsValue, JsValue> {
        let model = sim.run().model();
        let cells = model.cells();
        let agents = model.agents();
        let events = model.events();
        let bonds = model.bonds();
        let world = model.scene();
        let field = overlay
            .as_deref()
            .and_then(|name| model.field(name).map(|data| (name, data)));
        let overlay = field.as_ref().map(|(name, data)| {
            let (min, max) = range(data);
            Overlay {
                name,
                data,
                min,
                max,
            }
        });
        self.overlay_range = overlay.map(|o| (o.min, o.max));
        self.view.keep_in_view(&cells);
        let state = State {
            cells: &cells,
            agents: &agents,
            events: &events,
            bonds: &bonds,
            overlay,
            world: &world,
        };
        let stats = self.view.draw(&state)?;
        Ok(to_js(&stats)?)
    }

    /// Draws cells given by the page (an editor's shape, small) with a scene's ghost.
    pub fn draw_cells(&mut self, cells: &[u8], scene: JsValue) -> Result<JsValue, JsValue> {
        let world: Scene = if scene.is_null() || scene.is_undefined() {
            Scene::default()
        } else {
            serde_wasm_bindgen::from_value(scene)?
        };
        let state = State {
            cells,
            agents: &[],
            events: &[],
            bonds: &[],
            overlay: None,
            world: &world,
        };
        // An editor's cells change between calls without saying so: upload them every time.
        self.view.state_changed();
        let stats = self.view.draw(&state)?;
        Ok(to_js(&stats)?)
    }

    /// Frames drawn since the view began, and the milliseconds spent uploading the model's
    /// buffers and issuing draw calls: `[frames, upload_ms, draw_ms]`.
    pub fn timing(&self) -> Vec<f64> {
        let t = self.view.timing();
        vec![t.frames as f64, t.upload_ms, t.draw_ms]
    }

    /// The overlay's finite [min, max] in the last frame drawn, or undefined without one.
    pub fn overlay_range(&self) -> Option<Vec<f32>> {
        self.overlay_range.map(|(a, b)| vec![a, b])
    }

    /// What is under a screen point of the simulation's view.
    pub fn pick_sim(&self, sim: &Sim, sx: f64, sy: f64) -> Result<JsValue, JsError> {
        self.pick(&sim.run().model().cells(), sx, sy)
    }

    /// What is under a screen point, for cells given by the page.
    pub fn pick_cells(&self, cells: &[u8], sx: f64, sy: f64) -> Result<JsValue, JsError> {
        self.pick(cells, sx, sy)
    }

    /// The view as one bitmap (lattice and annotations), drawn just before.
    pub fn capture(&self) -> Result<ImageBitmap, JsValue> {
        self.view.capture()
    }
}

impl Viewer {
    fn pick(&self, cells: &[u8], sx: f64, sy: f64) -> Result<JsValue, JsError> {
        let (cell, hit) = self.view.pick(cells, sx, sy);
        let code = cell
            .and_then(|i| cells.get(i as usize).copied())
            .unwrap_or(0);
        to_js(&Picked {
            cell: cell.map_or(-1, i64::from),
            code,
            hit,
        })
    }
}

/// Lattice geometry for the page's editors and cursor: the same numbers the view draws with.
#[wasm_bindgen]
pub struct LatticeGeometry {
    grid: Grid,
}

#[wasm_bindgen]
impl LatticeGeometry {
    #[wasm_bindgen(constructor)]
    pub fn new(lattice_name: &str, w: u32, h: u32, d: u32) -> Result<LatticeGeometry, JsError> {
        Ok(LatticeGeometry {
            grid: Grid::new(lattice(lattice_name)?, [w, h, d.max(1)]),
        })
    }

    /// Centre of a planar cell in world units, [x, y].
    pub fn centre(&self, cell: u32) -> Vec<f64> {
        self.grid.centre(cell as usize).to_vec()
    }

    /// The planar cell under a world point, or -1.
    pub fn cell_at(&self, wx: f64, wy: f64) -> i32 {
        self.grid.cell_at(wx, wy).map_or(-1, |i| i as i32)
    }

    /// Neighbours in the core's direction order, -1 where off the lattice.
    pub fn neighbours(&self, cell: u32) -> Vec<i32> {
        self.grid
            .neighbours(cell as usize)
            .into_iter()
            .map(|n| n.map_or(-1, |i| i as i32))
            .collect()
    }

    /// The world rectangle of the whole lattice, [x0, y0, x1, y1].
    pub fn bounds(&self) -> Vec<f64> {
        let b = self.grid.bounds();
        vec![b.x0, b.y0, b.x1, b.y1]
    }

    /// Corners of the hexagon of radius `r` around a point, [x0, y0, x1, y1, ...].
    pub fn hex_corners(cx: f64, cy: f64, r: f64) -> Vec<f64> {
        hex_corners(cx, cy, r).into_iter().flatten().collect()
    }

    /// Centre-to-corner radius of a hex cell, and the distance between hex rows.
    pub fn hex_radius() -> f64 {
        HEX_RADIUS
    }

    pub fn hex_row() -> f64 {
        HEX_ROW
    }
}
