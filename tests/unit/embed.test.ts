import { describe, expect, it, vi } from 'vitest';
import type { Frame } from '../../web/contract.gen';
import { Embed, MAX_STEP, linkPayload, parseCommand } from '../../web/features/embed/embed';
import { embedEditRequested, embedRequested } from '../../web/page/address';

describe('embed commands', () => {
  it('are read only from the exact envelope', () => {
    expect(parseCommand({ source: 'kumiki', type: 'play' })).toEqual({ type: 'play' });
    expect(parseCommand({ source: 'kumiki', type: 'step' })).toEqual({ type: 'step', count: 1 });
    expect(parseCommand({ source: 'kumiki', type: 'step', count: 40 })).toEqual({ type: 'step', count: 40 });
    expect(parseCommand({ source: 'kumiki', type: 'load', link: 'k1.abc' })).toEqual({ type: 'load', link: 'k1.abc' });
  });

  it('ignore anything else', () => {
    for (const bad of [
      null,
      'play',
      [],
      { type: 'play' },
      { source: 'Kumiki', type: 'play' },
      { source: 'kumiki', type: 'eval', code: 'x' },
      { source: 'kumiki', type: 'play', extra: 1 },
      { source: 'kumiki', type: 'step', count: 0 },
      { source: 'kumiki', type: 'step', count: 1.5 },
      { source: 'kumiki', type: 'step', count: MAX_STEP + 1 },
      { source: 'kumiki', type: 'step', count: '3' },
      { source: 'kumiki', type: 'load', link: '' },
      { source: 'kumiki', type: 'load', link: 7 },
      { source: 'kumiki', type: 'toString' },
    ])
      expect(parseCommand(bad)).toBeNull();
  });

  it('take a link as a URL, a fragment or a payload', () => {
    expect(linkPayload('https://example.org/kumiki/?embed#k1.abc')).toBe('k1.abc');
    expect(linkPayload('#k1.abc')).toBe('k1.abc');
    expect(linkPayload(' k1.abc ')).toBe('k1.abc');
  });

  it('are on with ?embed, whatever its value', () => {
    expect(embedRequested('?embed')).toBe(true);
    expect(embedRequested('?x=1&embed=1')).toBe(true);
    expect(embedRequested('?embedded')).toBe(false);
    expect(embedRequested('')).toBe(false);
    expect(embedRequested('?embed=edit')).toBe(true);
    expect(embedEditRequested('?embed=edit')).toBe(true);
    expect(embedEditRequested('?embed')).toBe(false);
    expect(embedEditRequested('?embed=1&edit')).toBe(false);
  });
});

describe('embed events', () => {
  /** An Embed in a fake window framed by `parent`; `command` posts as the parent would. */
  function framed() {
    const listeners: ((e: MessageEvent) => void)[] = [];
    vi.stubGlobal('window', { addEventListener: (_: string, f: (e: MessageEvent) => void) => listeners.push(f) });
    // Each message with the time it was posted.
    const posted: { type: string; step?: number; at: number }[] = [];
    const parent = { postMessage: (m: { type: string; step?: number }) => posted.push({ ...m, at: performance.now() }) } as unknown as Window;
    const loads: string[] = [];
    const host = {
      load: async (p: string) => {
        loads.push(p);
        return null;
      },
      play() {},
      pause() {},
      step() {},
      reset() {},
      check() {},
    };
    const embed = new Embed(host, 'test', parent);
    const command = (data: unknown) => {
      for (const f of listeners) f({ source: parent, data } as unknown as MessageEvent);
    };
    const frame = (steps: number, hash: string) => embed.frame({ steps, hash, finished: false, completed: false, metrics: {} } as unknown as Frame);
    return { posted, loads, command, frame };
  }

  it("send a playing run's step events at most every 250 ms, and its last state after", () => {
    vi.useFakeTimers({ toFake: ['setTimeout', 'clearTimeout', 'performance'] });
    try {
      const { posted, frame } = framed();
      const steps = () => posted.filter((e) => e.type === 'step');
      // A new state every 40 ms for two seconds, as a fast run draws.
      for (let step = 0; step <= 50; step++) {
        frame(step, `h${step}`);
        vi.advanceTimersByTime(40);
      }
      vi.advanceTimersByTime(300);
      const sentAt = steps().map((e) => e.at);
      const gaps = sentAt.slice(1).map((t, i) => t - sentAt[i]);
      expect(gaps.length).toBeGreaterThan(4);
      expect(Math.min(...gaps)).toBeGreaterThanOrEqual(250);
      // Far fewer events than states, and the run's last state is among them.
      expect(steps().length).toBeLessThan(12);
      expect(steps().at(-1)?.step).toBe(50);
    } finally {
      vi.useRealTimers();
      vi.unstubAllGlobals();
    }
  });

  it('say ready once, then a step event per new state, and step 0 again after every load', async () => {
    vi.useFakeTimers();
    try {
      const { posted, loads, command, frame } = framed();
      frame(0, 'aa');
      frame(0, 'aa');
      expect(posted.map((e) => e.type)).toEqual(['ready', 'step']);
      // The same scenario loaded again starts in the same state: its step 0 is still news.
      command({ source: 'kumiki', type: 'load', link: 'https://x.org/#k1.same' });
      expect(loads).toEqual(['k1.same']);
      // The load is answered once the worker has opened it.
      await vi.advanceTimersByTimeAsync(300);
      frame(0, 'aa');
      vi.advanceTimersByTime(300);
      expect(posted.map((e) => e.type)).toEqual(['ready', 'step', 'step']);
      expect(posted.at(-1)?.step).toBe(0);
    } finally {
      vi.useRealTimers();
      vi.unstubAllGlobals();
    }
  });
});
