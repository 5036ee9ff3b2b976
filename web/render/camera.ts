// Cameras: a pan/zoom camera for the planar lattices and an orbit camera for the cubic one (the
// lattice view's and the voxel editor's), with the matrices the WebGL renderer needs, the picking
// both renderers share, and how gestures move either.
import type { Layout } from '../types';
import { type Bounds, cellAt, worldBounds } from './geometry';
import type { DragKind, GestureHandlers, Point } from './gestures';

export type Mat4 = Float32Array;

/** Column-major 4×4 product a·b. */
export function multiply(a: Mat4, b: Mat4): Mat4 {
  const out = new Float32Array(16);
  for (let col = 0; col < 4; col++) {
    for (let row = 0; row < 4; row++) {
      let s = 0;
      for (let k = 0; k < 4; k++) s += a[k * 4 + row] * b[col * 4 + k];
      out[col * 4 + row] = s;
    }
  }
  return out;
}

/** What gestures steer: both cameras pan by screen pixels and zoom about a screen point. */
interface ViewCamera {
  width: number;
  height: number;
  pan(dx: number, dy: number): void;
  zoom(factor: number, sx?: number, sy?: number): void;
}

export class Camera2D implements ViewCamera {
  readonly kind = '2d';
  cx = 0;
  cy = 0;
  /** Pixels per world unit. */
  scale = 10;
  width = 1;
  height = 1;

  fit(bounds: Bounds) {
    const bw = Math.max(1e-6, bounds.x1 - bounds.x0);
    const bh = Math.max(1e-6, bounds.y1 - bounds.y0);
    this.scale = Math.max(0.05, Math.min(this.width / bw, this.height / bh) * 0.94);
    this.cx = (bounds.x0 + bounds.x1) / 2;
    this.cy = (bounds.y0 + bounds.y1) / 2;
  }

  toScreen(wx: number, wy: number): [number, number] {
    return [(wx - this.cx) * this.scale + this.width / 2, (wy - this.cy) * this.scale + this.height / 2];
  }

  toWorld(sx: number, sy: number): [number, number] {
    return [(sx - this.width / 2) / this.scale + this.cx, (sy - this.height / 2) / this.scale + this.cy];
  }

  pan(dx: number, dy: number) {
    this.cx -= dx / this.scale;
    this.cy -= dy / this.scale;
  }

  /** Zooms by `factor` keeping the world point under (sx, sy) fixed. */
  zoom(factor: number, sx = this.width / 2, sy = this.height / 2) {
    const [wx, wy] = this.toWorld(sx, sy);
    this.scale = Math.min(400, Math.max(0.02, this.scale * factor));
    const [nx, ny] = this.toWorld(sx, sy);
    this.cx += wx - nx;
    this.cy += wy - ny;
  }

  /** World rectangle currently visible. */
  visible(): Bounds {
    const [x0, y0] = this.toWorld(0, 0);
    const [x1, y1] = this.toWorld(this.width, this.height);
    return { x0, y0, x1, y1 };
  }

  pick(layout: Layout, sx: number, sy: number): number {
    const [wx, wy] = this.toWorld(sx, sy);
    return cellAt(layout, wx, wy);
  }
}

export interface Hit {
  cell: number;
  /** The empty cell in front of the hit face, or -1 when it is outside the lattice. */
  front: number;
}

export class Camera3D implements ViewCamera {
  readonly kind = '3d';
  target: [number, number, number] = [0, 0, 0];
  yaw = Math.PI / 4;
  pitch = 0.6;
  distance = 20;
  fov = Math.PI / 4;
  width = 1;
  height = 1;

  fit(dims: [number, number, number]) {
    this.target = [dims[0] / 2, dims[1] / 2, dims[2] / 3];
    const radius = Math.hypot(dims[0], dims[1], dims[2]) / 2;
    this.distance = (radius / Math.sin(this.fov / 2)) * 0.9;
  }

  /** Looks at the centre of a world box from the current direction, close enough to fill the view. */
  fitBox(min: [number, number, number], max: [number, number, number], margin = 1.08) {
    this.target = [(min[0] + max[0]) / 2, (min[1] + max[1]) / 2, (min[2] + max[2]) / 2];
    const radius = Math.max(0.75, Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]) / 2);
    const aspect = this.width / Math.max(1, this.height);
    const half = Math.min(this.fov / 2, Math.atan(Math.tan(this.fov / 2) * aspect));
    this.distance = Math.min(2000, Math.max(1.5, (radius / Math.sin(half)) * margin));
  }

  /** Back to the default viewing direction. */
  resetOrientation() {
    this.yaw = Math.PI / 4;
    this.pitch = 0.6;
  }

  /** Screen position (CSS pixels) and eye distance of a world point, or null behind the eye. */
  project(x: number, y: number, z: number): [number, number, number] | null {
    const { f, right, up, eye } = this.basis();
    const d: V3 = [x - eye[0], y - eye[1], z - eye[2]];
    const depth = dot(d, f);
    if (depth <= 1e-6) return null;
    const t = Math.tan(this.fov / 2);
    const aspect = this.width / Math.max(1, this.height);
    const nx = dot(d, right) / (depth * t * aspect);
    const ny = dot(d, up) / (depth * t);
    return [((nx + 1) / 2) * this.width, ((1 - ny) / 2) * this.height, depth];
  }

  /** Where the ray through a screen point meets the horizontal plane at height z, or null. */
  hitPlaneZ(sx: number, sy: number, z: number): [number, number] | null {
    const { origin, dir } = this.ray(sx, sy);
    if (Math.abs(dir[2]) < 1e-9) return null;
    const t = (z - origin[2]) / dir[2];
    if (t <= 0) return null;
    return [origin[0] + dir[0] * t, origin[1] + dir[1] * t];
  }

  eye(): [number, number, number] {
    const cp = Math.cos(this.pitch);
    return [
      this.target[0] + this.distance * cp * Math.cos(this.yaw),
      this.target[1] + this.distance * cp * Math.sin(this.yaw),
      this.target[2] + this.distance * Math.sin(this.pitch),
    ];
  }

  orbit(dx: number, dy: number) {
    this.yaw -= dx * 0.008;
    this.pitch = Math.min(1.5, Math.max(-1.5, this.pitch + dy * 0.008));
  }

  pan(dx: number, dy: number) {
    const { right, up } = this.basis();
    const k = (this.distance * Math.tan(this.fov / 2) * 2) / this.height;
    for (let i = 0; i < 3; i++) this.target[i] += (-dx * right[i] + dy * up[i]) * k;
  }

  /** Moves toward the target (factor above 1) or away; a dolly, so the screen point is not kept. */
  zoom(factor: number) {
    this.distance = Math.min(2000, Math.max(1.5, this.distance / factor));
  }

  private basis() {
    const eye = this.eye();
    const f = normalize(sub(this.target, eye));
    const right = normalize(cross(f, [0, 0, 1]));
    const up = cross(right, f);
    return { f, right, up, eye };
  }

  view(): Mat4 {
    const { f, right, up, eye } = this.basis();
    const m = new Float32Array(16);
    m[0] = right[0]; m[4] = right[1]; m[8] = right[2];
    m[1] = up[0]; m[5] = up[1]; m[9] = up[2];
    m[2] = -f[0]; m[6] = -f[1]; m[10] = -f[2];
    m[12] = -dot(right, eye);
    m[13] = -dot(up, eye);
    m[14] = dot(f, eye);
    m[15] = 1;
    return m;
  }

  projection(): Mat4 {
    const near = Math.max(0.05, this.distance / 200);
    const far = this.distance * 20 + 100;
    const t = 1 / Math.tan(this.fov / 2);
    const aspect = this.width / Math.max(1, this.height);
    const m = new Float32Array(16);
    m[0] = t / aspect;
    m[5] = t;
    m[10] = (far + near) / (near - far);
    m[11] = -1;
    m[14] = (2 * far * near) / (near - far);
    return m;
  }

  /** The ray through a screen point, in world space. */
  ray(sx: number, sy: number): { origin: [number, number, number]; dir: [number, number, number] } {
    const { f, right, up, eye } = this.basis();
    const t = Math.tan(this.fov / 2);
    const aspect = this.width / Math.max(1, this.height);
    const nx = ((2 * sx) / this.width - 1) * t * aspect;
    const ny = (1 - (2 * sy) / this.height) * t;
    const dir = normalize([f[0] + nx * right[0] + ny * up[0], f[1] + nx * right[1] + ny * up[1], f[2] + nx * right[2] + ny * up[2]]);
    return { origin: eye, dir };
  }

  /** First occupied cell along the ray through (sx, sy), walking the voxel grid. */
  pick(dims: [number, number, number], occupied: (i: number) => boolean, sx: number, sy: number): Hit | null {
    const { origin, dir } = this.ray(sx, sy);
    const [w, h, d] = dims;
    // Enter the lattice box.
    let tmin = 0;
    let tmax = Infinity;
    const size = [w, h, d];
    for (let a = 0; a < 3; a++) {
      if (Math.abs(dir[a]) < 1e-12) {
        if (origin[a] < 0 || origin[a] > size[a]) return null;
      } else {
        let t0 = (0 - origin[a]) / dir[a];
        let t1 = (size[a] - origin[a]) / dir[a];
        if (t0 > t1) [t0, t1] = [t1, t0];
        tmin = Math.max(tmin, t0);
        tmax = Math.min(tmax, t1);
      }
    }
    if (tmin > tmax) return null;
    const p = [0, 1, 2].map((a) => origin[a] + dir[a] * (tmin + 1e-6));
    const cell = p.map((v, a) => Math.min(size[a] - 1, Math.max(0, Math.floor(v))));
    const step = dir.map((v) => (v > 0 ? 1 : -1));
    const next = [0, 1, 2].map((a) => (dir[a] > 0 ? cell[a] + 1 : cell[a]));
    const tMax = [0, 1, 2].map((a) => (Math.abs(dir[a]) < 1e-12 ? Infinity : tmin + (next[a] - p[a]) / dir[a]));
    const tDelta = [0, 1, 2].map((a) => (Math.abs(dir[a]) < 1e-12 ? Infinity : Math.abs(1 / dir[a])));
    let prev = -1;
    const index = (c: number[]) => (c[2] * h + c[1]) * w + c[0];
    for (let guard = 0; guard < w + h + d + 3; guard++) {
      if (cell[0] < 0 || cell[1] < 0 || cell[2] < 0 || cell[0] >= w || cell[1] >= h || cell[2] >= d) break;
      const i = index(cell);
      if (occupied(i)) return { cell: i, front: prev };
      prev = i;
      const a = tMax[0] < tMax[1] ? (tMax[0] < tMax[2] ? 0 : 2) : tMax[1] < tMax[2] ? 1 : 2;
      cell[a] += step[a];
      tMax[a] += tDelta[a];
    }
    return null;
  }
}

export type Camera = Camera2D | Camera3D;

/** Moves a camera by a drag: an orbit drag turns a 3-D camera; a planar one pans on either kind. */
function dragCamera(camera: Camera, dx: number, dy: number, kind: DragKind) {
  if (kind === 'orbit' && camera.kind === '3d') camera.orbit(dx, dy);
  else camera.pan(dx, dy);
}

/**
 * The drag and zoom handlers that steer whichever camera `camera()` returns now (the view swaps
 * cameras with the lattice), calling `changed` after each move.
 */
export function cameraGestures(camera: () => Camera, changed: () => void): Required<Pick<GestureHandlers, 'drag' | 'zoom'>> {
  return {
    drag(dx: number, dy: number, kind: DragKind) {
      dragCamera(camera(), dx, dy, kind);
      changed();
    },
    zoom(factor: number, centre: Point) {
      const c: ViewCamera = camera();
      c.zoom(factor, centre.x, centre.y);
      changed();
    },
  };
}

export function fitCamera(camera: Camera, layout: Layout) {
  if (camera.kind === '2d') camera.fit(worldBounds(layout));
  else camera.fit(layout.dims);
}

/**
 * The box around the occupied cells of a cubic lattice and any extra cells (a ghost), in world
 * units, or null when there are none: what a 3-D camera frames.
 */
export function occupiedBox(dims: [number, number, number], cells: ArrayLike<number>, extra: readonly number[] = []): { min: [number, number, number]; max: [number, number, number] } | null {
  const [w, h] = dims;
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  const take = (i: number) => {
    const c = [i % w, Math.floor(i / w) % h, Math.floor(i / (w * h))];
    for (let a = 0; a < 3; a++) {
      if (c[a] < min[a]) min[a] = c[a];
      if (c[a] + 1 > max[a]) max[a] = c[a] + 1;
    }
  };
  for (let i = 0; i < cells.length; i++) if (cells[i] !== 0) take(i);
  for (const i of extra) take(i);
  return min[0] <= max[0] ? { min, max } : null;
}

type V3 = [number, number, number];
const sub = (a: V3, b: V3): V3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: V3, b: V3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: V3, b: V3): V3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
function normalize(a: V3): V3 {
  const n = Math.hypot(a[0], a[1], a[2]) || 1;
  return [a[0] / n, a[1] / n, a[2] / n];
}
