// Experiments (sweeps): the Experiments tab runs a built-in experiment, or one edited, shared by
// link or file, on a pool of workers, draws its figures and exports its rows.
// Not on the first screen: its code comes after the first frame.
import type { Feature } from '../../page/context';

export const experiments: Feature = {
  name: 'experiments',
  tab: 'Experiments',
  later: true,
  mount: async (page) => (await import('./experiments')).setupExperiments(page),
};
