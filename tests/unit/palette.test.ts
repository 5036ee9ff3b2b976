import { describe, expect, it } from 'vitest';
import { css, heat, heatTable, legendTable, parseColor, range } from '../../web/render/palette';

describe('colours', () => {
  it('parses #rgb, #rrggbb and #rrggbbaa, and anything else as grey', () => {
    expect(parseColor('#f80')).toEqual([255, 136, 0, 255]);
    expect(parseColor(' #2b6cb0 ')).toEqual([43, 108, 176, 255]);
    expect(parseColor('#2b6cb080')).toEqual([43, 108, 176, 128]);
    expect(parseColor('red')).toEqual([128, 128, 128, 255]);
    expect(css([43, 108.7, 176, 128])).toBe('rgba(43,108,176,0.502)');
  });

  it('the legend table puts each colour at its code and leaves the rest transparent', () => {
    const t = legendTable([
      { code: 2, name: 'a', color: '#ff0000' },
      { code: 300, name: 'out of range', color: '#00ff00' },
    ]);
    expect(Array.from(t.slice(8, 12))).toEqual([255, 0, 0, 255]);
    expect(t.reduce((a, b) => a + b, 0)).toBe(255 * 2);
  });

  it('the heat map runs from viridis purple to yellow and clamps', () => {
    expect(heat(0)).toEqual([68, 1, 84, 255]);
    expect(heat(1)).toEqual([253, 231, 37, 255]);
    expect(heat(-3)).toEqual(heat(0));
    expect(heat(7)).toEqual(heat(1));
    const t = heatTable();
    expect(Array.from(t.slice(255 * 4))).toEqual([253, 231, 37, 255]);
  });

  it('the range of a field skips NaN and infinities', () => {
    expect(range(new Float32Array([3, Number.NaN, -2, Number.POSITIVE_INFINITY, 5, Number.NEGATIVE_INFINITY]))).toEqual([-2, 5]);
    expect(range(new Float32Array([Number.NaN]))).toEqual([0, 1]);
  });
});
