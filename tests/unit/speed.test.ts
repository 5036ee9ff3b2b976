import { describe, expect, it } from 'vitest';
import { SPEED_MAX, SPEED_NOTCH, speedText, stepsPerSecond } from '../../web/features/run/speed';

describe('the speed slider', () => {
  it('runs from 1 to 1,000 steps a second below its top, each notch faster, and max at the top', () => {
    const rates: number[] = [];
    for (let p = 0; p < SPEED_MAX; p += SPEED_NOTCH) rates.push(stepsPerSecond(p));
    expect(rates[0]).toBe(1);
    expect(rates.at(-1)).toBe(1000);
    for (let i = 1; i < rates.length; i++) expect(rates[i]).toBeGreaterThan(rates[i - 1]);
    // No notch jumps more than half again: every rate between 1 and 1,000 has a notch near it.
    for (let i = 1; i < rates.length; i++) expect(rates[i] / rates[i - 1]).toBeLessThan(1.5 + 1e-9);
    expect(stepsPerSecond(SPEED_MAX)).toBe(Infinity);
    expect(speedText(Infinity)).toEqual({ short: 'max', spoken: 'as fast as possible' });
    expect(speedText(1).spoken).toBe('1 step per second');
    expect(speedText(stepsPerSecond(3)).short).toBe('14 steps/s');
    expect(speedText(1.2).short).toBe('1.2 steps/s');
  });
});
