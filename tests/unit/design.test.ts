// The sweep design form's reading and writing (web/features/experiments/design.ts): a grid key as
// a list or a range, the sampling and the stop condition come out of the experiment's JSON and go
// back as the same keys, with the rest of the experiment as it was.
import { describe, expect, it } from 'vitest';
import { designOf, readValues, valuesText, withDesign } from '../../web/features/experiments/design';

const experiment = {
  version: 1,
  name: 'x',
  scenarios: ['amas-L'],
  grid: { robots: { start: 2, step: 2, end: 10 }, field: ['continuous', 'discrete'] },
  sample: { method: 'random', count: 20, seed: 7, ranges: { tip_load: { min: 0, max: 4 }, n: { min: 1, max: 9, integer: true } } },
  seeds: 3,
  stop: 'metrics.built >= 0.5 or steps >= 2000',
  plot: { kind: 'lines', x: 'params.robots', y: ['steps'] },
};

describe('the design form', () => {
  it('reads a list and a range, the sampling and the stop condition', () => {
    const d = designOf(experiment);
    expect(d.grid).toEqual([
      { key: 'robots', range: true, values: '', start: '2', step: '2', end: '10' },
      { key: 'field', range: false, values: 'continuous, discrete', start: '', step: '', end: '' },
    ]);
    expect(d).toMatchObject({ method: 'random', count: '20', seed: '7', stop: experiment.stop });
    expect(d.ranges).toEqual([
      { key: 'tip_load', min: '0', max: '4', integer: false },
      { key: 'n', min: '1', max: '9', integer: true },
    ]);
    expect(designOf({ sample: { count: 3, ranges: {} } }).method).toBe('latin');
    expect(designOf({}).method).toBe('grid');
  });

  it('writes back what it read, key for key and in the same order', () => {
    const back = withDesign(experiment, designOf(experiment));
    expect(back).toEqual(experiment);
    expect(Object.keys(back)).toEqual(Object.keys(experiment));
  });

  it('writes a change, drops what is emptied and places new keys where the format lists them', () => {
    const plain = { version: 1, name: 'x', scenarios: ['amas-L'], seeds: 2, plot: [] };
    const d = designOf(plain);
    d.grid.push({ key: 'robots', range: false, values: '1, 3', start: '', step: '', end: '' });
    d.method = 'latin';
    d.count = '10';
    d.ranges.push({ key: 'tip_load', min: '0', max: '2.5', integer: false });
    d.stop = 'steps >= 500';
    const out = withDesign(plain, d);
    expect(Object.keys(out)).toEqual(['version', 'name', 'scenarios', 'grid', 'sample', 'seeds', 'stop', 'plot']);
    expect(out).toMatchObject({
      grid: { robots: [1, 3] },
      sample: { method: 'latin', count: 10, ranges: { tip_load: { min: 0, max: 2.5 } } },
      stop: 'steps >= 500',
    });
    const emptied = withDesign(out, { ...designOf(out), grid: [], method: 'grid', stop: ' ' });
    expect(emptied).toEqual(plain);
  });

  it('keeps what is not a number as typed, for the core to name', () => {
    const d = designOf({});
    d.grid.push({ key: 'robots', range: true, values: '', start: '1', step: 'two', end: '' });
    expect(withDesign({}, d).grid).toEqual({ robots: { start: 1, step: 'two', end: '' } });
  });

  it('reads typed values as JSON where they read, else as text', () => {
    expect(readValues(' 1, 2.5, true, continuous, "a b" ,, ')).toEqual([1, 2.5, true, 'continuous', 'a b']);
    expect(valuesText([1, 2.5, true, 'continuous'])).toBe('1, 2.5, true, continuous');
  });
});
