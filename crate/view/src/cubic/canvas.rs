//! The cubic lattice in Canvas 2D, the fallback when WebGL2 is missing: the same scene as the
//! WebGL path ([`super::model`]), drawn as shaded faces in painter's order. Units are whole
//! cubes (their shared faces are hidden, so bonds are implied); the ghost, reachable cells and
//! the add cursor are translucent cubes; the plane is clipped at the eye so close-ups stay
//! correct.

use super::model::{
    CubicModel, Lamp, ModelCache, Plane, ADD_COLOR, ARROW_COLOR, GHOST_COLOR, LAMP_COLOR,
    REACH_COLOR,
};
use crate::camera::{cross, dot, norm, normalize, sub, Camera3D, V3};
use crate::palette::{css, parse_color};
use crate::scene::{CursorKind, RenderStats, SceneRef};
use wasm_bindgen::JsValue;
use web_sys::OffscreenCanvasRenderingContext2d as Ctx;

/// Distance of the near clipping plane from the eye.
const NEAR: f64 = 0.05;
const NORMALS: [V3; 6] = [
    [1.0, 0.0, 0.0],
    [-1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, -1.0, 0.0],
    [0.0, 0.0, 1.0],
    [0.0, 0.0, -1.0],
];
/// Direction of the key light.
const KEY: V3 = [0.42, 0.28, 0.86];
const UNIT_STROKE: &str = "rgba(0,0,0,0.4)";

type Point = [f64; 2];

/// View-space positions (right, up, depth) of world points, and their projection.
struct Projector {
    eye: V3,
    right: V3,
    up: V3,
    fwd: V3,
    /// Pixels per unit of x/depth and y/depth.
    scale: f64,
    width: f64,
    height: f64,
}

impl Projector {
    fn new(cam: &Camera3D) -> Projector {
        let eye = cam.eye();
        let fwd = normalize(sub(cam.target, eye));
        let right = normalize(cross(fwd, [0.0, 0.0, 1.0]));
        let up = cross(right, fwd);
        Projector {
            eye,
            right,
            up,
            fwd,
            scale: cam.height / 2.0 / (cam.fov / 2.0).tan(),
            width: cam.width,
            height: cam.height,
        }
    }

    fn view(&self, p: V3) -> V3 {
        let d = sub(p, self.eye);
        [dot(d, self.right), dot(d, self.up), dot(d, self.fwd)]
    }

    fn screen(&self, v: V3) -> Point {
        [
            self.width / 2.0 + v[0] / v[2] * self.scale,
            self.height / 2.0 - v[1] / v[2] * self.scale,
        ]
    }

    /// A polygon clipped at the near plane and projected, or `None` when wholly behind.
    fn polygon(&self, points: &[V3]) -> Option<Vec<Point>> {
        let v: Vec<V3> = points.iter().map(|&p| self.view(p)).collect();
        let mut out = Vec::with_capacity(v.len() + 1);
        for (i, &a) in v.iter().enumerate() {
            let b = v[(i + 1) % v.len()];
            let (ina, inb) = (a[2] >= NEAR, b[2] >= NEAR);
            if ina {
                out.push(a);
            }
            if ina != inb {
                out.push(cut(a, b));
            }
        }
        (out.len() >= 3).then(|| out.into_iter().map(|p| self.screen(p)).collect())
    }

    /// A segment clipped at the near plane and projected.
    fn segment(&self, a: V3, b: V3) -> Option<[Point; 2]> {
        let (mut va, mut vb) = (self.view(a), self.view(b));
        if va[2] < NEAR && vb[2] < NEAR {
            return None;
        }
        if va[2] < NEAR {
            va = cut(va, vb);
        } else if vb[2] < NEAR {
            vb = cut(vb, va);
        }
        Some([self.screen(va), self.screen(vb)])
    }

    fn pixels_per_unit(&self, depth: f64) -> f64 {
        self.scale / depth
    }

    fn distance(&self, p: V3) -> f64 {
        norm(sub(p, self.eye))
    }
}

/// Where the view-space segment from `p` to `q` crosses the near plane.
fn cut(p: V3, q: V3) -> V3 {
    let t = (NEAR - p[2]) / (q[2] - p[2]);
    [p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t, NEAR]
}

/// A cube face to paint: its distance from the eye, its outline on screen and its colours.
struct Face<'a> {
    depth: f64,
    pts: Vec<Point>,
    fill: String,
    stroke: &'a str,
}

/// Collects the faces of cubes that face the eye.
struct Faces<'a> {
    pr: &'a Projector,
    cells: &'a [u8],
    dims: [u32; 3],
    list: Vec<Face<'a>>,
}

impl<'a> Faces<'a> {
    fn occupied(&self, c: [i64; 3]) -> bool {
        let [w, h, d] = self.dims.map(i64::from);
        let inside = c.iter().zip([w, h, d]).all(|(&v, n)| v >= 0 && v < n);
        // A cell past the end of the buffer counts as occupied.
        inside && self.cells.get(((c[2] * h + c[1]) * w + c[0]) as usize) != Some(&0)
    }

    /// A cube of side `size` centred in cell `c`. A solid cube is shaded and loses the faces it
    /// shares with occupied cells.
    fn cube(
        &mut self,
        c: [u32; 3],
        size: f64,
        base: [f64; 3],
        alpha: f64,
        solid: bool,
        stroke: &'a str,
    ) {
        let key = normalize(KEY);
        for n in NORMALS {
            let next = std::array::from_fn(|a| i64::from(c[a]) + n[a] as i64);
            if solid && self.occupied(next) {
                continue;
            }
            let fc: V3 = std::array::from_fn(|a| f64::from(c[a]) + 0.5 + n[a] * size * 0.5);
            if dot(sub(self.pr.eye, fc), n) <= 0.0 {
                continue;
            }
            let Some(pts) = self.pr.polygon(&face_corners(c, n, size)) else {
                continue;
            };
            let shade = if solid {
                0.5 + 0.5 * dot(n, key).max(0.0) + 0.08 * n[2]
            } else {
                1.0
            };
            self.list.push(Face {
                depth: self.pr.distance(fc),
                pts,
                fill: rgba(base.map(|v| v * shade), alpha * 255.0),
                stroke,
            });
        }
    }
}

/// The Canvas 2D renderer of the cubic lattice.
#[derive(Default)]
pub struct CubicCanvas {
    cache: ModelCache,
}

impl CubicCanvas {
    /// Paints `scene` over a canvas the caller has cleared, with its transform in CSS pixels.
    /// The model is rebuilt only when `revision` differs from the last one drawn: the caller
    /// bumps it whenever the frame, overlay, world or marks change.
    pub fn draw(
        &mut self,
        ctx: &Ctx,
        scene: &SceneRef,
        cam: &Camera3D,
        revision: u64,
    ) -> RenderStats {
        self.cache.update(scene, revision);
        let m = self.cache.model();
        let pr = Projector::new(cam);
        if let Some(plane) = m.plane {
            draw_plane(ctx, m, plane, &pr);
        }

        let ghost = parse_color(GHOST_COLOR);
        let reach = parse_color(REACH_COLOR);
        let add = parse_color(ADD_COLOR);
        let edge = |c: [u8; 4]| css([c[0], c[1], c[2], 220]);
        let strokes = [edge(ghost), edge(reach), edge(add)];
        let rgb = |c: [u8; 4]| [c[0], c[1], c[2]].map(f64::from);

        let cells = scene.state.cells;
        let mut faces = Faces {
            pr: &pr,
            cells,
            dims: m.dims,
            list: Vec::new(),
        };
        for &u in &m.visible {
            let u = u as usize;
            faces.cube(
                m.unit_pos[u],
                1.0,
                rgb(m.unit_color[u]),
                1.0,
                true,
                UNIT_STROKE,
            );
        }
        let translucent = [
            (&m.ghost[..], 0.9, ghost, 0.14),
            (&m.highlight[..], 0.66, reach, 0.35),
        ];
        for ((list, size, base, alpha), stroke) in translucent.into_iter().zip(&strokes) {
            for &cell in list {
                faces.cube(m.coord(cell), size, rgb(base), alpha, false, stroke);
            }
        }
        if let Some(c) = scene.marks.cursor {
            if c.kind == CursorKind::Add && cells.get(c.cell as usize) == Some(&0) {
                faces.cube(m.coord(c.cell), 0.86, rgb(add), 0.4, false, &strokes[2]);
            }
        }
        let mut faces = faces.list;

        // The lamp is painted behind the faces when it is farther than the structure's centre.
        let lamp_depth = m.lamp.map_or(0.0, |l| pr.distance(l.at));
        let centre_depth = m.bounds.map_or(0.0, |b| pr.distance(b.centre()));
        let behind = lamp_depth > centre_depth;
        // Drawing the lamp fails only on non-finite coordinates; it is then left out.
        if let Some(lamp) = m.lamp.filter(|_| behind) {
            let _ = draw_lamp(ctx, lamp, &pr);
        }
        kumiki_model::sort::sort_by(&mut faces, |a, b| b.depth.total_cmp(&a.depth));
        ctx.set_line_width(1.0);
        ctx.set_line_join("round");
        for f in &faces {
            path(ctx, &f.pts);
            ctx.set_fill_style_str(&f.fill);
            ctx.fill();
            ctx.set_stroke_style_str(f.stroke);
            ctx.stroke();
        }
        if let Some(lamp) = m.lamp.filter(|_| !behind) {
            let _ = draw_lamp(ctx, lamp, &pr);
        }
        draw_outlines(ctx, scene, m, &pr);
        m.stats()
    }
}

/// A CSS colour from unrounded channels (truncated, as the page's `css` always has) and an
/// alpha in 0–255.
fn rgba([r, g, b]: [f64; 3], alpha: f64) -> String {
    format!(
        "rgba({},{},{},{:.3})",
        r as i64,
        g as i64,
        b as i64,
        alpha / 255.0
    )
}

/// Starts a closed path through `pts`.
fn path(ctx: &Ctx, pts: &[Point]) {
    ctx.begin_path();
    ctx.move_to(pts[0][0], pts[0][1]);
    for p in &pts[1..] {
        ctx.line_to(p[0], p[1]);
    }
    ctx.close_path();
}

fn draw_plane(ctx: &Ctx, m: &CubicModel, plane: Plane, pr: &Projector) {
    let z = plane.z;
    let (mut x0, mut y0, mut x1, mut y1) = (0.0, 0.0, f64::from(m.dims[0]), f64::from(m.dims[1]));
    if let Some(b) = m.bounds.filter(|_| !plane.solid) {
        let (w, h) = (x1, y1);
        let r = ((b.max[0] - b.min[0]).hypot(b.max[1] - b.min[1]) * 0.6 + 2.0)
            .max(4.0)
            .ceil();
        x0 = (b.min[0].floor() - r).max(0.0);
        y0 = (b.min[1].floor() - r).max(0.0);
        x1 = (b.max[0].ceil() + r).min(w);
        y1 = (b.max[1].ceil() + r).min(h);
    }
    let corners = [[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]];
    if let Some(poly) = pr.polygon(&corners) {
        path(ctx, &poly);
        ctx.set_fill_style_str(if plane.solid {
            "rgba(92,84,74,0.92)"
        } else {
            "rgba(51,64,79,0.55)"
        });
        ctx.fill();
    }
    ctx.set_stroke_style_str(if plane.solid {
        "rgba(158,146,128,0.55)"
    } else {
        "rgba(153,173,194,0.28)"
    });
    ctx.set_line_width(1.0);
    ctx.begin_path();
    let line = |a: V3, b: V3| {
        if let Some([p, q]) = pr.segment(a, b) {
            ctx.move_to(p[0], p[1]);
            ctx.line_to(q[0], q[1]);
        }
    };
    for x in x0 as i64..=x1 as i64 {
        let x = x as f64;
        line([x, y0, z], [x, y1, z]);
    }
    for y in y0 as i64..=y1 as i64 {
        let y = y as f64;
        line([x0, y, z], [x1, y, z]);
    }
    ctx.stroke();
    for s in &m.shadows {
        let (x, y) = (f64::from(s.x), f64::from(s.y));
        let square = [
            [x + 0.04, y + 0.04, z],
            [x + 0.96, y + 0.04, z],
            [x + 0.96, y + 0.96, z],
            [x + 0.04, y + 0.96, z],
        ];
        let Some(pts) = pr.polygon(&square) else {
            continue;
        };
        path(ctx, &pts);
        ctx.set_fill_style_str(&format!("rgba(0,0,0,{:.3})", 0.4 * f64::from(s.strength)));
        ctx.fill();
    }
}

/// The lamp as a glowing disc, with an arrow toward the structure.
fn draw_lamp(ctx: &Ctx, lamp: Lamp, pr: &Projector) -> Result<(), JsValue> {
    let v = pr.view(lamp.at);
    if v[2] < NEAR {
        return Ok(());
    }
    let [sx, sy] = pr.screen(v);
    let r = (0.4 * lamp.size * pr.pixels_per_unit(v[2])).max(4.0);
    let glow = ctx.create_radial_gradient(sx, sy, r * 0.3, sx, sy, r * 2.2)?;
    glow.add_color_stop(0.0, "rgba(255,209,102,0.55)")?;
    glow.add_color_stop(1.0, "rgba(255,209,102,0)")?;
    ctx.set_fill_style_canvas_gradient(&glow);
    ctx.begin_path();
    ctx.arc(sx, sy, r * 2.2, 0.0, std::f64::consts::TAU)?;
    ctx.fill();
    ctx.set_fill_style_str(LAMP_COLOR);
    ctx.begin_path();
    ctx.arc(sx, sy, r, 0.0, std::f64::consts::TAU)?;
    ctx.fill();

    // The arrow, from the lamp toward the structure.
    let (d, s) = (lamp.dir, lamp.size);
    let at = |k: f64| -> V3 { std::array::from_fn(|a| lamp.at[a] - d[a] * k * s) };
    let Some([[ax, ay], [bx, by]]) = pr.segment(at(0.7), at(2.0)) else {
        return Ok(());
    };
    ctx.set_stroke_style_str(ARROW_COLOR);
    ctx.set_fill_style_str(ARROW_COLOR);
    ctx.set_line_width((r * 0.3).max(2.0));
    ctx.begin_path();
    ctx.move_to(ax, ay);
    ctx.line_to(bx, by);
    ctx.stroke();
    let len = (bx - ax).hypot(by - ay);
    let len = if len > 0.0 { len } else { 1.0 };
    let (ux, uy) = ((bx - ax) / len, (by - ay) / len);
    let head = (r * 0.9).max(6.0);
    ctx.begin_path();
    ctx.move_to(bx + ux * head * 0.6, by + uy * head * 0.6);
    ctx.line_to(
        bx - ux * head * 0.4 - uy * head * 0.6,
        by - uy * head * 0.4 + ux * head * 0.6,
    );
    ctx.line_to(
        bx - ux * head * 0.4 + uy * head * 0.6,
        by - uy * head * 0.4 - ux * head * 0.6,
    );
    ctx.close_path();
    ctx.fill();
    Ok(())
}

/// Wire boxes: events of the last step, the selection, the hovered unit and the cursor.
fn draw_outlines(ctx: &Ctx, scene: &SceneRef, m: &CubicModel, pr: &Projector) {
    let wire = |cell: u32, color: &str, grow: f64| {
        let c = m.coord(cell);
        let lo: V3 = std::array::from_fn(|a| f64::from(c[a]) + 0.5 - grow);
        let hi: V3 = std::array::from_fn(|a| f64::from(c[a]) + 0.5 + grow);
        ctx.set_stroke_style_str(color);
        ctx.set_line_width(2.0);
        ctx.begin_path();
        for a in 0..3 {
            let others: Vec<usize> = (0..3).filter(|&x| x != a).collect();
            for s in 0..4 {
                let mut p = lo;
                if s & 1 != 0 {
                    p[others[0]] = hi[others[0]];
                }
                if s & 2 != 0 {
                    p[others[1]] = hi[others[1]];
                }
                let mut q = p;
                q[a] = hi[a];
                if let Some([from, to]) = pr.segment(p, q) {
                    ctx.move_to(from[0], from[1]);
                    ctx.line_to(to[0], to[1]);
                }
            }
        }
        ctx.stroke();
    };
    let legend = &scene.layout.events;
    for e in scene.state.events {
        let color = legend.iter().rev().find(|l| l.code == e.kind);
        wire(e.cell, color.map_or("#ff4d4f", |l| &l.color), 0.52);
    }
    let marks = scene.marks;
    if let Some(s) = marks.selected {
        wire(s, "#f0b429", 0.52);
    }
    if let Some(h) = marks.hover.filter(|&h| Some(h) != marks.selected) {
        wire(h, "rgba(255,255,255,0.95)", 0.5);
    }
    if let Some(c) = marks.cursor {
        let color = match c.kind {
            CursorKind::Remove => "#ff5a4d",
            CursorKind::Add => ADD_COLOR,
            CursorKind::Cursor => "#ffffff",
        };
        wire(c.cell, color, 0.52);
    }
}

/// The corners of the face with outward normal `n` of a cube of side `size` centred in cell `c`.
fn face_corners(c: [u32; 3], n: V3, size: f64) -> [V3; 4] {
    let axis = if n[0] != 0.0 {
        0
    } else if n[1] != 0.0 {
        1
    } else {
        2
    };
    let u = if axis == 0 { 1 } else { 0 };
    let v = if axis == 2 { 1 } else { 2 };
    let half = size / 2.0;
    let centre: V3 = std::array::from_fn(|a| f64::from(c[a]) + 0.5 + n[a] * half);
    let corner = |du: f64, dv: f64| {
        let mut p = centre;
        p[u] += du * half;
        p[v] += dv * half;
        p
    };
    [
        corner(-1.0, -1.0),
        corner(1.0, -1.0),
        corner(1.0, 1.0),
        corner(-1.0, 1.0),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera3D {
        let mut cam = Camera3D {
            width: 640.0,
            height: 400.0,
            ..Camera3D::default()
        };
        cam.fit([6, 5, 4]);
        cam.orbit(25.0, -10.0);
        cam
    }

    #[test]
    fn the_projector_agrees_with_the_camera() {
        let cam = camera();
        let pr = Projector::new(&cam);
        for p in [[1.0, 2.0, 0.5], [5.5, 0.5, 3.0], cam.target] {
            let [sx, sy, depth] = cam.project(p).unwrap();
            let v = pr.view(p);
            let [px, py] = pr.screen(v);
            assert!((px - sx).abs() < 1e-9 && (py - sy).abs() < 1e-9, "{p:?}");
            assert!((v[2] - depth).abs() < 1e-9);
            assert!((pr.distance(p) - norm(sub(p, cam.eye()))).abs() < 1e-12);
        }
    }

    #[test]
    fn polygons_and_segments_are_clipped_at_the_near_plane() {
        let cam = camera();
        let pr = Projector::new(&cam);
        let eye = cam.eye();
        let fwd = normalize(sub(cam.target, eye));
        let at = |k: f64, side: f64| -> V3 {
            std::array::from_fn(|a| eye[a] + fwd[a] * k + pr.right[a] * side)
        };
        // Wholly behind the eye: nothing.
        assert_eq!(
            pr.polygon(&[at(-1.0, 0.0), at(-2.0, 1.0), at(-1.0, 1.0)]),
            None
        );
        assert_eq!(pr.segment(at(-1.0, 0.0), at(-2.0, 0.0)), None);
        // A triangle with one corner behind becomes a quadrilateral in front.
        let tri = [at(-1.0, 0.0), at(3.0, 1.0), at(3.0, -1.0)];
        let clipped = pr.polygon(&tri).unwrap();
        assert_eq!(clipped.len(), 4);
        assert!(clipped.iter().flatten().all(|v| v.is_finite()));
        // A segment that crosses keeps its far end where it was.
        let [_, far] = pr.segment(at(-1.0, 0.5), at(4.0, 0.5)).unwrap();
        assert_eq!(far, pr.screen(pr.view(at(4.0, 0.5))));
    }

    #[test]
    fn face_corners_lie_on_the_face() {
        for n in NORMALS {
            let corners = face_corners([2, 3, 4], n, 0.5);
            let axis = n.iter().position(|&v| v != 0.0).unwrap();
            let plane = [2.0, 3.0, 4.0][axis] + 0.5 + n[axis] * 0.25;
            assert!(corners.iter().all(|c| c[axis] == plane), "{n:?}");
            let side = norm(sub(corners[1], corners[0]));
            assert!((side - 0.5).abs() < 1e-12);
            let diagonal = norm(sub(corners[2], corners[0]));
            assert!((diagonal - 0.5 * 2f64.sqrt()).abs() < 1e-12);
        }
    }
}
