// What every panel is given: the session, the worker, the view, the banner, the preferences, and
// the one way to open a scenario. Panels talk to each other through these, not directly.
import type { View } from '../render/view';
import type { Session } from '../session';
import type { SimClient } from '../sim/client';
import type { Prefs } from '../store';
import type { Banner } from '../ui/banner';
import type { Draft } from '../wasm';

export interface LoadOptions {
  /** The scenario replaced can be brought back by undo (default true). */
  record?: boolean;
  /** A scenario that cannot run is refused without a message (default false). */
  quiet?: boolean;
  /** Told why a scenario cannot run, instead of the banner (an editor shows it beside itself). */
  onProblem?: (message: string) => void;
  /**
   * It opens a scenario (a link, the gallery, the course page, the exercise editor) rather than
   * editing the one in view: an exercise's locks do not hold it back (default false).
   */
  opens?: boolean;
}

export interface Page {
  session: Session;
  sim: SimClient;
  view: View;
  banner: Banner;
  prefs: Prefs;
  persistPrefs(): void;
  /** The scenario in view, held in the wasm: its link, its comparison, a goal's names checked against it. */
  draft: Draft;
  /** Loads a scenario text: checked first, so a bad one never replaces a good run. */
  load(json: string, options?: LoadOptions): boolean;
  /** Changes one dotted path (`valueJson` is JSON, or else text); returns the problem, or null when applied. */
  applyChange(key: string, valueJson: string, onError?: (problem: string) => void): string | null;
  /** Changes several dotted paths at once, checked together; returns the problem, or null when applied. */
  applyChanges(changes: Record<string, unknown>): string | null;
}
