// Links that never rot, in the page: a link from tests/fixtures/links.json opens and runs to the
// hash it gave when it was made. (A link made with another behaviour of its model, which opens
// with the notice that results may differ, is tests/unit/features.test.ts's.)
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';
import { loadWasm, openPage, session } from './harness.mjs';

const wasm = loadWasm();
const s = session('/');
const fixture = JSON.parse(readFileSync(new URL('../fixtures/links.json', import.meta.url), 'utf8'));

test('a fixture link opens without a notice and runs to the hash it gave when it was made', async () => {
  // A link whose model has not changed behaviour since it was made (a changed one shows the notice).
  const entry = fixture.find((e) => {
    const v = wasm.link_model_versions(e.link);
    return v.made_with === v.current && e.steps <= 200;
  });
  assert.ok(entry, 'the fixture holds a link of an unchanged model');
  const { page, context, problems } = await openPage(s.browser, `${s.server.url}#${entry.link}`);
  // The header names the scenario (a preset by its title in words, its code name beside it), or
  // an exercise by its title.
  const doc = JSON.parse(wasm.decode_link(entry.link));
  if (doc.exercise) assert.equal(await page.textContent('#scenario-name'), doc.exercise.title);
  else assert.equal(await page.textContent('#scenario-code'), entry.preset);
  assert.match(await page.textContent('#scenario-name'), /\S/);
  assert.ok(await page.isHidden('#link-notice'));
  await page.locator('#view').focus();
  for (let i = 0; i < entry.steps; i++) await page.keyboard.press('ArrowRight');
  // The fixture's hash is taken after `steps` steps or at the end of the run, whichever is first.
  await page.waitForFunction((h) => document.querySelector('#state-hash').textContent === h, entry.hash);
  assert.deepEqual(problems, []);
  await context.close();
});
