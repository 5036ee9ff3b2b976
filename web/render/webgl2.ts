// WebGL2 renderer. Planar lattices: one full-screen pass that finds each pixel's cell (square or
// hex) and looks its code and its agent up in two integer textures, so a 1024×1024 lattice with
// thousands of robots costs two texture uploads and no geometry per frame. Cubic lattice: see
// cubic-gl.ts.
import type { Layout } from '../types';
import type { Camera2D, Camera3D } from './camera';
import { CubicGL } from './cubic-gl';
import { heatTable, legendTable } from './palette';
import { type Program, link } from './gl';
import type { Renderer, Scene } from './renderer';

const PLANAR_VS = `#version 300 es
in vec2 a_pos;
void main() { gl_Position = vec4(a_pos, 0.0, 1.0); }`;

const PLANAR_FS = `#version 300 es
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
}`;

export class WebGL2Renderer implements Renderer {
  readonly kind = 'webgl2' as const;
  private planar: Program;
  private quad: WebGLVertexArrayObject;
  private cubic: CubicGL | null = null;
  private cellTex: WebGLTexture;
  private agentTex: WebGLTexture;
  private agentPaletteTex: WebGLTexture;
  /** Agent kind + 1 per cell, rebuilt each frame from the agent list. */
  private agentCells = new Uint8Array(0);
  private fieldTex: WebGLTexture;
  private paletteTex: WebGLTexture;
  private heatTex: WebGLTexture;
  private layout: Layout | null = null;
  private palette = new Uint8Array(256 * 4);
  private agentPalette = new Uint8Array(256 * 4);
  private dpr = 1;

  private constructor(private readonly canvas: HTMLCanvasElement, private readonly gl: WebGL2RenderingContext) {
    this.planar = link(gl, PLANAR_VS, PLANAR_FS);

    this.quad = gl.createVertexArray()!;
    gl.bindVertexArray(this.quad);
    const quadBuf = gl.createBuffer()!;
    gl.bindBuffer(gl.ARRAY_BUFFER, quadBuf);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 3, -1, -1, 3]), gl.STATIC_DRAW);
    attribute(gl, this.planar.attrib('a_pos'), 2, gl.FLOAT, false, 0);

    gl.bindVertexArray(null);

    this.cellTex = texture(gl);
    this.agentTex = texture(gl);
    this.agentPaletteTex = texture(gl);
    this.fieldTex = texture(gl);
    this.paletteTex = texture(gl);
    this.heatTex = texture(gl);
    gl.bindTexture(gl.TEXTURE_2D, this.heatTex);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 256, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, heatTable());
  }

  static create(canvas: HTMLCanvasElement): WebGL2Renderer | null {
    const gl = canvas.getContext('webgl2', { antialias: true, alpha: false, preserveDrawingBuffer: true });
    if (!gl) return null;
    try {
      return new WebGL2Renderer(canvas, gl);
    } catch (e) {
      console.warn('WebGL2 renderer unavailable:', e);
      return null;
    }
  }

  setLayout(layout: Layout) {
    const { gl } = this;
    this.layout = layout;
    this.palette = legendTable(layout.cells);
    this.agentPalette = legendTable(layout.agents);
    gl.bindTexture(gl.TEXTURE_2D, this.paletteTex);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 256, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, this.palette);
    gl.bindTexture(gl.TEXTURE_2D, this.agentPaletteTex);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 256, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, this.agentPalette);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    const [w, h] = layout.dims;
    if (layout.lattice !== 'cubic') {
      gl.bindTexture(gl.TEXTURE_2D, this.cellTex);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.R8UI, w, h, 0, gl.RED_INTEGER, gl.UNSIGNED_BYTE, null);
      gl.bindTexture(gl.TEXTURE_2D, this.agentTex);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.R8UI, w, h, 0, gl.RED_INTEGER, gl.UNSIGNED_BYTE, null);
      this.agentCells = new Uint8Array(w * h);
      gl.bindTexture(gl.TEXTURE_2D, this.fieldTex);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.R32F, w, h, 0, gl.RED, gl.FLOAT, null);
    } else {
      this.cubic ??= new CubicGL(gl);
    }
  }

  resize(cssWidth: number, cssHeight: number, dpr: number) {
    this.dpr = dpr;
    this.canvas.width = Math.max(1, Math.round(cssWidth * dpr));
    this.canvas.height = Math.max(1, Math.round(cssHeight * dpr));
  }

  draw(scene: Scene) {
    const { gl, canvas } = this;
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(0.106, 0.137, 0.173, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    if (!this.layout) return;
    if (scene.camera.kind === '3d') this.drawCubic(scene, scene.camera);
    else this.drawPlanar(scene, scene.camera);
  }

  private drawPlanar(scene: Scene, cam: Camera2D) {
    const { gl, canvas, dpr } = this;
    const [w, h] = scene.layout.dims;
    gl.disable(gl.DEPTH_TEST);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.cellTex);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, w, h, gl.RED_INTEGER, gl.UNSIGNED_BYTE, scene.frame.cells);
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, this.paletteTex);
    gl.activeTexture(gl.TEXTURE2);
    gl.bindTexture(gl.TEXTURE_2D, this.fieldTex);
    if (scene.overlay) gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, w, h, gl.RED, gl.FLOAT, scene.overlay.data);
    gl.activeTexture(gl.TEXTURE3);
    gl.bindTexture(gl.TEXTURE_2D, this.heatTex);
    const list = scene.frame.agents;
    const agentCells = this.agentCells;
    agentCells.fill(0);
    for (let k = 0; k + 1 < list.length; k += 2) agentCells[list[k]] = list[k + 1] + 1;
    gl.activeTexture(gl.TEXTURE4);
    gl.bindTexture(gl.TEXTURE_2D, this.agentTex);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, w, h, gl.RED_INTEGER, gl.UNSIGNED_BYTE, agentCells);
    gl.activeTexture(gl.TEXTURE5);
    gl.bindTexture(gl.TEXTURE_2D, this.agentPaletteTex);

    const p = this.planar;
    gl.useProgram(p.program);
    gl.uniform1i(p.uniform('u_cells'), 0);
    gl.uniform1i(p.uniform('u_palette'), 1);
    gl.uniform1i(p.uniform('u_field'), 2);
    gl.uniform1i(p.uniform('u_heat'), 3);
    gl.uniform1i(p.uniform('u_agents'), 4);
    gl.uniform1i(p.uniform('u_agentPalette'), 5);
    gl.uniform2f(p.uniform('u_viewport'), canvas.width, canvas.height);
    gl.uniform3f(p.uniform('u_cam'), cam.cx, cam.cy, cam.scale * dpr);
    gl.uniform2i(p.uniform('u_dims'), w, h);
    gl.uniform1i(p.uniform('u_hex'), scene.layout.lattice === 'hex' ? 1 : 0);
    gl.uniform1i(p.uniform('u_overlay'), scene.overlay ? 1 : 0);
    gl.uniform2f(p.uniform('u_range'), scene.overlay?.min ?? 0, scene.overlay?.max ?? 1);
    gl.bindVertexArray(this.quad);
    gl.drawArrays(gl.TRIANGLES, 0, 3);

    gl.bindVertexArray(null);
  }

  private drawCubic(scene: Scene, cam: Camera3D) {
    this.cubic ??= new CubicGL(this.gl);
    const stats = this.cubic.draw(scene, cam);
    this.canvas.dataset.scene = JSON.stringify(stats);
  }

  destroy() {
    this.gl.getExtension('WEBGL_lose_context')?.loseContext();
  }
}

function attribute(gl: WebGL2RenderingContext, loc: number, size: number, type: number, normalized: boolean, divisor: number) {
  if (loc < 0) return;
  gl.enableVertexAttribArray(loc);
  gl.vertexAttribPointer(loc, size, type, normalized, 0, 0);
  gl.vertexAttribDivisor(loc, divisor);
}

function texture(gl: WebGL2RenderingContext): WebGLTexture {
  const tex = gl.createTexture()!;
  gl.bindTexture(gl.TEXTURE_2D, tex);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
  return tex;
}
