import { describe, expect, it } from 'vitest';
import { Camera2D, Camera3D, multiply, occupiedBox } from '../../web/render/camera';
import { cellCentre, worldBounds } from '../../web/render/geometry';
import { layout } from './helpers';

function camera2d(width = 800, height = 600) {
  const c = new Camera2D();
  c.width = width;
  c.height = height;
  return c;
}

function camera3d(width = 800, height = 600) {
  const c = new Camera3D();
  c.width = width;
  c.height = height;
  return c;
}

describe('Camera2D', () => {
  it('screen and world coordinates are inverse', () => {
    const c = camera2d();
    c.cx = 3;
    c.cy = -2;
    c.scale = 17;
    const [sx, sy] = c.toScreen(4.25, 1.5);
    const [wx, wy] = c.toWorld(sx, sy);
    expect(wx).toBeCloseTo(4.25, 10);
    expect(wy).toBeCloseTo(1.5, 10);
  });

  it('fit centres the bounds and shows all of them', () => {
    const c = camera2d();
    const b = worldBounds(layout('hex', 30, 10));
    c.fit(b);
    const v = c.visible();
    expect(v.x0).toBeLessThanOrEqual(b.x0);
    expect(v.x1).toBeGreaterThanOrEqual(b.x1);
    expect(v.y0).toBeLessThanOrEqual(b.y0);
    expect(v.y1).toBeGreaterThanOrEqual(b.y1);
    expect(c.toScreen((b.x0 + b.x1) / 2, (b.y0 + b.y1) / 2)).toEqual([400, 300]);
  });

  it('zoom keeps the point under the pointer where it is, within limits', () => {
    const c = camera2d();
    const before = c.toWorld(120, 450);
    c.zoom(2.5, 120, 450);
    const after = c.toWorld(120, 450);
    expect(after[0]).toBeCloseTo(before[0], 10);
    expect(after[1]).toBeCloseTo(before[1], 10);
    expect(c.scale).toBe(25);
    c.zoom(1e9);
    expect(c.scale).toBe(400);
  });

  it('picks the cell drawn under the pointer', () => {
    const c = camera2d();
    const l = layout('hex', 8, 6);
    c.fit(worldBounds(l));
    const [sx, sy] = c.toScreen(...cellCentre('hex', 5, 3));
    expect(c.pick(l, sx, sy)).toBe(3 * 8 + 5);
    // Dragging the view one cell to the left brings the next cell under the pointer.
    c.pan(-c.scale, 0);
    expect(c.pick(l, sx, sy)).toBe(3 * 8 + 6);
  });
});

describe('Camera3D', () => {
  it('projects the target to the middle of the screen', () => {
    const c = camera3d();
    c.fit([10, 6, 4]);
    const [x, y, depth] = c.project(...c.target) ?? [NaN, NaN, NaN];
    expect(x).toBeCloseTo(400, 8);
    expect(y).toBeCloseTo(300, 8);
    expect(depth).toBeCloseTo(c.distance, 8);
  });

  it('the ray through a projected point passes through the point', () => {
    const c = camera3d();
    c.fit([8, 8, 8]);
    c.orbit(70, -30);
    const p: [number, number, number] = [2.5, 6.25, 1.5];
    const [sx, sy] = c.project(...p) ?? [NaN, NaN];
    const { origin, dir } = c.ray(sx, sy);
    const t = Math.hypot(p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]);
    for (let a = 0; a < 3; a++) expect(origin[a] + dir[a] * t).toBeCloseTo(p[a], 6);
  });

  it('picks the unit in front and the empty cell before its face', () => {
    const c = camera3d();
    const dims: [number, number, number] = [5, 5, 5];
    c.fit(dims);
    const centre = (2 * 5 + 2) * 5 + 2;
    const [sx, sy] = c.project(2.5, 2.5, 2.5) ?? [NaN, NaN];
    const hit = c.pick(dims, (i) => i === centre, sx, sy);
    expect(hit?.cell).toBe(centre);
    // The eye is above and to the +x +y side (yaw 45°, pitch 0.6), so the face crossed is one of
    // the centre's +x, +y or +z neighbours.
    expect([centre + 1, centre + 5, centre + 25]).toContain(hit?.front);
    expect(c.pick(dims, () => false, sx, sy)).toBeNull();
  });

  it('view then projection maps the target to the centre of clip space', () => {
    const c = camera3d();
    c.fit([6, 6, 6]);
    const m = multiply(c.projection(), c.view());
    const [x, y, z] = c.target;
    const clip = [0, 1, 2, 3].map((r) => m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r]);
    expect(clip[0] / clip[3]).toBeCloseTo(0, 5);
    expect(clip[1] / clip[3]).toBeCloseTo(0, 5);
    expect(Math.abs(clip[2] / clip[3])).toBeLessThan(1);
  });

  it('zoom and orbit stay within their limits', () => {
    const c = camera3d();
    c.zoom(1e9);
    expect(c.distance).toBe(1.5);
    c.orbit(0, 1e6);
    expect(c.pitch).toBe(1.5);
  });
});

describe('matrices and boxes', () => {
  it('multiply is the column-major product', () => {
    const id = new Float32Array([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);
    const t = new Float32Array([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1]);
    expect(multiply(id, t)).toEqual(t);
    expect(Array.from(multiply(t, t).slice(12))).toEqual([10, 12, 14, 1]);
  });

  it('occupiedBox frames occupied cells and extras, or gives null', () => {
    const dims: [number, number, number] = [4, 3, 2];
    const cells = new Uint8Array(24);
    expect(occupiedBox(dims, cells)).toBeNull();
    cells[1 * 4 + 2] = 1; // (2, 1, 0)
    expect(occupiedBox(dims, cells)).toEqual({ min: [2, 1, 0], max: [3, 2, 1] });
    expect(occupiedBox(dims, cells, [12 + 4 * 2 + 0])).toEqual({ min: [0, 1, 0], max: [3, 3, 2] });
  });
});
