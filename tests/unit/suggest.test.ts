// The page's reading of the core's "did you mean" (web/features/experiments/suggest.ts): the name
// written and the one suggested, put in the experiment as a key or inside a value's text.
import { describe, expect, it } from 'vitest';
import { applyNearMiss, nearMiss, pageWords } from '../../web/features/experiments/suggest';

describe('nearMiss', () => {
  it('reads a misspelt field and a misspelt metric from the core’s messages', () => {
    expect(nearMiss("This experiment cannot run: grid.robot: amas-L with robot=1: unknown field 'robot'; did you mean 'robots'?")).toEqual({
      wrong: 'robot',
      right: 'robots',
      field: true,
    });
    expect(nearMiss("stop: 'metrics.placd' is not a metric of amas; did you mean 'metrics.placed'?")).toEqual({
      wrong: 'metrics.placd',
      right: 'metrics.placed',
      field: false,
    });
    expect(nearMiss("plot.statistic: 'mode' is not a choice; expected 'mean' or 'median'")).toBeNull();
  });
});

describe('applyNearMiss', () => {
  it('renames the misspelt key and leaves prose and other keys alone', () => {
    const json = JSON.stringify({ name: 'robot', title: 'A robot grid', grid: { robot: [1, 3] }, scenarios: ['amas-L'] });
    expect(JSON.parse(applyNearMiss(json, { wrong: 'robot', right: 'robots', field: true })!)).toEqual({
      name: 'robot',
      title: 'A robot grid',
      grid: { robots: [1, 3] },
      scenarios: ['amas-L'],
    });
  });

  it('replaces a misspelt metric where it stands as a word, in conditions and lists', () => {
    const json = JSON.stringify({ stop: 'metrics.placd >= 0.5 or steps >= 9', trace: { metrics: ['placd', 'placed'] } });
    const fixed = JSON.parse(applyNearMiss(json, { wrong: 'metrics.placd', right: 'metrics.placed', field: false })!);
    expect(fixed.stop).toBe('metrics.placed >= 0.5 or steps >= 9');
    expect(JSON.parse(applyNearMiss(json, { wrong: 'placd', right: 'placed', field: false })!).trace.metrics).toEqual(['placed', 'placed']);
  });

  it('gives nothing for text that does not read or holds no such name', () => {
    expect(applyNearMiss('{"grid": ', { wrong: 'a', right: 'b', field: true })).toBeNull();
    expect(applyNearMiss('{"grid": {}}', { wrong: 'a', right: 'b', field: true })).toBeNull();
  });
});

describe('pageWords', () => {
  const metricsOf = (model: string) => ({ amas: ['built', 'steps'], fracta: ['steps', 'moves'] })[model] ?? [];
  it('lists the models’ metrics where the core sends the reader to the docs', () => {
    expect(pageWords("stop: 'metrics.xyz' is not a metric of amas (each model's metrics are in docs/metrics.md)", metricsOf)).toBe(
      "stop: 'metrics.xyz' is not a metric of amas, whose metrics are built, steps",
    );
    expect(pageWords("plot.y: 'q' is not a metric of amas or fracta (each model's metrics are in docs/metrics.md)", metricsOf)).toBe(
      "plot.y: 'q' is not a metric of amas or fracta, whose metrics are built, steps, moves",
    );
  });
  it('leaves every other message, and one it cannot list, as it is', () => {
    const near = "stop: 'metrics.placd' is not a metric of amas; did you mean 'metrics.placed'?";
    expect(pageWords(near, metricsOf)).toBe(near);
    const unknown = "'x' is not a metric of nobody (each model's metrics are in docs/metrics.md)";
    expect(pageWords(unknown, metricsOf)).toBe(unknown);
  });
});
