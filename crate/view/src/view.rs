//! The lattice view: an OffscreenCanvas with its renderer (WebGL2, or Canvas 2D as the
//! fallback), an annotation canvas over it, the camera and the page's marks. It lives next to
//! the simulation (in the page's worker) and reads the model's buffers in place; the page sends
//! it sizes, gestures and marks, and asks it what is under the pointer.

use crate::annotate;
use crate::camera::{occupied_box, Camera, Hit};
use crate::cubic::canvas::CubicCanvas;
use crate::cubic::gl::CubicGl;
use crate::cubic::model::lamp_placement;
use crate::geometry::Grid;
use crate::gl::Multisample;
use crate::palette::{css, BACKGROUND};
use crate::planar::canvas::PlanarCanvas;
use crate::planar::gl::PlanarGl;
use crate::scene::{Marks, RenderStats, SceneRef, State};
use kumiki_model::lattice::LatticeKind;
use kumiki_model::model::Layout;
use wasm_bindgen::{JsCast, JsValue};
use web_sys::{
    ImageBitmap, OffscreenCanvas, OffscreenCanvasRenderingContext2d as Ctx,
    WebGl2RenderingContext as Gl,
};

/// Which renderer draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    WebGl2,
    Canvas2d,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::WebGl2 => "webgl2",
            Kind::Canvas2d => "canvas2d",
        }
    }
}

enum Backend {
    Gl {
        gl: Gl,
        planar: Box<PlanarGl>,
        cubic: Option<Box<CubicGl>>,
        /// Where the 3-D view draws, multisampled (the context has no antialiasing).
        multisample: Multisample,
    },
    Canvas {
        ctx: Ctx,
        planar: PlanarCanvas,
        cubic: Box<CubicCanvas>,
    },
}

pub struct View {
    canvas: OffscreenCanvas,
    annotations: Option<Ctx>,
    /// Whether the annotation canvas holds anything since it was last cleared.
    annotated: bool,
    backend: Backend,
    layout: Option<Layout>,
    grid: Grid,
    camera: Camera,
    marks: Marks,
    /// Size in CSS pixels and the device pixel ratio the buffers are drawn at.
    css: [f64; 2],
    dpr: f64,
    /// A new lattice is framed on its first frame.
    fit_pending: bool,
    /// The planar camera was last placed by a fit (not by the user's pan or zoom): it frames
    /// the content again whenever the content leaves the view (a bridge growing, a resize).
    follow: bool,
    /// Bumped whenever what is drawn changes (the frame, the marks): renderers upload again only
    /// then, so a camera move redraws without copying anything.
    revision: u64,
    /// Milliseconds now, for the frame-time breakdown; none natively.
    clock: Option<fn() -> f64>,
    /// Frames drawn, and the milliseconds spent uploading and drawing them, since the view began.
    timing: Timing,
}

/// Where a view's time goes: frames drawn, and the milliseconds spent uploading the model's
/// buffers and issuing the draw calls (the browser rasterises them after).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Timing {
    pub frames: u64,
    pub upload_ms: f64,
    pub draw_ms: f64,
}

fn options(pairs: &[(&str, bool)]) -> JsValue {
    let o = js_sys::Object::new();
    for (k, v) in pairs {
        let _ = js_sys::Reflect::set(&o, &JsValue::from_str(k), &JsValue::from_bool(*v));
    }
    o.into()
}

fn context_2d(canvas: &OffscreenCanvas, opaque: bool) -> Result<Ctx, JsValue> {
    let ctx = canvas.get_context_with_context_options("2d", &options(&[("alpha", !opaque)]))?;
    Ok(ctx
        .ok_or("this browser offers no Canvas 2D")?
        .dyn_into::<Ctx>()?)
}

impl View {
    /// A view drawing on `canvas` with WebGL2, unless `prefer` asks for Canvas 2D or WebGL2 is
    /// unavailable; annotations go on `annotations` when given.
    pub fn new(
        canvas: OffscreenCanvas,
        annotations: Option<OffscreenCanvas>,
        prefer: Option<Kind>,
    ) -> Result<View, JsValue> {
        let backend = match prefer {
            Some(Kind::Canvas2d) => None,
            _ => Self::webgl(&canvas),
        };
        let backend = match backend {
            Some(b) => b,
            None => Backend::Canvas {
                ctx: context_2d(&canvas, true)?,
                planar: PlanarCanvas::default(),
                cubic: Box::default(),
            },
        };
        let annotations = annotations.map(|c| context_2d(&c, false)).transpose()?;
        Ok(View {
            canvas,
            annotations,
            annotated: false,
            backend,
            layout: None,
            grid: Grid::new(LatticeKind::Square, [1, 1, 1]),
            camera: Camera::for_grid(&Grid::new(LatticeKind::Square, [1, 1, 1]), 1.0, 1.0),
            marks: Marks::default(),
            css: [1.0, 1.0],
            dpr: 1.0,
            fit_pending: false,
            follow: true,
            revision: 0,
            clock: None,
            timing: Timing::default(),
        })
    }

    fn webgl(canvas: &OffscreenCanvas) -> Option<Backend> {
        let opts = options(&[
            // Only the 3-D view is antialiased, through its own multisampled target.
            ("antialias", false),
            ("alpha", false),
            ("preserveDrawingBuffer", false),
        ]);
        let gl = canvas
            .get_context_with_context_options("webgl2", &opts)
            .ok()??
            .dyn_into::<Gl>()
            .ok()?;
        match PlanarGl::new(&gl).and_then(|p| Ok((p, Multisample::new(&gl)?))) {
            Ok((planar, multisample)) => Some(Backend::Gl {
                gl,
                planar: Box::new(planar),
                cubic: None,
                multisample,
            }),
            Err(e) => {
                web_sys::console::warn_2(&"WebGL2 renderer unavailable:".into(), &e);
                None
            }
        }
    }

    /// Times uploads and draws with `clock` (milliseconds).
    pub fn set_clock(&mut self, clock: fn() -> f64) {
        self.clock = Some(clock);
    }

    pub fn timing(&self) -> Timing {
        self.timing
    }

    pub fn kind(&self) -> Kind {
        match self.backend {
            Backend::Gl { .. } => Kind::WebGl2,
            Backend::Canvas { .. } => Kind::Canvas2d,
        }
    }

    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    pub fn camera(&self) -> &Camera {
        &self.camera
    }

    pub fn camera_mut(&mut self) -> &mut Camera {
        &mut self.camera
    }

    pub fn marks(&self) -> &Marks {
        &self.marks
    }

    /// A new layout. With `refit` (a new run), the camera stays when the lattice is the same
    /// kind and size, and otherwise the new lattice is framed on its first frame. Without it (an
    /// editor growing its box), the camera stays whenever the lattice is the same kind.
    pub fn set_layout(&mut self, layout: Layout, refit: bool) -> Result<(), JsValue> {
        let grid = Grid::new(layout.lattice, layout.dims);
        let same_kind = self.layout.is_some() && grid.kind == self.grid.kind;
        if !same_kind || (refit && grid != self.grid) {
            self.camera = Camera::for_grid(&grid, self.css[0], self.css[1]);
            self.fit_pending = refit;
        }
        self.grid = grid;
        match &mut self.backend {
            Backend::Gl {
                gl, planar, cubic, ..
            } => {
                if layout.lattice == LatticeKind::Cubic {
                    if cubic.is_none() {
                        *cubic = Some(Box::new(CubicGl::new(gl)?));
                    }
                } else {
                    planar.set_layout(gl, &layout)?;
                }
            }
            Backend::Canvas { planar, .. } => planar.set_layout(&layout)?,
        }
        self.layout = Some(layout);
        self.revision += 1;
        Ok(())
    }

    /// The state changed (a step, a seek, a click): the next draw uploads it.
    pub fn state_changed(&mut self) {
        self.revision += 1;
    }

    pub fn set_marks(&mut self, marks: Marks) {
        if marks != self.marks {
            self.marks = marks;
            self.revision += 1;
        }
    }

    /// Resizes the drawing buffers to the CSS size times the pixel ratio. A planar camera keeps
    /// the world point at the centre; a camera that had no size yet frames the lattice.
    pub fn resize(&mut self, css_width: f64, css_height: f64, dpr: f64) {
        let (w, h) = (css_width.max(1.0), css_height.max(1.0));
        let had_size = self.camera.size()[0] > 1.0;
        let centre = match &self.camera {
            Camera::Planar(c) if had_size => Some(c.to_world(c.width / 2.0, c.height / 2.0)),
            _ => None,
        };
        self.camera.set_size(w, h);
        match (&mut self.camera, centre) {
            (Camera::Planar(c), Some([x, y])) => {
                c.cx = x;
                c.cy = y;
            }
            (Camera::Orbit(_), _) if had_size => {}
            _ if self.layout.is_some() => self.fit_pending = true,
            _ => {}
        }
        self.css = [w, h];
        self.dpr = dpr;
        let (pw, ph) = (
            (w * dpr).round().max(1.0) as u32,
            (h * dpr).round().max(1.0) as u32,
        );
        self.canvas.set_width(pw);
        self.canvas.set_height(ph);
        if let Some(a) = &self.annotations {
            // Resizing clears a canvas.
            a.canvas().set_width(pw);
            a.canvas().set_height(ph);
            self.annotated = false;
        }
    }

    /// Frames what is on the lattice at the next draw.
    pub fn request_fit(&mut self) {
        self.fit_pending = true;
    }

    /// The camera was placed by its owner: no framing is pending any more, and the view no
    /// longer follows the content.
    pub fn cancel_fit(&mut self) {
        self.fit_pending = false;
        self.follow = false;
    }

    /// The user panned or zoomed: the view stays where they put it until the next fit.
    pub fn hold(&mut self) {
        self.follow = false;
    }

    /// While the view follows the content, frames it again at the next draw if any of `cells`
    /// (planar) is out of view, so a structure that grows stays in sight. A 3-D camera stays.
    pub fn keep_in_view(&mut self, cells: &[u8]) {
        let Camera::Planar(c) = &self.camera else {
            return;
        };
        if !self.follow || self.fit_pending || cells.len() != self.grid.len() {
            return;
        }
        if self.grid.content_bounds(cells).is_some_and(|b| !c.shows(b)) {
            self.fit_pending = true;
        }
    }

    /// Frames what is on the lattice with a margin (in 3-D with the ghost and the lamp), or the
    /// whole lattice when it is empty.
    pub fn fit(&mut self, state: &State) {
        self.fit_pending = false;
        self.follow = true;
        let grid = self.grid;
        match &mut self.camera {
            Camera::Orbit(c) => {
                let ghost: &[u32] = if self.marks.ghost {
                    &state.world.ghost
                } else {
                    &[]
                };
                match occupied_box(grid.dims, state.cells, ghost) {
                    Some((mut min, mut max)) => {
                        // The lamp of a light source is part of the picture.
                        if let Some(lamp) = state
                            .world
                            .light
                            .and_then(|l| lamp_placement(min, max, l, grid.dims))
                        {
                            let r = lamp.size * 0.9;
                            for a in 0..3 {
                                min[a] = min[a].min(lamp.at[a] - r);
                                max[a] = max[a].max(lamp.at[a] + r);
                            }
                        }
                        c.fit_box(min, max, 1.08);
                    }
                    None => c.fit(grid.dims),
                }
            }
            Camera::Planar(c) => match grid.content_bounds(state.cells) {
                Some(b) => c.fit(b),
                None => c.fit(grid.bounds()),
            },
        }
    }

    /// Draws the lattice and its annotations. Returns what a 3-D frame drew.
    pub fn draw(&mut self, state: &State) -> Result<Option<RenderStats>, JsValue> {
        if self.layout.is_none() || state.cells.len() != self.grid.len() {
            return Ok(None);
        }
        if self.fit_pending {
            self.fit(state);
        }
        let Some(layout) = &self.layout else {
            return Ok(None);
        };
        let scene = SceneRef {
            layout,
            grid: self.grid,
            state: *state,
            camera: &self.camera,
            marks: &self.marks,
        };
        let (pw, ph) = (self.canvas.width() as i32, self.canvas.height() as i32);
        let dpr = self.dpr;
        let revision = self.revision;
        let now = || self.clock.map_or(0.0, |c| c());
        let start = now();
        let mut uploaded = start;
        let stats = match &mut self.backend {
            Backend::Gl {
                gl,
                planar,
                cubic,
                multisample,
            } => {
                let resolve = matches!(self.camera, Camera::Orbit(_))
                    && cubic.is_some()
                    && multisample.begin(gl, pw, ph);
                gl.viewport(0, 0, pw, ph);
                let [r, g, b, _] = BACKGROUND.map(|c| f32::from(c) / 255.0);
                gl.clear_color(r, g, b, 1.0);
                gl.clear(Gl::COLOR_BUFFER_BIT | Gl::DEPTH_BUFFER_BIT);
                match (&self.camera, cubic) {
                    (Camera::Orbit(cam), Some(cubic)) => {
                        let stats = cubic.draw(gl, &scene, cam, revision);
                        if resolve {
                            multisample.resolve(gl);
                        }
                        Some(stats)
                    }
                    (Camera::Planar(cam), _) => {
                        planar.upload(gl, state, revision)?;
                        uploaded = now();
                        planar.draw(gl, &scene, cam, dpr, [pw, ph]);
                        None
                    }
                    _ => None,
                }
            }
            Backend::Canvas { ctx, planar, cubic } => {
                ctx.set_transform(1.0, 0.0, 0.0, 1.0, 0.0, 0.0)?;
                ctx.set_fill_style_str(&css(BACKGROUND));
                ctx.fill_rect(0.0, 0.0, f64::from(pw), f64::from(ph));
                // Everything below is drawn in CSS pixels, the camera's units.
                ctx.set_transform(dpr, 0.0, 0.0, dpr, 0.0, 0.0)?;
                match &self.camera {
                    Camera::Orbit(cam) => Some(cubic.draw(ctx, &scene, cam, revision)),
                    Camera::Planar(cam) => {
                        planar.draw(ctx, &scene, cam)?;
                        None
                    }
                }
            }
        };
        if let Some(a) = &self.annotations {
            // A canvas that is drawn on, even only cleared, is handed to the compositor again: on a
            // software rasteriser, a second full-size layer every frame. An empty one is left alone.
            a.set_transform(1.0, 0.0, 0.0, 1.0, 0.0, 0.0)?;
            if self.annotated {
                a.clear_rect(0.0, 0.0, f64::from(pw), f64::from(ph));
            }
            a.set_transform(dpr, 0.0, 0.0, dpr, 0.0, 0.0)?;
            self.annotated = match &self.camera {
                Camera::Planar(cam) => annotate::planar(a, &scene, cam),
                Camera::Orbit(cam) => annotate::reach(a, &scene, cam),
            };
        }
        let end = now();
        self.timing.frames += 1;
        self.timing.upload_ms += uploaded - start;
        self.timing.draw_ms += end - uploaded;
        Ok(stats)
    }

    /// The cell under a screen point (CSS pixels), and in 3-D the face hit.
    pub fn pick(&self, cells: &[u8], sx: f64, sy: f64) -> (Option<u32>, Option<Hit>) {
        if self.layout.is_none() {
            return (None, None);
        }
        match &self.camera {
            Camera::Planar(c) => (c.pick(&self.grid, sx, sy).map(|i| i as u32), None),
            Camera::Orbit(c) => {
                let hit = c.pick(
                    self.grid.dims,
                    |i| cells.get(i).is_some_and(|&v| v != 0),
                    sx,
                    sy,
                );
                (hit.map(|h| h.cell), hit)
            }
        }
    }

    /// The view as one picture, lattice and annotations at the drawing buffer's resolution. Call
    /// right after [`View::draw`], so the copy does not depend on when the canvas was presented.
    pub fn capture(&self) -> Result<ImageBitmap, JsValue> {
        let (w, h) = (self.canvas.width(), self.canvas.height());
        let out = OffscreenCanvas::new(w, h)?;
        let ctx = context_2d(&out, false)?;
        ctx.draw_image_with_offscreen_canvas(&self.canvas, 0.0, 0.0)?;
        if let Some(a) = &self.annotations {
            ctx.draw_image_with_offscreen_canvas(&a.canvas(), 0.0, 0.0)?;
        }
        out.transfer_to_image_bitmap()
    }
}
