// CHOBIE II: the side view painted in two aligned layers, robots and terrain (ground and cliff),
// which the core's `layers` query splits the world text into and its `merge` query merges back
// ('#' robot, '=' terrain, '.' empty); and the crawl forms of figure 7 drawn for any odd number of
// robots by the core's `crawl` query. Loads are placed during a run with the page's load tools;
// the generic panels show the mode, the leaders, the signals of each slot and the stress field.
import { clear, el } from '../widgets/dom';
import { message, modelQuery } from '../wasm';
import type { ModelEditor } from '../editors/editor';
import { GridEditor } from '../editors/grid/editor';

const MAX_PAINTED = 200;

/** The world text's robots and its terrain, each as a square shape. */
const layers = (world: string) => modelQuery<{ robots: string; terrain: string }>('chobie', 'layers', { world });

export const editor: ModelEditor = {
  title: 'World: robots and terrain',
  owns: ['world'],
  mount(root, ctx) {
    let world = String(ctx.scenario().world ?? '');
    let { robots, terrain } = layers(world);
    const note = el('p', {
      class: 'hint',
      text: 'Both layers are aligned at the top-left corner; gravity points down. A robot must rest on terrain, and the robots must form one piece.',
    });
    const error = el('p', { id: 'chobie-world-error', class: 'error', role: 'status', 'aria-live': 'polite' });
    const apply = async (): Promise<string | null> => {
      let problem: string | null;
      try {
        problem = await ctx.change({ world: modelQuery<{ world: string }>('chobie', 'merge', { robots, terrain }).world });
      } catch (e) {
        // Both layers paint one cell.
        problem = message(e);
      }
      error.textContent = problem ?? '';
      return problem;
    };
    const robotBox = el('div');
    const terrainBox = el('div');

    // The crawl forms of figure 7, reconstructed (see crate/models/chobie/README.md).
    const count = el('input', {
      type: 'number',
      min: 3,
      max: 199,
      step: 2,
      value: 7,
      id: 'chobie-crawl-robots',
      'aria-label': 'Number of robots in the crawl form (odd)',
    });
    const form = el('select', { id: 'chobie-crawl-form', 'aria-label': 'Crawl form' });
    for (const f of [1, 2, 3, 4]) form.append(el('option', { value: String(f), text: `form ${f}` }));
    const draw = el('button', { type: 'button', text: 'Draw crawl form', title: 'Replace the world by the chosen crawl form' });
    draw.addEventListener('click', () => {
      try {
        const answer = modelQuery<{ world: string }>('chobie', 'crawl', { robots: Number(count.value), form: Number(form.value), margin: 12 });
        void ctx.change({ world: answer.world }).then((problem) => (error.textContent = problem ?? ''));
      } catch (e) {
        error.textContent = message(e);
      }
    });

    root.append(
      note,
      el('div', { class: 'row-buttons' }, el('label', {}, 'Robots ', count), form, draw),
      el('h4', { text: 'Robots' }),
      robotBox,
      el('h4', { text: 'Terrain (ground and cliff)' }),
      terrainBox,
      error,
    );
    const robotEditor = new GridEditor(robotBox, {
      lattice: 'square',
      label: 'CHOBIE robots',
      text: robots,
      apply: (text) => {
        robots = text;
        return apply();
      },
      maxSide: MAX_PAINTED,
    });
    const terrainEditor = new GridEditor(terrainBox, {
      lattice: 'square',
      label: 'CHOBIE terrain',
      text: terrain,
      apply: (text) => {
        terrain = text;
        return apply();
      },
      maxSide: MAX_PAINTED,
    });

    return {
      update(scenario) {
        const next = String(scenario.world ?? '');
        if (next === world) return;
        world = next;
        ({ robots, terrain } = layers(world));
        robotEditor.setText(robots);
        terrainEditor.setText(terrain);
        error.textContent = '';
      },
      destroy() {
        robotEditor.destroy();
        terrainEditor.destroy();
        clear(root);
      },
    };
  },
};

/** Its built-in scenarios' titles in words, by code name (the gallery and the page's header show both). */
export const titles: Record<string, string> = {
  'chobie-bridge': 'A bridge over a cliff, adapting to its load',
  'chobie-crawl3': 'Crawling with 3 robots',
  'chobie-crawl5': 'Crawling with 5 robots',
  'chobie-crawl7': 'Crawling with 7 robots',
  'chobie-crawl9': 'Crawling with 9 robots',
  'chobie-fig13': 'A load overloads the bridge (figure 13)',
  'chobie-form-a': 'Electing a leader: form (a)',
  'chobie-form-b': 'Electing a leader: form (b), a lone row',
  'chobie-form-c': 'Electing a leader: form (c), a block',
  'chobie-form-d': 'Electing a leader: form (d), two leaders',
  'chobie-load5': 'Load adaptation with five robots (figure 14)',
};
