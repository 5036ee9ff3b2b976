// Sharing: the link button, opening the link in the address bar (with its introduction and the
// notice when it was made with another version of its model).
import type { PageContext } from '../../page/context';
import type { Exercise } from '../../scenario.gen';
import { byId, clear, displayText, el, markup } from '../../widgets/dom';
import { copyLink } from '../../widgets/copylink';
import { renderMarkdown } from '../../widgets/markdown';
import * as core from '../../wasm';
import introHtml from './intro.html?raw';

/** A scenario's link in the address: not an experiment's (`x1.`) nor a claim's (`claim=`). */
export function scenarioHash(hash: string): boolean {
  return hash.length > 0 && !hash.startsWith('x1.') && !hash.startsWith('claim=');
}

export function setupShare(page: PageContext) {
  const { session, banner, embedded, events } = page;
  document.body.append(markup(introHtml));
  const linkNotice = byId('link-notice');

  function replaceHash(hash: string) {
    const url = `${location.pathname}${location.search}${hash ? `#${hash}` : ''}`;
    window.history.replaceState(null, '', url);
  }

  /**
   * An edited preset says so where it introduces itself: what differs from the preset it is named
   * after, and whether the description it shows is still the preset's. False when it is no edited
   * preset (or an exercise, whose differences may give the answer away).
   */
  async function markModified(json: string, doc: { name?: string; description?: string }, exercise: boolean): Promise<boolean> {
    if (exercise) return false;
    let changes: string[];
    let preset: { description?: string };
    try {
      const found = await core.presetChanges(json, doc.name ?? '');
      if (!found?.changes.length) return false;
      changes = found.changes;
      preset = JSON.parse(found.preset) as { description?: string };
    } catch {
      return false;
    }
    const shown = changes.slice(0, 6).map((c) => displayText(c, 200));
    const words = `${shown.join('; ')}${changes.length > shown.length ? `; and ${changes.length - shown.length} more` : ''}`;
    const same = preset.description === doc.description ? ' The description below is the preset’s.' : '';
    byId('intro-modified').textContent = `Modified from the preset “${displayText(doc.name ?? '', 100)}”: ${words}.${same}`;
    return true;
  }

  /** The introduction whose mark is being worked out: a later one's mark is not overwritten by an earlier one's. */
  let introductions = 0;

  /**
   * Whoever opens a shared link sees its name and description first, at once, as the page becomes
   * interactive (a dialog that came later would take a click meant for the page); whether it is
   * an edited preset is added when the catalogue has said so (`data-checked` then marks the line).
   */
  function introduce(json: string) {
    if (embedded) return;
    const doc = JSON.parse(json) as { name?: string; description?: string; model?: string; exercise?: Exercise };
    const exercise = doc.exercise;
    byId('intro-title').textContent = displayText(exercise?.title ?? doc.name ?? '', 100) || 'A shared scenario';
    byId('intro-model').textContent = String(doc.model ?? '');
    const description = byId('intro-description');
    clear(description);
    // An exercise shows its instructions and goal, never its preset's description (which may
    // give the answer away).
    if (exercise)
      description.append(
        ...renderMarkdown(exercise.instructions),
        el('p', { class: 'exercise-goal' }, `Goal: ${core.goalWords(exercise.goal) ?? exercise.goal}`),
      );
    else description.append(el('p', { text: displayText(doc.description ?? '', 4000, true) || 'It comes with no description.' }));
    const modified = byId('intro-modified');
    modified.hidden = true;
    delete modified.dataset.checked;
    const introduction = ++introductions;
    void markModified(json, doc, exercise !== undefined).then((marked) => {
      if (introduction !== introductions) return;
      modified.hidden = !marked;
      modified.dataset.checked = 'true';
    });
    const dialog = byId<HTMLDialogElement>('intro');
    if (!dialog.open) dialog.showModal();
  }

  byId('copy-link').addEventListener('click', async () => {
    let payload: string;
    try {
      payload = await session.link();
    } catch (e) {
      banner.report(`No link can be made: ${core.message(e)}`);
      return;
    }
    const url = `${location.origin}${location.pathname}${location.search}#${payload}`;
    replaceHash(payload);
    await copyLink(byId('copy-link'), url, 'Copy link');
  });

  /** Opens the scenario of the link in the address bar; false when it is bad (the banner says why). */
  async function openHash(hash: string): Promise<boolean> {
    /** Why the link cannot be opened: brief, and whole when that says more. */
    let problem = { brief: '', full: '' };
    try {
      const unpacked = core.unpackLink(hash);
      // A link made with another behaviour of its model opens, but its run may not be its maker's.
      const { made_with, current } = unpacked;
      // A large scenario is checked by the worker as it opens (once agreed to, when it needs
      // much memory); a small one at once.
      const opened = await session.open(unpacked.scenario, {
        opens: true,
        fromLink: true,
        onProblem: (brief, full) => (problem = { brief, full }),
        onLoaded: introduce,
      });
      if (opened) {
        linkNotice.textContent = `This link was made with ${made_with < current ? 'an earlier' : 'a newer'} Kumiki; results may differ.`;
        linkNotice.hidden = made_with === current;
        banner.dismiss();
        return true;
      }
    } catch (e) {
      problem = { brief: core.message(e), full: '' };
    }
    // The message is brief; the whole of it is a click away when there is more.
    const say = (message: string) => `This link could not be opened, so your last scenario is shown instead.\n${message}`;
    const { brief, full } = problem;
    banner.report(say(brief), full && full !== brief ? { label: 'Show all of it', run: () => banner.report(say(full)) } : undefined);
    return false;
  }

  events.on('open-address', (claim) => {
    const hash = location.hash.slice(1);
    if (scenarioHash(hash)) claim.opened = openHash(hash);
  });
  window.addEventListener('hashchange', () => {
    const hash = location.hash.slice(1);
    if (!scenarioHash(hash)) return;
    void session
      .link()
      .catch(() => '')
      .then((shown) => {
        if (shown !== hash) void openHash(hash);
      });
  });
  // The scenario in view replaced the link's: the address bar and the notice let it go. A claim's
  // link (`claim=`) names no scenario: it stays while scenarios change.
  session.on('replaced', () => {
    if (location.hash && !location.hash.startsWith('#claim=')) replaceHash('');
    linkNotice.hidden = true;
  });
}
