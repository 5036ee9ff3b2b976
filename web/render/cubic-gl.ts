// The cubic lattice in WebGL2: instanced, lit cubes with darkened edges; bonds as short arms
// between adjacent units; the target as a translucent ghost; the ground (or a reference grid)
// with the units' shadows; the light as a lamp with an arrow; reachable cells, hover, selection
// and an editing cursor in depth. Instance buffers are rebuilt only when the frame or the marks
// change, so orbiting a large structure costs one draw call per kind of thing.
import { multiply, type Camera3D } from './camera';
import { CubicBuilder, type CubicModel, type RenderStats, type V3, statsOf } from './cubic-scene';
import { coordOf } from './geometry';
import { type Program, link } from './gl';
import { parseColor } from './palette';
import type { Scene } from './renderer';

const MESH_VS = `#version 300 es
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_offset;
layout(location = 3) in vec3 a_scale;
layout(location = 4) in vec4 a_color;
uniform mat4 u_vp;
uniform mat3 u_rot;
out vec3 v_normal;
out vec3 v_local;
out vec4 v_color;
void main() {
  vec3 world = a_offset + u_rot * (a_pos * a_scale);
  gl_Position = u_vp * vec4(world, 1.0);
  v_normal = u_rot * a_normal;
  v_local = a_pos;
  v_color = a_color;
}`;

// Modes: 0 lit solid with dark edges, 1 translucent ghost with bright edges, 2 soft shadow,
// 3 emissive (the lamp).
const MESH_FS = `#version 300 es
precision highp float;
in vec3 v_normal;
in vec3 v_local;
in vec4 v_color;
uniform int u_mode;
uniform vec3 u_key;
uniform vec3 u_eye_dir;
uniform vec3 u_lamp;
uniform float u_lamp_on;
uniform float u_alpha;
uniform float u_fill;
uniform float u_edge;
out vec4 outColor;
void main() {
  vec3 n = normalize(v_normal);
  vec3 base = v_color.rgb;
  // Distance to the face's border, 0 at its centre and 1 on its edges.
  vec3 a = abs(v_local) * 2.0;
  vec3 inPlane = step(abs(n), vec3(0.5));
  float e = max(max(a.x * inPlane.x, a.y * inPlane.y), a.z * inPlane.z);
  float aa = max(fwidth(e), 1e-4);
  float edge = smoothstep(1.0 - u_edge - aa, 1.0 - u_edge + aa, e);
  if (u_mode == 2) {
    float r = max(a.x, a.y);
    outColor = vec4(0.0, 0.0, 0.0, u_alpha * v_color.a * (1.0 - smoothstep(0.45, 1.05, r)));
    return;
  }
  if (u_mode == 3) {
    outColor = vec4(base, v_color.a * u_alpha);
    return;
  }
  float hemi = 0.5 + 0.5 * n.z;
  float key = max(dot(n, u_key), 0.0);
  float head = max(dot(n, u_eye_dir), 0.0);
  float lamp = u_lamp_on * max(dot(n, u_lamp), 0.0);
  vec3 lit = base * (0.26 + 0.20 * hemi + 0.48 * key + 0.16 * head) + base * vec3(1.0, 0.86, 0.55) * 0.30 * lamp;
  if (u_mode == 1) {
    vec3 col = mix(base * (0.75 + 0.35 * key), vec3(1.0), 0.25 * edge);
    outColor = vec4(col, u_alpha * mix(u_fill, 0.85, edge));
    return;
  }
  lit = mix(lit, lit * 0.52, edge);
  outColor = vec4(lit, v_color.a * u_alpha);
}`;

const PLANE_VS = `#version 300 es
layout(location = 0) in vec2 a_uv;
uniform mat4 u_vp;
uniform vec2 u_min;
uniform vec2 u_max;
uniform float u_z;
out vec2 v_xy;
void main() {
  v_xy = mix(u_min, u_max, a_uv);
  gl_Position = u_vp * vec4(v_xy, u_z, 1.0);
}`;

const PLANE_FS = `#version 300 es
precision highp float;
in vec2 v_xy;
uniform vec4 u_fill;
uniform vec4 u_line;
uniform vec2 u_centre;
uniform float u_fade;
out vec4 outColor;
void main() {
  vec2 g = abs(fract(v_xy) - 0.5);
  vec2 w = fwidth(v_xy);
  vec2 l = 1.0 - smoothstep(vec2(0.0), w * 1.2, 0.5 - g);
  float line = max(l.x, l.y);
  float fade = u_fade > 0.0 ? 1.0 - smoothstep(u_fade * 0.45, u_fade, length(v_xy - u_centre)) : 1.0;
  vec3 col = mix(u_fill.rgb, u_line.rgb, line * u_line.a);
  float alpha = max(u_fill.a, line * u_line.a) * fade;
  if (alpha <= 0.003) discard;
  outColor = vec4(col, alpha);
}`;

const LINE_VS = `#version 300 es
layout(location = 0) in vec3 a_pos;
uniform mat4 u_vp;
void main() { gl_Position = u_vp * vec4(a_pos, 1.0); }`;

const LINE_FS = `#version 300 es
precision mediump float;
uniform vec4 u_color;
out vec4 outColor;
void main() { outColor = u_color; }`;


/** Bytes per instance: offset and scale (6 floats) and an RGBA colour. */
const STRIDE = 28;

interface Mesh {
  buffer: WebGLBuffer;
  count: number;
}

/** A mesh drawn many times, with its own instance buffer. */
class Batch {
  readonly vao: WebGLVertexArrayObject;
  private readonly instances: WebGLBuffer;
  private data = new ArrayBuffer(0);
  count = 0;

  constructor(private readonly gl: WebGL2RenderingContext, readonly mesh: Mesh) {
    this.vao = gl.createVertexArray()!;
    gl.bindVertexArray(this.vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, mesh.buffer);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 24, 0);
    gl.enableVertexAttribArray(1);
    gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 24, 12);
    this.instances = gl.createBuffer()!;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.instances);
    gl.enableVertexAttribArray(2);
    gl.vertexAttribPointer(2, 3, gl.FLOAT, false, STRIDE, 0);
    gl.vertexAttribDivisor(2, 1);
    gl.enableVertexAttribArray(3);
    gl.vertexAttribPointer(3, 3, gl.FLOAT, false, STRIDE, 12);
    gl.vertexAttribDivisor(3, 1);
    gl.enableVertexAttribArray(4);
    gl.vertexAttribPointer(4, 4, gl.UNSIGNED_BYTE, true, STRIDE, 24);
    gl.vertexAttribDivisor(4, 1);
    gl.bindVertexArray(null);
  }

  /** Fills the instance buffer: `fill(k, put)` is called for k = 0..count-1. */
  set(count: number, fill: (k: number, put: (offset: V3, scale: V3, rgba: ArrayLike<number>) => void) => void) {
    const bytes = count * STRIDE;
    if (this.data.byteLength < bytes) this.data = new ArrayBuffer(Math.max(bytes, this.data.byteLength * 2));
    const f = new Float32Array(this.data);
    const b = new Uint8Array(this.data);
    let k = 0;
    const put = (offset: V3, scale: V3, rgba: ArrayLike<number>) => {
      const at = (k * STRIDE) / 4;
      f[at] = offset[0];
      f[at + 1] = offset[1];
      f[at + 2] = offset[2];
      f[at + 3] = scale[0];
      f[at + 4] = scale[1];
      f[at + 5] = scale[2];
      const c = k * STRIDE + 24;
      b[c] = rgba[0];
      b[c + 1] = rgba[1];
      b[c + 2] = rgba[2];
      b[c + 3] = rgba[3];
    };
    for (; k < count; k++) fill(k, put);
    this.count = count;
    const { gl } = this;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.instances);
    gl.bufferData(gl.ARRAY_BUFFER, new Uint8Array(this.data, 0, bytes), gl.DYNAMIC_DRAW);
  }

  draw() {
    if (this.count === 0) return;
    const { gl } = this;
    gl.bindVertexArray(this.vao);
    gl.drawArraysInstanced(gl.TRIANGLES, 0, this.mesh.count, this.count);
  }
}

const IDENTITY = new Float32Array([1, 0, 0, 0, 1, 0, 0, 0, 1]);
const GHOST = parseColor('#bfe3ff');
const REACH = parseColor('#f0b429');
const ADD = parseColor('#3ddc84');
const BOND = parseColor('#c9d3dd');
const LAMP = parseColor('#ffd166');
const ARROW = parseColor('#ffc23d');

export class CubicGL {
  private readonly mesh: Program;
  private readonly plane: Program;
  private readonly lines: Program;
  private readonly units: Batch;
  private readonly bondsBatch: Batch;
  private readonly ghost: Batch;
  private readonly reach: Batch;
  private readonly shadows: Batch;
  private readonly cursor: Batch;
  private readonly lampBatch: Batch;
  private readonly haloBatch: Batch;
  private readonly shaft: Batch;
  private readonly head: Batch;
  private readonly quad: WebGLVertexArrayObject;
  private readonly lineVao: WebGLVertexArrayObject;
  private readonly lineBuffer: WebGLBuffer;
  private readonly builder = new CubicBuilder();
  private built: CubicModel | null = null;
  private builtMarks = '';

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.mesh = link(gl, MESH_VS, MESH_FS);
    this.plane = link(gl, PLANE_VS, PLANE_FS);
    this.lines = link(gl, LINE_VS, LINE_FS);
    const cube = upload(gl, cubeMesh());
    const sphere = upload(gl, sphereMesh(14, 10));
    const cone = upload(gl, coneMesh(18));
    this.units = new Batch(gl, cube);
    this.bondsBatch = new Batch(gl, cube);
    this.ghost = new Batch(gl, cube);
    this.reach = new Batch(gl, cube);
    this.shadows = new Batch(gl, cube);
    this.cursor = new Batch(gl, cube);
    this.lampBatch = new Batch(gl, sphere);
    this.haloBatch = new Batch(gl, sphere);
    this.shaft = new Batch(gl, cube);
    this.head = new Batch(gl, cone);

    this.quad = gl.createVertexArray()!;
    gl.bindVertexArray(this.quad);
    const q = gl.createBuffer()!;
    gl.bindBuffer(gl.ARRAY_BUFFER, q);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1]), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);

    this.lineVao = gl.createVertexArray()!;
    gl.bindVertexArray(this.lineVao);
    this.lineBuffer = gl.createBuffer()!;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.lineBuffer);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
    gl.bindVertexArray(null);
  }

  draw(scene: Scene, cam: Camera3D): RenderStats {
    const { gl } = this;
    const m = this.builder.build(scene);
    if (m !== this.built) this.upload(m);
    const marks = scene.marks;
    const cursorKey = `${marks?.cursor?.cell ?? -1}:${marks?.cursor?.kind ?? ''}`;
    if (m !== this.built || cursorKey !== this.builtMarks) this.uploadCursor(m, scene);
    this.built = m;
    this.builtMarks = cursorKey;

    const vp = multiply(cam.projection(), cam.view());
    const eye = cam.eye();
    const toEye = norm([eye[0] - cam.target[0], eye[1] - cam.target[1], eye[2] - cam.target[2]]);
    const p = this.mesh;
    gl.useProgram(p.program);
    gl.uniformMatrix4fv(p.uniform('u_vp'), false, vp);
    gl.uniformMatrix3fv(p.uniform('u_rot'), false, IDENTITY);
    gl.uniform3fv(p.uniform('u_key'), norm([0.42, 0.28, 0.86]));
    gl.uniform3fv(p.uniform('u_eye_dir'), toEye);
    gl.uniform3fv(p.uniform('u_lamp'), m.lamp ? m.lamp.dir : [0, 0, 1]);
    gl.uniform1f(p.uniform('u_lamp_on'), m.lamp ? 1 : 0);
    const mode = (k: number, alpha: number, edge: number, fill = 0.12) => {
      gl.uniform1i(p.uniform('u_mode'), k);
      gl.uniform1f(p.uniform('u_alpha'), alpha);
      gl.uniform1f(p.uniform('u_edge'), edge);
      gl.uniform1f(p.uniform('u_fill'), fill);
    };

    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LEQUAL);
    gl.enable(gl.CULL_FACE);
    gl.cullFace(gl.BACK);
    gl.disable(gl.BLEND);
    gl.depthMask(true);

    // Opaque: units, bonds, the lamp and its arrow.
    mode(0, 1, 0.055);
    this.units.draw();
    mode(0, 1, 0.0);
    this.bondsBatch.draw();
    if (m.lamp) {
      mode(3, 1, 0);
      this.lampBatch.draw();
      const rot = rotationTo([-m.lamp.dir[0], -m.lamp.dir[1], -m.lamp.dir[2]]);
      gl.uniformMatrix3fv(p.uniform('u_rot'), false, rot);
      mode(0, 1, 0);
      this.shaft.draw();
      this.head.draw();
      gl.uniformMatrix3fv(p.uniform('u_rot'), false, IDENTITY);
    }

    // Translucent, back to front by kind: the plane, shadows, ghost, reachable cells, cursor.
    gl.enable(gl.BLEND);
    gl.blendFuncSeparate(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA, gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
    gl.depthMask(false);
    if (m.plane) this.drawPlane(m, vp);
    gl.useProgram(p.program);
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(-1, -4);
    mode(2, 0.5, 0);
    this.shadows.draw();
    gl.disable(gl.POLYGON_OFFSET_FILL);
    mode(1, 1, 0.06, 0.1);
    this.ghost.draw();
    mode(1, 1, 0.1, 0.3);
    this.reach.draw();
    mode(1, 1, 0.08, 0.38);
    this.cursor.draw();
    if (m.lamp) {
      mode(3, 0.16, 0);
      this.haloBatch.draw();
    }
    gl.disable(gl.CULL_FACE);

    this.drawOutlines(scene, m, vp);
    gl.depthMask(true);
    gl.disable(gl.BLEND);
    gl.disable(gl.DEPTH_TEST);
    gl.bindVertexArray(null);
    return statsOf(m);
  }

  private upload(m: CubicModel) {
    const unitSize = m.bonds > 0 ? 0.76 : 0.92;
    this.units.set(m.visible.length, (k, put) => {
      const u = m.visible[k];
      put([m.unitPos[3 * u] + 0.5, m.unitPos[3 * u + 1] + 0.5, m.unitPos[3 * u + 2] + 0.5], [unitSize, unitSize, unitSize], m.unitColor.subarray(4 * u, 4 * u + 4));
    });
    const arm = 0.26;
    const reach = 1 - unitSize + 0.08;
    this.bondsBatch.set(m.bonds, (k, put) => {
      const a = m.bondAxis[k];
      put([m.bondMid[3 * k], m.bondMid[3 * k + 1], m.bondMid[3 * k + 2]], [a === 0 ? reach : arm, a === 1 ? reach : arm, a === 2 ? reach : arm], BOND);
    });
    const cellBox = (list: number[], size: number, rgba: ArrayLike<number>) => (k: number, put: (o: V3, s: V3, c: ArrayLike<number>) => void) => {
      const c = coordOf(m.dims, list[k]);
      put([c[0] + 0.5, c[1] + 0.5, c[2] + 0.5], [size, size, size], rgba);
    };
    this.ghost.set(m.ghost.length, cellBox(m.ghost, 0.9, GHOST));
    this.reach.set(m.highlight.length, cellBox(m.highlight, 0.66, REACH));
    const z = (m.plane?.z ?? 0) + 0.001;
    this.shadows.set(m.shadows.length / 3, (k, put) => {
      put([m.shadows[3 * k] + 0.5, m.shadows[3 * k + 1] + 0.5, z], [1.08, 1.08, 0.002], [0, 0, 0, Math.round(255 * m.shadows[3 * k + 2])]);
    });
    const lamp = m.lamp;
    if (lamp) {
      const s = lamp.size;
      this.lampBatch.set(1, (_, put) => put(lamp.at, [0.8 * s, 0.8 * s, 0.8 * s], LAMP));
      this.haloBatch.set(1, (_, put) => put(lamp.at, [1.6 * s, 1.6 * s, 1.6 * s], LAMP));
      // The arrow points from the lamp toward the structure, along the light's travel.
      const d = lamp.dir;
      const shaftLen = 0.9 * s;
      const start = 0.7 * s;
      const mid = start + shaftLen / 2;
      this.shaft.set(1, (_, put) => put([lamp.at[0] - d[0] * mid, lamp.at[1] - d[1] * mid, lamp.at[2] - d[2] * mid], [0.16 * s, 0.16 * s, shaftLen], ARROW));
      const tip = start + shaftLen + 0.25 * s;
      this.head.set(1, (_, put) => put([lamp.at[0] - d[0] * tip, lamp.at[1] - d[1] * tip, lamp.at[2] - d[2] * tip], [0.5 * s, 0.5 * s, 0.55 * s], ARROW));
    } else {
      this.lampBatch.set(0, () => {});
      this.haloBatch.set(0, () => {});
      this.shaft.set(0, () => {});
      this.head.set(0, () => {});
    }
  }

  private uploadCursor(m: CubicModel, scene: Scene) {
    const c = scene.marks?.cursor;
    const show = c && c.kind === 'add' && c.cell >= 0 && scene.frame.cells[c.cell] === 0;
    this.cursor.set(show ? 1 : 0, (_, put) => {
      const p = coordOf(m.dims, c!.cell);
      put([p[0] + 0.5, p[1] + 0.5, p[2] + 0.5], [0.86, 0.86, 0.86], ADD);
    });
  }

  private drawPlane(m: CubicModel, vp: Float32Array) {
    const { gl } = this;
    const plane = m.plane!;
    const pl = this.plane;
    gl.useProgram(pl.program);
    gl.uniformMatrix4fv(pl.uniform('u_vp'), false, vp);
    gl.uniform1f(pl.uniform('u_z'), plane.z);
    const [w, h] = m.dims;
    const b = m.box;
    const centre = b ? [(b.min[0] + b.max[0]) / 2, (b.min[1] + b.max[1]) / 2] : [w / 2, h / 2];
    if (plane.solid) {
      // The model's ground: the whole floor of the space, edges included.
      gl.uniform2f(pl.uniform('u_min'), 0, 0);
      gl.uniform2f(pl.uniform('u_max'), w, h);
      gl.uniform4f(pl.uniform('u_fill'), 0.36, 0.33, 0.29, 0.92);
      gl.uniform4f(pl.uniform('u_line'), 0.62, 0.57, 0.5, 0.55);
      gl.uniform1f(pl.uniform('u_fade'), 0);
    } else {
      // A reference grid fading out around the structure.
      const r = b ? Math.max(6, Math.hypot(b.max[0] - b.min[0], b.max[1] - b.min[1]) * 1.2 + 4) : Math.max(w, h);
      gl.uniform2f(pl.uniform('u_min'), Math.max(0, centre[0] - r), Math.max(0, centre[1] - r));
      gl.uniform2f(pl.uniform('u_max'), Math.min(w, centre[0] + r), Math.min(h, centre[1] + r));
      gl.uniform4f(pl.uniform('u_fill'), 0.2, 0.25, 0.31, 0.55);
      gl.uniform4f(pl.uniform('u_line'), 0.6, 0.68, 0.76, 0.35);
      gl.uniform1f(pl.uniform('u_fade'), r);
    }
    gl.uniform2f(pl.uniform('u_centre'), centre[0], centre[1]);
    gl.disable(gl.CULL_FACE);
    gl.bindVertexArray(this.quad);
    gl.drawArrays(gl.TRIANGLES, 0, 6);
    gl.enable(gl.CULL_FACE);
  }

  /** Wire boxes: events of the last step, the selection, the hovered unit and the cursor. */
  private drawOutlines(scene: Scene, m: CubicModel, vp: Float32Array) {
    const { gl } = this;
    const groups: { cells: number[]; color: [number, number, number, number]; grow: number }[] = [];
    const events = scene.frame.events;
    if (events.length) {
      const colors = new Map(scene.layout.events.map((e) => [e.code, parseColor(e.color)]));
      const byKind = new Map<number, number[]>();
      for (let k = 0; k + 1 < events.length; k += 2) {
        const list = byKind.get(events[k + 1]) ?? [];
        list.push(events[k]);
        byKind.set(events[k + 1], list);
      }
      for (const [kind, cells] of byKind) {
        const c = colors.get(kind) ?? [255, 77, 79, 255];
        groups.push({ cells, color: [c[0] / 255, c[1] / 255, c[2] / 255, 0.95], grow: 0.5 });
      }
    }
    const marks = scene.marks;
    if (marks?.selected !== undefined && marks.selected >= 0) groups.push({ cells: [marks.selected], color: [0.94, 0.71, 0.16, 1], grow: 0.5 });
    if (marks && marks.hover >= 0 && marks.hover !== marks.selected) groups.push({ cells: [marks.hover], color: [1, 1, 1, 0.95], grow: 0.47 });
    const cursor = marks?.cursor;
    if (cursor && cursor.cell >= 0) {
      const color: [number, number, number, number] = cursor.kind === 'remove' ? [1, 0.35, 0.3, 1] : cursor.kind === 'add' ? [0.24, 0.86, 0.52, 1] : [1, 1, 1, 1];
      groups.push({ cells: [cursor.cell], color, grow: 0.5 });
    }
    if (!groups.length) return;
    const l = this.lines;
    gl.useProgram(l.program);
    gl.uniformMatrix4fv(l.uniform('u_vp'), false, vp);
    gl.bindVertexArray(this.lineVao);
    for (const g of groups) {
      const verts: number[] = [];
      for (const cell of g.cells) boxEdges(coordOf(m.dims, cell), g.grow, verts);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.lineBuffer);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(verts), gl.STREAM_DRAW);
      // Visible edges bright, hidden ones faint: the mark shows through what covers it.
      gl.depthFunc(gl.GREATER);
      gl.uniform4f(l.uniform('u_color'), g.color[0], g.color[1], g.color[2], g.color[3] * 0.35);
      gl.drawArrays(gl.LINES, 0, verts.length / 3);
      gl.depthFunc(gl.LEQUAL);
      gl.uniform4f(l.uniform('u_color'), g.color[0], g.color[1], g.color[2], g.color[3]);
      gl.drawArrays(gl.LINES, 0, verts.length / 3);
    }
  }
}

function boxEdges(c: V3, grow: number, out: number[]) {
  const lo = [c[0] + 0.5 - grow, c[1] + 0.5 - grow, c[2] + 0.5 - grow];
  const hi = [c[0] + 0.5 + grow, c[1] + 0.5 + grow, c[2] + 0.5 + grow];
  const p = (bx: number, by: number, bz: number) => [bx ? hi[0] : lo[0], by ? hi[1] : lo[1], bz ? hi[2] : lo[2]];
  for (let a = 0; a < 3; a++) {
    for (let s = 0; s < 4; s++) {
      const bits = [0, 0, 0];
      const others = [0, 1, 2].filter((x) => x !== a);
      bits[others[0]] = s & 1;
      bits[others[1]] = (s >> 1) & 1;
      const from = [...bits];
      const to = [...bits];
      to[a] = 1;
      out.push(...p(from[0], from[1], from[2]), ...p(to[0], to[1], to[2]));
    }
  }
}

function norm(v: V3): V3 {
  const n = Math.hypot(v[0], v[1], v[2]) || 1;
  return [v[0] / n, v[1] / n, v[2] / n];
}

/** Column-major rotation taking +z to the unit vector d. */
function rotationTo(d: V3): Float32Array {
  const c = d[2];
  if (c > 0.9999) return IDENTITY;
  if (c < -0.9999) return new Float32Array([1, 0, 0, 0, -1, 0, 0, 0, -1]);
  // Axis z × d, angle acos(c): Rodrigues' formula.
  const axis = norm([-d[1], d[0], 0]);
  const s = Math.sqrt(1 - c * c);
  const t = 1 - c;
  const [x, y, z] = axis;
  return new Float32Array([
    t * x * x + c, t * x * y + s * z, t * x * z - s * y,
    t * x * y - s * z, t * y * y + c, t * y * z + s * x,
    t * x * z + s * y, t * y * z - s * x, t * z * z + c,
  ]);
}

function upload(gl: WebGL2RenderingContext, data: Float32Array): Mesh {
  const buffer = gl.createBuffer()!;
  gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
  gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
  return { buffer, count: data.length / 6 };
}

/** 36 vertices of a unit cube centred on the origin, counter-clockwise outside: position, normal. */
export function cubeMesh(): Float32Array {
  const out: number[] = [];
  const faces: [number[], number[], number[]][] = [
    [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
    [[-1, 0, 0], [0, 0, 1], [0, 1, 0]],
    [[0, 1, 0], [0, 0, 1], [1, 0, 0]],
    [[0, -1, 0], [1, 0, 0], [0, 0, 1]],
    [[0, 0, 1], [1, 0, 0], [0, 1, 0]],
    [[0, 0, -1], [0, 1, 0], [1, 0, 0]],
  ];
  for (const [n, u, v] of faces) {
    const corner = (su: number, sv: number) => [0, 1, 2].map((a) => n[a] * 0.5 + u[a] * su * 0.5 + v[a] * sv * 0.5);
    for (const p of [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, -1), corner(1, 1), corner(-1, 1)]) out.push(...p, ...n);
  }
  return new Float32Array(out);
}

/** A sphere of diameter 1: position, normal. */
function sphereMesh(segments: number, rings: number): Float32Array {
  const out: number[] = [];
  const at = (i: number, j: number) => {
    const th = (i / segments) * Math.PI * 2;
    const ph = (j / rings) * Math.PI;
    const n = [Math.sin(ph) * Math.cos(th), Math.sin(ph) * Math.sin(th), Math.cos(ph)];
    return [n[0] * 0.5, n[1] * 0.5, n[2] * 0.5, ...n];
  };
  for (let j = 0; j < rings; j++) {
    for (let i = 0; i < segments; i++) {
      const a = at(i, j);
      const b = at(i, j + 1);
      const c = at(i + 1, j + 1);
      const d = at(i + 1, j);
      out.push(...a, ...b, ...c, ...a, ...c, ...d);
    }
  }
  return new Float32Array(out);
}

/** A cone along +z (base at z = -0.5, apex at +0.5), diameter 1: position, normal. */
function coneMesh(segments: number): Float32Array {
  const out: number[] = [];
  const slope = 0.5;
  for (let i = 0; i < segments; i++) {
    const a0 = (i / segments) * Math.PI * 2;
    const a1 = ((i + 1) / segments) * Math.PI * 2;
    const am = (a0 + a1) / 2;
    const rim = (a: number) => [Math.cos(a) * 0.5, Math.sin(a) * 0.5, -0.5];
    const side = (a: number) => norm([Math.cos(a), Math.sin(a), slope]);
    out.push(...rim(a0), ...side(a0), ...rim(a1), ...side(a1), 0, 0, 0.5, ...side(am));
    out.push(...rim(a1), 0, 0, -1, ...rim(a0), 0, 0, -1, 0, 0, -0.5, 0, 0, -1);
  }
  return new Float32Array(out);
}
