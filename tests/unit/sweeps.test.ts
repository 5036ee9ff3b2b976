// The saved sweeps' store (web/features/experiments/store.ts) on fake-indexeddb: what is saved comes
// back whole and newest first, survives a new connection, is deleted and put back under its id,
// and a full storage is told apart from other failures.
import { IDBFactory, IDBObjectStore } from 'fake-indexeddb';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { bytesText, isQuotaError, partial, type SavedSweep, StoreFull, SweepStore } from '../../web/features/experiments/store';

const sweep = (name: string, rows = 2, jobs = 2): SavedSweep => ({
  name,
  title: `The ${name}`,
  text: JSON.stringify({ version: 1, name, scenarios: ['amas-L'] }),
  rows: Array.from({ length: rows }, (_, i) => JSON.stringify({ seed: i + 1, steps: 10 * (i + 1) })),
  jobs,
  time: '2026-11-28T08:00:00Z',
  build: 'kumiki 0.1.0 (commit 0123456789ab)',
  exports: { csv: `# kumiki 0.1.0\n${name}\n`, json: `{"name":"${name}"}\n` },
});

afterEach(() => vi.restoreAllMocks());

describe('SweepStore', () => {
  it('keeps sweeps across connections, lists them newest first and deletes one', async () => {
    const factory = new IDBFactory();
    const store = new SweepStore(factory);
    const a = await store.save(sweep('first'));
    const b = await store.save(sweep('second', 1, 3));
    expect(b).toBeGreaterThan(a);
    await store.close();

    const again = new SweepStore(factory);
    const listed = await again.list();
    expect(listed.map((s) => s.name)).toEqual(['second', 'first']);
    expect(listed[1]).toEqual({ ...sweep('first'), id: a });
    expect(partial(listed[0])).toBe(true);
    expect(partial(listed[1])).toBe(false);
    expect((await again.get(b))?.rows).toEqual(sweep('second', 1, 3).rows);

    await again.remove(a);
    expect((await again.list()).map((s) => s.name)).toEqual(['second']);
    expect(await again.get(a)).toBeUndefined();
  });

  it('puts a deleted sweep back under its own id (undo)', async () => {
    const store = new SweepStore(new IDBFactory());
    await store.save(sweep('old'));
    const id = await store.save(sweep('kept'));
    await store.save(sweep('new'));
    const gone = await store.get(id);
    await store.remove(id);
    expect(await store.save(gone!)).toBe(id);
    expect((await store.list()).map((s) => s.name)).toEqual(['new', 'kept', 'old']);
  });

  it('says the storage is full when the browser refuses the write, and keeps what it had', async () => {
    const store = new SweepStore(new IDBFactory());
    await store.save(sweep('before'));
    vi.spyOn(IDBObjectStore.prototype, 'put').mockImplementation(() => {
      throw new DOMException('over quota', 'QuotaExceededError');
    });
    await expect(store.save(sweep('too big'))).rejects.toBeInstanceOf(StoreFull);
    vi.restoreAllMocks();
    expect((await store.list()).map((s) => s.name)).toEqual(['before']);
  });

  it('passes other failures on as they are', async () => {
    const store = new SweepStore(new IDBFactory());
    vi.spyOn(IDBObjectStore.prototype, 'put').mockImplementation(() => {
      throw new DOMException('cannot clone', 'DataCloneError');
    });
    const refused = await store.save(sweep('x')).catch((e: unknown) => e);
    expect(refused).not.toBeInstanceOf(StoreFull);
    expect((refused as DOMException).name).toBe('DataCloneError');
  });

  it('fails with a message where the browser keeps no IndexedDB', async () => {
    const store = new SweepStore(undefined as unknown as IDBFactory);
    await expect(store.list()).rejects.toThrow(/no IndexedDB/);
  });
});

describe('helpers', () => {
  it('tells a quota error by its name, in the browsers that name it differently', () => {
    expect(isQuotaError(new DOMException('x', 'QuotaExceededError'))).toBe(true);
    expect(isQuotaError({ name: 'NS_ERROR_DOM_QUOTA_REACHED' })).toBe(true);
    expect(isQuotaError(new DOMException('x', 'AbortError'))).toBe(false);
    expect(isQuotaError(null)).toBe(false);
  });

  it('writes sizes in words', () => {
    expect(bytesText(512)).toBe('512 B');
    expect(bytesText(1_400_000)).toBe('1.4 MB');
    expect(bytesText(250_000_000)).toBe('250 MB');
    expect(bytesText(3_200_000_000)).toBe('3.2 GB');
  });
});
