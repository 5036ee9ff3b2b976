// Regenerates the README's pictures: the page in headless Chromium, a preset or a lesson part-way
// through, at a window size. Usage (after npm run build):
//   node scripts/screenshot.mjs [preset|lesson] [steps] [overlay] [file] [WIDTHxHEIGHT]
// The README's three pictures, the first screen on a laptop and on a tablet and a comparison:
//   node scripts/screenshot.mjs amas-L 120 '' docs/screenshot.png 1366x768
//   node scripts/screenshot.mjs amas-L 120 '' docs/screenshot-tablet.png 768x1024
//   node scripts/screenshot.mjs lesson-amas-compare 60 '' docs/compare.png 1366x768
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import * as wasm from '../web/pkg/kumiki_wasm.js';
import { launch, serve } from '../tests/e2e/harness.mjs';
import { readCatalogue } from './catalog.mjs';

wasm.initSync({ module: readFileSync(fileURLToPath(new URL('../web/pkg/kumiki_wasm_bg.wasm', import.meta.url))) });
const [preset = 'amas-L', steps = '120', overlay = '', file = 'docs/screenshot.png', size = '1366x768'] = process.argv.slice(2);
const [width, height] = size.split('x').map(Number);
// The built-in scenarios and lessons, as the page fetches them (its module leaves them out: scripts/catalog.mjs).
const catalog = readCatalogue();
const link = wasm.encode_link(preset.startsWith('lesson-') ? catalog.lessonText[preset] : catalog.presetText[preset]);
const server = await serve('/');
const browser = await launch();
const page = await (await browser.newContext({ viewport: { width, height }, deviceScaleFactor: 1 })).newPage();
await page.goto(`${server.url}#${link}`);
await page.waitForSelector('body[data-ready="true"]');
// A link opens with its introduction; the screenshot shows the page behind it.
if (await page.isVisible('#intro')) {
  await page.click('#intro button.primary');
  await page.waitForSelector('#intro', { state: 'hidden' });
}
if (overlay) {
  await page.selectOption('#overlay', overlay);
}
await page.$eval('#speed', (s) => {
  s.value = '4';
  s.dispatchEvent(new Event('input'));
});
await page.click('#play');
await page.waitForFunction((n) => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) >= n, Number(steps), { timeout: 60000 });
await page.click('#play');
await page.waitForTimeout(400);
await page.screenshot({ path: fileURLToPath(new URL(`../${file}`, import.meta.url)) });
await browser.close();
await server.close();
console.log(`${file} written`);
