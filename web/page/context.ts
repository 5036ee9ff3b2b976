// The page context: what every feature is given when it mounts (web/features/index.ts lists the
// features). A feature reads and changes the scenario through the session, drives the run through
// the simulation client, and tells the other features what happened through the page's events:
// no feature imports another.
import type { Credit, Frame } from '../contract.gen';
import type { Hit, RendererKind, View } from '../render/view';
import type { RendererChoice } from '../sim/protocol';
import type { SimClient } from '../sim/client';
import type { Banner } from '../widgets/banner';
import type { RunLabels } from '../widgets/chart';
import type { EarlyInput } from './early';
import type { Events } from './events';
import type { Session } from './session';
import type { Prefs } from './store';
import type { Tabs } from './tabs';

export type { RunLabels } from '../widgets/chart';

/** What features tell each other. */
export interface PageEvents {
  /** Opens a part of the page by name: `gallery` (with `part`: lessons, scenarios), `grade`, `record`, `welcome`. */
  open: { what: string; part?: string };
  /** A tab was shown. */
  tab: string;
  /** A click (or Enter on the keyboard cursor) on a cell of the view; -1 beside the structure. */
  'cell-click': { cell: number; hit: Hit | null };
  /** The pointer is over a cell of the view (-1: over none). */
  'cell-hover': number;
  /** Two runs are compared side by side, named in words; null: one run again. */
  compare: RunLabels | null;
  /** A frame of the second run of a comparison. */
  'second-frame': Frame;
  /** Opens a built-in experiment in the Experiments tab (the reproduction report's). */
  'open-experiment': string;
  /** Something to say in the run's live region for screen readers. */
  say: string;
  /** The exercise's verdict on the run: when it ends, or when asked. */
  goal: { met: boolean; because: string; steps: number; credit: Credit[] };
  /** A student handed in their exercise: the link and their name. */
  handin: { link: string; name: string };
  /** The view draws with this renderer (it started, or the choice changed). */
  renderer: RendererKind | null;
  /** A first visit: no link, nothing seen before. */
  'first-visit': null;
  /**
   * At start, the link in the address is opened: the feature whose link it is opens it and sets
   * `opened` to whether it did (having said why when it could not).
   */
  'open-address': { opened: Promise<boolean> | null };
}

export interface PageContext {
  /** The scenario in view and the run's state as the page knows it (web/page/session.ts). */
  session: Session;
  /** The simulation worker of the run in view. */
  sim: SimClient;
  /** The lattice view. */
  view: View;
  banner: Banner;
  prefs: Prefs;
  persistPrefs(): void;
  tabs: Tabs;
  events: Events<PageEvents>;
  /** In a course page's iframe (`?embed`): the view, the run controls and the exercise panel. */
  embedded: boolean;
  /** What the visitor did while the page loaded: a Play pressed, the page used at all. */
  early: EarlyInput;
  /** Draws the view with this renderer (the worker falls back to Canvas 2D without WebGL2). */
  useRenderer(choice: RendererChoice): Promise<void>;
}

/** A feature of the page: its own folder under web/features/, one line in their list. */
export interface Feature {
  /** Its name, its folder's. */
  name: string;
  /** Its tab, when it has one (labelled so); other features may add sections to it. */
  tab?: string;
  /**
   * Not on the first screen: mounted once the first frame is drawn, its code fetched then (its
   * `mount` imports it), so that it is no part of the first load. It catches up at mount with what
   * happened before it: the scenario in view, the tab shown, the link in the address.
   */
  later?: true;
  /** Sets the feature up, once: before the first scenario opens, or after its first frame when `later`. */
  mount(page: PageContext): void | Promise<void>;
}
