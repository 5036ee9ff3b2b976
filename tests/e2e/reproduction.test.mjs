// The reproduction report as a doorway: a claim opens by its link, opens its experiment in the
// Experiments tab, and re-runs in the page to the report's own row (figure, runs and verdict,
// compared here with docs/reproduction.json); a long re-run can be cancelled.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';
import { loadWasm, openPage, session } from './harness.mjs';

const s = session('/');
const report = JSON.parse(readFileSync(new URL('../../docs/reproduction.json', import.meta.url), 'utf8'));
const claim = (model, id) => report.models[model].findings.find((c) => c.id === id);

// A quick claim: its experiment runs in well under a second natively.
const QUICK = { model: 'chobie', id: 'chobie-with-five-robots-a-load-at' };

test("a claim's link opens it, and its re-run in the page gives the report's row", async () => {
  const row = claim(QUICK.model, QUICK.id);
  assert.ok(row, `the report has the claim ${QUICK.id}`);
  assert.deepEqual(row.experiments, ['chobie-load']);
  const { page, context, problems } = await openPage(s.browser, `${s.server.url}#claim=${QUICK.id}`);
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  // The About tab shows the claim's model (whatever model is in view), the row focused.
  await page.waitForFunction((id) => document.activeElement?.id === `claim-${id}`, QUICK.id);
  assert.equal(await page.getAttribute('#tab-about', 'aria-selected'), 'true');
  const tr = page.locator(`#claim-${QUICK.id}`);
  assert.equal(await tr.locator('.claim-text').textContent(), row.claim);
  assert.match(await tr.getAttribute('class'), /claim-target/);

  // The link is shown (the section links to it) and copied.
  assert.equal(await tr.locator('td').first().locator('a').getAttribute('href'), `#claim=${QUICK.id}`);
  await tr.locator('button:text-is("Copy link")').click();
  assert.equal(await tr.locator('button[data-link]').getAttribute('data-link'), `${s.server.url}#claim=${QUICK.id}`);

  // Re-run from the keyboard: the experiment runs on the pool, then the core recomputes the claim.
  await tr.locator('button.rerun').focus();
  await page.keyboard.press('Enter');
  await page.waitForSelector('#paper-report .rerun-match', { timeout: 60000 });
  assert.equal(await page.getAttribute('#paper-report .rerun-box .progress', 'aria-valuenow'), '100');
  assert.equal(await page.textContent('#paper-report .rerun-figure'), row.kumiki);
  assert.equal(await page.textContent('#paper-report .rerun-runs'), String(row.runs));
  assert.equal(await page.getAttribute('#paper-report .rerun-verdict', 'class'), `verdict verdict-${row.verdict} rerun-verdict`);
  assert.equal(await page.getAttribute('#paper-report .rerun-match', 'data-same'), 'true');

  // The claim's experiment opens in the Experiments tab.
  await tr.locator('button:text-is("chobie-load")').click();
  assert.equal(await page.getAttribute('#tab-experiments', 'aria-selected'), 'true');
  assert.equal(JSON.parse(await page.inputValue('#experiment-json')).name, 'chobie-load');
  assert.deepEqual(problems, []);
  await context.close();
});

test("a claim read from two experiments re-runs both to the report's row", async () => {
  const id = 'fracta-11-units-starting-from-a-two';
  const row = claim('fracta', id);
  assert.deepEqual(row.experiments, ['fracta-assembly', 'fracta-rings']);
  const { page, context, problems } = await openPage(s.browser, `${s.server.url}#claim=${id}`);
  await page.waitForFunction((id) => document.activeElement?.id === `claim-${id}`, id);
  await page.click(`#claim-${id} button.rerun`);
  await page.waitForSelector('#paper-report .rerun-match', { timeout: 120000 });
  assert.equal(await page.textContent('#paper-report .rerun-figure'), row.kumiki);
  assert.equal(await page.textContent('#paper-report .rerun-runs'), String(row.runs));
  assert.equal(await page.getAttribute('#paper-report .rerun-match', 'data-same'), 'true');
  assert.deepEqual(problems, []);
  await context.close();
});

test('a long re-run shows its progress and stops on Cancel; a row with no experiment says so', async () => {
  const id = 'cubes3d-from-the-zigzag-the-proposed-mrf';
  assert.deepEqual(claim('cubes3d', id).experiments, ['cubes-fig8']);
  const { page, context, problems } = await openPage(s.browser, `${s.server.url}#claim=${id}`);
  await page.waitForFunction((id) => document.activeElement?.id === `claim-${id}`, id);
  await page.click(`#claim-${id} button.rerun`);
  await page.waitForFunction(() => /^[1-9]\d* \/ \d+ runs/.test(document.querySelector('#paper-report .rerun-box [role="status"]')?.textContent ?? ''), null, {
    timeout: 60000,
  });
  await page.click('#paper-report .rerun-box button:text-is("Cancel")');
  assert.match(await page.textContent('#paper-report .rerun-box [role="status"]'), /^Cancelled after \d+ of \d+ runs\.$/);
  assert.equal(await page.$('#paper-report .rerun-match'), null);

  // The fracta pointer to the cubes3d section reads no experiment: nothing to re-run.
  const pointer = 'fracta-twelve-3-d-units-build-a';
  assert.deepEqual(claim('fracta', pointer).experiments, []);
  await page.evaluate((id) => (location.hash = `claim=${id}`), pointer);
  await page.waitForSelector(`#claim-${pointer}`);
  assert.equal(await page.$(`#claim-${pointer} button.rerun`), null);
  assert.match(await page.textContent(`#claim-${pointer}`), /nothing to re-run/);

  // A link to a claim the report does not have says so.
  await page.evaluate(() => (location.hash = 'claim=amas-no-such-claim'));
  await page.waitForSelector('#paper-report [role="alert"]');
  assert.match(await page.textContent('#paper-report [role="alert"]'), /amas-no-such-claim/);
  assert.deepEqual(problems, []);
  await context.close();
});

test("every model's rows fit the About panel, on a laptop (1366 × 768) and on a tablet: no sideways scrolling", async () => {
  const wasm = loadWasm();
  const models = new Map();
  for (const p of wasm.presets()) if (!models.has(p.model)) models.set(p.model, p.name);
  assert.deepEqual([...models.keys()].sort(), Object.keys(report.models).sort());
  // One page; each model's scenario opens from a link, as a shared one would.
  const { page, context, problems } = await openPage(s.browser, s.server.url, { width: 1366, height: 768 });
  for (const [model, preset] of models) {
    await page.setViewportSize({ width: 1366, height: 768 });
    await page.evaluate(
      (l) => {
        location.hash = l;
      },
      wasm.encode_link(wasm.preset_json(preset)),
    );
    await page.waitForFunction((m) => document.querySelector('#scenario-model').textContent === m, model);
    if (await page.isVisible('#intro')) {
      await page.click('#intro button.primary');
      await page.waitForSelector('#intro', { state: 'hidden' });
    }
    await page.click('#tab-about');
    await page.waitForFunction((m) => document.querySelector('#paper-report table.findings caption')?.textContent === `Reproduction of ${m}'s paper`, model);
    assert.equal(await page.locator('#paper-report table.findings tbody tr').count(), report.models[model].findings.length, model);
    for (const [width, height] of [
      [1366, 768],
      [768, 1024],
    ]) {
      await page.setViewportSize({ width, height });
      const [table, tableRoom, panel, panelRoom, doc] = await page.evaluate(() => {
        const t = document.querySelector('#paper-report .table-scroll');
        const p = document.querySelector('#panel-about');
        return [t.scrollWidth, t.clientWidth, p.scrollWidth, p.clientWidth, document.documentElement.scrollWidth];
      });
      assert.ok(
        table <= tableRoom && panel <= panelRoom && doc <= width,
        `${model} at ${width} px: table ${table}/${tableRoom}, panel ${panel}/${panelRoom}, page ${doc}`,
      );
    }
  }
  assert.deepEqual(problems, []);
  await context.close();
});
