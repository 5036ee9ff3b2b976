// The gallery: the built-in lessons first (classroom exercises, each with its paper's section),
// then every built-in scenario grouped by model; one filter for both.
import type { LessonInfo, PresetInfo } from '../types';
import { byId, clear, el } from './dom';

export function setupGallery(presets: PresetInfo[], lessons: LessonInfo[], choose: (name: string) => void, chooseLesson: (name: string) => void) {
  const dialog = byId<HTMLDialogElement>('gallery');
  const list = byId('gallery-list');
  const filter = byId<HTMLInputElement>('gallery-filter');

  const card = (attrs: Record<string, string>, open: () => void, ...children: HTMLElement[]) => {
    const button = el('button', { type: 'button', class: 'card', ...attrs }, ...children);
    button.addEventListener('click', () => {
      dialog.close();
      open();
    });
    return button;
  };

  const render = () => {
    clear(list);
    const q = filter.value.trim().toLowerCase();
    const matches = (text: string) => !q || text.toLowerCase().includes(q);
    const shownLessons = lessons.filter((l) => matches(`lesson ${l.name} ${l.model} ${l.title} ${l.section} ${l.description}`));
    if (shownLessons.length) list.append(el('h3', { id: 'gallery-lessons', text: 'Lessons' }));
    for (const l of shownLessons) {
      list.append(
        card(
          { 'data-lesson': l.name, class: 'card lesson' },
          () => chooseLesson(l.name),
          el('strong', { text: l.title }),
          el('span', { class: 'lesson-where', text: `${l.model} · ${l.section}` }),
          el('span', { text: l.paper }),
        ),
      );
    }
    const shown = presets.filter((p) => matches(`${p.name} ${p.model} ${p.description}`));
    let model = '';
    for (const p of shown) {
      if (p.model !== model) {
        model = p.model;
        list.append(el('h3', { text: p.title || p.model }));
      }
      list.append(card({ 'data-preset': p.name }, () => choose(p.name), el('strong', { text: p.name }), el('span', { text: p.description })));
    }
    if (!shown.length && !shownLessons.length) list.append(el('p', { class: 'hint', text: 'No scenario matches.' }));
  };
  filter.addEventListener('input', render);
  byId('open-gallery').addEventListener('click', () => {
    render();
    dialog.showModal();
    filter.focus();
  });
}
