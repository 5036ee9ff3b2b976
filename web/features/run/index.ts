// Running the scenario in view: the transport under the view (play, step, reset, speed, timeline,
// seed) with its keys, and the Run tab with the metrics, the chart, the overlays and the legend.
import type { Feature } from '../../page/context';
import { setupRunPanel } from './run';
import { setupTransport } from './transport';

export const run: Feature = {
  name: 'run',
  tab: 'Run',
  mount(page) {
    setupTransport(page);
    setupRunPanel(page);
  },
};
