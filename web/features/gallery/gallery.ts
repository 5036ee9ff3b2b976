// The gallery: the built-in lessons first (classroom exercises, each with its paper's section),
// then every built-in scenario grouped by model, each card with a picture of its first step and
// its title in words; one filter for both. The Lessons button and the first screen's ways in open
// it on one part.
import type { PageContext } from '../../page/context';
import { byId, clear, el, markup } from '../../widgets/dom';
import { scenarioTitle } from '../../models/index';
import * as core from '../../wasm';
import type { Catalogue } from '../../wasm';
import dialogHtml from './dialog.html?raw';
import { Pictures } from './pictures';

/** What the gallery shows: the lessons, the scenarios, or both. */
export type GalleryPart = 'lessons' | 'scenarios' | 'all';

const TITLES: Record<GalleryPart, string> = { lessons: 'Lessons', scenarios: "The papers' scenarios", all: 'Scenarios' };

export function setupGallery(page: PageContext) {
  const { session, events } = page;
  document.body.append(markup(dialogHtml));
  // The built-in scenarios and lessons (web/wasm.ts's catalogue): fetched when the gallery first opens.
  let lists: Catalogue | null = null;
  const choose = (name: string) => void session.open(lists?.presetText[name] ?? '', { opens: true });
  // A lesson opens on the run tab, where its exercise panel is.
  const chooseLesson = (name: string) =>
    void session.open(lists?.lessonText[name] ?? '', { opens: true }).then((opened) => {
      if (opened) page.tabs.select('run');
    });
  const dialog = byId<HTMLDialogElement>('gallery');
  const pictures = new Pictures();
  const list = byId('gallery-list');
  const filter = byId<HTMLInputElement>('gallery-filter');
  let part: GalleryPart = 'all';

  const card = (attrs: Record<string, string>, open: () => void, ...children: HTMLElement[]) => {
    const button = el('button', { type: 'button', class: 'card', ...attrs }, ...children);
    button.addEventListener('click', () => {
      dialog.close();
      open();
    });
    return button;
  };

  const render = () => {
    if (!lists) return;
    const { presets, lessons, presetText, lessonText } = lists;
    clear(list);
    const q = filter.value.trim().toLowerCase();
    const matches = (text: string) => !q || text.toLowerCase().includes(q);
    const shownLessons = part === 'scenarios' ? [] : lessons.filter((l) => matches(`lesson ${l.name} ${l.model} ${l.title} ${l.section} ${l.description}`));
    if (shownLessons.length) list.append(el('h3', { id: 'gallery-lessons', text: 'Lessons' }));
    for (const l of shownLessons) {
      list.append(
        card(
          { 'data-lesson': l.name, class: 'card lesson' },
          () => chooseLesson(l.name),
          pictures.canvas(l.name, lessonText[l.name], true),
          el('strong', { text: l.title }),
          el('span', { class: 'lesson-where', text: `${l.model} · ${l.section}` }),
          el('span', { text: l.paper }),
        ),
      );
    }
    const shown = part === 'lessons' ? [] : presets.filter((p) => matches(`${p.name} ${scenarioTitle(p.name) ?? ''} ${p.model} ${p.description}`));
    let model = '';
    for (const p of shown) {
      if (p.model !== model) {
        model = p.model;
        list.append(el('h3', { text: p.title || p.model }));
      }
      // Its title in words first, its code name (what the command line takes) beside it.
      list.append(
        card(
          { 'data-preset': p.name },
          () => choose(p.name),
          pictures.canvas(p.name, presetText[p.name], false),
          el('strong', { text: scenarioTitle(p.name) ?? p.name }),
          el('code', { class: 'card-code', text: p.name }),
          el('span', { class: 'card-about', text: p.description }),
        ),
      );
    }
    if (!shown.length && !shownLessons.length) list.append(el('p', { class: 'hint', text: 'No scenario matches.' }));
  };
  filter.addEventListener('input', render);
  const open = (shown: GalleryPart) =>
    void core.loadCatalogue().then(
      (catalogue) => {
        lists = catalogue;
        part = shown;
        byId('gallery-title').textContent = TITLES[shown];
        render();
        if (!dialog.open) dialog.showModal();
        filter.focus();
      },
      (e: unknown) => page.banner.report(`The scenarios could not be loaded: ${core.message(e)}`),
    );
  byId('open-gallery').addEventListener('click', () => open('all'));
  byId('open-scenarios').addEventListener('click', () => open('all'));
  byId('open-lessons').addEventListener('click', () => open('lessons'));
  byId('open-grade').addEventListener('click', () => {
    dialog.close();
    events.emit('open', { what: 'grade' });
  });
  events.on('open', ({ what, part }) => {
    if (what === 'gallery') open((part as GalleryPart | undefined) ?? 'all');
  });
}
