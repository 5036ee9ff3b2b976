// Kumiki in a course page's iframe (`?embed`): the postMessage API that drives it.
import type { Feature } from '../../page/context';
import { setupEmbed } from './embed';

export const embed: Feature = {
  name: 'embed',
  mount(page) {
    if (page.embedded) setupEmbed(page);
  },
};
