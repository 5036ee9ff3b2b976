//! Square and hex lattices in WebGL2: one full-screen pass that finds each pixel's cell and looks
//! its code up in an integer texture, then one pass that puts a disc on each agent's cell: an
//! instanced quad, or a point when cells are too small on screen for a disc (a point is one vertex
//! where a quad is six, which a software rasteriser feels with thousands of robots). A 1024×1024
//! lattice with thousands of robots costs the upload of the rows of codes that changed and a few
//! kilobytes of agents per frame.

use crate::camera::Camera2D;
use crate::gl::{attribute, static_buffer, texture, upload_table, Program};
use crate::palette::{heat_table, legend_table};
use crate::scene::{SceneRef, State};
use kumiki_model::lattice::LatticeKind;
use kumiki_model::model::Layout;
use wasm_bindgen::JsValue;
use web_sys::{WebGl2RenderingContext as Gl, WebGlBuffer, WebGlTexture, WebGlVertexArrayObject};

const VS: &str = "#version 300 es
in vec2 a_pos;
void main() { gl_Position = vec4(a_pos, 0.0, 1.0); }";

const FS: &str = "#version 300 es
precision highp float;
precision highp int;
precision highp usampler2D;
uniform usampler2D u_cells;
uniform sampler2D u_palette;
uniform sampler2D u_field;
uniform sampler2D u_heat;
uniform vec2 u_viewport;
uniform vec3 u_cam;
uniform ivec2 u_dims;
uniform int u_hex;
uniform int u_overlay;
uniform vec2 u_range;
out vec4 outColor;
const float ROW = 0.8660254;
const float RAD = 0.5773503;
void main() {
  vec2 s = vec2(gl_FragCoord.x, u_viewport.y - gl_FragCoord.y);
  vec2 w = (s - 0.5 * u_viewport) / u_cam.z + u_cam.xy;
  ivec2 c;
  vec2 local;
  if (u_hex == 1) {
    float r = (w.y - RAD) / ROW;
    float q = (w.x - 0.5) - r * 0.5;
    vec3 cube = vec3(q, r, -q - r);
    vec3 rc = floor(cube + 0.5);
    vec3 d = abs(rc - cube);
    if (d.x > d.y && d.x > d.z) rc.x = -rc.y - rc.z;
    else if (d.y > d.z) rc.y = -rc.x - rc.z;
    int rr = int(rc.y);
    int rq = int(rc.x);
    c = ivec2(rq + (rr - (rr & 1)) / 2, rr);
    vec2 centre = vec2(float(c.x) + 0.5 + ((c.y & 1) == 1 ? 0.5 : 0.0), float(c.y) * ROW + RAD);
    local = w - centre;
  } else {
    c = ivec2(floor(w));
    local = w - (vec2(c) + 0.5);
  }
  if (c.x < 0 || c.y < 0 || c.x >= u_dims.x || c.y >= u_dims.y) discard;
  uint code = texelFetch(u_cells, c, 0).r;
  if (code == 0u) discard;
  vec4 col = texelFetch(u_palette, ivec2(int(code), 0), 0);
  if (u_overlay == 1) {
    float v = texelFetch(u_field, c, 0).r;
    if (!isnan(v) && !isinf(v)) {
      float t = clamp((v - u_range.x) / max(u_range.y - u_range.x, 1e-9), 0.0, 1.0);
      col = texelFetch(u_heat, ivec2(int(t * 255.0), 0), 0);
    }
  }
  float edge;
  if (u_hex == 1) {
    edge = 0.5 - max(abs(local.x), max(abs(0.5 * local.x + ROW * local.y), abs(-0.5 * local.x + ROW * local.y)));
  } else {
    vec2 p = 0.5 - abs(local);
    edge = min(p.x, p.y);
  }
  if (u_cam.z > 6.0 && edge < 1.0 / u_cam.z) col.rgb *= 0.62;
  if (col.a == 0.0) discard;
  outColor = col;
}";

/// One quad per agent, on its cell (none on an empty cell); as a point, `a_corner` is left at 0 and
/// the point covers the cell.
const AGENT_VS: &str = "#version 300 es
precision highp float;
precision highp int;
precision highp usampler2D;
layout(location = 0) in vec2 a_corner;
layout(location = 1) in uvec2 a_agent;
uniform usampler2D u_cells;
uniform vec2 u_viewport;
uniform vec3 u_cam;
uniform ivec2 u_dims;
uniform int u_hex;
out vec2 v_local;
flat out uint v_kind;
const float ROW = 0.8660254;
const float RAD = 0.5773503;
void main() {
  int cell = int(a_agent.x);
  ivec2 c = ivec2(cell % u_dims.x, cell / u_dims.x);
  vec2 centre = u_hex == 1
    ? vec2(float(c.x) + 0.5 + ((c.y & 1) == 1 ? 0.5 : 0.0), float(c.y) * ROW + RAD)
    : vec2(c) + 0.5;
  v_local = a_corner;
  v_kind = a_agent.y;
  gl_PointSize = u_cam.z;
  vec2 s = (centre + a_corner - u_cam.xy) * u_cam.z + 0.5 * u_viewport;
  bool empty = texelFetch(u_cells, c, 0).r == 0u;
  gl_Position = empty ? vec4(2.0, 2.0, 2.0, 1.0) : vec4(2.0 * s.x / u_viewport.x - 1.0, 1.0 - 2.0 * s.y / u_viewport.y, 0.0, 1.0);
}";

/// Below this many pixels a cell, an agent fills its whole cell (a square) instead of a disc.
const DISC_PX: f32 = 5.0;

/// A disc with a dark rim on a quad; a point (below DISC_PX, `v_local` 0) fills its whole cell.
const AGENT_FS: &str = "#version 300 es
precision highp float;
precision highp int;
uniform sampler2D u_agentPalette;
in vec2 v_local;
flat in uint v_kind;
out vec4 outColor;
void main() {
  vec4 a = texelFetch(u_agentPalette, ivec2(int(v_kind), 0), 0);
  float r = length(v_local);
  if (r < 0.3) outColor = a;
  else if (r < 0.37) outColor = vec4(0.0, 0.0, 0.0, 1.0);
  else discard;
  if (outColor.a == 0.0) discard;
}";

/// Sizes an overlay texture: one float a cell.
fn size_field(gl: &Gl, tex: &WebGlTexture, w: i32, h: i32) -> Result<(), JsValue> {
    gl.bind_texture(Gl::TEXTURE_2D, Some(tex));
    gl.tex_image_2d_with_i32_and_i32_and_i32_and_format_and_type_and_opt_u8_array(
        Gl::TEXTURE_2D,
        0,
        Gl::R32F as i32,
        w,
        h,
        0,
        Gl::RED,
        Gl::FLOAT,
        None,
    )
}

/// Two increasing lists of rows merged into one, each row once.
fn merged(a: &[usize], b: &[usize]) -> Vec<usize> {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() || j < b.len() {
        let next = match (a.get(i), b.get(j)) {
            (Some(&x), Some(&y)) => x.min(y),
            (Some(&x), None) => x,
            (None, Some(&y)) => y,
            (None, None) => unreachable!(),
        };
        i += usize::from(a.get(i) == Some(&next));
        j += usize::from(b.get(j) == Some(&next));
        out.push(next);
    }
    out
}

/// Changed rows this close together are uploaded as one band: a call per row would cost more than
/// the few unchanged rows between them.
const ROW_GAP: usize = 16;

/// The bands of rows to upload, first and last row of each, for the rows that changed (in
/// increasing order): rows at most `gap` apart share a band. A model that changes a row at the
/// lattice's top and one at its bottom uploads two rows, not the lattice.
fn row_bands(changed: impl IntoIterator<Item = usize>, gap: usize) -> Vec<(usize, usize)> {
    let mut bands: Vec<(usize, usize)> = Vec::new();
    for y in changed {
        match bands.last_mut() {
            Some((_, last)) if y - *last <= gap => *last = y,
            _ => bands.push((y, y)),
        }
    }
    bands
}

/// One frame's textures: a code per cell, and the overlay's values.
struct Frames {
    cells: WebGlTexture,
    field: WebGlTexture,
    /// `field` is sized to the lattice: only once an overlay is drawn, since it takes 4 bytes a
    /// cell (the GPU process held 128 MB of them for the 4096² AMAS that showed none).
    field_sized: bool,
}

impl Frames {
    fn new(gl: &Gl) -> Result<Frames, JsValue> {
        Ok(Frames {
            cells: texture(gl)?,
            field: texture(gl)?,
            field_sized: false,
        })
    }
}

/// The planar passes and their textures and buffers.
pub struct PlanarGl {
    program: Program,
    quad: WebGlVertexArrayObject,
    agent_program: Program,
    agent_vao: WebGlVertexArrayObject,
    /// The same agents as one point each, for cells smaller than DISC_PX on screen.
    agent_points: WebGlVertexArrayObject,
    agent_buffer: WebGlBuffer,
    /// (cell, kind) per agent, as last uploaded.
    agent_data: Vec<u32>,
    /// Two sets of the per-frame textures, used in turn: a frame uploads into the set the
    /// previous draw is not reading, so the upload need not wait for that draw to finish.
    sets: [Frames; 2],
    /// The set drawn from.
    current: usize,
    /// The codes of the last frame uploaded (into the set drawn from), so an upload sends only
    /// the rows that changed since: one copy of the lattice for both sets.
    shadow: Vec<u8>,
    /// The rows that changed at the last upload: the other set, which did not get them, takes
    /// them with its next upload.
    last_changed: Vec<usize>,
    palette: WebGlTexture,
    agent_palette: WebGlTexture,
    heat: WebGlTexture,
    dims: [i32; 2],
    /// The frame revision last uploaded: redrawing for a camera move uploads nothing.
    uploaded: Option<u64>,
}

impl PlanarGl {
    pub fn new(gl: &Gl) -> Result<PlanarGl, JsValue> {
        let program = Program::link(gl, VS, FS)?;
        let quad = gl.create_vertex_array().ok_or("no vertex array")?;
        gl.bind_vertex_array(Some(&quad));
        static_buffer(gl, &[-1.0, -1.0, 3.0, -1.0, -1.0, 3.0])?;
        attribute(gl, program.attrib(gl, "a_pos"), 2, Gl::FLOAT, false, 0);

        let agent_program = Program::link(gl, AGENT_VS, AGENT_FS)?;
        let agent_buffer = gl.create_buffer().ok_or("no buffer")?;
        // (cell, kind) per agent from `agent_buffer`: per instance for quads, per vertex for points.
        let agents_from = |divisor: u32| {
            gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&agent_buffer));
            gl.enable_vertex_attrib_array(1);
            gl.vertex_attrib_i_pointer_with_i32(1, 2, Gl::UNSIGNED_INT, 0, 0);
            gl.vertex_attrib_divisor(1, divisor);
        };
        let agent_vao = gl.create_vertex_array().ok_or("no vertex array")?;
        gl.bind_vertex_array(Some(&agent_vao));
        static_buffer(
            gl,
            &[
                -0.5, -0.5, 0.5, -0.5, 0.5, 0.5, -0.5, -0.5, 0.5, 0.5, -0.5, 0.5,
            ],
        )?;
        attribute(gl, 0, 2, Gl::FLOAT, false, 0);
        agents_from(1);
        // Points: one vertex per agent, with no corner (attribute 0 keeps its constant 0).
        let agent_points = gl.create_vertex_array().ok_or("no vertex array")?;
        gl.bind_vertex_array(Some(&agent_points));
        agents_from(0);
        gl.bind_vertex_array(None);
        gl.vertex_attrib2f(0, 0.0, 0.0);

        let heat = texture(gl)?;
        upload_table(gl, &heat, &heat_table())?;
        Ok(PlanarGl {
            program,
            quad,
            agent_program,
            agent_vao,
            agent_points,
            agent_buffer,
            agent_data: Vec::new(),
            sets: [Frames::new(gl)?, Frames::new(gl)?],
            current: 0,
            shadow: Vec::new(),
            last_changed: Vec::new(),
            palette: texture(gl)?,
            agent_palette: texture(gl)?,
            heat,
            dims: [0, 0],
            uploaded: None,
        })
    }

    /// Sizes the textures for a lattice and uploads its legends.
    pub fn set_layout(&mut self, gl: &Gl, layout: &Layout) -> Result<(), JsValue> {
        upload_table(gl, &self.palette, &legend_table(&layout.cells))?;
        upload_table(gl, &self.agent_palette, &legend_table(&layout.agents))?;
        let [w, h, _] = layout.dims.map(|d| d as i32);
        self.dims = [w, h];
        gl.pixel_storei(Gl::UNPACK_ALIGNMENT, 1);
        for set in &mut self.sets {
            gl.bind_texture(Gl::TEXTURE_2D, Some(&set.cells));
            gl.tex_image_2d_with_i32_and_i32_and_i32_and_format_and_type_and_opt_u8_array(
                Gl::TEXTURE_2D,
                0,
                Gl::R8UI as i32,
                w,
                h,
                0,
                Gl::RED_INTEGER,
                Gl::UNSIGNED_BYTE,
                None,
            )?;
            // Sized with the first overlay; until then a single value.
            size_field(gl, &set.field, 1, 1)?;
            set.field_sized = false;
        }
        // A fresh texture holds zeros: empty cells.
        self.shadow = vec![0; (w * h) as usize];
        self.last_changed.clear();
        self.uploaded = None;
        Ok(())
    }

    /// Uploads the frame: the rows of codes that changed since this texture set last held a
    /// frame, the overlay, and the agents; nothing when this revision already was.
    pub fn upload(&mut self, gl: &Gl, state: &State, revision: u64) -> Result<(), JsValue> {
        let [w, h] = self.dims;
        if state.cells.len() != (w * h) as usize || self.uploaded == Some(revision) {
            return Ok(());
        }
        self.uploaded = Some(revision);
        self.current ^= 1;
        gl.pixel_storei(Gl::UNPACK_ALIGNMENT, 1);
        let set = &mut self.sets[self.current];
        let row = w as usize;
        let shadow = &mut self.shadow;
        let changed: Vec<usize> = (0..h as usize)
            .filter(|y| state.cells[y * row..(y + 1) * row] != shadow[y * row..(y + 1) * row])
            .collect();
        // This set missed what the other one took at the last upload.
        let missed = std::mem::take(&mut self.last_changed);
        gl.bind_texture(Gl::TEXTURE_2D, Some(&set.cells));
        for (first, last) in row_bands(merged(&changed, &missed), ROW_GAP) {
            let band = first * row..(last + 1) * row;
            gl.tex_sub_image_2d_with_i32_and_i32_and_u32_and_type_and_opt_u8_array(
                Gl::TEXTURE_2D,
                0,
                0,
                first as i32,
                w,
                (last + 1 - first) as i32,
                Gl::RED_INTEGER,
                Gl::UNSIGNED_BYTE,
                Some(&state.cells[band]),
            )?;
        }
        for &y in &changed {
            let band = y * row..(y + 1) * row;
            shadow[band.clone()].copy_from_slice(&state.cells[band]);
        }
        self.last_changed = changed;
        if let Some(o) = state.overlay.filter(|o| o.data.len() == state.cells.len()) {
            if !set.field_sized {
                size_field(gl, &set.field, w, h)?;
                set.field_sized = true;
            }
            gl.bind_texture(Gl::TEXTURE_2D, Some(&set.field));
            // A view of wasm memory, handed straight to WebGL: nothing allocates meanwhile.
            let view = unsafe { js_sys::Float32Array::view(o.data) };
            gl.tex_sub_image_2d_with_i32_and_i32_and_u32_and_type_and_opt_array_buffer_view(
                Gl::TEXTURE_2D,
                0,
                0,
                0,
                w,
                h,
                Gl::RED,
                Gl::FLOAT,
                Some(&view),
            )?;
        }
        self.agent_data.clear();
        let cells = state.cells.len() as u32;
        for a in state.agents.iter().filter(|a| a.cell < cells) {
            self.agent_data.extend([a.cell, u32::from(a.kind)]);
        }
        gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&self.agent_buffer));
        // A view of wasm memory, copied by WebGL at once.
        let view = unsafe { js_sys::Uint32Array::view(&self.agent_data) };
        gl.buffer_data_with_array_buffer_view(Gl::ARRAY_BUFFER, &view, Gl::STREAM_DRAW);
        Ok(())
    }

    /// Draws the lattice and its agents from what was last uploaded.
    pub fn draw(&self, gl: &Gl, scene: &SceneRef, cam: &Camera2D, dpr: f64, viewport: [i32; 2]) {
        let [w, h] = self.dims;
        let state = &scene.state;
        if state.cells.len() != (w * h) as usize {
            return;
        }
        gl.disable(Gl::DEPTH_TEST);
        gl.disable(Gl::CULL_FACE);
        gl.disable(Gl::BLEND);
        let set = &self.sets[self.current];
        let hex = i32::from(scene.layout.lattice == LatticeKind::Hex);
        let camera = [cam.cx as f32, cam.cy as f32, (cam.scale * dpr) as f32];
        for (unit, tex) in [
            (0, &set.cells),
            (1, &self.palette),
            (2, &set.field),
            (3, &self.heat),
            (5, &self.agent_palette),
        ] {
            gl.active_texture(Gl::TEXTURE0 + unit);
            gl.bind_texture(Gl::TEXTURE_2D, Some(tex));
        }
        gl.active_texture(Gl::TEXTURE0);
        let p = &self.program;
        gl.use_program(Some(&p.program));
        for (name, unit) in [
            ("u_cells", 0),
            ("u_palette", 1),
            ("u_field", 2),
            ("u_heat", 3),
        ] {
            gl.uniform1i(p.uniform(gl, name).as_ref(), unit);
        }
        let view = Shared {
            viewport,
            camera,
            dims: [w, h],
            hex,
        };
        view.set(gl, p);
        let overlay = state.overlay.filter(|o| o.data.len() == state.cells.len());
        gl.uniform1i(
            p.uniform(gl, "u_overlay").as_ref(),
            i32::from(overlay.is_some()),
        );
        let (lo, hi) = overlay.map_or((0.0, 1.0), |o| (o.min, o.max));
        gl.uniform2f(p.uniform(gl, "u_range").as_ref(), lo, hi);
        gl.bind_vertex_array(Some(&self.quad));
        gl.draw_arrays(Gl::TRIANGLES, 0, 3);

        let agents = (self.agent_data.len() / 2) as i32;
        if agents > 0 {
            let a = &self.agent_program;
            gl.use_program(Some(&a.program));
            gl.uniform1i(a.uniform(gl, "u_cells").as_ref(), 0);
            gl.uniform1i(a.uniform(gl, "u_agentPalette").as_ref(), 5);
            view.set(gl, a);
            if camera[2] < DISC_PX {
                gl.bind_vertex_array(Some(&self.agent_points));
                gl.draw_arrays(Gl::POINTS, 0, agents);
            } else {
                gl.bind_vertex_array(Some(&self.agent_vao));
                gl.draw_arrays_instanced(Gl::TRIANGLES, 0, 6, agents);
            }
        }
        gl.bind_vertex_array(None);
    }
}

/// The uniforms both planar passes read: the drawing buffer's size, the camera (centre and
/// pixels per cell), the lattice's size and whether it is hex.
struct Shared {
    viewport: [i32; 2],
    camera: [f32; 3],
    dims: [i32; 2],
    hex: i32,
}

impl Shared {
    fn set(&self, gl: &Gl, p: &Program) {
        let [x, y, z] = self.camera;
        gl.uniform2f(
            p.uniform(gl, "u_viewport").as_ref(),
            self.viewport[0] as f32,
            self.viewport[1] as f32,
        );
        gl.uniform3f(p.uniform(gl, "u_cam").as_ref(), x, y, z);
        gl.uniform2i(p.uniform(gl, "u_dims").as_ref(), self.dims[0], self.dims[1]);
        gl.uniform1i(p.uniform(gl, "u_hex").as_ref(), self.hex);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_changed_now_and_at_the_last_upload_are_merged_once_each() {
        assert_eq!(merged(&[], &[]), Vec::<usize>::new());
        assert_eq!(merged(&[1, 5, 9], &[]), vec![1, 5, 9]);
        assert_eq!(merged(&[1, 5, 9], &[0, 5, 10]), vec![0, 1, 5, 9, 10]);
    }

    #[test]
    fn changed_rows_close_together_share_a_band_and_far_ones_do_not() {
        assert_eq!(row_bands([], 16), vec![]);
        assert_eq!(row_bands([3], 16), vec![(3, 3)]);
        assert_eq!(
            row_bands([0, 1, 17, 40, 1023], 16),
            vec![(0, 17), (40, 40), (1023, 1023)]
        );
    }
}
