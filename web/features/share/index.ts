// Sharing a scenario: Copy link puts the whole scenario in the address, and a link opened here
// introduces its scenario before it runs.
import type { Feature } from '../../page/context';
import { setupShare } from './share';

export const share: Feature = {
  name: 'share',
  mount: setupShare,
};
