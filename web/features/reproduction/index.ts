// The reproduction report in the page: the About tab's claims of the model's paper beside Kumiki's
// figures, each re-run here on demand, and `#claim=ID` links to one.
// Not on the first screen: its code comes after the first frame.
import type { Feature } from '../../page/context';

export const reproduction: Feature = {
  name: 'reproduction',
  later: true,
  mount: async (page) => (await import('./reproduction')).setupReproduction(page),
};
