// The Experiments panel: a grid runs on a pool of workers with progress, is drawn by the core's
// figures, saved as SVG and PNG, exported with provenance byte for byte as the CLI writes it, and
// travels as a link, a file and across reloads.
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';
import { kumiki, openPage, session } from './harness.mjs';

const s = session('/');

const experiment = {
  version: 1,
  name: 'e2e-small',
  title: 'A small grid',
  scenarios: ['amas-L'],
  grid: { robots: [1, 3] },
  seeds: 3,
  trace: { every: 50, metrics: ['built'] },
  plot: [
    { kind: 'lines', x: 'params.robots', y: ['metrics.total_steps'], statistic: 'median', spread: 'iqr', title: 'Total steps' },
    { kind: 'summary', group: ['params.robots'], values: ['steps'] },
  ],
};

async function edit(page, text) {
  await page.$eval('details:has(#experiment-json)', (d) => (d.open = true));
  await page.fill('#experiment-json', text);
}

async function downloaded(page, selector) {
  const [file] = await Promise.all([page.waitForEvent('download'), page.click(selector)]);
  return { name: file.suggestedFilename(), bytes: await readFile(await file.path()) };
}

test('an experiment runs on a worker pool, is drawn as it says, and exports what the CLI writes', async () => {
  const { page, context, problems } = await openPage(s.browser, s.server.url);
  await page.click('#tab-experiments');
  const text = JSON.stringify(experiment, null, 2);
  await edit(page, text);
  await page.fill('#experiment-workers', '2');
  await page.dispatchEvent('#experiment-workers', 'change');
  // The workers run the page's compiled module: none downloads the wasm again.
  const fetched = [];
  context.on('request', (r) => r.url().endsWith('.wasm') && fetched.push(r.url()));
  await page.click('#experiment-run');
  await page.waitForFunction(() => document.querySelector('#experiment-status').textContent.startsWith('Done'), null, { timeout: 60000 });
  assert.deepEqual(fetched, []);
  assert.equal(await page.getAttribute('#experiment-progress', 'aria-valuenow'), '100');

  // The figure names the statistic its spec asks for and draws it: medians with IQR bands.
  const caption = await page.textContent('#experiment-plots figure[data-kind="lines"] figcaption');
  assert.equal(caption, 'median, interquartile range; n = 3 runs per point');
  assert.equal(await page.$$eval('#experiment-plots figure[data-kind="lines"] svg circle[data-band]', (c) => c.length), 2);
  assert.equal(await page.$$eval('#experiment-plots figure[data-kind="summary"] tbody tr', (r) => r.length), 2);
  // A column per condition path, named in words, then the statistics.
  assert.deepEqual(await page.$$eval('#experiment-plots figure[data-kind="summary"] thead th', (ths) => ths.map((t) => t.textContent)), [
    'robots',
    'value',
    'n',
    'mean',
    'sd',
    'median',
    'IQR',
    '95% CI of the mean',
  ]);
  assert.deepEqual(
    await page.$$eval('#experiment-plots figure[data-kind="summary"] tbody tr', (trs) => trs.map((t) => [...t.cells].slice(0, 3).map((c) => c.textContent))),
    [
      ['1', 'steps [steps]', '3'],
      ['3', 'steps [steps]', '3'],
    ],
  );
  // Two conditions are compared.
  assert.match(
    await page.textContent('#experiment-plots figure[data-kind="summary"] .comparisons'),
    /robots: 1 against robots: 3: .*Cohen's d .*Mann-Whitney U = /,
  );

  // SVG and PNG (twice the size) of the figure.
  const svg = await downloaded(page, '#experiment-plots figure[data-kind="lines"] button:has-text("Save SVG")');
  assert.equal(svg.name, 'e2e-small-1.svg');
  const svgText = svg.bytes.toString('utf8');
  assert.match(svgText, /^<svg xmlns="http:\/\/www.w3.org\/2000\/svg" width="720"/);
  assert.ok(svgText.includes('median, interquartile range; n = 3 runs per point'));
  assert.ok(svgText.includes('>total steps [robot steps]</text>'), 'the y axis names its unit');
  assert.ok(svgText.includes('>robots: 1') === false && svgText.includes('>robots</text>'), 'the x axis is named');
  const png = await downloaded(page, '#experiment-plots figure[data-kind="lines"] button:has-text("Save PNG")');
  assert.equal(png.name, 'e2e-small-1.png');
  assert.equal(png.bytes.subarray(1, 4).toString('latin1'), 'PNG');
  assert.equal(png.bytes.readUInt32BE(16), 1440, 'twice the SVG width');
  const pdf = await downloaded(page, '#experiment-plots figure[data-kind="lines"] button:has-text("Save PDF")');
  assert.equal(pdf.name, 'e2e-small-1.pdf');
  assert.equal(pdf.bytes.subarray(0, 5).toString('latin1'), '%PDF-');

  // CSV, JSON lines and traces: the CLI writes the same bytes for the same experiment and time.
  const dir = mkdtempSync(join(tmpdir(), 'kumiki-e2e-'));
  const file = join(dir, 'e2e-small.json');
  writeFileSync(file, text);
  const csv = (await downloaded(page, '#export-csv')).bytes.toString('utf8');
  const time = csv.match(/^# time: (.+)$/m)[1];
  const epoch = String(Date.parse(time) / 1000);
  const cli = (...args) => kumiki(['sweep', file, ...args], { env: { SOURCE_DATE_EPOCH: epoch } });
  assert.match(csv, /^# kumiki \S+ \(commit [0-9a-f]{12}\)\n# models: amas behaviour version \d+\n# seeds: 1 2 3\n/);
  assert.match(csv, /\nscenario,seed,completed,steps \[steps\],hash,scenario_hash,version,params\.robots,.*metrics\.total_steps \[robot steps\]/);
  assert.equal(csv, cli('--format', 'csv'));
  const jsonl = (await downloaded(page, '#export-json')).bytes.toString('utf8');
  assert.equal(jsonl, cli());
  assert.equal(JSON.parse(jsonl.split('\n')[0]).provenance.experiment.name, 'e2e-small');
  const traces = (await downloaded(page, '#export-traces')).bytes.toString('utf8');
  cli('--traces', join(dir, 'traces.csv'));
  // The PDF is the figure `kumiki sweep --plot pdf` writes, byte for byte.
  cli('--plot', 'pdf', '--plot-dir', dir);
  assert.ok(pdf.bytes.equals(readFileSync(join(dir, 'e2e-small-1.pdf'))), 'the page saves the PDF the CLI writes');
  assert.equal(traces, readFileSync(join(dir, 'traces.csv'), 'utf8'));
  assert.match(traces, /\nscenario,seed,params\.robots,step \[steps\],metric,unit,value\namas-L,1,1,0,built,fraction,/);
  assert.deepEqual(problems, []);
  await context.close();
});

/** Runs the experiment in view on two workers and returns its CSV export. */
async function runToCsv(page) {
  await page.fill('#experiment-workers', '2');
  await page.dispatchEvent('#experiment-workers', 'change');
  await page.click('#experiment-run');
  await page.waitForFunction(() => document.querySelector('#experiment-status').textContent.startsWith('Done'), null, { timeout: 60000 });
  return (await downloaded(page, '#export-csv')).bytes.toString('utf8');
}

/** What `kumiki sweep FILE --format csv` writes, at the time the page's CSV says it ran. */
function cliCsv(file, pageCsv) {
  const epoch = String(Date.parse(pageCsv.match(/^# time: (.+)$/m)[1]) / 1000);
  return kumiki(['sweep', file, '--format', 'csv'], { env: { SOURCE_DATE_EPOCH: epoch } });
}

test('an edited experiment travels by link and by file, survives a reload, and each copy exports what the CLI writes', async () => {
  const { page, context, problems } = await openPage(s.browser, s.server.url);
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await page.click('#tab-experiments');
  const edited = { ...experiment, name: 'e2e-travel', seeds: [4, 9] };
  const text = JSON.stringify(edited, null, 2);
  await edit(page, text);

  // The file the page saves is the experiment as edited; the CLI runs it.
  const saved = await downloaded(page, '#experiment-save');
  assert.equal(saved.name, 'e2e-travel.json');
  assert.equal(saved.bytes.toString('utf8'), text);
  const file = join(mkdtempSync(join(tmpdir(), 'kumiki-e2e-')), saved.name);
  writeFileSync(file, saved.bytes);

  // By link: another page opens it in the Experiments tab, runs it and exports the CLI's bytes.
  await page.click('#experiment-link');
  const link = await page.getAttribute('#experiment-link', 'data-link');
  assert.match(link, /#x1\./);
  const other = await openPage(s.browser, link);
  await other.page.waitForFunction(() => document.querySelector('#tab-experiments').getAttribute('aria-selected') === 'true');
  assert.deepEqual(JSON.parse(await other.page.inputValue('#experiment-json')), edited);
  const linked = await runToCsv(other.page);
  assert.match(
    linked,
    /^# kumiki \S+ \(commit [0-9a-f]{12}\)\n# models: amas behaviour version \d+\n# seeds: 4 9\n# time: .+\n# experiment: \{.*"name":"e2e-travel".*\}\n/,
  );
  assert.equal(linked, cliCsv(file, linked));
  assert.deepEqual(other.problems, []);
  await other.context.close();

  // By file: opened over a built-in experiment, it is the same text, and runs to the CLI's bytes.
  await page.selectOption('#experiment-select', 'amas-fig23');
  await page.setInputFiles('#experiment-open', { name: 'mine.json', mimeType: 'application/json', buffer: saved.bytes });
  // The file is read asynchronously: wait for its text to arrive before comparing.
  await page.waitForFunction(() => document.querySelector('#experiment-json').value.includes('e2e-travel'));
  assert.equal(await page.inputValue('#experiment-json'), text);
  const opened = await runToCsv(page);
  assert.equal(opened, cliCsv(file, opened));

  await page.reload();
  await page.waitForFunction(() => document.querySelector('#experiment-json').value.includes('e2e-travel'));
  assert.equal(await page.inputValue('#experiment-json'), text);
  assert.deepEqual(problems, []);
  await context.close();
});

test('an invalid experiment or plot is refused with a message and nothing runs', async () => {
  const { page, context } = await openPage(s.browser, s.server.url);
  await page.click('#tab-experiments');
  await edit(page, '{"version": 1, "name": "x", "scenarios": ["amas-L"], "grid": {"robots": [0]}}');
  await page.click('#experiment-run');
  await page.waitForFunction(() => document.querySelector('#experiment-status').textContent.includes('cannot run'));
  assert.match(await page.textContent('#experiment-status'), /robots/);
  assert.equal(await page.isDisabled('#experiment-run'), false);
  await edit(page, '{"version": 1, "name": "x", "scenarios": ["amas-L"], "plot": {"kind": "bars", "x": "scenario", "y": "steps", "statistic": "mode"}}');
  await page.click('#experiment-run');
  await page.waitForFunction(() => document.querySelector('#experiment-status').textContent.includes('mode'));
  assert.equal(await page.textContent('#experiment-status'), "This experiment cannot run: plot.statistic: 'mode' is not a choice; expected 'mean' or 'median'");
  await context.close();
});
