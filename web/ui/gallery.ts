// The preset gallery: every built-in scenario, grouped by model, filterable.
import type { PresetInfo } from '../types';
import { byId, clear, el } from './dom';

export function setupGallery(presets: PresetInfo[], choose: (name: string) => void) {
  const dialog = byId<HTMLDialogElement>('gallery');
  const list = byId('gallery-list');
  const filter = byId<HTMLInputElement>('gallery-filter');

  const render = () => {
    clear(list);
    const q = filter.value.trim().toLowerCase();
    const shown = presets.filter((p) => !q || `${p.name} ${p.model} ${p.description}`.toLowerCase().includes(q));
    let model = '';
    for (const p of shown) {
      if (p.model !== model) {
        model = p.model;
        list.append(el('h3', { text: p.title || p.model }));
      }
      const card = el('button', { type: 'button', class: 'card', 'data-preset': p.name }, el('strong', { text: p.name }), el('span', { text: p.description }));
      card.addEventListener('click', () => {
        dialog.close();
        choose(p.name);
      });
      list.append(card);
    }
    if (!shown.length) list.append(el('p', { class: 'hint', text: 'No scenario matches.' }));
  };
  filter.addEventListener('input', render);
  byId('open-gallery').addEventListener('click', () => {
    render();
    dialog.showModal();
    filter.focus();
  });
}
