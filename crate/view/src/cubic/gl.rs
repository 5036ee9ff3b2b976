//! The cubic lattice in WebGL2: instanced, lit cubes with darkened edges; bonds as short arms
//! between adjacent units; the target as a translucent ghost; the ground (or a reference grid)
//! with the units' shadows; the light as a lamp with an arrow; reachable cells, hover, selection
//! and an editing cursor in depth. Instance and outline buffers are uploaded only when the
//! revision changes, so orbiting a large structure costs one draw call per kind of thing.

use super::mesh::{
    box_edges, centre, cone_mesh, cube_mesh, f32s, rotation_to, sphere_mesh, IDENTITY, VERTEX,
};
use super::model::{
    CubicModel, ModelCache, ADD_COLOR, ARROW_COLOR, GHOST_COLOR, LAMP_COLOR, REACH_COLOR,
};
use super::shaders::{LINE_FS, LINE_VS, MESH_FS, MESH_VS, PLANE_FS, PLANE_VS};
use crate::camera::{normalize, Camera3D, Mat4, V3};
use crate::gl::{attribute, push_f32s, static_buffer, Program};
use crate::palette::{parse_color, Rgba};
use crate::scene::{CursorKind, RenderStats, SceneRef};
use wasm_bindgen::JsValue;
use web_sys::{WebGl2RenderingContext as Gl, WebGlBuffer, WebGlVertexArrayObject};

/// Bytes per instance: offset and scale (6 floats) and an RGBA colour.
const STRIDE: usize = 28;

const BOND_COLOR: &str = "#c9d3dd";

/// A static mesh of positions and normals.
struct Mesh {
    buffer: WebGlBuffer,
    vertices: i32,
}

impl Mesh {
    fn upload(gl: &Gl, data: &[f32]) -> Result<Mesh, JsValue> {
        Ok(Mesh {
            buffer: static_buffer(gl, data)?,
            vertices: (data.len() / VERTEX) as i32,
        })
    }
}

/// A mesh drawn many times, with its own instance buffer.
struct Batch {
    vao: WebGlVertexArrayObject,
    instances: WebGlBuffer,
    vertices: i32,
    count: i32,
}

impl Batch {
    fn new(gl: &Gl, mesh: &Mesh) -> Result<Batch, JsValue> {
        let vao = gl.create_vertex_array().ok_or("no vertex array")?;
        gl.bind_vertex_array(Some(&vao));
        gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&mesh.buffer));
        let vertex = (VERTEX * 4) as i32;
        gl.enable_vertex_attrib_array(0);
        gl.vertex_attrib_pointer_with_i32(0, 3, Gl::FLOAT, false, vertex, 0);
        gl.enable_vertex_attrib_array(1);
        gl.vertex_attrib_pointer_with_i32(1, 3, Gl::FLOAT, false, vertex, 12);
        let instances = gl.create_buffer().ok_or("no buffer")?;
        gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&instances));
        for (loc, size, kind, normalized, offset) in [
            (2, 3, Gl::FLOAT, false, 0),
            (3, 3, Gl::FLOAT, false, 12),
            (4, 4, Gl::UNSIGNED_BYTE, true, 24),
        ] {
            gl.enable_vertex_attrib_array(loc);
            gl.vertex_attrib_pointer_with_i32(loc, size, kind, normalized, STRIDE as i32, offset);
            gl.vertex_attrib_divisor(loc, 1);
        }
        gl.bind_vertex_array(None);
        Ok(Batch {
            vao,
            instances,
            vertices: mesh.vertices,
            count: 0,
        })
    }

    /// Uploads instances written with [`put`].
    fn set(&mut self, gl: &Gl, instances: &[u8]) {
        self.count = (instances.len() / STRIDE) as i32;
        gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&self.instances));
        gl.buffer_data_with_u8_array(Gl::ARRAY_BUFFER, instances, Gl::DYNAMIC_DRAW);
    }

    fn draw(&self, gl: &Gl) {
        if self.count == 0 {
            return;
        }
        gl.bind_vertex_array(Some(&self.vao));
        gl.draw_arrays_instanced(Gl::TRIANGLES, 0, self.vertices, self.count);
    }
}

/// Appends one instance: offset, scale and colour.
fn put(out: &mut Vec<u8>, offset: V3, scale: V3, rgba: Rgba) {
    push_f32s(out, offset.into_iter().chain(scale).map(|v| v as f32));
    out.extend_from_slice(&rgba);
}

/// A group of wire boxes in the outline buffer, drawn in one colour.
struct Outline {
    first: i32,
    vertices: i32,
    color: [f32; 4],
}

/// The WebGL2 renderer of the cubic lattice.
pub struct CubicGl {
    mesh: Program,
    plane: Program,
    lines: Program,
    units: Batch,
    bonds: Batch,
    ghost: Batch,
    reach: Batch,
    shadows: Batch,
    cursor: Batch,
    lamp: Batch,
    halo: Batch,
    shaft: Batch,
    head: Batch,
    quad: WebGlVertexArrayObject,
    line_vao: WebGlVertexArrayObject,
    line_buffer: WebGlBuffer,
    outlines: Vec<Outline>,
    cache: ModelCache,
    /// Reused for every upload.
    scratch: Vec<u8>,
}

impl CubicGl {
    /// Compiles the programs and uploads the meshes.
    pub fn new(gl: &Gl) -> Result<CubicGl, JsValue> {
        let cube = Mesh::upload(gl, &cube_mesh())?;
        let sphere = Mesh::upload(gl, &sphere_mesh(14, 10))?;
        let cone = Mesh::upload(gl, &cone_mesh(18))?;

        let quad = gl.create_vertex_array().ok_or("no vertex array")?;
        gl.bind_vertex_array(Some(&quad));
        static_buffer(
            gl,
            &[0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 1.0],
        )?;
        attribute(gl, 0, 2, Gl::FLOAT, false, 0);

        let line_vao = gl.create_vertex_array().ok_or("no vertex array")?;
        gl.bind_vertex_array(Some(&line_vao));
        let line_buffer = gl.create_buffer().ok_or("no buffer")?;
        gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&line_buffer));
        attribute(gl, 0, 3, Gl::FLOAT, false, 0);
        gl.bind_vertex_array(None);

        Ok(CubicGl {
            mesh: Program::link(gl, MESH_VS, MESH_FS)?,
            plane: Program::link(gl, PLANE_VS, PLANE_FS)?,
            lines: Program::link(gl, LINE_VS, LINE_FS)?,
            units: Batch::new(gl, &cube)?,
            bonds: Batch::new(gl, &cube)?,
            ghost: Batch::new(gl, &cube)?,
            reach: Batch::new(gl, &cube)?,
            shadows: Batch::new(gl, &cube)?,
            cursor: Batch::new(gl, &cube)?,
            lamp: Batch::new(gl, &sphere)?,
            halo: Batch::new(gl, &sphere)?,
            shaft: Batch::new(gl, &cube)?,
            head: Batch::new(gl, &cone)?,
            quad,
            line_vao,
            line_buffer,
            outlines: Vec::new(),
            cache: ModelCache::default(),
            scratch: Vec::new(),
        })
    }

    /// Draws `scene` into the bound framebuffer, over a viewport the caller has set and cleared
    /// (colour and depth). Buffers are rebuilt only when `revision` differs from the last one
    /// drawn: the caller bumps it whenever the frame, overlay, world or marks change.
    pub fn draw(
        &mut self,
        gl: &Gl,
        scene: &SceneRef,
        cam: &Camera3D,
        revision: u64,
    ) -> RenderStats {
        if self.cache.update(scene, revision) {
            self.upload(gl);
            self.upload_cursor(gl, scene);
            self.upload_outlines(gl, scene);
        }
        let m = self.cache.model();

        let vp = cam.view_projection();
        let p = &self.mesh;
        let u = |name| p.uniform(gl, name);
        gl.use_program(Some(&p.program));
        gl.uniform_matrix4fv_with_f32_array(u("u_vp").as_ref(), false, &vp);
        gl.uniform_matrix3fv_with_f32_array(u("u_rot").as_ref(), false, &IDENTITY);
        gl.uniform3fv_with_f32_array(u("u_key").as_ref(), &f32s(normalize([0.42, 0.28, 0.86])));
        gl.uniform3fv_with_f32_array(u("u_eye_dir").as_ref(), &f32s(cam.toward_eye()));
        let lamp_dir = m.lamp.map_or([0.0, 0.0, 1.0], |l| l.dir);
        gl.uniform3fv_with_f32_array(u("u_lamp").as_ref(), &f32s(lamp_dir));
        gl.uniform1f(
            u("u_lamp_on").as_ref(),
            if m.lamp.is_some() { 1.0 } else { 0.0 },
        );
        let mode = |k: i32, alpha: f32, edge: f32, fill: f32| {
            gl.uniform1i(u("u_mode").as_ref(), k);
            gl.uniform1f(u("u_alpha").as_ref(), alpha);
            gl.uniform1f(u("u_edge").as_ref(), edge);
            gl.uniform1f(u("u_fill").as_ref(), fill);
        };

        gl.enable(Gl::DEPTH_TEST);
        gl.depth_func(Gl::LEQUAL);
        gl.enable(Gl::CULL_FACE);
        gl.cull_face(Gl::BACK);
        gl.disable(Gl::BLEND);
        gl.depth_mask(true);

        // Opaque: units, bonds, the lamp and its arrow.
        mode(0, 1.0, 0.055, 0.12);
        self.units.draw(gl);
        mode(0, 1.0, 0.0, 0.12);
        self.bonds.draw(gl);
        if let Some(lamp) = m.lamp {
            mode(3, 1.0, 0.0, 0.12);
            self.lamp.draw(gl);
            let rot = rotation_to(lamp.dir.map(|v| -v));
            gl.uniform_matrix3fv_with_f32_array(u("u_rot").as_ref(), false, &rot);
            mode(0, 1.0, 0.0, 0.12);
            self.shaft.draw(gl);
            self.head.draw(gl);
            gl.uniform_matrix3fv_with_f32_array(u("u_rot").as_ref(), false, &IDENTITY);
        }

        // Translucent, back to front by kind: the plane, shadows, ghost, reachable cells, cursor.
        gl.enable(Gl::BLEND);
        gl.blend_func_separate(
            Gl::SRC_ALPHA,
            Gl::ONE_MINUS_SRC_ALPHA,
            Gl::ONE,
            Gl::ONE_MINUS_SRC_ALPHA,
        );
        gl.depth_mask(false);
        self.draw_plane(gl, m, &vp);
        gl.use_program(Some(&p.program));
        gl.enable(Gl::POLYGON_OFFSET_FILL);
        gl.polygon_offset(-1.0, -4.0);
        mode(2, 0.5, 0.0, 0.12);
        self.shadows.draw(gl);
        gl.disable(Gl::POLYGON_OFFSET_FILL);
        mode(1, 1.0, 0.06, 0.1);
        self.ghost.draw(gl);
        mode(1, 1.0, 0.1, 0.3);
        self.reach.draw(gl);
        mode(1, 1.0, 0.08, 0.38);
        self.cursor.draw(gl);
        if m.lamp.is_some() {
            mode(3, 0.16, 0.0, 0.12);
            self.halo.draw(gl);
        }
        gl.disable(Gl::CULL_FACE);

        self.draw_outlines(gl, &vp);
        gl.depth_mask(true);
        gl.disable(Gl::BLEND);
        gl.disable(Gl::DEPTH_TEST);
        gl.bind_vertex_array(None);
        m.stats()
    }

    /// Fills the instance buffers from the model.
    fn upload(&mut self, gl: &Gl) {
        let m = self.cache.model();
        let buf = &mut self.scratch;

        let unit_size = if m.bonds.is_empty() { 0.92 } else { 0.76 };
        buf.clear();
        for &u in &m.visible {
            let u = u as usize;
            put(buf, centre(m.unit_pos[u]), [unit_size; 3], m.unit_color[u]);
        }
        self.units.set(gl, buf);

        let arm = 0.26;
        let reach = 1.0 - unit_size + 0.08;
        let bond = parse_color(BOND_COLOR);
        buf.clear();
        for b in &m.bonds {
            let scale = std::array::from_fn(|a| if a == usize::from(b.axis) { reach } else { arm });
            put(buf, b.mid.map(f64::from), scale, bond);
        }
        self.bonds.set(gl, buf);

        let cells = |buf: &mut Vec<u8>, list: &[u32], size: f64, color: &str| {
            let rgba = parse_color(color);
            buf.clear();
            for &cell in list {
                put(buf, centre(m.coord(cell)), [size; 3], rgba);
            }
        };
        cells(buf, &m.ghost, 0.9, GHOST_COLOR);
        self.ghost.set(gl, buf);
        cells(buf, &m.highlight, 0.66, REACH_COLOR);
        self.reach.set(gl, buf);

        let z = m.plane.map_or(0.0, |p| p.z) + 0.001;
        buf.clear();
        for s in &m.shadows {
            let alpha = (255.0 * f64::from(s.strength)).round() as u8;
            put(
                buf,
                [f64::from(s.x) + 0.5, f64::from(s.y) + 0.5, z],
                [1.08, 1.08, 0.002],
                [0, 0, 0, alpha],
            );
        }
        self.shadows.set(gl, buf);

        let lamp_color = parse_color(LAMP_COLOR);
        let arrow = parse_color(ARROW_COLOR);
        let mut one = |batch: &mut Batch, at: Option<(V3, V3, Rgba)>| {
            buf.clear();
            if let Some((at, scale, rgba)) = at {
                put(buf, at, scale, rgba);
            }
            batch.set(gl, buf);
        };
        let (mut lamp, mut halo, mut shaft, mut head) = (None, None, None, None);
        if let Some(l) = m.lamp {
            let s = l.size;
            lamp = Some((l.at, [0.8 * s; 3], lamp_color));
            halo = Some((l.at, [1.6 * s; 3], lamp_color));
            // The arrow points from the lamp toward the structure, along the light's travel.
            let back = |k: f64| std::array::from_fn(|a| l.at[a] - l.dir[a] * k);
            let shaft_len = 0.9 * s;
            let start = 0.7 * s;
            shaft = Some((
                back(start + shaft_len / 2.0),
                [0.16 * s, 0.16 * s, shaft_len],
                arrow,
            ));
            let tip = start + shaft_len + 0.25 * s;
            head = Some((back(tip), [0.5 * s, 0.5 * s, 0.55 * s], arrow));
        }
        one(&mut self.lamp, lamp);
        one(&mut self.halo, halo);
        one(&mut self.shaft, shaft);
        one(&mut self.head, head);
    }

    /// The add cursor's translucent cube, over an empty cell.
    fn upload_cursor(&mut self, gl: &Gl, scene: &SceneRef) {
        let m = self.cache.model();
        let buf = &mut self.scratch;
        buf.clear();
        if let Some(c) = scene.marks.cursor {
            if c.kind == CursorKind::Add && scene.state.cells.get(c.cell as usize) == Some(&0) {
                put(
                    buf,
                    centre(m.coord(c.cell)),
                    [0.86; 3],
                    parse_color(ADD_COLOR),
                );
            }
        }
        self.cursor.set(gl, buf);
    }

    /// Wire boxes: events of the last step, the selection, the hovered unit and the cursor, all
    /// in one buffer, one group per colour.
    fn upload_outlines(&mut self, gl: &Gl, scene: &SceneRef) {
        let m = self.cache.model();
        let mut groups: Vec<(Vec<u32>, [f64; 4], f64)> = Vec::new();
        let mut kinds: Vec<(u8, Vec<u32>)> = Vec::new();
        for e in scene.state.events {
            match kinds.iter_mut().find(|(k, _)| *k == e.kind) {
                Some((_, cells)) => cells.push(e.cell),
                None => kinds.push((e.kind, vec![e.cell])),
            }
        }
        for (kind, cells) in kinds {
            let legend = scene.layout.events.iter().rev().find(|e| e.code == kind);
            let c = legend.map_or([255, 77, 79, 255], |e| parse_color(&e.color));
            let [r, g, b] = [c[0], c[1], c[2]].map(|v| f64::from(v) / 255.0);
            groups.push((cells, [r, g, b, 0.95], 0.5));
        }
        let marks = scene.marks;
        if let Some(s) = marks.selected {
            groups.push((vec![s], [0.94, 0.71, 0.16, 1.0], 0.5));
        }
        if let Some(h) = marks.hover.filter(|&h| Some(h) != marks.selected) {
            groups.push((vec![h], [1.0, 1.0, 1.0, 0.95], 0.47));
        }
        if let Some(c) = marks.cursor {
            let color = match c.kind {
                CursorKind::Remove => [1.0, 0.35, 0.3, 1.0],
                CursorKind::Add => [0.24, 0.86, 0.52, 1.0],
                CursorKind::Cursor => [1.0, 1.0, 1.0, 1.0],
            };
            groups.push((vec![c.cell], color, 0.5));
        }

        let buf = &mut self.scratch;
        buf.clear();
        self.outlines.clear();
        let mut first = 0;
        for (cells, color, grow) in groups {
            for cell in cells {
                box_edges(m.coord(cell), grow, buf);
            }
            let end = (buf.len() / 12) as i32;
            self.outlines.push(Outline {
                first,
                vertices: end - first,
                color: color.map(|v| v as f32),
            });
            first = end;
        }
        gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&self.line_buffer));
        gl.buffer_data_with_u8_array(Gl::ARRAY_BUFFER, buf, Gl::DYNAMIC_DRAW);
    }

    fn draw_plane(&self, gl: &Gl, m: &CubicModel, vp: &Mat4) {
        let Some(plane) = m.plane else {
            return;
        };
        let pl = &self.plane;
        let u = |name| pl.uniform(gl, name);
        gl.use_program(Some(&pl.program));
        gl.uniform_matrix4fv_with_f32_array(u("u_vp").as_ref(), false, vp);
        gl.uniform1f(u("u_z").as_ref(), plane.z as f32);
        let [w, h] = [m.dims[0], m.dims[1]].map(f64::from);
        let c = m.bounds.map_or([w / 2.0, h / 2.0, 0.0], |b| b.centre());
        let uniform2 = |name, x: f64, y: f64| gl.uniform2f(u(name).as_ref(), x as f32, y as f32);
        if plane.solid {
            // The model's ground: the whole floor of the space, edges included.
            uniform2("u_min", 0.0, 0.0);
            uniform2("u_max", w, h);
            gl.uniform4f(u("u_fill").as_ref(), 0.36, 0.33, 0.29, 0.92);
            gl.uniform4f(u("u_line").as_ref(), 0.62, 0.57, 0.5, 0.55);
            gl.uniform1f(u("u_fade").as_ref(), 0.0);
        } else {
            // A reference grid fading out around the structure.
            let r = m.bounds.map_or(w.max(h), |b| {
                ((b.max[0] - b.min[0]).hypot(b.max[1] - b.min[1]) * 1.2 + 4.0).max(6.0)
            });
            uniform2("u_min", (c[0] - r).max(0.0), (c[1] - r).max(0.0));
            uniform2("u_max", (c[0] + r).min(w), (c[1] + r).min(h));
            gl.uniform4f(u("u_fill").as_ref(), 0.2, 0.25, 0.31, 0.55);
            gl.uniform4f(u("u_line").as_ref(), 0.6, 0.68, 0.76, 0.35);
            gl.uniform1f(u("u_fade").as_ref(), r as f32);
        }
        uniform2("u_centre", c[0], c[1]);
        gl.disable(Gl::CULL_FACE);
        gl.bind_vertex_array(Some(&self.quad));
        gl.draw_arrays(Gl::TRIANGLES, 0, 6);
        gl.enable(Gl::CULL_FACE);
    }

    fn draw_outlines(&self, gl: &Gl, vp: &Mat4) {
        if self.outlines.is_empty() {
            return;
        }
        let l = &self.lines;
        let color = l.uniform(gl, "u_color");
        gl.use_program(Some(&l.program));
        gl.uniform_matrix4fv_with_f32_array(l.uniform(gl, "u_vp").as_ref(), false, vp);
        gl.bind_vertex_array(Some(&self.line_vao));
        for o in &self.outlines {
            let [r, g, b, a] = o.color;
            // Visible edges bright, hidden ones faint: the mark shows through what covers it.
            gl.depth_func(Gl::GREATER);
            gl.uniform4f(color.as_ref(), r, g, b, a * 0.35);
            gl.draw_arrays(Gl::LINES, o.first, o.vertices);
            gl.depth_func(Gl::LEQUAL);
            gl.uniform4f(color.as_ref(), r, g, b, a);
            gl.draw_arrays(Gl::LINES, o.first, o.vertices);
        }
    }
}
