// The first screen and the tour. A first visit (no link, nothing seen before) opens with what
// Kumiki is and the ways in: watch a paper's scenarios, take a lesson, build your own, compare
// two runs side by side; from there a short tour of five stops points at the parts of the page.
// "Start here" at the top brings both back. The tour is a non-modal box beside the part of the page
// each stop marks (never over it): the page stays usable, and Esc or "End the tour" leaves it.
import type { PageContext } from '../../page/context';
import { byId, markup } from '../../widgets/dom';
import { placeBeside } from './place';
import * as core from '../../wasm';
import dialogHtml from './dialog.html?raw';
import tourHtml from './tour.html?raw';

/** The lesson the first screen's "Compare two runs" opens: two runs side by side. */
const COMPARE_LESSON = 'lesson-amas-compare';

interface Stop {
  /** The element the stop points at. */
  target: string;
  title: string;
  text: string;
}

const TOUR: Stop[] = [
  {
    target: 'canvas-wrap',
    title: 'The view',
    text: 'The lattice and its robots. Drag to pan, the wheel or a pinch zooms; with the view focused, C shows a cursor for the keyboard. A click applies the tool chosen on the Run tab.',
  },
  {
    target: 'transport',
    title: 'Run it',
    text: 'Play (Space), one step (→) and reset (R). The speed goes from 1 to 1,000 steps a second, or max. The seed fixes the randomness, so a run replays exactly.',
  },
  {
    target: 'timeline-row',
    title: 'Go back',
    text: 'Drag the timeline to any step already reached, or press ← with the view focused; holding it scrubs.',
  },
  {
    target: 'side-tabs',
    title: 'The panels',
    text: 'Run: live metrics, chart, overlays, click tools. Scenario: the shape, every parameter and the JSON. Experiments: many runs, plotted like the papers. About: what each paper claims and what Kumiki finds.',
  },
  {
    target: 'ways-in',
    title: 'Lessons, the gallery, sharing',
    text: 'Lessons are short exercises on the papers; the gallery holds every built-in scenario. Copy link puts the whole scenario in the address, so whoever opens it gets the same run.',
  },
];

export function setupWelcome(page: PageContext) {
  const { session, events, tabs } = page;
  document.body.append(markup(dialogHtml), markup(tourHtml));
  const actions = {
    watch: () => events.emit('open', { what: 'gallery', part: 'scenarios' }),
    lesson: () => events.emit('open', { what: 'gallery', part: 'lessons' }),
    build: () => tabs.select('scenario', true),
    compare: () =>
      void core
        .lessonJson(COMPARE_LESSON)
        .then((text) => session.open(text, { opens: true }))
        .then((opened) => {
          if (opened) tabs.select('run');
        }),
  };
  const dialog = byId<HTMLDialogElement>('welcome');
  const box = byId('tour');
  const back = byId<HTMLButtonElement>('tour-back');
  const next = byId<HTMLButtonElement>('tour-next');
  let at = -1;
  let marked: HTMLElement | null = null;

  function show() {
    if (!dialog.open) dialog.showModal();
  }

  // The dialog hides at once, but its 'close' event, and the browser's move of the focus off its
  // buttons, come a task later: keys pressed meanwhile reached a hidden button, which the page's
  // keys (the arrows, Space) ignore. The focus leaves as the dialog is answered.
  const letGo = () => {
    if (document.activeElement instanceof HTMLElement && dialog.contains(document.activeElement)) document.activeElement.blur();
  };
  dialog.addEventListener('submit', letGo);
  dialog.addEventListener('cancel', letGo);
  dialog.addEventListener('close', () => {
    switch (dialog.returnValue) {
      case 'watch':
        actions.watch();
        break;
      case 'lesson':
        actions.lesson();
        break;
      case 'build':
        actions.build();
        break;
      case 'compare':
        actions.compare();
        break;
      case 'tour':
        go(0);
        break;
    }
    dialog.returnValue = '';
  });

  function mark(el: HTMLElement | null) {
    marked?.classList.remove('tour-target');
    marked = el;
    marked?.classList.add('tour-target');
  }

  function go(i: number) {
    if (i < 0 || i >= TOUR.length) {
      end();
      return;
    }
    at = i;
    const stop = TOUR[i];
    byId('tour-count').textContent = `Stop ${i + 1} of ${TOUR.length}`;
    byId('tour-title').textContent = stop.title;
    byId('tour-text').textContent = stop.text;
    back.disabled = i === 0;
    next.textContent = i === TOUR.length - 1 ? 'Done' : 'Next';
    const target = byId(stop.target);
    mark(target);
    box.hidden = false;
    box.dataset.stop = String(i);
    target.scrollIntoView({ block: 'nearest' });
    placeBox();
    next.focus();
  }

  /** Puts the box beside the part the stop points at, never over it. */
  function placeBox() {
    const target = at >= 0 ? byId(TOUR[at].target) : null;
    if (!target) return;
    const heightAt = (width: number) => {
      box.style.width = `${width}px`;
      return box.offsetHeight;
    };
    const place = placeBeside(target.getBoundingClientRect(), Math.min(520, window.innerWidth - 28), heightAt, {
      width: window.innerWidth,
      height: window.innerHeight,
    });
    box.style.width = `${place.width}px`;
    box.style.left = `${place.left}px`;
    box.style.top = `${place.top}px`;
  }
  window.addEventListener('resize', placeBox);

  function end() {
    at = -1;
    mark(null);
    box.hidden = true;
    delete box.dataset.stop;
    byId('open-welcome').focus();
  }

  back.addEventListener('click', () => go(at - 1));
  next.addEventListener('click', () => go(at + 1));
  byId('tour-close').addEventListener('click', end);
  box.addEventListener('keydown', (e) => {
    if (e.key === 'Escape') {
      e.preventDefault();
      end();
    }
  });
  byId('open-welcome').addEventListener('click', show);
  events.on('first-visit', show);
}
