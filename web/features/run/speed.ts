// The speed slider: positions 0 to SPEED_MAX in quarter notches. Below the top, a position is a
// rate a person can watch, logarithmic from 1 to 1,000 steps a second (each notch about 25 %
// faster, rounded to two significant figures); the top is "max", as fast as the machine goes, for
// batch use.

/** The slider's top position: as fast as possible. */
export const SPEED_MAX = 8;
/** The slider's notch. */
export const SPEED_NOTCH = 0.25;
/** The fastest watchable rate, one notch below the top. */
const FASTEST = 1000;

/** Steps a second at slider `position` (Infinity at the top). */
export function stepsPerSecond(position: number): number {
  if (!Number.isFinite(position) || position >= SPEED_MAX) return Infinity;
  const p = Math.max(0, position) / (SPEED_MAX - SPEED_NOTCH);
  const raw = FASTEST ** Math.min(1, p);
  const digits = 10 ** (Math.floor(Math.log10(raw)) - 1);
  return Math.max(1, Number((Math.round(raw / digits) * digits).toPrecision(2)));
}

/** The rate in words: what the slider's output shows and what a screen reader says. */
export function speedText(rate: number): { short: string; spoken: string } {
  if (!Number.isFinite(rate)) return { short: 'max', spoken: 'as fast as possible' };
  const n = rate.toLocaleString('en-US', { maximumFractionDigits: 1 });
  return { short: `${n} steps/s`, spoken: `${n} step${rate === 1 ? '' : 's'} per second` };
}
