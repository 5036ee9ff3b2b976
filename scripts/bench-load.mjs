// The first load: time to interactive and the bytes sent before it, with a cold cache (a fresh
// browser context each load: no HTTP cache, no service worker, a first visit), median of LOADS
// loads, on two profiles: loopback, and a classroom laptop on school wifi (Chromium's own
// throttling over CDP: 1.6 Mbps down, 750 kbps up, 150 ms round trip, the CPU slowed 4x; the
// figures of Lighthouse's mobile profile). Interactive is the page's own mark,
// body[data-ready="true"]: its first frame has been drawn, and the transport (Play) is mounted on
// a loaded run. After each load the bench checks, untimed, that Play then runs the scenario.
// The page is served by `npm start`'s server (scripts/serve.mjs: precompressed files, the host's
// headers) behind a counting relay: the bytes are what the server sent on the wire (headers and
// bodies) from the navigation to interactive, whoever asked for them (the page, its workers, the
// service worker). The budget for them is scripts/budget.mjs's.
// Usage: node scripts/bench-load.mjs [--url http://host:port/]   (another server, for comparison)
import { createConnection, createServer } from 'node:net';
import { fileURLToPath } from 'node:url';
import { launch } from '../tests/e2e/harness.mjs';
import { LOAD_BUDGET_KB, loadVerdict } from './budget.mjs';
import { serveDist } from './serve.mjs';

export const LOADS = 5;
export const PROFILES = [
  { name: 'loopback', network: null, cpu: 1, goalMs: 1000 },
  {
    name: 'classroom',
    network: { offline: false, latency: 150, downloadThroughput: (1.6e6 / 8) | 0, uploadThroughput: (750e3 / 8) | 0 },
    cpu: 4,
    goalMs: 3500,
  },
];

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

/**
 * A TCP relay in front of `target` (host, port) that counts the bytes the server sends and the
 * requests it is asked (their first lines). Resolves to { url, sent(), requests(), close }.
 */
function countingRelay(target) {
  let sent = 0;
  const requests = [];
  const sockets = new Set();
  const relay = createServer((client) => {
    const upstream = createConnection(target);
    sockets.add(client).add(upstream);
    client.on('data', (chunk) => {
      for (const m of chunk.toString('latin1').matchAll(/^(GET|HEAD) (\S+) HTTP/gm)) requests.push({ path: m[2], at: sent });
      upstream.write(chunk);
    });
    upstream.on('data', (chunk) => {
      sent += chunk.length;
      client.write(chunk);
    });
    const end = () => {
      client.destroy();
      upstream.destroy();
      sockets.delete(client);
      sockets.delete(upstream);
    };
    client.on('close', end).on('error', end);
    upstream.on('close', end).on('error', end);
  });
  return new Promise((resolve) => {
    relay.listen(0, '127.0.0.1', () => {
      resolve({
        url: `http://127.0.0.1:${relay.address().port}/`,
        sent: () => sent,
        requests: () => requests.splice(0),
        reset: () => {
          sent = 0;
          requests.length = 0;
        },
        close: () => {
          for (const s of sockets) s.destroy();
          return new Promise((r) => relay.close(r));
        },
      });
    });
  });
}

/** One cold load on `profile`: { ms, bytes, files } at interactive. */
async function coldLoad(browser, relay, profile) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  try {
    const page = await context.newPage();
    const cdp = await context.newCDPSession(page);
    await cdp.send('Network.enable');
    if (profile.network) await cdp.send('Network.emulateNetworkConditions', profile.network);
    if (profile.cpu !== 1) await cdp.send('Emulation.setCPUThrottlingRate', { rate: profile.cpu });
    let atReady = null;
    // The moment the page marks itself ready: its own clock from the navigation, and the bytes so far.
    await page.exposeBinding('__kumikiReady', (_source, ms) => {
      atReady ??= { ms, bytes: relay.sent(), files: relay.requests() };
    });
    await page.addInitScript(() => {
      new MutationObserver((_, observer) => {
        if (document.body?.dataset.ready === 'true') {
          observer.disconnect();
          window.__kumikiReady(performance.now());
        }
      }).observe(document, { attributes: true, subtree: true, attributeFilter: ['data-ready'] });
    });
    relay.reset();
    await page.goto(relay.url);
    await page.waitForSelector('body[data-ready="true"]', { timeout: 120000 });
    for (let i = 0; i < 50 && !atReady; i++) await page.waitForTimeout(10);
    if (!atReady) throw new Error('the page marked itself ready but the bench never heard of it');
    // Untimed: Play then runs the scenario (past the welcome of a first visit, if it opened).
    if (await page.isVisible('#welcome')) await page.click('#welcome-skip');
    await page.click('#play');
    await page.waitForFunction(() => Number(document.querySelector('#step-count')?.textContent?.replace(/,/g, '')) > 0, null, { timeout: 60000 });
    return atReady;
  } finally {
    await context.close();
  }
}

/** Loads the page LOADS times cold on each profile from `url` (default: `npm start`'s server on dist/). */
export async function benchLoad({ url } = {}) {
  const server = url ? null : await serveDist({ port: 0, host: '127.0.0.1' });
  const target = new URL(url ?? server.url);
  const relay = await countingRelay({ host: target.hostname, port: Number(target.port || 80) });
  const browser = await launch();
  try {
    const profiles = [];
    for (const profile of PROFILES) {
      const loads = [];
      for (let i = 0; i < LOADS; i++) loads.push(await coldLoad(browser, relay, profile));
      const ms = median(loads.map((l) => l.ms));
      const bytes = median(loads.map((l) => l.bytes));
      profiles.push({ name: profile.name, goalMs: profile.goalMs, loads, ms, bytes, files: loads.at(-1).files.map((f) => f.path) });
    }
    return { profiles };
  } finally {
    await browser.close();
    await relay.close();
    await server?.close();
  }
}

/** Prints the load's figures; false when the bytes before interactive are over their budget. */
export function printLoad({ profiles }) {
  let within = true;
  for (const p of profiles) {
    const kb = p.bytes / 1024;
    const each = p.loads.map((l) => l.ms.toFixed(0)).join(', ');
    console.log(
      `first load, ${p.name}: interactive in ${p.ms.toFixed(0)} ms (median of ${p.loads.length}: ${each}; goal ${p.goalMs} ms: ` +
        `${p.ms <= p.goalMs ? 'met' : 'missed'}), ${kb.toFixed(1)} KB sent before it (budget ${LOAD_BUDGET_KB} KB: ${loadVerdict(kb)})`,
    );
    if (kb > LOAD_BUDGET_KB) within = false;
  }
  const files = profiles[0]?.files ?? [];
  console.log(`  fetched before interactive: ${files.join(' ')}`);
  return within;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const i = process.argv.indexOf('--url');
  const result = await benchLoad({ url: i > 0 ? process.argv[i + 1] : undefined });
  if (!printLoad(result)) process.exitCode = 1;
}
