// The "Saved sweeps" list of the Experiments panel: each sweep kept in IndexedDB (./store.ts) with
// its name, date, runs and a partial mark, opened, compared with the sweep in view, or deleted
// (with an undo); the storage the page uses, and a full storage said plainly with what to do.
import { byId, el } from '../../widgets/dom';
import { bytesText, partial, type SavedSweep, StoreFull, type SweepStore, storageUse } from './store';

export interface SavedActions {
  open(sweep: SavedSweep): void;
  compare(sweep: SavedSweep): void;
  /** Whether a sweep is in view to compare with. */
  canCompare(): boolean;
}

/** "2026-11-28 08:00 UTC" from the provenance's RFC 3339 time. */
export const dateText = (time: string) => time.replace('T', ' ').replace(/:\d\dZ$/, ' UTC');

/** A sweep's runs in words: "6 runs", or "2 of 6 runs" for a cancelled one. */
export const runsText = (s: SavedSweep) =>
  partial(s) ? `${s.rows.length.toLocaleString('en-US')} of ${s.jobs.toLocaleString('en-US')} runs` : `${s.jobs.toLocaleString('en-US')} runs`;

export class SavedSweeps {
  private readonly list = byId<HTMLUListElement>('saved-sweeps-list');
  private readonly usage = byId('saved-sweeps-usage');
  private readonly persist = byId('saved-sweeps-persist');
  private readonly problem = byId('saved-sweeps-problem');
  private readonly note = byId('saved-sweeps-note');
  private sweeps: SavedSweep[] = [];
  /** A sweep the storage refused, kept here until it can be saved again. */
  private refused: SavedSweep | null = null;

  constructor(
    private readonly store: SweepStore,
    private readonly actions: SavedActions,
  ) {}

  /** Keeps a sweep; a full storage is said, with the sweep held for "Try again". Resolves to its id, or null. */
  async keep(sweep: SavedSweep): Promise<number | null> {
    try {
      const id = await this.store.save(sweep);
      this.refused = null;
      this.problem.replaceChildren();
      await this.refresh();
      return id;
    } catch (e) {
      this.refused = sweep;
      await this.showUsage();
      const why =
        e instanceof StoreFull
          ? `“${sweep.name}” was not saved: the browser’s storage for this page is full. Delete old sweeps below, then try again.`
          : `“${sweep.name}” was not saved: ${e instanceof Error ? e.message : String(e)}.`;
      const again = el('button', { type: 'button', text: 'Try again' });
      again.addEventListener('click', () => {
        if (this.refused) void this.keep(this.refused);
      });
      this.problem.replaceChildren(why, ' ', again);
      return null;
    }
  }

  /** Reads the list again and draws it, with the storage in use. */
  async refresh(): Promise<void> {
    try {
      this.sweeps = await this.store.list();
    } catch (e) {
      this.problem.textContent = `The saved sweeps could not be read: ${e instanceof Error ? e.message : String(e)}.`;
      return;
    }
    this.draw();
    await this.showUsage();
  }

  /** Draws the list; "Compare" is enabled while a sweep is in view. */
  draw() {
    const items = this.sweeps.map((s) => this.item(s));
    this.list.replaceChildren(...items);
    if (!items.length) this.list.append(el('li', { class: 'hint', text: 'No sweep saved yet: each sweep run here is kept once it ends.' }));
  }

  private item(s: SavedSweep): HTMLLIElement {
    const label = `${s.name}, ${dateText(s.time)}`;
    const facts = el('span', { class: 'saved-facts' }, el('strong', { text: s.name }), ` · ${dateText(s.time)} · ${runsText(s)}`);
    if (partial(s)) facts.append(' ', el('span', { class: 'partial-mark', text: 'partial' }));
    const open = el('button', { type: 'button', text: 'Open', 'aria-label': `Open ${label}` });
    const compare = el('button', { type: 'button', text: 'Compare', 'aria-label': `Compare ${label} with the sweep in view` });
    const remove = el('button', { type: 'button', text: 'Delete', 'aria-label': `Delete ${label}` });
    compare.disabled = !this.actions.canCompare();
    open.addEventListener('click', () => this.actions.open(s));
    compare.addEventListener('click', () => this.actions.compare(s));
    remove.addEventListener('click', () => void this.remove(s));
    return el('li', { 'data-id': String(s.id) }, facts, el('span', { class: 'row-buttons' }, open, compare, remove));
  }

  private async remove(s: SavedSweep) {
    if (s.id === undefined) return;
    try {
      await this.store.remove(s.id);
    } catch (e) {
      this.problem.textContent = `“${s.name}” could not be deleted: ${e instanceof Error ? e.message : String(e)}.`;
      return;
    }
    const undo = el('button', { type: 'button', text: 'Undo', 'aria-label': `Undo: keep ${s.name}, ${dateText(s.time)}` });
    undo.addEventListener('click', async () => {
      this.note.replaceChildren();
      await this.keep(s);
    });
    this.note.replaceChildren(`Deleted “${s.name}” of ${dateText(s.time)}. `, undo);
    await this.refresh();
  }

  private async showUsage() {
    const use = await storageUse();
    const count = `${this.sweeps.length} saved sweep${this.sweeps.length === 1 ? '' : 's'}`;
    this.usage.textContent = use
      ? `${count}. This page’s storage uses ${bytesText(use.usage)} of the ${bytesText(use.quota)} the browser allows it.`
      : `${count}. The browser does not say how much storage it allows.`;
    await this.showPersistence();
  }

  /**
   * Whether the browser keeps the page's storage until it is deleted, or may clear it when the disk
   * runs short (its default); a button asks it to keep it (`navigator.storage.persist`), which some
   * browsers ask their user about, so only a press asks.
   */
  private async showPersistence(refused = false) {
    const storage = globalThis.navigator?.storage;
    const kept = await storage?.persisted?.().catch(() => undefined);
    if (kept === undefined) {
      this.persist.replaceChildren();
      return;
    }
    if (kept) {
      this.persist.replaceChildren('The browser keeps the saved sweeps until you delete them.');
      return;
    }
    const ask = el('button', { type: 'button', text: 'Ask the browser to keep them' });
    ask.addEventListener('click', async () => {
      const granted = await storage.persist().catch(() => false);
      await this.showPersistence(!granted);
    });
    const why = refused
      ? 'The browser did not agree to keep them: it may still clear them when the disk runs short, so export the sweeps you need.'
      : 'The browser may clear the saved sweeps when the disk runs short.';
    this.persist.replaceChildren(why, ' ', ask);
  }
}
