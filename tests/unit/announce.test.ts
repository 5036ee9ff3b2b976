import { beforeAll, afterEach, beforeEach, describe, expect, it, vi } from 'vitest';

import { Announcer, CALM_MS } from '../../web/features/announce/announcer';
import type { Frame } from '../../web/contract.gen';
import { startCore } from './page';

// Numbers are written by the core's one rule (web/wasm.ts's formatNumber).
beforeAll(startCore);

/** A live region stand-in that keeps every text it is given. */
function region() {
  const said: string[] = [];
  let text = '';
  return {
    said,
    node: {
      get textContent() {
        return text;
      },
      set textContent(t: string) {
        text = t;
        said.push(t);
      },
    } as unknown as HTMLElement,
  };
}

function frame(steps: number, finished = false, completed = false): Frame {
  return { steps, finished, completed, metrics: { built: steps / 100 } } as unknown as Frame;
}

describe('the live region', () => {
  let now = 0;
  beforeEach(() => {
    now = 0;
    vi.spyOn(performance, 'now').mockImplementation(() => now);
  });
  afterEach(() => vi.restoreAllMocks());
  const at = (t: number) => {
    now = t;
  };

  it('tells a playing run calmly, at most once per CALM_MS, and its disturbances and end at once', () => {
    const r = region();
    const a = new Announcer(r.node);
    a.loaded('fracta-repair', [{ at: 10, kind: 'fault', unit: 3 }]);
    const cell = (c: number) => `cell ${c}`;
    // Sixty frames a second for 30 s.
    for (let i = 1; i <= 1800; i++) {
      at((i * 1000) / 60);
      a.frame(frame(i), true, 'built', cell);
    }
    const progress = r.said.filter((t) => t.startsWith('Running'));
    expect(progress.length).toBeGreaterThan(2);
    expect(progress.length).toBeLessThanOrEqual(30_000 / CALM_MS);
    // Said at once, joined to the load message said just before it.
    expect(r.said.filter((t) => t.includes('Step 10: fault, unit 3.'))).toHaveLength(1);
    expect(progress[0]).toMatch(/^Running: step [\d,]+, built [\d.]+\.$/);
    at(40_000);
    a.frame(frame(1801, true, true), false, 'built', cell);
    a.say('Goal met: the run completed.');
    expect(r.node.textContent).toBe('Completed in 1,801 steps. Goal met: the run completed.');
  });

  it('says a clicked disturbance once, even when the run passes it again after going back', () => {
    const r = region();
    const a = new Announcer(r.node);
    a.loaded('amas-L', []);
    at(10_000);
    const clicked = [{ at: 5, kind: 'remove', cells: [7] }];
    a.disturbed(clicked, (c) => `cell (${c}, 0)`);
    expect(r.node.textContent).toBe('Step 5: remove, at cell (7, 0).');
    at(20_000);
    a.frame(frame(3), false, 'built', String);
    a.frame(frame(9), false, 'built', String);
    expect(r.said.filter((t) => t.includes('remove'))).toHaveLength(1);
  });

  it('says only what changed: a new scenario by name, a run sent back to step 0, and nothing for edits at step 0', () => {
    const r = region();
    const a = new Announcer(r.node);
    a.loaded('amas-L', []);
    expect(r.said).toEqual(['amas-L opened.']);
    // Four edits (erase clicks) at step 0: the run did not move, nothing is said.
    for (let i = 1; i <= 4; i++) {
      at(i * 1000);
      a.loaded('amas-L', []);
    }
    expect(r.said).toEqual(['amas-L opened.']);
    at(10_000);
    a.frame(frame(40), false, 'built', String);
    a.loaded('amas-L', []);
    expect(r.said.at(-1)).toBe('Back to step 0.');
    at(20_000);
    a.loaded('fracta-repair', []);
    expect(r.said.at(-1)).toBe('fracta-repair opened.');
    expect(r.said).toHaveLength(3);
  });
});
