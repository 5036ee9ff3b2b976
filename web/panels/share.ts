// Sharing: the link button, opening the link in the address bar (with its introduction and the
// notice when it was made with another version of its model), and the link in a bug report.
import type { Exercise } from '../scenario.gen';
import { byId, clear, displayText, el } from '../ui/dom';
import { renderMarkdown } from '../ui/markdown';
import type { LargeOpening } from '../ui/opening';
import * as core from '../wasm';
import type { Page } from './page';

export interface SharePanel {
  /** Opens the scenario of the link in the address bar; false when there is none or it is bad. */
  openHash(): boolean;
  /** The scenario in view replaced the link's: the address bar and the notice let it go. */
  leaveLink(): void;
  /** A link to the scenario in view, or its JSON when it cannot be encoded. */
  scenarioLink(): string;
}

export interface ShareDeps {
  large: LargeOpening;
  /** Starts the worker on a scenario text. */
  open(json: string): void;
  /** In a course page's iframe the course introduces the scenario itself. */
  embedded: boolean;
}

export function setupSharePanel(page: Page, { large, open, embedded }: ShareDeps): SharePanel {
  const { session, banner } = page;
  const linkNotice = byId('link-notice');

  function replaceHash(hash: string) {
    const url = `${location.pathname}${location.search}${hash ? `#${hash}` : ''}`;
    window.history.replaceState(null, '', url);
  }

  function scenarioLink(): string {
    try {
      return `${location.origin}${location.pathname}#${page.draft.link()}`;
    } catch {
      return session.scenario;
    }
  }

  /** Whoever opens a shared link sees its name and description first. */
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
    const dialog = byId<HTMLDialogElement>('intro');
    if (!dialog.open) dialog.showModal();
  }

  byId('copy-link').addEventListener('click', async () => {
    let payload: string;
    try {
      payload = page.draft.link();
    } catch (e) {
      banner.report(`No link can be made: ${core.message(e)}`);
      return;
    }
    const url = `${location.origin}${location.pathname}${location.search}#${payload}`;
    replaceHash(payload);
    const button = byId('copy-link');
    try {
      await navigator.clipboard.writeText(url);
      button.textContent = 'Link copied';
    } catch {
      button.textContent = 'Link in address bar';
    }
    button.dataset.link = url;
    setTimeout(() => (button.textContent = 'Copy link'), 2000);
  });

  function openHash(): boolean {
    const hash = location.hash.slice(1);
    // An experiment link (`x1.`) is the Experiments panel's, a claim's (`claim=`) the About panel's.
    if (!hash || hash.startsWith('x1.') || hash.startsWith('claim=')) return false;
    /** Why the link cannot be opened: brief, and whole when that says more. */
    let problem: { brief: string; full: string };
    try {
      const unpacked = core.unpackLink(hash);
      const previous = session.scenario;
      const remember = (json: string) => {
        session.remember(previous, json);
        introduce(json);
      };
      // A link made with another behaviour of its model opens, but its run may not be its maker's.
      const { made_with, current } = unpacked;
      const notice = () => {
        linkNotice.textContent = `This link was made with ${made_with < current ? 'an earlier' : 'a newer'} Kumiki; results may differ.`;
        linkNotice.hidden = made_with === current;
      };
      // A large scenario is checked by the worker as it opens (once agreed to, when it needs
      // much memory); a small one here, at once.
      const proposal = page.draft.open(unpacked.scenario, false);
      if (!proposal.problem) {
        if (proposal.large_cells > 0)
          large.begin(proposal.large_cells, remember, () => {
            notice();
            open(proposal.text);
          });
        else {
          remember(proposal.text);
          session.scenario = proposal.text;
          notice();
          open(proposal.text);
        }
        banner.dismiss();
        return true;
      }
      problem = { brief: proposal.problem, full: proposal.in_full ?? '' };
    } catch (e) {
      problem = { brief: core.message(e), full: '' };
    }
    // The message is brief; the whole of it is a click away when there is more.
    const say = (message: string) => `This link could not be opened, so your last scenario is shown instead.\n${message}`;
    const { brief, full } = problem;
    banner.report(say(brief), full && full !== brief ? { label: 'Show all of it', run: () => banner.report(say(full)) } : undefined);
    return false;
  }
  window.addEventListener('hashchange', () => {
    if (location.hash.length > 1 && !location.hash.startsWith('#x1.') && !location.hash.startsWith('#claim=') && page.draft.link() !== location.hash.slice(1))
      openHash();
  });

  return {
    openHash,
    leaveLink() {
      // A claim's link (`claim=`) names no scenario: it stays while scenarios change.
      if (location.hash && !location.hash.startsWith('#claim=')) replaceHash('');
      linkNotice.hidden = true;
    },
    scenarioLink,
  };
}
