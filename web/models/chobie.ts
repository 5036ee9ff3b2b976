// CHOBIE II: the side view painted in two aligned layers, robots and terrain (ground and cliff),
// merged into the world text the core reads ('#' robot, '=' terrain, '.' empty); and the crawl
// forms of figure 7 drawn for any odd number of robots by the core's `crawl` query. Loads are
// placed during a run with the page's load tools; the generic panels show the mode, the
// leaders, the signals of each slot and the stress field.
import { clear, el } from '../ui/dom';
import { message, query } from '../wasm';
import type { ModelEditor } from './editor';
import { GridEditor } from './grid-editor';

const MAX_PAINTED = 200;

/** One layer of the world text as a square shape: `mark` becomes '#', everything else '.'. */
function layer(world: string, mark: string): string {
  return world
    .split('\n')
    .filter((line, i, all) => line.length > 0 || i < all.length - 1)
    .map((line) => [...line].map((c) => (c === mark ? '#' : '.')).join(''))
    .join('\n');
}

/** Merges the two layers (aligned at the top-left) into world text, or says where they clash. */
function merge(robots: string, terrain: string): { world: string } | { problem: string } {
  const r = robots.split('\n');
  const t = terrain.split('\n');
  const rows: string[] = [];
  for (let y = 0; y < Math.max(r.length, t.length); y++) {
    const a = r[y] ?? '';
    const b = t[y] ?? '';
    let row = '';
    for (let x = 0; x < Math.max(a.length, b.length); x++) {
      const robot = a[x] === '#';
      const ground = b[x] === '#';
      if (robot && ground) return { problem: `row ${y + 1}, column ${x + 1} is both a robot and terrain` };
      row += robot ? '#' : ground ? '=' : '.';
    }
    rows.push(row);
  }
  return { world: `${rows.join('\n').replace(/\n+$/, '')}\n` };
}

export const editor: ModelEditor = {
  title: 'World: robots and terrain',
  owns: ['world'],
  mount(root, ctx) {
    let world = String(ctx.scenario().world ?? '');
    let robots = layer(world, '#');
    let terrain = layer(world, '=');
    const note = el('p', {
      class: 'hint',
      text: 'Both layers are aligned at the top-left corner; gravity points down. A robot must rest on terrain, and the robots must form one piece.',
    });
    const error = el('p', { id: 'chobie-world-error', class: 'error', role: 'status', 'aria-live': 'polite' });
    const apply = (): string | null => {
      const merged = merge(robots, terrain);
      const problem = 'problem' in merged ? merged.problem : ctx.change({ world: merged.world });
      error.textContent = problem ?? '';
      return problem;
    };
    const robotBox = el('div');
    const terrainBox = el('div');

    // The crawl forms of figure 7, reconstructed (see docs/models/chobie.md).
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
        const answer = query<{ world: string }>('chobie', 'crawl', { robots: Number(count.value), form: Number(form.value), margin: 12 });
        error.textContent = ctx.change({ world: answer.world }) ?? '';
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
        robots = layer(world, '#');
        terrain = layer(world, '=');
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
