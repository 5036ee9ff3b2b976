// The reproduction report in the page: the About tab's claims of the model's paper beside Kumiki's
// figures, each re-run here on demand, and `#claim=ID` links to one.
import type { Feature } from '../../page/context';
import { setupReproduction } from './reproduction';

export const reproduction: Feature = {
  name: 'reproduction',
  mount: setupReproduction,
};
