// What survives a reload: the scenario being edited and the page's preferences. Also the undo
// history of scenario changes.

const SCENARIO_KEY = 'kumiki.scenario.v1';
const PREFS_KEY = 'kumiki.prefs.v1';

export interface Prefs {
  /** The speed slider's position (web/features/run/speed.ts). */
  speedIndex: number;
  overlay: string;
  arrows: boolean;
  labels: boolean;
  renderer: 'auto' | 'webgl2' | 'canvas2d';
  tab: string;
  chartMetric: string;
  experiment: string;
  /** The experiment as last edited (JSON text), kept across reloads; empty for a built-in one. */
  experimentText: string;
  workers: number;
  /** The first screen was shown once: it no longer opens by itself. */
  welcomed: boolean;
}

const DEFAULT_PREFS: Prefs = {
  speedIndex: 3,
  overlay: '',
  arrows: true,
  labels: true,
  renderer: 'auto',
  tab: 'run',
  chartMetric: '',
  experiment: '',
  experimentText: '',
  workers: 0,
  welcomed: false,
};

function read(key: string): string | null {
  try {
    return localStorage.getItem(key);
  } catch {
    return null;
  }
}

function write(key: string, value: string) {
  try {
    localStorage.setItem(key, value);
  } catch {
    // Storage full or disabled: the page still works, edits just do not survive a reload.
  }
}

export const savedScenario = (): string | null => read(SCENARIO_KEY);
export const saveScenario = (json: string) => write(SCENARIO_KEY, json);

// A scenario being opened is noted here and the note removed once it has drawn. A note still
// present at start-up means the page was closed or stopped while opening it: that scenario is
// then offered, never reopened by itself.
const OPENING_KEY = 'kumiki.opening.v1';
export const openingScenario = (): string | null => read(OPENING_KEY);
export const noteOpening = (json: string) => write(OPENING_KEY, json);
export function openedScenario() {
  try {
    localStorage.removeItem(OPENING_KEY);
  } catch {
    // Storage disabled: there is no note either.
  }
}

export function loadPrefs(): Prefs {
  try {
    return { ...DEFAULT_PREFS, ...(JSON.parse(read(PREFS_KEY) ?? '{}') as Partial<Prefs>) };
  } catch {
    return { ...DEFAULT_PREFS };
  }
}

export function savePrefs(prefs: Prefs) {
  write(PREFS_KEY, JSON.stringify(prefs));
}

/** Undo and redo over whole states (scenario texts, an editor's shape), the oldest dropped. */
export class History<T = string> {
  private past: T[] = [];
  private future: T[] = [];

  constructor(private readonly limit = 100) {}

  /** Records `previous` before a change to something else. */
  push(previous: T) {
    this.past.push(previous);
    if (this.past.length > this.limit) this.past.shift();
    this.future = [];
  }
  undo(current: T): T | null {
    const prev = this.past.pop();
    if (prev === undefined) return null;
    this.future.push(current);
    return prev;
  }
  redo(current: T): T | null {
    const next = this.future.pop();
    if (next === undefined) return null;
    this.past.push(current);
    return next;
  }
  clear() {
    this.past = [];
    this.future = [];
  }
  get canUndo() {
    return this.past.length > 0;
  }
  get canRedo() {
    return this.future.length > 0;
  }
}
