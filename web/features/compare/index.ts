// Two runs side by side, differing in one setting: the second run's worker and view, paired with
// the first run's, and the Run tab's controls that choose the setting.
import type { Feature } from '../../page/context';
import { setupCompare } from './compare';

export const compare: Feature = {
  name: 'compare',
  mount: setupCompare,
};
