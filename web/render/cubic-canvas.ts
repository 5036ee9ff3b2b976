// The cubic lattice in Canvas 2D, the fallback when WebGL2 is missing: the same scene as the WebGL
// path (cubic-scene.ts), drawn as shaded faces in painter's order. Units are whole cubes (their
// shared faces are hidden, so bonds are implied); the ghost, reachable cells and the add cursor are
// translucent cubes; the plane is clipped at the eye so close-ups stay correct.
import type { Camera3D } from './camera';
import { CubicBuilder, type CubicModel, type RenderStats, type V3, statsOf } from './cubic-scene';
import { coordOf } from './geometry';
import { css, parseColor, type RGBA } from './palette';
import type { Scene } from './renderer';

const NEAR = 0.05;
const NORMALS: V3[] = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]];
const KEY: V3 = normalize([0.42, 0.28, 0.86]);

interface Face {
  depth: number;
  pts: [number, number][];
  fill: string;
  stroke: string;
}

/** View-space position (right, up, depth) of world points, and their projection. */
class Projector {
  private readonly right: V3;
  private readonly up: V3;
  private readonly fwd: V3;
  private readonly eye: V3;
  private readonly sx: number;
  private readonly sy: number;

  constructor(private readonly cam: Camera3D) {
    const eye = cam.eye();
    this.eye = eye;
    this.fwd = normalize([cam.target[0] - eye[0], cam.target[1] - eye[1], cam.target[2] - eye[2]]);
    this.right = normalize(cross(this.fwd, [0, 0, 1]));
    this.up = cross(this.right, this.fwd);
    const t = Math.tan(cam.fov / 2);
    this.sy = cam.height / 2 / t;
    this.sx = this.sy;
  }

  view(p: V3): V3 {
    const d: V3 = [p[0] - this.eye[0], p[1] - this.eye[1], p[2] - this.eye[2]];
    return [dot(d, this.right), dot(d, this.up), dot(d, this.fwd)];
  }

  screen(v: V3): [number, number] {
    return [this.cam.width / 2 + (v[0] / v[2]) * this.sx, this.cam.height / 2 - (v[1] / v[2]) * this.sy];
  }

  /** A polygon clipped at the near plane and projected, or null when wholly behind. */
  polygon(points: V3[]): [number, number][] | null {
    const v = points.map((p) => this.view(p));
    const out: V3[] = [];
    for (let i = 0; i < v.length; i++) {
      const a = v[i];
      const b = v[(i + 1) % v.length];
      const ina = a[2] >= NEAR;
      const inb = b[2] >= NEAR;
      if (ina) out.push(a);
      if (ina !== inb) {
        const t = (NEAR - a[2]) / (b[2] - a[2]);
        out.push([a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, NEAR]);
      }
    }
    return out.length >= 3 ? out.map((p) => this.screen(p)) : null;
  }

  /** A segment clipped at the near plane and projected. */
  segment(a: V3, b: V3): [[number, number], [number, number]] | null {
    let va = this.view(a);
    let vb = this.view(b);
    if (va[2] < NEAR && vb[2] < NEAR) return null;
    const cut = (p: V3, q: V3): V3 => {
      const t = (NEAR - p[2]) / (q[2] - p[2]);
      return [p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t, NEAR];
    };
    if (va[2] < NEAR) va = cut(va, vb);
    else if (vb[2] < NEAR) vb = cut(vb, va);
    return [this.screen(va), this.screen(vb)];
  }

  pixelsPerUnit(depth: number): number {
    return this.sy / depth;
  }

  distance(p: V3): number {
    return Math.hypot(p[0] - this.eye[0], p[1] - this.eye[1], p[2] - this.eye[2]);
  }

  get eyePoint(): V3 {
    return this.eye;
  }
}

export class CubicCanvas {
  private readonly builder = new CubicBuilder();

  draw(ctx: CanvasRenderingContext2D, scene: Scene, cam: Camera3D): RenderStats {
    const m = this.builder.build(scene);
    const pr = new Projector(cam);
    if (m.plane) this.drawPlane(ctx, m, pr);

    const faces: Face[] = [];
    const cells = scene.frame.cells;
    const [w, h, d] = m.dims;
    const occupied = (x: number, y: number, z: number) => x >= 0 && y >= 0 && z >= 0 && x < w && y < h && z < d && cells[(z * h + y) * w + x] !== 0;
    const eye = pr.eyePoint;
    const cube = (c: V3, size: number, base: RGBA, alpha: number, solid: boolean, stroke: string) => {
      for (const n of NORMALS) {
        if (solid && occupied(c[0] + n[0], c[1] + n[1], c[2] + n[2])) continue;
        const fc: V3 = [c[0] + 0.5 + n[0] * size * 0.5, c[1] + 0.5 + n[1] * size * 0.5, c[2] + 0.5 + n[2] * size * 0.5];
        if ((eye[0] - fc[0]) * n[0] + (eye[1] - fc[1]) * n[1] + (eye[2] - fc[2]) * n[2] <= 0) continue;
        const pts = pr.polygon(faceCorners(c, n, size));
        if (!pts) continue;
        const shade = solid ? 0.5 + 0.5 * Math.max(0, dot(n, KEY)) + 0.08 * n[2] : 1;
        faces.push({ depth: pr.distance(fc), pts, fill: css([base[0] * shade, base[1] * shade, base[2] * shade, alpha * 255]), stroke });
      }
    };
    for (const k of m.visible) {
      const c: V3 = [m.unitPos[3 * k], m.unitPos[3 * k + 1], m.unitPos[3 * k + 2]];
      const rgba = m.unitColor.subarray(4 * k, 4 * k + 4);
      cube(c, 1, [rgba[0], rgba[1], rgba[2], 255], 1, true, 'rgba(0,0,0,0.4)');
    }
    const translucent = (list: number[], size: number, color: string, alpha: number) => {
      const base = parseColor(color);
      for (const cell of list) cube(coordOf(m.dims, cell), size, base, alpha, false, css([base[0], base[1], base[2], 220]));
    };
    translucent(m.ghost, 0.9, '#bfe3ff', 0.14);
    translucent(m.highlight, 0.66, '#f0b429', 0.35);
    const cursor = scene.marks?.cursor;
    if (cursor?.kind === 'add' && cursor.cell >= 0 && cells[cursor.cell] === 0) translucent([cursor.cell], 0.86, '#3ddc84', 0.4);

    const lampDepth = m.lamp ? pr.distance(m.lamp.at) : 0;
    const centreDepth = m.box ? pr.distance(centreOf(m)) : 0;
    if (m.lamp && lampDepth > centreDepth) this.drawLamp(ctx, m, pr);
    faces.sort((a, b) => b.depth - a.depth);
    ctx.lineWidth = 1;
    ctx.lineJoin = 'round';
    for (const f of faces) {
      ctx.beginPath();
      ctx.moveTo(f.pts[0][0], f.pts[0][1]);
      for (let k = 1; k < f.pts.length; k++) ctx.lineTo(f.pts[k][0], f.pts[k][1]);
      ctx.closePath();
      ctx.fillStyle = f.fill;
      ctx.fill();
      ctx.strokeStyle = f.stroke;
      ctx.stroke();
    }
    if (m.lamp && lampDepth <= centreDepth) this.drawLamp(ctx, m, pr);
    this.drawOutlines(ctx, scene, m, pr);
    return statsOf(m);
  }

  private drawPlane(ctx: CanvasRenderingContext2D, m: CubicModel, pr: Projector) {
    const plane = m.plane!;
    const [w, h] = m.dims;
    const z = plane.z;
    let x0 = 0;
    let y0 = 0;
    let x1 = w;
    let y1 = h;
    if (!plane.solid && m.box) {
      const r = Math.ceil(Math.max(4, Math.hypot(m.box.max[0] - m.box.min[0], m.box.max[1] - m.box.min[1]) * 0.6 + 2));
      x0 = Math.max(0, Math.floor(m.box.min[0]) - r);
      y0 = Math.max(0, Math.floor(m.box.min[1]) - r);
      x1 = Math.min(w, Math.ceil(m.box.max[0]) + r);
      y1 = Math.min(h, Math.ceil(m.box.max[1]) + r);
    }
    const poly = pr.polygon([[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]]);
    if (poly) {
      ctx.beginPath();
      ctx.moveTo(poly[0][0], poly[0][1]);
      for (let k = 1; k < poly.length; k++) ctx.lineTo(poly[k][0], poly[k][1]);
      ctx.closePath();
      ctx.fillStyle = plane.solid ? 'rgba(92,84,74,0.92)' : 'rgba(51,64,79,0.55)';
      ctx.fill();
    }
    ctx.strokeStyle = plane.solid ? 'rgba(158,146,128,0.55)' : 'rgba(153,173,194,0.28)';
    ctx.lineWidth = 1;
    ctx.beginPath();
    const line = (a: V3, b: V3) => {
      const s = pr.segment(a, b);
      if (!s) return;
      ctx.moveTo(s[0][0], s[0][1]);
      ctx.lineTo(s[1][0], s[1][1]);
    };
    for (let x = x0; x <= x1; x++) line([x, y0, z], [x, y1, z]);
    for (let y = y0; y <= y1; y++) line([x0, y, z], [x1, y, z]);
    ctx.stroke();
    for (let k = 0; k < m.shadows.length; k += 3) {
      const x = m.shadows[k];
      const y = m.shadows[k + 1];
      const s = pr.polygon([[x + 0.04, y + 0.04, z], [x + 0.96, y + 0.04, z], [x + 0.96, y + 0.96, z], [x + 0.04, y + 0.96, z]]);
      if (!s) continue;
      ctx.beginPath();
      ctx.moveTo(s[0][0], s[0][1]);
      for (let i = 1; i < s.length; i++) ctx.lineTo(s[i][0], s[i][1]);
      ctx.closePath();
      ctx.fillStyle = `rgba(0,0,0,${(0.4 * m.shadows[k + 2]).toFixed(3)})`;
      ctx.fill();
    }
  }

  private drawLamp(ctx: CanvasRenderingContext2D, m: CubicModel, pr: Projector) {
    const lamp = m.lamp!;
    const v = pr.view(lamp.at);
    if (v[2] < NEAR) return;
    const [sx, sy] = pr.screen(v);
    const r = Math.max(4, 0.4 * lamp.size * pr.pixelsPerUnit(v[2]));
    const glow = ctx.createRadialGradient(sx, sy, r * 0.3, sx, sy, r * 2.2);
    glow.addColorStop(0, 'rgba(255,209,102,0.55)');
    glow.addColorStop(1, 'rgba(255,209,102,0)');
    ctx.fillStyle = glow;
    ctx.beginPath();
    ctx.arc(sx, sy, r * 2.2, 0, Math.PI * 2);
    ctx.fill();
    ctx.fillStyle = '#ffd166';
    ctx.beginPath();
    ctx.arc(sx, sy, r, 0, Math.PI * 2);
    ctx.fill();
    // The arrow, from the lamp toward the structure.
    const d = lamp.dir;
    const s = lamp.size;
    const at = (k: number): V3 => [lamp.at[0] - d[0] * k * s, lamp.at[1] - d[1] * k * s, lamp.at[2] - d[2] * k * s];
    const seg = pr.segment(at(0.7), at(2.0));
    if (!seg) return;
    const [[ax, ay], [bx, by]] = seg;
    ctx.strokeStyle = '#ffc23d';
    ctx.fillStyle = '#ffc23d';
    ctx.lineWidth = Math.max(2, r * 0.3);
    ctx.beginPath();
    ctx.moveTo(ax, ay);
    ctx.lineTo(bx, by);
    ctx.stroke();
    const len = Math.hypot(bx - ax, by - ay) || 1;
    const ux = (bx - ax) / len;
    const uy = (by - ay) / len;
    const head = Math.max(6, r * 0.9);
    ctx.beginPath();
    ctx.moveTo(bx + ux * head * 0.6, by + uy * head * 0.6);
    ctx.lineTo(bx - ux * head * 0.4 - uy * head * 0.6, by - uy * head * 0.4 + ux * head * 0.6);
    ctx.lineTo(bx - ux * head * 0.4 + uy * head * 0.6, by - uy * head * 0.4 - ux * head * 0.6);
    ctx.closePath();
    ctx.fill();
  }

  private drawOutlines(ctx: CanvasRenderingContext2D, scene: Scene, m: CubicModel, pr: Projector) {
    const box = (cell: number, color: string, grow: number) => {
      const c = coordOf(m.dims, cell);
      const lo = [c[0] + 0.5 - grow, c[1] + 0.5 - grow, c[2] + 0.5 - grow];
      const hi = [c[0] + 0.5 + grow, c[1] + 0.5 + grow, c[2] + 0.5 + grow];
      ctx.strokeStyle = color;
      ctx.lineWidth = 2;
      ctx.beginPath();
      for (let a = 0; a < 3; a++) {
        for (let s = 0; s < 4; s++) {
          const others = [0, 1, 2].filter((x) => x !== a);
          const p: V3 = [lo[0], lo[1], lo[2]];
          if (s & 1) p[others[0]] = hi[others[0]];
          if (s & 2) p[others[1]] = hi[others[1]];
          const q: V3 = [p[0], p[1], p[2]];
          q[a] = hi[a];
          const seg = pr.segment(p, q);
          if (!seg) continue;
          ctx.moveTo(seg[0][0], seg[0][1]);
          ctx.lineTo(seg[1][0], seg[1][1]);
        }
      }
      ctx.stroke();
    };
    const events = scene.frame.events;
    const colors = new Map(scene.layout.events.map((e) => [e.code, e.color]));
    for (let k = 0; k + 1 < events.length; k += 2) box(events[k], colors.get(events[k + 1]) ?? '#ff4d4f', 0.52);
    const marks = scene.marks;
    if (marks?.selected !== undefined && marks.selected >= 0) box(marks.selected, '#f0b429', 0.52);
    if (marks && marks.hover >= 0 && marks.hover !== marks.selected) box(marks.hover, 'rgba(255,255,255,0.95)', 0.5);
    const cursor = marks?.cursor;
    if (cursor && cursor.cell >= 0) box(cursor.cell, cursor.kind === 'remove' ? '#ff5a4d' : cursor.kind === 'add' ? '#3ddc84' : '#ffffff', 0.52);
  }
}

function centreOf(m: CubicModel): V3 {
  const b = m.box!;
  return [(b.min[0] + b.max[0]) / 2, (b.min[1] + b.max[1]) / 2, (b.min[2] + b.max[2]) / 2];
}

/** The corners of the face with outward normal n of a cube of side `size` centred in cell c. */
function faceCorners(c: V3, n: V3, size: number): V3[] {
  const axis = n[0] !== 0 ? 0 : n[1] !== 0 ? 1 : 2;
  const u = axis === 0 ? 1 : 0;
  const v = axis === 2 ? 1 : 2;
  const half = size / 2;
  const centre: V3 = [c[0] + 0.5 + n[0] * half, c[1] + 0.5 + n[1] * half, c[2] + 0.5 + n[2] * half];
  const corner = (du: number, dv: number): V3 => {
    const p: V3 = [centre[0], centre[1], centre[2]];
    p[u] += du * half;
    p[v] += dv * half;
    return p;
  };
  return [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)];
}

function dot(a: V3, b: V3): number {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
function cross(a: V3, b: V3): V3 {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}
function normalize(a: V3): V3 {
  const n = Math.hypot(a[0], a[1], a[2]) || 1;
  return [a[0] / n, a[1] / n, a[2] / n];
}
