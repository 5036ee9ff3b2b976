// Links anyone can send: hostile ones are refused with a plain message, quickly, and the scenario
// in view is kept; a page stopped while opening a scenario does not reopen it by itself. Also the
// About tab's reproduction rows, which come from the same report as docs/reproduction.md.
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { describe, test } from 'node:test';
import { deflateRawSync } from 'node:zlib';
import { createServer } from 'node:http';
import { audit, loadWasm, openPage, session, waitForSteps } from './harness.mjs';

const wasm = loadWasm();
const s = session();

/** A share link for any text, valid or not, made the way the page makes them. */
const linkOf = (text) => `k1.${deflateRawSync(Buffer.from(text)).toString('base64url')}`;
const amas = () => JSON.parse(wasm.preset_json('amas-L'));
const withKeys = (keys) => JSON.stringify({ ...amas(), ...keys });

/**
 * Resident memory of every Chromium process, in MB (Linux's /proc). The simulation worker lives in
 * the page's renderer process, so what a link makes it allocate shows here.
 */
function chromiumMb() {
  let kb = 0;
  for (const pid of readdirSync('/proc').filter((p) => /^\d+$/.test(p))) {
    try {
      if (!/chrom/.test(readFileSync(`/proc/${pid}/cmdline`, 'utf8'))) continue;
      kb += Number(/VmRSS:\s+(\d+)/.exec(readFileSync(`/proc/${pid}/status`, 'utf8'))?.[1] ?? 0);
    } catch {
      // The process ended while it was read.
    }
  }
  return kb / 1024;
}

/** Milliseconds the page takes to answer a trivial question. */
async function answerTime(page) {
  const t0 = Date.now();
  await page.evaluate(() => 1);
  return Date.now() - t0;
}

const HOSTILE = [
  [
    'a square shape of 2.7 × 10^11 cells in a few kilobytes',
    withKeys({ target: `${'#'.repeat(1 << 19)}\n${'#\n'.repeat(1 << 19)}` }),
    /target: the shape spans 524288 × 524289 cells/,
  ],
  [
    'a hex shape far over the limit',
    JSON.stringify({ ...JSON.parse(wasm.preset_json('fracta-triangle10')), start: `${'# '.repeat(20000)}\n${'#\n'.repeat(20000)}` }),
    /the shape spans/,
  ],
  [
    'a cubic shape far over the limit',
    JSON.stringify({ ...JSON.parse(wasm.preset_json('cubes-cube8-ladder')), shape: `${'#'.repeat(5000)}\n${'#\n'.repeat(5000)}---\n#` }),
    /the shape spans/,
  ],
  ['a deflate bomb', ' '.repeat(6 << 20), /larger than 4 MiB/],
  ['deep nesting', `${'['.repeat(100000)}${']'.repeat(100000)}`, /not valid JSON/],
  ['a huge number', withKeys({ robots: 1e12 }), /robots: 1000000000000 is not a whole number from 0 to/],
  ['not an object', '[1, 2, 3]', /^(?!.*: a scenario)(?=.*a scenario is a JSON object)/s],
];

describe('hostile links', () => {
  for (const [what, text, expected] of HOSTILE) {
    test(`${what}: a plain message, an answer within 1 s, under 200 MB more memory, and the scenario in view kept`, async () => {
      const { page, context, problems } = await openPage(s.browser, s.server.url);
      const before = await page.textContent('#state-hash');
      const memoryBefore = chromiumMb();
      assert.ok(memoryBefore > 50, `the browser's memory is measured (${memoryBefore.toFixed(0)} MB)`);
      const link = linkOf(text);
      assert.ok(link.length <= 64 * 1024, `the link is ${link.length} bytes`);
      await page.evaluate((l) => {
        location.hash = l;
      }, link);
      await page.waitForSelector('#banner:not([hidden])');
      assert.ok((await answerTime(page)) < 1000, 'the page answers within 1 s');
      const grown = chromiumMb() - memoryBefore;
      assert.ok(grown < 200, `the browser grew by ${grown.toFixed(0)} MB`);
      const message = await page.textContent('#banner-text');
      assert.match(message, expected);
      assert.doesNotMatch(message, /unreachable|invalid type|Invalid symbol|expected u32/);
      assert.equal(await page.textContent('#state-hash'), before, 'the scenario in view is kept');
      await page.click('#step');
      await waitForSteps(page, 1);
      assert.deepEqual(problems, []);
      await context.close();
    });
  }

  test('a scenario that never finished opening is offered after a reload, not reopened', async () => {
    const { page, context } = await openPage(s.browser, s.server.url);
    const stuck = withKeys({ name: 'stuck' });
    await page.evaluate((json) => localStorage.setItem('kumiki.opening.v1', json), stuck);
    await page.reload();
    await page.waitForSelector('body[data-ready="true"]');
    await page.waitForSelector('#banner:not([hidden])');
    assert.match(await page.textContent('#banner-text'), /did not finish opening/);
    assert.notEqual(await page.textContent('#scenario-name'), 'stuck');
    await page.click('#banner-action');
    await page.waitForFunction(() => document.querySelector('#scenario-name').textContent === 'stuck');
    await page.waitForFunction(() => localStorage.getItem('kumiki.opening.v1') === null);
    await context.close();
  });
});

describe('a shared link', () => {
  test('introduces itself first: its name and description, in a panel that Escape closes', async () => {
    const description = 'Line one.\nLine two, with <b>markup</b> that stays text.';
    const link = wasm.encode_link(withKeys({ name: 'Class 3: \u202Eexercise', description }));
    const { page, context } = await openPage(s.browser, `${s.server.url}#${link}`, { keepIntro: true });
    await page.waitForSelector('#intro[open]');
    assert.equal(await page.textContent('#intro-title'), 'Class 3: exercise');
    assert.equal(await page.textContent('#intro-model'), 'amas');
    await page.waitForSelector('#intro-modified[data-checked]', { state: 'attached' });
    assert.ok(await page.isHidden('#intro-modified'), 'a scenario named after no preset is not marked');
    // biome-ignore lint/performance/useDomNodeTextContent: innerText is the text as laid out, line breaks included.
    assert.equal(await page.$eval('#intro-description', (p) => p.innerText), 'Line one.\nLine two, with <b>markup</b> that stays text.');
    await page.keyboard.press('Escape');
    await page.waitForSelector('#intro', { state: 'hidden' });
    await page.click('#step');
    await waitForSteps(page, 1);
    await context.close();
  });

  test('an edited preset says what differs from the preset, and that the description is the preset’s', async () => {
    const edited = wasm.encode_link(withKeys({ robots: 3 }));
    const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${edited}`, { keepIntro: true });
    await page.waitForSelector('#intro[open]');
    // The dialog opens at once; the mark follows once the catalogue has said what differs.
    await page.waitForSelector('#intro-modified[data-checked]', { state: 'attached' });
    assert.equal(await page.textContent('#intro-modified'), 'Modified from the preset “amas-L”: robots: 5 → 3. The description below is the preset’s.');
    assert.ok(await page.isVisible('#intro-modified'));
    assert.deepEqual(await audit(page, 'an edited preset introduced'), []);
    assert.deepEqual(problems, []);
    await context.close();
    // The preset as it is: no mark.
    const same = await openPage(s.browser, `${s.server.url}#${wasm.encode_link(JSON.stringify(amas()))}`, { keepIntro: true });
    await same.page.waitForSelector('#intro[open]');
    assert.equal(await same.page.textContent('#intro-title'), 'amas-L');
    await same.page.waitForSelector('#intro-modified[data-checked]', { state: 'attached' });
    assert.ok(await same.page.isHidden('#intro-modified'));
    await same.context.close();
  });

  test('a preset opened from the gallery is not introduced', async () => {
    const { page, context } = await openPage(s.browser, s.server.url, { keepIntro: true });
    assert.equal(await page.isVisible('#intro'), false);
    await context.close();
  });
});

describe('framing', () => {
  test('the page is sent with its policy as a header, frame-ancestors included', async () => {
    const res = await fetch(s.server.url);
    const policy = res.headers.get('content-security-policy');
    const meta = /http-equiv="Content-Security-Policy" content="([^"]+)"/.exec(await res.text())[1];
    assert.equal(policy, `${meta}; frame-ancestors 'self' https: http://localhost:* http://127.0.0.1:*`);
    assert.equal(res.headers.get('x-content-type-options'), 'nosniff');
  });

  test('a course page on another origin may embed it; a page with no origin may not', async () => {
    const host = createServer((_, res) =>
      res.writeHead(200, { 'content-type': 'text/html' }).end(`<iframe id="k" src="${s.server.url}" width="900" height="600"></iframe>`),
    );
    await new Promise((r) => host.listen(0, '127.0.0.1', r));
    const context = await s.browser.newContext();
    const page = await context.newPage();
    await page.goto(`http://127.0.0.1:${host.address().port}/`);
    const frame = await (await page.waitForSelector('#k')).contentFrame();
    await frame.waitForSelector('body[data-ready="true"]', { timeout: 30000 });

    await page.goto(`data:text/html,<iframe id="k" src="${s.server.url}"></iframe>`);
    const blocked = await (await page.waitForSelector('#k')).contentFrame();
    await page.waitForFunction(() => document.querySelector('#k').contentWindow !== null);
    await blocked.waitForLoadState();
    assert.equal(await blocked.$('body[data-ready="true"]'), null);
    assert.match(blocked.url(), /^chrome-error:/, 'the browser refused to frame it');
    await context.close();
    await new Promise((r) => host.close(r));
  });
});

describe('the About tab', () => {
  test("shows the model's reproduction rows, the same as docs/reproduction.json", async () => {
    const report = JSON.parse(readFileSync(new URL('../../docs/reproduction.json', import.meta.url), 'utf8'));
    const { page, context } = await openPage(s.browser, s.server.url);
    const model = await page.textContent('#scenario-model');
    const findings = report.models[model]?.findings ?? [];
    assert.ok(findings.length > 0, `the report has findings for ${model}`);
    await page.click('#tab-about');
    // The rows come with the lab module, loaded when the tab is first shown.
    await page.waitForSelector('#paper-report table.findings');
    const rows = page.locator('#paper-report table.findings tbody tr');
    assert.equal(await rows.count(), findings.length);
    const first = rows.first().locator('td');
    assert.equal(await first.nth(1).locator('.claim-text').textContent(), findings[0].claim);
    assert.equal(await first.nth(3).textContent(), String(findings[0].runs));
    // The table fits its panel, on a laptop (1366 × 768) and on a tablet: no sideways scrolling.
    for (const [width, height] of [
      [1366, 768],
      [768, 1024],
    ]) {
      await page.setViewportSize({ width, height });
      const [scroll, client] = await page.$eval('#paper-report .table-scroll', (d) => [d.scrollWidth, d.clientWidth]);
      assert.ok(scroll <= client, `the table fits at ${width} px (${scroll} > ${client})`);
      const [panel, room] = await page.$eval('#panel-about', (d) => [d.scrollWidth, d.clientWidth]);
      assert.ok(panel <= room, `the About panel needs no sideways scrolling at ${width} px (${panel} > ${room})`);
    }
    // Each experiment behind the figures opens in the Experiments tab (its text once the lab
    // module, which holds the experiments, has loaded).
    const name = report.models[model].experiments[0];
    await page.click(`#paper-report p.row-buttons button:text-is("${name}")`);
    assert.equal(await page.getAttribute('#tab-experiments', 'aria-selected'), 'true');
    await page.waitForFunction(() => document.querySelector('#experiment-json').value !== '');
    assert.equal(JSON.parse(await page.inputValue('#experiment-json')).name, name);
    await context.close();
  });
});
