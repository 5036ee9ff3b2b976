// The first screen and the tour: what Kumiki is and the ways in, shown on a first visit and by
// "Start here".
import type { Feature } from '../../page/context';
import { setupWelcome } from './welcome';

export const welcome: Feature = {
  name: 'welcome',
  mount: setupWelcome,
};
