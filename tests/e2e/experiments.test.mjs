// The Experiments panel: a grid runs on a pool of workers with progress, is drawn by the core's
// figures, saved as SVG and PNG, exported with provenance byte for byte as the CLI writes it, and
// travels as a link, a file and across reloads.
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';
import { audit, kumiki, openPage, session } from './harness.mjs';

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
  // The description follows the text a moment after it is typed and moves what is below it: a
  // click made meanwhile lands where a button was. Wait until it has stood still for 0.8 s.
  await page.waitForFunction(
    () =>
      new Promise((resolve) => {
        const d = document.querySelector('#experiment-description');
        let last = d.textContent;
        let still = 0;
        const t = setInterval(() => {
          if (d.textContent !== last) [last, still] = [d.textContent, 0];
          else if (++still >= 8) {
            clearInterval(t);
            resolve(true);
          }
        }, 100);
      }),
  );
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
  // The tab shows as soon as the experiments are mounted (after the first frame); the lab module fills it once it has arrived.
  await other.page.waitForFunction(() => document.querySelector('#experiment-json').value !== '');
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
  // After a reload the experiments mount after the first frame: wait for them, then for the text.
  await page.waitForFunction(() => document.querySelector('#experiment-json')?.value.includes('e2e-travel'));
  assert.equal(await page.inputValue('#experiment-json'), text);
  assert.deepEqual(problems, []);
  await context.close();
});

test('an invalid experiment or plot is refused with a message and nothing runs', async () => {
  const { page, context } = await openPage(s.browser, s.server.url);
  await page.click('#tab-experiments');
  await edit(page, '{"version": 1, "name": "x", "scenarios": ["amas-L"], "grid": {"robots": [0]}}');
  await page.click('#experiment-run');
  await page.waitForFunction(() => document.querySelector('#experiment-problem').textContent.includes('cannot run'));
  assert.match(await page.textContent('#experiment-problem'), /robots/);
  assert.equal(await page.getAttribute('#experiment-problem', 'role'), 'alert');
  assert.equal(await page.isDisabled('#experiment-run'), false);
  await edit(page, '{"version": 1, "name": "x", "scenarios": ["amas-L"], "plot": {"kind": "bars", "x": "scenario", "y": "steps", "statistic": "mode"}}');
  await page.click('#experiment-run');
  await page.waitForFunction(() => document.querySelector('#experiment-problem').textContent.includes('mode'));
  assert.equal(
    await page.textContent('#experiment-problem'),
    "This experiment cannot run: plot.statistic: 'mode' is not a choice; expected 'mean' or 'median'",
  );
  // The description says it too, styled as an error, not as a hint.
  await page.waitForFunction(() => document.querySelector('#experiment-description').textContent.includes('plot.statistic'));
  assert.match(await page.textContent('#experiment-description'), /^This experiment cannot run: plot\.statistic/);
  assert.equal(await page.getAttribute('#experiment-description', 'class'), 'error');
  await context.close();
});

test('a near miss is named with the core’s suggestion, which one press puts in the experiment', async () => {
  const { page, context, problems } = await openPage(s.browser, s.server.url);
  await page.click('#tab-experiments');
  await edit(page, JSON.stringify({ ...experiment, grid: { robot: [1, 3] }, stop: 'metrics.placd >= 0.5' }, null, 2));
  // The stop condition is read first: its misspelt metric is named, and the suggestion put in.
  await page.click('#experiment-run');
  await page.waitForFunction(() => document.querySelector('#experiment-problem').textContent.includes('did you mean'));
  assert.match(await page.textContent('#experiment-problem'), /stop: 'metrics\.placd' is not a metric of amas; did you mean 'metrics\.placed'\?/);
  await page.click('#experiment-problem button:has-text("Use \'metrics.placed\'")');
  assert.equal(JSON.parse(await page.inputValue('#experiment-json')).stop, 'metrics.placed >= 0.5');
  // Then the grid key the scenario refuses is blamed on the grid, with the field it meant.
  await page.click('#experiment-run');
  await page.waitForFunction(() => document.querySelector('#experiment-problem').textContent.includes('grid.robot'));
  assert.match(await page.textContent('#experiment-problem'), /grid\.robot: .*unknown field 'robot'; did you mean 'robots'\?/);
  await page.click('#experiment-problem button:has-text("Use \'robots\'")');
  assert.deepEqual(JSON.parse(await page.inputValue('#experiment-json')).grid, { robots: [1, 3] });
  assert.equal(await page.textContent('#experiment-problem'), '');
  await page.waitForFunction(() => !document.querySelector('#experiment-description').textContent.includes('cannot run'));
  // A name with no near miss: the page lists the model's metrics, not a file of the repository.
  await edit(page, JSON.stringify({ ...experiment, stop: 'metrics.xyzzy >= 1' }, null, 2));
  await page.waitForFunction(() => document.querySelector('#experiment-description').textContent.includes('xyzzy'));
  const listed = await page.textContent('#experiment-description');
  assert.match(listed, /^This experiment cannot run: stop: 'metrics\.xyzzy' is not a metric of amas, whose metrics are [a-z_]+(, [a-z_]+)+$/);
  assert.ok(listed.includes(' built,') && listed.includes(' total_steps,'));
  assert.doesNotMatch(listed, /docs\/metrics\.md/);
  assert.equal(await page.getAttribute('#experiment-description', 'class'), 'error');
  assert.deepEqual(problems, []);
  await context.close();
});

test('the description follows the experiment: a preset, every edit, a file and a link', async () => {
  const { page, context, problems } = await openPage(s.browser, s.server.url);
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await page.click('#tab-experiments');
  await page.selectOption('#experiment-select', 'amas-fig23');
  const preset = await page.textContent('#experiment-description');
  assert.match(preset, /\([\d,]+ runs\)$/);
  const described = (text) => page.waitForFunction((t) => document.querySelector('#experiment-description').textContent === t, text);

  // Typed: the description is the edited experiment's, with its runs.
  await edit(page, JSON.stringify({ ...experiment, description: 'First draft' }, null, 2));
  await described('First draft (6 runs)');
  await edit(page, JSON.stringify({ ...experiment, description: 'Second draft', seeds: 5 }, null, 2));
  await described('Second draft (10 runs)');
  // Back to a preset, then a file, then a link.
  await page.selectOption('#experiment-select', 'amas-fig23');
  await described(preset);
  const file = JSON.stringify({ ...experiment, description: 'From a file', seeds: 1 }, null, 2);
  await page.setInputFiles('#experiment-open', { name: 'mine.json', mimeType: 'application/json', buffer: Buffer.from(file) });
  await described('From a file (2 runs)');
  await edit(page, JSON.stringify({ ...experiment, description: 'By link', seeds: 4 }, null, 2));
  await page.click('#experiment-link');
  const link = await page.getAttribute('#experiment-link', 'data-link');
  await page.selectOption('#experiment-select', 'amas-fig23');
  await described(preset);
  await page.goto(link);
  await described('By link (8 runs)');
  assert.deepEqual(problems, []);
  await context.close();
});

test('a sweep is kept: it survives a reload, reopens with the same exports, is compared with another, and deleted', async () => {
  const { page, context, problems } = await openPage(s.browser, s.server.url);
  await page.click('#tab-experiments');
  const first = { ...experiment, name: 'e2e-kept', seeds: 2 };
  const text = JSON.stringify(first, null, 2);
  await edit(page, text);
  const csv = await runToCsv(page);
  const jsonl = (await downloaded(page, '#export-json')).bytes.toString('utf8');
  const listed = () => page.$$eval('#saved-sweeps-list li[data-id]', (lis) => lis.map((li) => li.querySelector('.saved-facts').textContent));
  await page.waitForFunction(() => document.querySelectorAll('#saved-sweeps-list li[data-id]').length === 1);

  // After a reload the sweep is listed, with its name, date and runs.
  await page.reload();
  await page.click('#tab-experiments');
  await page.waitForFunction(() => document.querySelectorAll('#saved-sweeps-list li[data-id]').length === 1);
  const date = csv.match(/^# time: (\d{4}-\d\d-\d\d)T(\d\d:\d\d):\d\dZ$/m);
  assert.deepEqual(await listed(), [`e2e-kept · ${date[1]} ${date[2]} UTC · 4 runs`]);
  assert.match(
    await page.textContent('#saved-sweeps-usage'),
    /^1 saved sweep\. This page’s storage uses [\d.]+ [kMG]?B of the [\d.]+ [kMGT]?B the browser allows it\.$/,
  );
  // Whether the browser may clear them, and a press to ask it not to; either answer is said.
  if (await page.isVisible('#saved-sweeps-persist button')) {
    assert.equal(
      await page.textContent('#saved-sweeps-persist'),
      'The browser may clear the saved sweeps when the disk runs short. Ask the browser to keep them',
    );
    await page.click('#saved-sweeps-persist button');
    await page.waitForFunction(() => /keeps the saved sweeps|did not agree/.test(document.querySelector('#saved-sweeps-persist').textContent));
  } else assert.equal(await page.textContent('#saved-sweeps-persist'), 'The browser keeps the saved sweeps until you delete them.');

  // Reopened: its figures are drawn again, and its exports are the bytes it saved when it ran,
  // which the CLI writes for that experiment at that time.
  await edit(page, JSON.stringify({ ...experiment, name: 'something-else' }));
  await page.click('#saved-sweeps-list button:has-text("Open")');
  await page.waitForSelector('#experiment-plots figure[data-kind="summary"]');
  assert.equal(await page.inputValue('#experiment-json'), text);
  assert.match(
    await page.textContent('#experiment-shown'),
    /^Showing the saved sweep “e2e-kept” of .* UTC, 4 runs, made by kumiki \S+ \(commit [0-9a-f]{12}\)\.$/,
  );
  assert.equal(await page.$$eval('#experiment-plots figure[data-kind="summary"] tbody tr', (r) => r.length), 2);
  const reopenedCsv = (await downloaded(page, '#export-csv')).bytes.toString('utf8');
  assert.equal(reopenedCsv, csv);
  assert.equal((await downloaded(page, '#export-json')).bytes.toString('utf8'), jsonl);
  const file = join(mkdtempSync(join(tmpdir(), 'kumiki-e2e-')), 'e2e-kept.json');
  writeFileSync(file, text);
  assert.equal(reopenedCsv, cliCsv(file, csv));

  // A second sweep, cancelled part way: kept as partial, and compared with the first.
  const second = { ...experiment, name: 'e2e-second', grid: { robots: [1, 3] }, seeds: 40 };
  await edit(page, JSON.stringify(second, null, 2));
  await page.fill('#experiment-workers', '1');
  await page.dispatchEvent('#experiment-workers', 'change');
  await page.click('#experiment-run');
  await page.waitForFunction(() => /^[1-9]\d* \/ 80 runs/.test(document.querySelector('#experiment-status').textContent));
  await page.click('#experiment-cancel');
  await page.waitForFunction(() => document.querySelectorAll('#saved-sweeps-list li[data-id]').length === 2);
  const [newest] = await listed();
  assert.match(newest, /^e2e-second · .* UTC · \d+ of 80 runs partial$/);
  await page.click('#saved-sweeps-list li:nth-child(2) button:has-text("Compare")');
  await page.waitForSelector('#sweep-compare:not([hidden]) .compare-grid');
  const sides = await page.$$eval('#sweep-compare .compare-side', (ps) => ps.map((p) => p.textContent));
  assert.match(sides[0], /^A · In view: “e2e-second” of .* UTC, \d+ of 80 runs \(partial\)$/);
  assert.match(sides[1], /^B · Saved: “e2e-kept” of .* UTC, 4 runs$/);
  // Figure beside figure: both sweeps' line plots, then both summaries, each saying its side.
  assert.deepEqual(
    await page.$$eval('#sweep-compare .compare-grid > figure', (fs) => fs.map((f) => `${f.dataset.kind} ${f.querySelector('h3').textContent}`)),
    ['lines A · Total steps', 'lines B · Total steps', 'summary A · Figure 2', 'summary B · Figure 2'],
  );
  // The cancelled sweep ran robots = 1 first (jobs go grid combination, then seed): its summary has the conditions it reached.
  const rows = await page.$$eval('#sweep-compare .compare-grid > figure[data-kind="summary"]', (fs) => fs.map((f) => f.querySelectorAll('tbody tr').length));
  assert.equal(rows[1], 2);
  assert.ok(rows[0] >= 1);
  assert.equal(
    await page.getAttribute('#sweep-compare figure[data-kind="lines"]:nth-of-type(2) button:has-text("Save SVG")', 'aria-label'),
    'Save SVG of “B · Total steps”',
  );
  // First the two summaries in one table: each condition's n, mean and interval, A beside B (a
  // condition the cancelled sweep did not reach shows a dash on its side).
  const joined = await page.$$eval('#sweep-compare-figures > .table-scroll tbody tr', (trs) => trs.map((t) => [...t.cells].map((c) => c.textContent)));
  assert.deepEqual(
    joined.map((r) => [r[0], r[1], r[5]]),
    [
      ['1', 'steps [steps]', '2'],
      ['3', 'steps [steps]', '2'],
    ],
  );
  assert.ok(joined.every((r) => r.length === 8));
  assert.deepEqual(await audit(page, 'two sweeps compared'), []);

  // Deleted, put back by Undo, deleted again; a reload agrees.
  await page.click('#saved-sweeps-list li:nth-child(2) button:has-text("Delete")');
  await page.waitForFunction(() => document.querySelectorAll('#saved-sweeps-list li[data-id]').length === 1);
  assert.match(await page.textContent('#saved-sweeps-note'), /^Deleted “e2e-kept” of .* UTC\. Undo$/);
  await page.click('#saved-sweeps-note button:has-text("Undo")');
  await page.waitForFunction(() => document.querySelectorAll('#saved-sweeps-list li[data-id]').length === 2);
  assert.equal((await listed())[1], `e2e-kept · ${date[1]} ${date[2]} UTC · 4 runs`);
  await page.click('#saved-sweeps-list li:nth-child(2) button:has-text("Delete")');
  await page.waitForFunction(() => document.querySelectorAll('#saved-sweeps-list li[data-id]').length === 1);
  await page.reload();
  await page.click('#tab-experiments');
  await page.waitForFunction(() => document.querySelectorAll('#saved-sweeps-list li[data-id]').length === 1);
  assert.match((await listed())[0], /^e2e-second /);
  assert.deepEqual(await audit(page, 'saved sweeps'), []);
  assert.deepEqual(problems, []);
  await context.close();
});

test('the design form writes ranges, a Latin-hypercube sample and a stop condition, checked beside each field, and the page runs the CLI’s rows', async () => {
  const { page, context, problems } = await openPage(s.browser, s.server.url);
  await page.click('#tab-experiments');
  const start = { version: 1, name: 'e2e-design', scenarios: ['amas-L'], seeds: 2, plot: { kind: 'summary', group: ['params.robots'], values: ['steps'] } };
  await page.waitForSelector('#experiment-json:not([readonly])', { state: 'attached' });
  const described = await page.textContent('#experiment-description');
  await edit(page, JSON.stringify(start, null, 2));
  // The description follows the text a moment after it is typed, moving what is below it: a click
  // made meanwhile lands where the summary was.
  await page.waitForFunction((was) => document.querySelector('#experiment-description').textContent !== was, described);
  await page.click('#experiment-design summary');
  await page.waitForFunction(() => !document.querySelector('#experiment-design-form fieldset').disabled);
  const json = async () => JSON.parse(await page.inputValue('#experiment-json'));
  // Typed and left with Tab, as a keyboard user does: each field is written when it changes.
  const type = async (selector, text) => {
    await page.fill(selector, text);
    await page.press(selector, 'Tab');
  };

  // A grid key as a range.
  await page.click('#design-add-grid');
  assert.equal(await page.evaluate(() => document.activeElement.getAttribute('aria-label')), 'Grid key 1: scenario path');
  await type('#design-grid-rows li:nth-child(1) [data-field="key"]', 'set.max_steps');
  await page.selectOption('#design-grid-rows li:nth-child(1) [data-field="kind"]', 'range');
  await type('#design-grid-rows li:nth-child(1) [data-field="start"]', '3000');
  await type('#design-grid-rows li:nth-child(1) [data-field="step"]', '1000');
  await type('#design-grid-rows li:nth-child(1) [data-field="end"]', '4000');
  assert.deepEqual((await json()).grid, { 'set.max_steps': { start: 3000, step: 1000, end: 4000 } });

  // A misspelt key is blamed beside the grid, with the core's suggestion.
  await type('#design-grid-rows li:nth-child(1) [data-field="key"]', 'robot');
  await page.waitForFunction(() => document.querySelector('#design-grid-problem').textContent.includes('did you mean'));
  assert.match(await page.textContent('#design-grid-problem'), /^grid\.robot: .*unknown field 'robot'; did you mean 'robots'\?$/);
  assert.equal(await page.getAttribute('#design-grid-rows li:nth-child(1) [data-field="key"]', 'aria-invalid'), 'true');
  await page.click('#design-grid-rows li:nth-child(1) button:has-text("Remove")');
  assert.equal((await json()).grid, undefined);
  assert.equal(await page.textContent('#design-grid-problem'), '');

  // A Latin-hypercube sample of the robots.
  await page.selectOption('#design-method', 'latin');
  await type('#design-count', '3');
  await type('#design-seed', '7');
  await page.click('#design-add-range');
  await type('#design-range-rows li:nth-child(1) [data-field="key"]', 'robots');
  await type('#design-range-rows li:nth-child(1) [data-field="min"]', '1');
  await type('#design-range-rows li:nth-child(1) [data-field="max"]', '4');
  await page.check('#design-range-rows li:nth-child(1) [data-field="integer"]');
  assert.deepEqual((await json()).sample, { method: 'latin', count: 3, seed: 7, ranges: { robots: { min: 1, max: 4, integer: true } } });

  // A stop condition, checked by the core: the message stands beside the field.
  await type('#design-stop', 'metrics.placd >= 40');
  await page.waitForFunction(() => document.querySelector('#design-stop-problem').textContent !== '');
  assert.equal(await page.textContent('#design-stop-problem'), "stop: 'metrics.placd' is not a metric of amas; did you mean 'metrics.placed'?");
  assert.equal(await page.getAttribute('#design-stop', 'aria-invalid'), 'true');
  await type('#design-stop', 'metrics.placed >= 40 or steps >= 1500');
  await page.waitForFunction(() => document.querySelector('#design-stop-problem').textContent === '');
  assert.equal(await page.getAttribute('#design-stop', 'aria-invalid'), null);
  assert.match(await page.textContent('#experiment-description'), /\(6 runs\)$/);
  const designed = await json();
  assert.deepEqual(Object.keys(designed), ['version', 'name', 'scenarios', 'sample', 'seeds', 'stop', 'plot']);
  assert.deepEqual(await audit(page, 'the design form'), []);

  // The JSON edited by hand comes back into the form.
  await edit(page, JSON.stringify({ ...designed, grid: { field: ['continuous', 'discrete'] } }, null, 2));
  await page.waitForFunction(() => document.querySelector('#design-grid-rows [data-field="values"]')?.value === 'continuous, discrete');

  // The page runs what the CLI runs: the same Latin-hypercube points, stopped at the same steps.
  await edit(page, JSON.stringify(designed, null, 2));
  const csv = await runToCsv(page);
  const file = join(mkdtempSync(join(tmpdir(), 'kumiki-e2e-')), 'e2e-design.json');
  writeFileSync(file, JSON.stringify(designed, null, 2));
  assert.equal(csv, cliCsv(file, csv));
  assert.deepEqual(problems, []);
  await context.close();
});
