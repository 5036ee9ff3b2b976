// Offline use: after one visit the built site opens without the network, and a new version is
// offered when one has installed. The service worker is registered only once the page is
// interactive (its first frame drawn) and idle: on a first visit its install fetches every file of
// the build (the lab and rules modules, the rule editor), which must not compete with the first frame.
import type { Feature } from '../../page/context';
import { whenIdle } from '../../widgets/idle';
import { registerOffline } from './offline';

/** The longest the registration waits for an idle moment (a page kept busy still gets its worker). */
const IDLE_TIMEOUT_MS = 10000;

export const offline: Feature = {
  name: 'offline',
  mount({ banner, session }) {
    let asked = false;
    session.on('frame', () => {
      if (asked) return;
      asked = true;
      whenIdle(
        () =>
          registerOffline((reload) => {
            banner.keep = true;
            banner.report('A new version of Kumiki is ready.', { label: 'Reload', run: reload });
          }),
        IDLE_TIMEOUT_MS,
      );
    });
  },
};
