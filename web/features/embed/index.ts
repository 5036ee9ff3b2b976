// Kumiki in a course page's iframe (`?embed`): the postMessage API that drives it.
import type { Feature, PageContext } from '../../page/context';
import * as core from '../../wasm';
import { Embed } from './embed';

/** Takes the host's commands in a course page's frame (`?embed`), and tells it what happens. */
function setupEmbed(page: PageContext) {
  const { session, sim, events } = page;
  const embed = new Embed(
    {
      async load(payload) {
        try {
          let problem: string | null = null;
          await session.open(core.unpackLink(payload).scenario, { opens: true, onProblem: (brief) => (problem = brief) });
          return problem;
        } catch (e) {
          return core.message(e);
        }
      },
      play: () => sim.play(),
      pause: () => sim.pause(),
      step: (count) => sim.step(count),
      reset: () => session.reset(),
      check: () => sim.check(),
    },
    core.version(),
  );
  session.on('frame', (frame) => embed.frame(frame));
  events.on('goal', ({ met, because, steps }) => embed.goal(met, because, steps));
  events.on('handin', ({ link, name }) => embed.handin(link, name));
}

export const embed: Feature = {
  name: 'embed',
  mount(page) {
    if (page.embedded) setupEmbed(page);
  },
};
