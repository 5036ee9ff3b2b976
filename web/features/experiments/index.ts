// Experiments (sweeps): the Experiments tab runs a built-in experiment, or one edited, shared by
// link or file, on a pool of workers, draws its figures and exports its rows.
import type { Feature } from '../../page/context';
import { setupExperiments } from './experiments';

export const experiments: Feature = {
  name: 'experiments',
  tab: 'Experiments',
  mount: setupExperiments,
};
