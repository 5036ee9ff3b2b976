// Offline use: after one visit the built site opens without the network, and a new version is
// offered when one has installed.
import type { Feature } from '../../page/context';
import { registerOffline } from './offline';

export const offline: Feature = {
  name: 'offline',
  mount({ banner }) {
    registerOffline((reload) => {
      banner.keep = true;
      banner.report('A new version of Kumiki is ready.', { label: 'Reload', run: reload });
    });
  },
};
