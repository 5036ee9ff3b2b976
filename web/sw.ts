// Kumiki's service worker: after one visit the page, its code and its wasm open offline.
// The build (vite.pwa.ts) writes the list of the built files and a version made from them into
// this file; a new build is a new version, which installs beside the old one and takes over when
// the page accepts it ("A new version is ready — reload") or when every Kumiki tab has closed.
// Hashed assets never change under their name: cache first. The page itself (index.html) may:
// network first, the cached copy when offline.

const sw = self as unknown as ServiceWorkerGlobalScope;
/** Filled in by the build: the files to keep, relative to this script, and their version. */
const PRECACHE: { version: string; files: string[] } = JSON.parse('__KUMIKI_PRECACHE__');
const CACHE = `kumiki-${PRECACHE.version}`;
const PAGE = new URL('./', sw.location.href).href;

sw.addEventListener('install', (event) => {
  event.waitUntil(
    caches.open(CACHE).then((cache) =>
      // The page is stored under its directory URL, the one a visitor opens.
      cache.addAll(PRECACHE.files.map((f) => new URL(f === 'index.html' ? './' : f, sw.location.href).href)),
    ),
  );
});

sw.addEventListener('activate', (event) => {
  event.waitUntil(
    (async () => {
      for (const name of await caches.keys()) if (name.startsWith('kumiki-') && name !== CACHE) await caches.delete(name);
      await sw.clients.claim();
    })(),
  );
});

sw.addEventListener('message', (event) => {
  // The page's "reload" on the new-version notice.
  if (event.data && typeof event.data === 'object' && (event.data as { type?: unknown }).type === 'skip-waiting') void sw.skipWaiting();
});

/** The page: from the network when it answers (and the host is not failing), else the copy kept. */
async function pageFirstFromNetwork(request: Request): Promise<Response> {
  const cache = await caches.open(CACHE);
  let response: Response | null = null;
  try {
    response = await fetch(request);
  } catch {
    // Offline: the kept copy below.
  }
  if (response?.ok) {
    await cache.put(PAGE, response.clone());
    return response;
  }
  const kept = await cache.match(PAGE, { ignoreVary: true });
  return kept ?? response ?? Response.error();
}

/**
 * Anything else of the build: the kept copy, else the network. `ignoreVary`: a server that
 * answers `Vary: Origin` (vite preview, which `npm start` ran before it served dist/ itself) would
 * otherwise make every kept file miss, because the page's module scripts and styles load with `crossorigin` (an Origin
 * header) while the install stored them without one; the outage then left an unstyled page.
 */
async function keptFirst(request: Request): Promise<Response> {
  const kept = await caches.match(request, { cacheName: CACHE, ignoreSearch: true, ignoreVary: true });
  return kept ?? fetch(request);
}

sw.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET') return;
  const url = new URL(request.url);
  if (url.origin !== sw.location.origin || !url.href.startsWith(PAGE)) return;
  if (request.mode === 'navigate' || url.href === PAGE || url.href === `${PAGE}index.html`) {
    event.respondWith(pageFirstFromNetwork(request));
    return;
  }
  event.respondWith(keptFirst(request));
});
