// The server `npm start` runs (and `npm run bench` measures the first load against): dist/ as a
// static host serves it, with the headers of dist/_headers (the Content-Security-Policy with
// frame-ancestors, nosniff, no referrer) and each file's precompressed sibling (.br, else .gz,
// written by the build: vite.compress.ts) when the browser accepts it. Hashed assets are kept a
// year (their name changes with their content); the page, the service worker and the manifest
// are revalidated on every visit.
// Usage: node scripts/serve.mjs [--port 8080] [--host localhost]
import { createServer } from 'node:http';
import { createReadStream, readFileSync } from 'node:fs';
import { stat } from 'node:fs/promises';
import { extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';

export const DIST = fileURLToPath(new URL('../dist/', import.meta.url));
/** The content type of each file the build writes, by extension (the browser tests' server sends the same). */
export const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.wasm': 'application/wasm',
  '.svg': 'image/svg+xml',
  '.json': 'application/json',
  '.png': 'image/png',
  '.webmanifest': 'application/manifest+json',
};
/** The encodings the build writes beside a file, best first. */
const ENCODINGS = [
  { name: 'br', ext: '.br' },
  { name: 'gzip', ext: '.gz' },
];

/** The headers a static host sends with every file, from the build's dist/_headers. */
export function hostHeaders(root = DIST) {
  const out = {};
  for (const line of readFileSync(join(root, '_headers'), 'utf8').split('\n')) {
    const m = /^\s+([\w-]+): (.+)$/.exec(line);
    if (m) out[m[1].toLowerCase()] = m[2];
  }
  return out;
}

/** The encodings an Accept-Encoding header allows (q=0 refuses one). */
function accepted(header = '') {
  const ok = new Set();
  for (const part of header.split(',')) {
    const [name, ...params] = part.trim().toLowerCase().split(';');
    const q = params.map((p) => /^\s*q=([\d.]+)/.exec(p)).find(Boolean);
    if (name && (!q || Number(q[1]) > 0)) ok.add(name);
  }
  return ok;
}

/** A file's path, size and validator (ETag), or null when there is no such file. */
async function fileAt(path) {
  try {
    const info = await stat(path);
    if (info.isFile()) return { path, size: info.size, etag: `"${info.size.toString(36)}-${Math.round(info.mtimeMs).toString(36)}"` };
  } catch {
    // Missing, or a directory: the caller tries the next candidate.
  }
  return null;
}

/** The request handler serving `root`. */
export function handler(root = DIST) {
  const headers = hostHeaders(root);
  return async (req, res) => {
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      res.writeHead(405, { allow: 'GET, HEAD' }).end();
      return;
    }
    let rel = normalize(decodeURIComponent(new URL(req.url, 'http://x').pathname)).replace(/^([/\\]|\.\.[/\\])+/, '');
    if (rel === '' || rel === '.' || rel.endsWith('/')) rel = join(rel, 'index.html');
    const file = join(root, rel);
    if (!file.startsWith(root)) {
      res.writeHead(404).end('not found');
      return;
    }
    const ok = accepted(req.headers['accept-encoding']);
    let found = null;
    let encoding = null;
    for (const e of ENCODINGS) {
      if (!ok.has(e.name)) continue;
      found = await fileAt(file + e.ext);
      if (found) {
        encoding = e.name;
        break;
      }
    }
    found ??= await fileAt(file);
    if (!found) {
      res.writeHead(404, { 'content-type': 'text/plain; charset=utf-8' }).end('not found');
      return;
    }
    const hashed = rel.startsWith('assets/') || rel.startsWith('icons/');
    const common = {
      ...headers,
      'cache-control': hashed ? 'public, max-age=31536000, immutable' : 'no-cache',
      vary: 'Accept-Encoding',
      etag: found.etag,
    };
    // A revalidation (the page, the service worker) of an unchanged file: no body.
    if (req.headers['if-none-match'] === found.etag) {
      res.writeHead(304, common).end();
      return;
    }
    res.writeHead(200, {
      ...common,
      'content-type': TYPES[extname(file)] ?? 'application/octet-stream',
      'content-length': found.size,
      ...(encoding ? { 'content-encoding': encoding } : {}),
    });
    if (req.method === 'HEAD') {
      res.end();
      return;
    }
    const stream = createReadStream(found.path);
    stream.on('error', () => res.destroy());
    // A browser that goes away mid-file (a closed tab) leaves the file to close here.
    res.on('close', () => stream.destroy());
    stream.pipe(res);
  };
}

/** Serves `root` on `host`:`port` (0: any free port). Resolves to { url, port, close }. */
export function serveDist({ root = DIST, port = 8080, host = 'localhost' } = {}) {
  const server = createServer(handler(root));
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => {
      const bound = server.address().port;
      resolve({ url: `http://${host}:${bound}/`, port: bound, close: () => new Promise((r) => server.close(r)) });
    });
  });
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const arg = (name, fallback) => {
    const i = process.argv.indexOf(name);
    return i > 0 ? process.argv[i + 1] : fallback;
  };
  const { url } = await serveDist({ port: Number(arg('--port', 8080)), host: arg('--host', 'localhost') });
  console.log(`Kumiki is running at ${url}  (Ctrl+C to stop)`);
}
