//! Square and hex lattices in WebGL2: one full-screen pass that finds each pixel's cell and looks
//! its code and its agent up in two integer textures, so a 1024×1024 lattice with thousands of
//! robots costs two texture uploads and no geometry per frame.

use crate::camera::Camera2D;
use crate::gl::{attribute, texture, upload_table, Program};
use crate::palette::{heat_table, legend_table};
use crate::scene::{Frame, SceneRef};
use kumiki_core::lattice::LatticeKind;
use kumiki_core::models::Layout;
use wasm_bindgen::JsValue;
use web_sys::{WebGl2RenderingContext as Gl, WebGlTexture, WebGlVertexArrayObject};

const VS: &str = "#version 300 es
in vec2 a_pos;
void main() { gl_Position = vec4(a_pos, 0.0, 1.0); }";

const FS: &str = "#version 300 es
precision highp float;
precision highp int;
precision highp usampler2D;
uniform usampler2D u_cells;
uniform usampler2D u_agents;
uniform sampler2D u_palette;
uniform sampler2D u_agentPalette;
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
  // An agent on this cell: a disc with a dark rim, or the whole cell when cells are too small
  // on screen for a disc to show.
  uint agent = texelFetch(u_agents, c, 0).r;
  if (agent > 0u) {
    vec4 a = texelFetch(u_agentPalette, ivec2(int(agent - 1u), 0), 0);
    float r = length(local);
    if (u_cam.z < 5.0) col = a;
    else if (r < 0.3) col = a;
    else if (r < 0.37) col = vec4(0.0, 0.0, 0.0, 1.0);
  }
  if (col.a == 0.0) discard;
  outColor = col;
}";

/// The planar pass and its textures.
pub struct PlanarGl {
    program: Program,
    quad: WebGlVertexArrayObject,
    cells: WebGlTexture,
    agents: WebGlTexture,
    field: WebGlTexture,
    palette: WebGlTexture,
    agent_palette: WebGlTexture,
    heat: WebGlTexture,
    /// Agent kind + 1 per cell, kept in step with the agent list.
    agent_cells: Vec<u8>,
    /// The cells `agent_cells` marks, to clear before the next frame's agents.
    agent_at: Vec<u32>,
    dims: [i32; 2],
    /// The frame revision last uploaded: redrawing for a camera move uploads nothing.
    uploaded: Option<u64>,
}

impl PlanarGl {
    pub fn new(gl: &Gl) -> Result<PlanarGl, JsValue> {
        let program = Program::link(gl, VS, FS)?;
        let quad = gl.create_vertex_array().ok_or("no vertex array")?;
        gl.bind_vertex_array(Some(&quad));
        let buf = gl.create_buffer().ok_or("no buffer")?;
        gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&buf));
        let corners: [f32; 6] = [-1.0, -1.0, 3.0, -1.0, -1.0, 3.0];
        let bytes: Vec<u8> = corners.iter().flat_map(|v| v.to_le_bytes()).collect();
        gl.buffer_data_with_u8_array(Gl::ARRAY_BUFFER, &bytes, Gl::STATIC_DRAW);
        attribute(gl, program.attrib(gl, "a_pos"), 2, Gl::FLOAT, false, 0);
        gl.bind_vertex_array(None);
        let heat = texture(gl)?;
        upload_table(gl, &heat, &heat_table())?;
        Ok(PlanarGl {
            program,
            quad,
            cells: texture(gl)?,
            agents: texture(gl)?,
            field: texture(gl)?,
            palette: texture(gl)?,
            agent_palette: texture(gl)?,
            heat,
            agent_cells: Vec::new(),
            agent_at: Vec::new(),
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
        for (tex, internal, format, kind) in [
            (&self.cells, Gl::R8UI, Gl::RED_INTEGER, Gl::UNSIGNED_BYTE),
            (&self.agents, Gl::R8UI, Gl::RED_INTEGER, Gl::UNSIGNED_BYTE),
            (&self.field, Gl::R32F, Gl::RED, Gl::FLOAT),
        ] {
            gl.bind_texture(Gl::TEXTURE_2D, Some(tex));
            gl.tex_image_2d_with_i32_and_i32_and_i32_and_format_and_type_and_opt_u8_array(
                Gl::TEXTURE_2D,
                0,
                internal as i32,
                w,
                h,
                0,
                format,
                kind,
                None,
            )?;
        }
        self.agent_cells = vec![0; (w * h) as usize];
        self.agent_at.clear();
        self.uploaded = None;
        Ok(())
    }

    /// Uploads the frame's cells, field and agents, unless this revision already was.
    pub fn upload(&mut self, gl: &Gl, frame: &Frame, revision: u64) -> Result<(), JsValue> {
        let [w, h] = self.dims;
        if frame.cells.len() != (w * h) as usize || self.uploaded == Some(revision) {
            return Ok(());
        }
        gl.pixel_storei(Gl::UNPACK_ALIGNMENT, 1);
        {
            self.uploaded = Some(revision);
            gl.bind_texture(Gl::TEXTURE_2D, Some(&self.cells));
            gl.tex_sub_image_2d_with_i32_and_i32_and_u32_and_type_and_opt_u8_array(
                Gl::TEXTURE_2D,
                0,
                0,
                0,
                w,
                h,
                Gl::RED_INTEGER,
                Gl::UNSIGNED_BYTE,
                Some(frame.cells),
            )?;
            if let Some(o) = frame.overlay.filter(|o| o.data.len() == frame.cells.len()) {
                gl.bind_texture(Gl::TEXTURE_2D, Some(&self.field));
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
            for &i in &self.agent_at {
                self.agent_cells[i as usize] = 0;
            }
            self.agent_at.clear();
            for a in frame.agents {
                if let Some(slot) = self.agent_cells.get_mut(a.cell as usize) {
                    *slot = a.kind.saturating_add(1);
                    self.agent_at.push(a.cell);
                }
            }
            gl.bind_texture(Gl::TEXTURE_2D, Some(&self.agents));
            gl.tex_sub_image_2d_with_i32_and_i32_and_u32_and_type_and_opt_u8_array(
                Gl::TEXTURE_2D,
                0,
                0,
                0,
                w,
                h,
                Gl::RED_INTEGER,
                Gl::UNSIGNED_BYTE,
                Some(&self.agent_cells),
            )?;
        }
        Ok(())
    }

    /// Draws the lattice from the textures last uploaded.
    pub fn draw(&self, gl: &Gl, scene: &SceneRef, cam: &Camera2D, dpr: f64, viewport: [i32; 2]) {
        let [w, h] = self.dims;
        let frame = &scene.frame;
        if frame.cells.len() != (w * h) as usize {
            return;
        }
        gl.disable(Gl::DEPTH_TEST);
        let p = &self.program;
        gl.use_program(Some(&p.program));
        for (unit, tex, name) in [
            (0, &self.cells, "u_cells"),
            (1, &self.palette, "u_palette"),
            (2, &self.field, "u_field"),
            (3, &self.heat, "u_heat"),
            (4, &self.agents, "u_agents"),
            (5, &self.agent_palette, "u_agentPalette"),
        ] {
            gl.active_texture(Gl::TEXTURE0 + unit);
            gl.bind_texture(Gl::TEXTURE_2D, Some(tex));
            gl.uniform1i(p.uniform(gl, name).as_ref(), unit as i32);
        }
        gl.active_texture(Gl::TEXTURE0);
        gl.uniform2f(
            p.uniform(gl, "u_viewport").as_ref(),
            viewport[0] as f32,
            viewport[1] as f32,
        );
        gl.uniform3f(
            p.uniform(gl, "u_cam").as_ref(),
            cam.cx as f32,
            cam.cy as f32,
            (cam.scale * dpr) as f32,
        );
        gl.uniform2i(p.uniform(gl, "u_dims").as_ref(), w, h);
        gl.uniform1i(
            p.uniform(gl, "u_hex").as_ref(),
            i32::from(scene.layout.lattice == LatticeKind::Hex),
        );
        let overlay = frame.overlay.filter(|o| o.data.len() == frame.cells.len());
        gl.uniform1i(
            p.uniform(gl, "u_overlay").as_ref(),
            i32::from(overlay.is_some()),
        );
        let (lo, hi) = overlay.map_or((0.0, 1.0), |o| (o.min, o.max));
        gl.uniform2f(p.uniform(gl, "u_range").as_ref(), lo, hi);
        gl.bind_vertex_array(Some(&self.quad));
        gl.draw_arrays(Gl::TRIANGLES, 0, 3);
        gl.bind_vertex_array(None);
    }
}
