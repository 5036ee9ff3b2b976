// Offline use: registers the service worker of the built site (web/sw.ts) and offers a new version
// when one has installed. The dev server has no service worker: there, any left by a build on the
// same address is removed.

/**
 * Registers the service worker. When a new version has installed beside the running one,
 * `offer(reload)` is called; `reload()` lets the new version take over and reloads the page.
 * Without that, the new version takes over once every Kumiki tab has closed.
 */
export function registerOffline(offer: (reload: () => void) => void) {
  if (!('serviceWorker' in navigator) || !/^https?:$/.test(location.protocol)) return;
  const container = navigator.serviceWorker;
  if (!import.meta.env.PROD) {
    // The dev server may run on the address where a built Kumiki (npm start) left its worker:
    // it must not sit between the dev server and the page.
    void container.getRegistrations().then((all) => Promise.all(all.map((r) => r.unregister())));
    return;
  }
  let accepted = false;
  container.addEventListener('controllerchange', () => {
    // The first visit's worker takes control without a reload; a new version reloads the page
    // that accepted it.
    if (accepted) location.reload();
  });
  const offerIfNew = (worker: ServiceWorker) => {
    if (!container.controller) return;
    offer(() => {
      accepted = true;
      worker.postMessage({ type: 'skip-waiting' });
    });
  };
  container
    .register('./sw.js')
    .then((registration) => {
      if (registration.waiting) offerIfNew(registration.waiting);
      registration.addEventListener('updatefound', () => {
        const worker = registration.installing;
        worker?.addEventListener('statechange', () => {
          if (worker.state === 'installed') offerIfNew(worker);
        });
      });
    })
    .catch((e: unknown) => console.warn(`Kumiki will not work offline: ${e instanceof Error ? e.message : String(e)}`));
}
