import { describe, expect, it } from 'vitest';
import type { Row } from '../../web/types';
import { spreadOf, stats, valueAt } from '../../web/ui/plots';

const row: Row = {
  scenario: 'amas-L',
  seed: 3,
  completed: true,
  steps: 209,
  hash: '2cce7f7c37266b5e',
  metrics: { collisions: 9, built: 1 },
  params: { robots: 5, field: 'discrete' },
  scenario_hash: '0123456789abcdef',
  version: 'kumiki 0.1.0',
};

describe('plot helpers', () => {
  it('valueAt reads top-level fields, params.* and metrics.*', () => {
    expect(valueAt(row, 'steps')).toBe(209);
    expect(valueAt(row, 'completed')).toBe(true);
    expect(valueAt(row, 'params.field')).toBe('discrete');
    expect(valueAt(row, 'metrics.collisions')).toBe(9);
    expect(valueAt(row, 'metrics.missing')).toBeUndefined();
  });

  it('stats: sample sd and quartiles interpolated between order statistics, non-finite values left out', () => {
    const s = stats([7, 1, Number.NaN, 3, 5, Number.POSITIVE_INFINITY]);
    expect(s.n).toBe(4);
    expect(s.mean).toBe(4);
    expect(s.sd).toBeCloseTo(Math.sqrt(20 / 3), 12);
    expect([s.min, s.q1, s.median, s.q3, s.max]).toEqual([1, 2.5, 4, 5.5, 7]);
    const odd = stats([10, 30, 20]);
    expect(odd.median).toBe(20);
    expect(odd.q1).toBe(15);
    expect(stats([]).n).toBe(0);
    expect(stats([]).mean).toBeNaN();
  });

  it('spreads: min-max, mean ± sd, quartiles, or none', () => {
    const s = stats([1, 3, 5, 7]);
    expect(spreadOf(s, 'minmax')).toEqual([1, 7]);
    expect(spreadOf(s, 'quartiles')).toEqual([2.5, 5.5]);
    const [lo, hi] = spreadOf(s, 'sd') ?? [NaN, NaN];
    expect(lo).toBeCloseTo(4 - s.sd, 12);
    expect(hi).toBeCloseTo(4 + s.sd, 12);
    expect(spreadOf(s, 'none')).toBeNull();
  });
});
