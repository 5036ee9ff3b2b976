// Saved sweeps: every finished or cancelled sweep kept in the browser's IndexedDB, with its
// experiment text, its rows, and the exports made when it ran (so a sweep reopened after the page
// was updated still saves the bytes that the CLI of its own commit writes). The raw IndexedDB API,
// wrapped in promises: one object store, keyed by an increasing id.

/** A sweep as kept: what it ran, what came back, and its provenance. */
export interface SavedSweep {
  /** Given by the store on first save. */
  id?: number;
  /** The experiment's name and title, as `experimentInfo` read them. */
  name: string;
  title: string;
  /** The experiment's JSON text, as run. */
  text: string;
  /** The rows' JSON texts, in job order (a cancelled sweep keeps only the runs that finished). */
  rows: string[];
  /** How many runs the experiment asks for; `rows.length` below it marks a partial sweep. */
  jobs: number;
  /** The time the sweep started, as its provenance records it (RFC 3339). */
  time: string;
  /** The exports' first provenance line, "kumiki 0.1.0 (commit …)". */
  build: string;
  /** The exports as made when the sweep ended: CSV, JSON lines, and traces when the experiment traces. */
  exports: { csv: string; json: string; traces?: string };
}

/** Whether a sweep ended before every run: cancelled, with some runs. */
export const partial = (s: SavedSweep): boolean => s.rows.length < s.jobs;

/** The store is full: the browser refused to keep more (QuotaExceededError). */
export class StoreFull extends Error {
  constructor() {
    super('the browser’s storage for this page is full');
    this.name = 'StoreFull';
  }
}

/** Whether an IndexedDB error (or the transaction's) is the browser's quota refusing a write. */
export function isQuotaError(e: unknown): boolean {
  if (!e || typeof e !== 'object') return false;
  const name = (e as { name?: unknown }).name;
  return name === 'QuotaExceededError' || name === 'NS_ERROR_DOM_QUOTA_REACHED';
}

const DB = 'kumiki-sweeps';
const STORE = 'sweeps';

const request = <T>(r: IDBRequest<T>): Promise<T> =>
  new Promise((resolve, reject) => {
    r.onsuccess = () => resolve(r.result);
    r.onerror = () => reject(r.error);
  });

/** Resolves when the transaction has committed; rejects with its error (a full store as `StoreFull`). */
const committed = (tx: IDBTransaction): Promise<void> =>
  new Promise((resolve, reject) => {
    tx.oncomplete = () => resolve();
    const fail = () => reject(isQuotaError(tx.error) ? new StoreFull() : (tx.error ?? new Error('the transaction was aborted')));
    tx.onerror = fail;
    tx.onabort = fail;
  });

/** The saved sweeps of one browser (or of the `factory` a test gives). */
export class SweepStore {
  private db: Promise<IDBDatabase> | null = null;

  constructor(private readonly factory: IDBFactory = globalThis.indexedDB) {}

  private open(): Promise<IDBDatabase> {
    this.db ??= new Promise<IDBDatabase>((resolve, reject) => {
      if (!this.factory) return reject(new Error('this browser keeps no IndexedDB'));
      const r = this.factory.open(DB, 1);
      r.onupgradeneeded = () => r.result.createObjectStore(STORE, { keyPath: 'id', autoIncrement: true });
      r.onsuccess = () => resolve(r.result);
      r.onerror = () => reject(r.error);
    }).catch((e: unknown) => {
      this.db = null;
      throw e;
    });
    return this.db;
  }

  private async tx(mode: IDBTransactionMode): Promise<{ tx: IDBTransaction; store: IDBObjectStore }> {
    const tx = (await this.open()).transaction(STORE, mode);
    return { tx, store: tx.objectStore(STORE) };
  }

  /** Keeps a sweep and returns its id; a sweep with an id (one put back after a delete) keeps it. */
  async save(sweep: SavedSweep): Promise<number> {
    const { tx, store } = await this.tx('readwrite');
    const record = { ...sweep };
    if (record.id === undefined) delete record.id;
    let id: number;
    try {
      id = (await Promise.all([request(store.put(record)), committed(tx)]))[0] as number;
    } catch (e) {
      throw isQuotaError(e) ? new StoreFull() : e;
    }
    return id;
  }

  /** Every saved sweep, newest first. */
  async list(): Promise<SavedSweep[]> {
    const { store } = await this.tx('readonly');
    const all = (await request(store.getAll())) as SavedSweep[];
    return all.sort((a, b) => (b.id ?? 0) - (a.id ?? 0));
  }

  async get(id: number): Promise<SavedSweep | undefined> {
    const { store } = await this.tx('readonly');
    return (await request(store.get(id))) as SavedSweep | undefined;
  }

  async remove(id: number): Promise<void> {
    const { tx, store } = await this.tx('readwrite');
    store.delete(id);
    await committed(tx);
  }

  /** Closes the database (tests open a fresh store on the same factory). */
  async close(): Promise<void> {
    if (this.db) (await this.db).close();
    this.db = null;
  }
}

/** The bytes the page's storage uses and may use, when the browser says (`navigator.storage.estimate`). */
export async function storageUse(): Promise<{ usage: number; quota: number } | null> {
  const storage = globalThis.navigator?.storage;
  if (!storage?.estimate) return null;
  try {
    const { usage, quota } = await storage.estimate();
    return usage === undefined || quota === undefined ? null : { usage, quota };
  } catch {
    return null;
  }
}

/** A size in words: "1.4 MB". */
export function bytesText(n: number): string {
  if (n < 1000) return `${n} B`;
  const units = ['kB', 'MB', 'GB', 'TB'];
  let v = n / 1000;
  let i = 0;
  while (v >= 1000 && i < units.length - 1) {
    v /= 1000;
    i++;
  }
  return `${v >= 100 ? v.toFixed(0) : v.toFixed(1)} ${units[i]}`;
}
