// The gallery: the built-in lessons and scenarios, filtered, each opened with a click; the top's
// Lessons, Gallery and scenario name open it.
import type { Feature } from '../../page/context';
import { setupGallery } from './gallery';

export const gallery: Feature = {
  name: 'gallery',
  mount: setupGallery,
};
