// The worker's play loop (web/sim/pace.ts) on a stand-in run and view: at max speed stepping never
// waits for a frame, and the view is drawn only when the page says a frame is free; below max it
// draws on the worker's own animation frames, as before.
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';

vi.mock('../../web/pkg/kumiki_wasm.js', () => ({ panic_message: () => undefined }));

/** What the worker posted, and the animation frames it asked for (called back only when a test says). */
const posted: { type: string }[] = [];
const animationFrames: (() => void)[] = [];
(globalThis as unknown as { self: unknown }).self = {
  postMessage: (msg: { type: string }) => posted.push(msg),
  requestAnimationFrame: (f: () => void) => animationFrames.push(f),
};

/**
 * A run whose every step takes `stepMs` of real time, and a view that counts its draws. `until(n)`
 * resolves once the run has taken n steps in all, between two of the loop's tasks (a timer would
 * wait behind the loop's own tasks in Node).
 */
function standIns(stepMs: number) {
  let steps = 0;
  let waiting: { steps: number; resolve: () => void } | null = null;
  /** The longest time between two calls to step, and when the last call ended. */
  const gap = { longest: 0, last: 0 };
  const sim = {
    advance(n: number) {
      if (gap.last) gap.longest = Math.max(gap.longest, performance.now() - gap.last);
      const until = performance.now() + n * stepMs;
      while (performance.now() < until);
      steps += n;
      gap.last = performance.now();
      if (waiting && steps >= waiting.steps) {
        waiting.resolve();
        waiting = null;
      }
      return n;
    },
    steps: () => steps,
    finished: () => false,
    stopped: () => undefined,
    frame: () => ({ steps, finished: false }),
  };
  const drawnAt: number[] = [];
  const viewer = {
    state_changed() {},
    draw_sim() {
      drawnAt.push(steps);
      return null;
    },
    timing: () => [drawnAt.length, 0, 0],
    overlay_range: () => undefined,
  };
  const until = (n: number) => new Promise<void>((resolve) => (waiting = { steps: n, resolve }));
  return { sim, viewer, drawnAt, steps: () => steps, until, gap };
}
const count = (type: string) => posted.filter((m) => m.type === type).length;

type Pace = typeof import('../../web/sim/pace');
let pace: Pace;
let host: typeof import('../../web/sim/host');

beforeEach(async () => {
  vi.resetModules();
  posted.length = 0;
  animationFrames.length = 0;
  pace = await import('../../web/sim/pace');
  host = await import('../../web/sim/host');
});

afterEach(() => pace.setPlaying(false));

/** The stand-ins held as the worker's run and view, the run started and its first frame taken. */
function started<R extends { sim: unknown; viewer: unknown }>(run: R): R {
  host.run.sim = run.sim as never;
  host.run.viewer = run.viewer as never;
  pace.started();
  pace.acknowledged();
  return run;
}

describe('the play loop', () => {
  it('at max speed steps on without waiting for a frame, and draws once for each frame the page frees', async () => {
    const run = started(standIns(2));
    const drawsAtStart = run.drawnAt.length;
    pace.setSpeed(Infinity);
    pace.play();
    await run.until(150);
    // No frame came, and the run never stopped for one (a hold waits up to a second), and asked
    // the page for one frame, not one per step.
    expect(run.gap.longest).toBeLessThan(500);
    expect(count('frame-wanted')).toBe(1);
    expect(run.drawnAt.length).toBe(drawsAtStart);
    // The worker's own animation frames are not what it waits for at max speed.
    for (const f of animationFrames.splice(0)) f();
    expect(run.drawnAt.length).toBe(drawsAtStart);
    // The page's frame: the state as it stands is drawn once and told to the page.
    pace.frameFree();
    expect(run.drawnAt.length).toBe(drawsAtStart + 1);
    expect(run.drawnAt.at(-1)).toBe(run.steps());
    expect(count('frame')).toBe(2);
    // A second answer with nothing asked draws nothing more.
    pace.frameFree();
    expect(run.drawnAt.length).toBe(drawsAtStart + 1);
    // The next frame is asked for once the last is old enough, while stepping goes on.
    pace.acknowledged();
    await run.until(run.steps() + 150);
    expect(count('frame-wanted')).toBe(2);
  });

  it('below max speed draws on the worker animation frames, and pausing at max draws there too', async () => {
    const run = started(standIns(1));
    pace.setSpeed(100);
    pace.play();
    await run.until(10);
    expect(count('frame-wanted')).toBe(0);
    expect(animationFrames.length).toBeGreaterThan(0);
    for (const f of animationFrames.splice(0)) f();
    const drawn = run.drawnAt.length;
    expect(drawn).toBeGreaterThan(1);
    // Max speed, then a pause while the page's frame is still to come: the worker's animation
    // frame draws the paused state, and the page's late answer adds no draw.
    pace.setSpeed(Infinity);
    await run.until(run.steps() + 300);
    pace.setPlaying(false);
    for (const f of animationFrames.splice(0)) f();
    expect(run.drawnAt.at(-1)).toBe(run.steps());
    const paused = run.drawnAt.length;
    pace.frameFree();
    for (const f of animationFrames.splice(0)) f();
    expect(run.drawnAt.length).toBe(paused);
  });
});
