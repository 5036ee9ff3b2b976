// The Experiments panel: a grid runs on a pool of workers with progress, is plotted and exported.
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { test } from 'node:test';
import { openPage, session } from './harness.mjs';

const s = session('/');

test('an experiment runs on a worker pool with a progress bar, is plotted, and exports CSV and JSON', async () => {
  const { page, context, problems } = await openPage(s.browser, s.server.url);
  await page.click('#tab-experiments');
  const experiment = {
    version: 1,
    name: 'e2e-small',
    title: 'A small grid',
    scenarios: ['amas-L'],
    grid: { robots: [1, 3] },
    seeds: 3,
    plot: [
      { kind: 'lines', x: 'params.robots', y: ['metrics.total_steps'], spread: 'minmax', title: 'total steps' },
      { kind: 'summary', group: ['params.robots'], values: ['steps'] },
    ],
  };
  await page.click('#experiment-json', { force: true }).catch(() => {});
  await page.$eval('details:has(#experiment-json)', (d) => (d.open = true));
  await page.fill('#experiment-json', JSON.stringify(experiment));
  await page.fill('#experiment-workers', '2');
  await page.dispatchEvent('#experiment-workers', 'change');
  // The workers run the page's compiled module: none downloads the wasm again.
  const fetched = [];
  context.on('request', (r) => r.url().endsWith('.wasm') && fetched.push(r.url()));
  await page.click('#experiment-run');
  await page.waitForFunction(() => document.querySelector('#experiment-status').textContent.startsWith('Done'), null, { timeout: 60000 });
  assert.deepEqual(fetched, []);
  assert.equal(await page.getAttribute('#experiment-progress', 'aria-valuenow'), '100');
  assert.ok(await page.$('#experiment-plots .uplot canvas'), 'a chart was drawn');
  assert.equal(await page.$$eval('#experiment-plots figure:last-child tbody tr', (r) => r.length), 2);

  const [csv] = await Promise.all([page.waitForEvent('download'), page.click('#export-csv')]);
  const text = await readFile(await csv.path(), 'utf8');
  const lines = text.trim().split('\n');
  assert.equal(lines.length, 7);
  assert.match(lines[0], /^scenario,seed,completed,steps,hash,scenario_hash,version,params\.robots/);

  const [json] = await Promise.all([page.waitForEvent('download'), page.click('#export-json')]);
  const rows = JSON.parse(await readFile(await json.path(), 'utf8'));
  assert.equal(rows.length, 6);
  assert.ok(rows.every((r) => /^kumiki /.test(r.version) && /^[0-9a-f]{16}$/.test(r.scenario_hash)));
  assert.deepEqual(problems, []);
  await context.close();
});

test('an invalid experiment is refused with a message and nothing runs', async () => {
  const { page, context } = await openPage(s.browser, s.server.url);
  await page.click('#tab-experiments');
  await page.$eval('details:has(#experiment-json)', (d) => (d.open = true));
  await page.fill('#experiment-json', '{"version": 1, "name": "x", "scenarios": ["amas-L"], "grid": {"robots": [0]}}');
  await page.click('#experiment-run');
  await page.waitForFunction(() => document.querySelector('#experiment-status').textContent.includes('cannot run'));
  assert.match(await page.textContent('#experiment-status'), /robots/);
  assert.equal(await page.isDisabled('#experiment-run'), false);
  await context.close();
});
