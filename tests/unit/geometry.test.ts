import { describe, expect, it } from 'vitest';
import { cellAt, cellCentre, HEX_RADIUS, HEX_ROW, hexCorners, neighbours, worldBounds } from '../../web/render/geometry';
import { layout } from './helpers';

describe('cell centres and picking', () => {
  for (const lattice of ['square', 'hex'] as const) {
    it(`${lattice}: the cell under each centre is that cell, and outside is -1`, () => {
      const l = layout(lattice, 7, 5);
      for (let y = 0; y < 5; y++) {
        for (let x = 0; x < 7; x++) {
          const [cx, cy] = cellCentre(lattice, x, y);
          expect(cellAt(l, cx, cy)).toBe(y * 7 + x);
          // A little off centre still picks the same cell.
          expect(cellAt(l, cx + 0.3, cy - 0.2)).toBe(y * 7 + x);
        }
      }
      expect(cellAt(l, -0.6, 0.5)).toBe(-1);
      expect(cellAt(l, 0.5, -0.6)).toBe(-1);
      expect(cellAt(l, 20, 2)).toBe(-1);
    });
  }

  it('odd hex rows sit half a cell to the right, rows sqrt(3)/2 apart', () => {
    expect(cellCentre('hex', 0, 0)).toEqual([0.5, HEX_RADIUS]);
    const [x1, y1] = cellCentre('hex', 0, 1);
    expect(x1).toBe(1);
    expect(y1).toBeCloseTo(HEX_ROW + HEX_RADIUS, 12);
    expect(cellCentre('square', 3, 2)).toEqual([3.5, 2.5]);
  });

  it('the world bounds hold every cell centre', () => {
    for (const lattice of ['square', 'hex'] as const) {
      const b = worldBounds(layout(lattice, 6, 4));
      for (let y = 0; y < 4; y++) {
        for (let x = 0; x < 6; x++) {
          const [cx, cy] = cellCentre(lattice, x, y);
          expect(cx).toBeGreaterThan(b.x0);
          expect(cx).toBeLessThan(b.x1);
          expect(cy).toBeGreaterThan(b.y0);
          expect(cy).toBeLessThan(b.y1);
        }
      }
    }
  });

  it('hexagon corners are at the radius, a flat side up and down', () => {
    const corners = hexCorners(2, 3, HEX_RADIUS);
    expect(corners).toHaveLength(6);
    for (const [x, y] of corners) expect(Math.hypot(x - 2, y - 3)).toBeCloseTo(HEX_RADIUS, 12);
    expect(corners[0][0]).toBeCloseTo(2 + HEX_RADIUS * Math.cos(-Math.PI / 6), 12);
  });
});

describe('neighbours, in the core direction order', () => {
  it('square: right, up, left, down', () => {
    const l = layout('square', 4, 3);
    expect(neighbours(l, 5)).toEqual([6, 1, 4, 9]);
    expect(neighbours(l, 0)).toEqual([1, 4]);
    expect(neighbours(l, 0, true)).toEqual([1, -1, -1, 4]);
  });

  it('hex (odd-r): E, NE, NW, W, SW, SE on even and odd rows', () => {
    const l = layout('hex', 5, 5);
    // (2, 2), an even row; (2, 1), an odd row.
    expect(neighbours(l, 12)).toEqual([13, 7, 6, 11, 16, 17]);
    expect(neighbours(l, 7)).toEqual([8, 3, 2, 6, 12, 13]);
    expect(neighbours(l, 0, true)).toEqual([1, -1, -1, -1, -1, 5]);
  });

  it('hex: direction k points at -60k degrees, one cell away', () => {
    const l = layout('hex', 6, 6);
    for (let y = 1; y < 5; y++) {
      for (let x = 1; x < 5; x++) {
        const i = y * 6 + x;
        const [cx, cy] = cellCentre('hex', x, y);
        neighbours(l, i, true).forEach((j, k) => {
          const [nx, ny] = cellCentre('hex', j % 6, Math.floor(j / 6));
          const angle = (-Math.PI / 3) * k;
          expect(nx - cx).toBeCloseTo(Math.cos(angle), 12);
          expect(ny - cy).toBeCloseTo(Math.sin(angle), 12);
        });
      }
    }
  });

  it('neighbourhoods are symmetric', () => {
    for (const lattice of ['square', 'hex'] as const) {
      const l = layout(lattice, 5, 4);
      for (let i = 0; i < 20; i++) for (const j of neighbours(l, i)) expect(neighbours(l, j)).toContain(i);
    }
  });
});
