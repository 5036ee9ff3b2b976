// Experiments (sweeps): the Experiments tab runs a built-in experiment, or one edited, shared by
// link or file, on a pool of workers, draws its figures and exports its rows.
// Not on the first screen: its code comes after the first frame.
import type { Feature } from '../../page/context';

/**
 * The address as the page opened it, read as this list is: an experiment's link (`#x1.…`) is
 * opened when the feature mounts, after the first scenario has opened and taken the address.
 */
const address = location.hash;

export const experiments: Feature = {
  name: 'experiments',
  tab: 'Experiments',
  later: true,
  mount: async (page) => (await import('./experiments')).setupExperiments(page, address),
};
