// Shared pieces of the browser tests: a static server for dist/ (optionally under a sub-path, to
// prove the build uses relative URLs) and Debian's Chromium driven by playwright-core.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { createServer } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import { extname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';
import { after, before } from 'node:test';
import { chromium } from 'playwright-core';
// The rules module: the page's module with the built-in scenarios and lessons (the page's own leaves them out).
import * as wasm from '../../web/pkg/kumiki_wasm_rules.js';
import { DIST, TYPES } from '../../scripts/serve.mjs';

export { DIST };

/** The headers a static host sends with every file, from the build's dist/_headers. */
function hostHeaders() {
  const out = {};
  for (const line of readFileSync(join(DIST, '_headers'), 'utf8').split('\n')) {
    const m = /^\s+([\w-]+): (.+)$/.exec(line);
    if (m) out[m[1].toLowerCase()] = m[2];
  }
  return out;
}

/**
 * Serves dist/ at `prefix` (e.g. '/' or '/classes/kumiki/') with the headers of dist/_headers,
 * as a static host would. Resolves to { url, close }. `rewrite(path, body)` may change a file as
 * it is served (a new deployment), or return null to drop the connection (the network is down).
 */
export function serve(prefix = '/', { rewrite = (_path, body) => body } = {}) {
  const headers = hostHeaders();
  const server = createServer(async (req, res) => {
    const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (!path.startsWith(prefix)) {
      res.writeHead(404).end('not here');
      return;
    }
    let rel = normalize(path.slice(prefix.length)).replace(/^(\.\.[/\\])+/, '');
    if (rel === '' || rel === '.' || rel.endsWith('/')) rel = join(rel, 'index.html');
    const file = join(DIST, rel);
    try {
      if (!(await stat(file)).isFile()) throw new Error('not a file');
      const body = rewrite(rel, await readFile(file));
      if (body === null) {
        req.socket.destroy();
        return;
      }
      res.writeHead(200, { ...headers, 'content-type': TYPES[extname(file)] ?? 'application/octet-stream', 'cache-control': 'no-store' });
      res.end(body);
    } catch {
      res.writeHead(404).end('not found');
    }
  });
  return new Promise((resolve) => {
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      resolve({ url: `http://127.0.0.1:${port}${prefix}`, close: () => new Promise((r) => server.close(r)) });
    });
  });
}

export const CHROMIUM = process.env.KUMIKI_CHROMIUM ?? '/usr/bin/chromium';

export function launch() {
  return chromium.launch({
    executablePath: CHROMIUM,
    headless: true,
    args: [
      '--no-sandbox',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
      '--disable-quic',
      '--no-first-run',
      '--use-angle=swiftshader',
      '--enable-unsafe-swiftshader',
    ],
  });
}

/**
 * A page that records console errors, page errors and CSP violations. A shared link opens with
 * its introduction, and a first visit with the welcome; each is closed unless `keepIntro` (or
 * `keepWelcome`) is set. `init`, if given, runs in the page before its own scripts (to watch what
 * they do). `serviceWorkers: 'block'` keeps the offline worker out (it fetches every file of the
 * build to keep them), so that every request seen is the page's own.
 */
export async function openPage(
  browser,
  url,
  { width = 1280, height = 800, keepIntro = false, keepWelcome = false, init = null, serviceWorkers = 'allow' } = {},
) {
  const context = await browser.newContext({ viewport: { width, height }, serviceWorkers });
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  await page.addInitScript(() => {
    document.addEventListener('securitypolicyviolation', (e) => console.error(`CSP violation: ${e.violatedDirective} ${e.blockedURI}`));
  });
  if (init) await page.addInitScript(init);
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
  if (!keepIntro && (await page.isVisible('#intro'))) {
    await page.click('#intro button.primary');
    await page.waitForSelector('#intro', { state: 'hidden' });
  }
  if (!keepWelcome && (await page.isVisible('#welcome'))) {
    await page.click('#welcome-skip');
    await page.waitForSelector('#welcome', { state: 'hidden' });
  }
  return { page, context, problems };
}

export async function stepCount(page) {
  return Number((await page.textContent('#step-count')).replace(/,/g, ''));
}

/** Resolves once the page has run `count` more animation frames. */
export async function animationFrames(page, count) {
  await page.evaluate(
    (n) =>
      new Promise((resolve) => {
        let left = n;
        const next = () => (--left <= 0 ? resolve() : requestAnimationFrame(next));
        requestAnimationFrame(next);
      }),
    count,
  );
}

/** Resolves once the page has drawn two more animation frames: whatever was requested is drawn. */
export async function settle(page) {
  await animationFrames(page, 2);
}

/**
 * Does `action` (a click, a camera move) and waits until the worker has drawn a frame after it
 * (its count of frames, body[data-work]) and the page has composited it: the view is drawn by the
 * worker, so two of the page's animation frames alone may still show the frame before.
 */
export async function afterDraw(page, action) {
  const drawn = () => page.evaluate(() => JSON.parse(document.body.dataset.work ?? '{}').frames ?? 0);
  const before = await drawn();
  await action();
  await page.waitForFunction((n) => (JSON.parse(document.body.dataset.work ?? '{}').frames ?? 0) > n, before);
  await settle(page);
}

export async function waitForSteps(page, atLeast, timeout = 20000) {
  await page.waitForFunction((n) => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) >= n, atLeast, { timeout });
  return stepCount(page);
}

/**
 * One server and one browser for a test file: registers the hooks that start and stop them and
 * returns an object whose `server` and `browser` are set once the tests run.
 */
export function session(prefix = '/') {
  const s = { server: null, browser: null };
  before(async () => {
    s.server = await serve(prefix);
    s.browser = await launch();
  });
  after(async () => {
    await s.browser?.close();
    await s.server?.close();
  });
  return s;
}

/** The wasm package, loaded in Node, for tests that build scenarios and links themselves. */
export function loadWasm() {
  wasm.initSync({ module: readFileSync(fileURLToPath(new URL('../../web/pkg/kumiki_wasm_rules_bg.wasm', import.meta.url))) });
  return wasm;
}

/**
 * Runs the command line (`kumiki ARGS`) and returns what it printed. It is built in the `quick`
 * profile, the one npm test builds for its report and schema checks before the browser tests, so
 * no test waits for a build of its own (a file run alone builds it once).
 */
export function kumiki(args, { env = {} } = {}) {
  return execFileSync('cargo', ['run', '--profile', 'quick', '--quiet', '-p', 'kumiki-cli', '--', ...args], {
    encoding: 'utf8',
    env: { ...process.env, ...env },
  });
}

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');

/**
 * The accessibility audit's check: axe-core (WCAG 2.1 A and AA, and its best practices) on the page
 * as it stands; its serious and critical violations, one line each, named `where`.
 */
export async function audit(page, where) {
  if (!(await page.evaluate(() => 'axe' in window))) await page.evaluate(AXE);
  const violations = await page.evaluate(async () => {
    const result = await window.axe.run(document, {
      runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'best-practice'] },
      // WCAG 2.5.3 (label in name): a control's accessible name holds its visible text. axe marks
      // the rule experimental and leaves it out unless asked.
      rules: { 'label-content-name-mismatch': { enabled: true } },
      resultTypes: ['violations'],
    });
    return result.violations
      .filter((v) => v.impact === 'serious' || v.impact === 'critical')
      .map((v) => ({ id: v.id, impact: v.impact, targets: v.nodes.map((n) => n.target.join(' ')).slice(0, 5) }));
  });
  return violations.map((v) => `${where}: ${v.id} (${v.impact}) at ${v.targets.join(', ')}`);
}
