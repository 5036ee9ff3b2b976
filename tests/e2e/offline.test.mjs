// Offline use: the built site is an installable app (a manifest with icons) whose service worker
// keeps the page, its code and its wasm. It registers once the first visit is interactive and idle,
// so what it keeps (the lab and rules modules, the rule editor) never competes with the first frame.
// After one visit the page opens and runs with the network off; a new deployment installs beside the running version, is offered ("A new version of Kumiki
// is ready"), and takes over when accepted.
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { after, before, describe, test } from 'node:test';
import { launch, loadWasm, serve, stepCount, waitForSteps } from './harness.mjs';

const wasm = loadWasm();
/** What the test host serves: the build as it is, a newer build, or nothing (the network is down). */
let host = 'up';
/** The paths the test host has served, in order. */
const served = [];
let server;
let browser;
before(async () => {
  server = await serve('/', {
    rewrite: (path, body) => {
      served.push(path);
      if (host === 'down') return null;
      // A new deployment: the same files under a new service-worker version.
      if (host === 'newer' && path === 'sw.js') return Buffer.from(body.toString().replace(/\\"version\\":\\"([0-9a-f]+)\\"/, '\\"version\\":\\"$1-next\\"'));
      return body;
    },
  });
  browser = await launch();
});
after(async () => {
  await browser?.close();
  await server?.close();
});

/** A first visit: the page opens and its service worker has kept the build and taken control. */
async function visit(url = server.url) {
  host = 'up';
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
  // A first visit (no link) opens with the welcome, which may come just after the page is ready;
  // skipping it is remembered, so the reloads below open straight onto the run.
  await page.waitForSelector('#welcome[open]', { timeout: 30000 });
  await page.click('#welcome-skip');
  await page.waitForSelector('#welcome', { state: 'hidden' });
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null, null, { timeout: 30000 });
  return { context, page, problems };
}

const cached = (page) =>
  page.evaluate(async () => {
    const out = {};
    for (const name of await caches.keys()) out[name] = (await (await caches.open(name)).keys()).map((r) => new URL(r.url).pathname);
    return out;
  });

describe('offline', () => {
  test('a first visit asks for nothing but what its first frame needs before it is interactive; the worker keeps the rest after', async () => {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    const page = await context.newPage();
    let atReady = null;
    await page.exposeBinding('markReady', () => {
      atReady ??= served.length;
    });
    await page.addInitScript(() => {
      new MutationObserver((_, observer) => {
        if (document.body?.dataset.ready !== 'true') return;
        observer.disconnect();
        window.markReady();
      }).observe(document, { attributes: true, subtree: true, attributeFilter: ['data-ready'] });
    });
    served.length = 0;
    await page.goto(server.url);
    await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
    await page.waitForFunction(() => navigator.serviceWorker.controller !== null, null, { timeout: 30000 });
    assert.ok(atReady !== null);
    const before = served.slice(0, atReady);
    const later = /sw\.js|kumiki_lab|kumiki_wasm_rules|editor-|experiment-worker|picture-worker/;
    assert.deepEqual(
      before.filter((p) => later.test(p)),
      [],
      `asked before interactive: ${before.join(' ')}`,
    );
    assert.ok(
      before.some((p) => /kumiki_wasm_bg-.*\.wasm$/.test(p)),
      'the page wasm module is part of the first load',
    );
    const kept = Object.values(await cached(page)).flat();
    for (const part of ['kumiki_lab_bg', 'kumiki_wasm_rules_bg', 'editor-'])
      assert.ok(
        kept.some((p) => p.includes(part)),
        `${part} is kept once the page is idle`,
      );
    await context.close();
  });

  test('the manifest names the app and its icons, and every icon is served', async () => {
    const manifest = await (await fetch(`${server.url}manifest.webmanifest`)).json();
    assert.equal(manifest.short_name, 'Kumiki');
    assert.equal(manifest.start_url, './');
    assert.equal(manifest.display, 'standalone');
    const sizes = manifest.icons.map((i) => i.sizes);
    assert.ok(sizes.includes('192x192') && sizes.includes('512x512'));
    assert.ok(manifest.icons.some((i) => i.purpose === 'maskable'));
    for (const icon of manifest.icons) {
      const res = await fetch(new URL(icon.src, server.url));
      assert.equal(res.status, 200, icon.src);
      const bytes = Buffer.from(await res.arrayBuffer());
      assert.equal(bytes.toString('latin1', 1, 4), 'PNG');
      assert.equal(`${bytes.readUInt32BE(16)}x${bytes.readUInt32BE(20)}`, icon.sizes);
    }
    const page = await (await fetch(server.url)).text();
    assert.match(page, /<link rel="manifest" href="\.\/manifest\.webmanifest">/);
  });

  test('after one visit the page opens and runs a preset with the network off', async () => {
    const { context, page, problems } = await visit();
    const kept = Object.values(await cached(page)).flat();
    assert.ok(
      kept.some((p) => p.endsWith('.wasm')),
      'the wasm is kept',
    );
    assert.ok(kept.includes('/'), 'the page is kept');
    assert.ok(kept.includes('/manifest.webmanifest'));

    host = 'down';
    await context.setOffline(true);
    await page.reload();
    await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
    await page.click('#step');
    await waitForSteps(page, 1);
    await page.click('#play');
    await waitForSteps(page, 20);
    await page.click('#play');
    assert.ok((await stepCount(page)) >= 20);

    // Another preset, through a link and with ?embed: the same kept page, the 3-D renderer.
    const link = wasm.encode_link(wasm.preset_json('cubes-cube8-ladder'));
    await page.goto(`${server.url}?embed#${link}`);
    await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
    assert.equal(
      await page.textContent('#state-hash'),
      (() => {
        const sim = new wasm.Sim(wasm.decode_link(link));
        const hash = sim.hash();
        sim.free();
        return hash;
      })(),
    );
    await page.click('#step');
    await waitForSteps(page, 1);
    assert.deepEqual(problems, []);
    await context.close();
  });

  /** The server stops (an outage, not the browser's offline switch): a reload opens the kept copy and runs. */
  async function survivesOutage(url, stop) {
    const { context, page, problems } = await visit(url);
    await stop();
    const failed = [];
    page.on('requestfailed', (r) => failed.push(r.url()));
    await page.reload();
    await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
    assert.notEqual(await page.$eval('.top', (e) => getComputedStyle(e).display), 'inline', 'the page is styled');
    await page.click('#step');
    await waitForSteps(page, 1);
    assert.deepEqual(problems, []);
    await context.close();
    return failed;
  }

  test('the server `npm start` runs (scripts/serve.mjs) stops: a reload still opens and runs', async () => {
    const port = 18000 + (process.pid % 1000);
    const npmStart = spawn('node', ['scripts/serve.mjs', '--port', String(port), '--host', '127.0.0.1'], {
      stdio: 'ignore',
      detached: true,
    });
    const url = `http://127.0.0.1:${port}/`;
    for (let i = 0; i < 100; i++) {
      if (
        await fetch(url).then(
          (r) => r.ok,
          () => false,
        )
      )
        break;
      await new Promise((r) => setTimeout(r, 200));
    }
    // It sends the build's precompressed copies (Vary: Accept-Encoding), the wasm included; the
    // worker's kept copies are matched whatever the Vary.
    const page = await (await fetch(url)).text();
    const wasmPath = /href="\.\/(assets\/kumiki_wasm_bg-[\w-]+\.wasm)"/.exec(page)?.[1];
    assert.ok(wasmPath, 'index.html preloads the page wasm module');
    const wasmResponse = await fetch(new URL(wasmPath, url), { headers: { 'accept-encoding': 'br, gzip' } });
    assert.equal(wasmResponse.headers.get('content-encoding'), 'br');
    assert.match(wasmResponse.headers.get('vary') ?? '', /Accept-Encoding/);
    assert.match(wasmResponse.headers.get('content-security-policy') ?? '', /frame-ancestors/);
    await survivesOutage(url, async () => {
      process.kill(-npmStart.pid);
      for (
        let i = 0;
        i < 50 &&
        (await fetch(url).then(
          () => true,
          () => false,
        ));
        i++
      )
        await new Promise((r) => setTimeout(r, 100));
    });
  });

  test('a plain static host stops: a reload still opens and runs', async () => {
    const own = await serve('/');
    await survivesOutage(own.url, async () => {
      await own.close();
    });
  });

  test('a new deployment is offered, and reloading puts it in charge', async () => {
    const { context, page, problems } = await visit();
    const [before] = Object.keys(await cached(page));
    assert.match(before, /^kumiki-[0-9a-f]{16}$/);
    assert.equal(await page.isVisible('#banner'), false, 'no notice on the first visit');

    host = 'newer';
    await page.evaluate(() => navigator.serviceWorker.getRegistration().then((r) => r.update()));
    await page.waitForSelector('#banner:not([hidden])', { timeout: 30000 });
    assert.equal(await page.textContent('#banner-text'), 'A new version of Kumiki is ready.');
    assert.equal(await page.textContent('#banner-action'), 'Reload');
    await page.evaluate(() => {
      window.beforeUpdate = true;
    });
    await Promise.all([page.waitForEvent('load', { timeout: 30000 }), page.click('#banner-action')]);
    await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
    assert.equal(await page.evaluate(() => window.beforeUpdate), undefined, 'the page reloaded');
    assert.deepEqual(Object.keys(await cached(page)), [`${before}-next`], 'the new version replaced the old one');
    assert.equal(await page.isVisible('#banner'), false);
    assert.deepEqual(problems, []);
    await context.close();
  });
});
