//! WebGL2 helpers shared by the renderers: shader programs, textures, attributes, and the
//! multisampled target the 3-D view draws into.

use wasm_bindgen::JsValue;
use web_sys::{
    WebGl2RenderingContext as Gl, WebGlBuffer, WebGlFramebuffer, WebGlProgram, WebGlRenderbuffer,
    WebGlShader, WebGlTexture, WebGlUniformLocation,
};

/// A linked program and its uniform locations, looked up once each.
pub struct Program {
    pub program: WebGlProgram,
    uniforms: std::cell::RefCell<Vec<(&'static str, Option<WebGlUniformLocation>)>>,
}

impl Program {
    pub fn link(gl: &Gl, vs: &str, fs: &str) -> Result<Program, JsValue> {
        let program = gl.create_program().ok_or("no program")?;
        gl.attach_shader(&program, &compile(gl, Gl::VERTEX_SHADER, vs)?);
        gl.attach_shader(&program, &compile(gl, Gl::FRAGMENT_SHADER, fs)?);
        gl.link_program(&program);
        if !gl
            .get_program_parameter(&program, Gl::LINK_STATUS)
            .as_bool()
            .unwrap_or(false)
        {
            return Err(format!(
                "program: {}",
                gl.get_program_info_log(&program).unwrap_or_default()
            )
            .into());
        }
        Ok(Program {
            program,
            uniforms: Default::default(),
        })
    }

    /// A uniform's location (cached).
    pub fn uniform(&self, gl: &Gl, name: &'static str) -> Option<WebGlUniformLocation> {
        let mut cache = self.uniforms.borrow_mut();
        if let Some((_, loc)) = cache.iter().find(|(n, _)| *n == name) {
            return loc.clone();
        }
        let loc = gl.get_uniform_location(&self.program, name);
        cache.push((name, loc.clone()));
        loc
    }

    pub fn attrib(&self, gl: &Gl, name: &str) -> i32 {
        gl.get_attrib_location(&self.program, name)
    }
}

fn compile(gl: &Gl, kind: u32, source: &str) -> Result<WebGlShader, JsValue> {
    let shader = gl.create_shader(kind).ok_or("no shader")?;
    gl.shader_source(&shader, source);
    gl.compile_shader(&shader);
    if !gl
        .get_shader_parameter(&shader, Gl::COMPILE_STATUS)
        .as_bool()
        .unwrap_or(false)
    {
        return Err(format!(
            "shader: {}",
            gl.get_shader_info_log(&shader).unwrap_or_default()
        )
        .into());
    }
    Ok(shader)
}

/// A texture sampled exactly (nearest, clamped).
pub fn texture(gl: &Gl) -> Result<WebGlTexture, JsValue> {
    let tex = gl.create_texture().ok_or("no texture")?;
    gl.bind_texture(Gl::TEXTURE_2D, Some(&tex));
    for (p, v) in [
        (Gl::TEXTURE_MIN_FILTER, Gl::NEAREST),
        (Gl::TEXTURE_MAG_FILTER, Gl::NEAREST),
        (Gl::TEXTURE_WRAP_S, Gl::CLAMP_TO_EDGE),
        (Gl::TEXTURE_WRAP_T, Gl::CLAMP_TO_EDGE),
    ] {
        gl.tex_parameteri(Gl::TEXTURE_2D, p, v as i32);
    }
    Ok(tex)
}

/// Points attribute `loc` at the bound array buffer, advancing per instance when `divisor` is 1.
pub fn attribute(gl: &Gl, loc: i32, size: i32, kind: u32, normalized: bool, divisor: u32) {
    if loc < 0 {
        return;
    }
    gl.enable_vertex_attrib_array(loc as u32);
    gl.vertex_attrib_pointer_with_i32(loc as u32, size, kind, normalized, 0, 0);
    gl.vertex_attrib_divisor(loc as u32, divisor);
}

/// Appends `values` as little-endian f32, the layout WebGL reads from a buffer.
pub fn push_f32s(out: &mut Vec<u8>, values: impl IntoIterator<Item = f32>) {
    for v in values {
        out.extend_from_slice(&v.to_le_bytes());
    }
}

/// A new array buffer holding `data`, left bound to ARRAY_BUFFER.
pub fn static_buffer(gl: &Gl, data: &[f32]) -> Result<WebGlBuffer, JsValue> {
    let buffer = gl.create_buffer().ok_or("no buffer")?;
    gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&buffer));
    let mut bytes = Vec::with_capacity(data.len() * 4);
    push_f32s(&mut bytes, data.iter().copied());
    gl.buffer_data_with_u8_array(Gl::ARRAY_BUFFER, &bytes, Gl::STATIC_DRAW);
    Ok(buffer)
}

/// Uploads a 256×1 RGBA lookup table into `tex`.
pub fn upload_table(gl: &Gl, tex: &WebGlTexture, table: &[u8]) -> Result<(), JsValue> {
    gl.bind_texture(Gl::TEXTURE_2D, Some(tex));
    gl.tex_image_2d_with_i32_and_i32_and_i32_and_format_and_type_and_opt_u8_array(
        Gl::TEXTURE_2D,
        0,
        Gl::RGBA8 as i32,
        256,
        1,
        0,
        Gl::RGBA,
        Gl::UNSIGNED_BYTE,
        Some(table),
    )
}

/// Samples per pixel of the 3-D view's target (fewer where the context allows fewer).
const SAMPLES: i32 = 4;

/// A multisampled colour and depth target, resolved into the canvas after drawing. The context
/// itself is made without antialiasing: the flat lattices gain nothing from it (their cells are
/// found per pixel in one full-screen pass) and a software rasteriser pays for every sample, so
/// only the 3-D view, whose cube edges need it, draws multisampled.
pub struct Multisample {
    framebuffer: WebGlFramebuffer,
    colour: WebGlRenderbuffer,
    depth: WebGlRenderbuffer,
    size: [i32; 2],
    /// The framebuffer was complete at this size.
    complete: bool,
}

impl Multisample {
    pub fn new(gl: &Gl) -> Result<Multisample, JsValue> {
        Ok(Multisample {
            framebuffer: gl.create_framebuffer().ok_or("no framebuffer")?,
            colour: gl.create_renderbuffer().ok_or("no renderbuffer")?,
            depth: gl.create_renderbuffer().ok_or("no renderbuffer")?,
            size: [0, 0],
            complete: false,
        })
    }

    /// Binds the target at `w`×`h` (sized again when that changed) for drawing. False when the
    /// context cannot make it: the caller then draws into the canvas directly.
    pub fn begin(&mut self, gl: &Gl, w: i32, h: i32) -> bool {
        gl.bind_framebuffer(Gl::FRAMEBUFFER, Some(&self.framebuffer));
        if self.size != [w, h] {
            let max = gl
                .get_parameter(Gl::MAX_SAMPLES)
                .ok()
                .and_then(|v| v.as_f64())
                .map_or(0, |v| v as i32);
            let samples = SAMPLES.min(max);
            // RGB8, the canvas's own format (it has no alpha): a multisampled blit must keep it.
            for (buffer, format, attachment) in [
                (&self.colour, Gl::RGB8, Gl::COLOR_ATTACHMENT0),
                (&self.depth, Gl::DEPTH_COMPONENT24, Gl::DEPTH_ATTACHMENT),
            ] {
                gl.bind_renderbuffer(Gl::RENDERBUFFER, Some(buffer));
                gl.renderbuffer_storage_multisample(Gl::RENDERBUFFER, samples, format, w, h);
                gl.framebuffer_renderbuffer(
                    Gl::FRAMEBUFFER,
                    attachment,
                    Gl::RENDERBUFFER,
                    Some(buffer),
                );
            }
            gl.bind_renderbuffer(Gl::RENDERBUFFER, None);
            self.size = [w, h];
            self.complete =
                gl.check_framebuffer_status(Gl::FRAMEBUFFER) == Gl::FRAMEBUFFER_COMPLETE;
        }
        if !self.complete {
            gl.bind_framebuffer(Gl::FRAMEBUFFER, None);
        }
        self.complete
    }

    /// Resolves what was drawn into the canvas, and leaves the canvas bound.
    pub fn resolve(&self, gl: &Gl) {
        let [w, h] = self.size;
        gl.bind_framebuffer(Gl::READ_FRAMEBUFFER, Some(&self.framebuffer));
        gl.bind_framebuffer(Gl::DRAW_FRAMEBUFFER, None);
        gl.blit_framebuffer(0, 0, w, h, 0, 0, w, h, Gl::COLOR_BUFFER_BIT, Gl::NEAREST);
        gl.bind_framebuffer(Gl::FRAMEBUFFER, None);
    }
}
