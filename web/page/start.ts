// The page's start: the page's wasm module, the view, the features, and the first scenario: the
// link in the address, else the one being edited before the page was closed, else the default.
// A first visit opens on what Kumiki is and where to start (the welcome feature's).
import * as core from '../wasm';
import { whenIdle } from '../widgets/idle';
import type { Feature, PageContext } from './context';
import { openedScenario, openingScenario, savedScenario } from './store';

/** Opens the default preset (amas-L: scripts/catalog.mjs), as a fresh start (not an edit, not in the undo history). */
export function openDefault(page: PageContext): Promise<boolean> {
  return page.session.open(core.defaultScenario(), { record: false, opens: true });
}

/** Opens the link in the address, if a feature takes it; true when one did. */
function openAddress(page: PageContext): Promise<boolean> {
  const claim: { opened: Promise<boolean> | null } = { opened: null };
  page.events.emit('open-address', claim);
  return claim.opened ?? Promise.resolve(false);
}

/** The longest the features that come `later` wait, after the first frame, for an idle moment. */
const LATER_MS = 1000;

/**
 * Mounts the features that come `later`, each as its code arrives: in the first idle moment after
 * the first frame, so that their code does not compete with it; at once after it when the address
 * holds a link (it may be theirs) or a tab is shown meanwhile (it may be theirs).
 */
function mountLater(page: PageContext, features: readonly Feature[], linked: boolean) {
  let state: 'loading' | 'drawn' | 'mounted' = 'loading';
  const mount = () => {
    if (state === 'mounted') return;
    state = 'mounted';
    for (const feature of features.filter((f) => f.later))
      Promise.resolve(feature.mount(page)).catch((e: unknown) => page.banner.report(`Part of the page could not be loaded: ${core.message(e)}`));
  };
  page.session.on('frame', () => {
    if (state !== 'loading') return;
    state = 'drawn';
    if (linked) mount();
    else whenIdle(mount, LATER_MS);
  });
  page.events.on('tab', () => {
    if (state === 'drawn') mount();
  });
}

export async function start(page: PageContext, features: readonly Feature[]) {
  const { session, banner, prefs, embedded } = page;
  await core.loadCore();
  // The worker reports its renderer when its view is ready; the first scenario need not wait.
  void page.useRenderer(prefs.renderer);
  for (const feature of features) if (!feature.later) void feature.mount(page);
  // The address as the page opened it: the first scenario may take it.
  mountLater(page, features, location.hash !== '');
  page.tabs.select(!embedded && page.tabs.all.includes(prefs.tab) ? prefs.tab : 'run');
  // An embedded page shows its link or the default scenario, never what this browser last edited.
  if (embedded) {
    if (!(await openAddress(page))) await openDefault(page);
    return;
  }
  const unfinished = openingScenario();
  if (unfinished !== null) {
    // The page was closed or stopped while a scenario was opening: it may be what stopped it.
    openedScenario();
    await openDefault(page);
    banner.keep = true;
    banner.report('The last scenario did not finish opening before the page closed, so the default one is shown. It may be too large for this device.', {
      label: 'Open it anyway',
      run: () => void session.open(unfinished, { opens: true }),
    });
    return;
  }
  // A first visit opens on what Kumiki is and where to start; a shared link has its own introduction.
  // Shown once, it is seen: a reload does not bring it back ("Start here" does). It opens before
  // the page can be used, or not at all: never over a page already used while it loaded.
  if (!prefs.welcomed && !location.hash.slice(1) && !page.early.used) {
    page.events.emit('first-visit', null);
    prefs.welcomed = true;
    page.persistPrefs();
  }
  if (await openAddress(page)) return;
  // A link that could not be opened is explained in the banner; the scenario shown instead keeps it.
  banner.keep = banner.shown;
  const saved = savedScenario();
  if (!(saved && (await session.open(saved, { record: false, quiet: true, opens: true })))) await openDefault(page);
}
