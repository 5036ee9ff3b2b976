import { afterEach, describe, expect, it, vi } from 'vitest';
import { History, loadPrefs, savedScenario, savePrefs, saveScenario } from '../../web/page/store';

/** A localStorage stand-in: a Map, or one that refuses every call like a disabled storage. */
function fakeStorage(refuse = false) {
  const items = new Map<string, string>();
  const guard = () => {
    if (refuse) throw new DOMException('denied', 'SecurityError');
  };
  return {
    items,
    getItem: (k: string) => {
      guard();
      return items.get(k) ?? null;
    },
    setItem: (k: string, v: string) => {
      guard();
      items.set(k, v);
    },
  };
}

afterEach(() => vi.unstubAllGlobals());

describe('History', () => {
  it('undoes and redoes in order, and a new change drops the redo list', () => {
    const h = new History<string>();
    expect(h.canUndo).toBe(false);
    h.push('a');
    h.push('b');
    expect(h.undo('c')).toBe('b');
    expect(h.undo('b')).toBe('a');
    expect(h.undo('a')).toBeNull();
    expect(h.redo('a')).toBe('b');
    expect(h.canRedo).toBe(true);
    h.push('b');
    expect(h.canRedo).toBe(false);
    expect(h.redo('x')).toBeNull();
  });

  it('keeps at most `limit` states, dropping the oldest', () => {
    const h = new History<number>(3);
    for (let i = 0; i < 5; i++) h.push(i);
    expect([h.undo(5), h.undo(4), h.undo(3), h.undo(2)]).toEqual([4, 3, 2, null]);
    h.clear();
    expect(h.canUndo || h.canRedo).toBe(false);
  });
});

describe('what survives a reload', () => {
  it('preferences: defaults, then saved values over them', () => {
    const storage = fakeStorage();
    vi.stubGlobal('localStorage', storage);
    const prefs = loadPrefs();
    expect(prefs.renderer).toBe('auto');
    expect(prefs.arrows).toBe(true);
    savePrefs({ ...prefs, renderer: 'canvas2d', workers: 3 });
    const again = loadPrefs();
    expect(again.renderer).toBe('canvas2d');
    expect(again.workers).toBe(3);
    expect(again.tab).toBe(prefs.tab);
  });

  it('damaged preferences give the defaults; a refusing storage loses nothing but the save', () => {
    const storage = fakeStorage();
    vi.stubGlobal('localStorage', storage);
    storage.items.set('kumiki.prefs.v1', '{not json');
    expect(loadPrefs().renderer).toBe('auto');
    vi.stubGlobal('localStorage', fakeStorage(true));
    expect(() => saveScenario('{}')).not.toThrow();
    expect(savedScenario()).toBeNull();
    expect(loadPrefs().speedIndex).toBe(3);
  });

  it('the scenario is kept as written', () => {
    vi.stubGlobal('localStorage', fakeStorage());
    saveScenario('{"model":"amas"}');
    expect(savedScenario()).toBe('{"model":"amas"}');
  });
});
