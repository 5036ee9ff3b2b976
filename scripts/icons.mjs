// Regenerates the installed app's icons (static/icons/*.png) from static/icon.svg, drawn by
// headless Chromium: 192 and 512 pixels, and a maskable 512 whose picture keeps inside the
// central 80 % circle that launchers may crop to. Usage: node scripts/icons.mjs
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { launch } from '../tests/e2e/harness.mjs';

const svg = readFileSync(fileURLToPath(new URL('../static/icon.svg', import.meta.url)), 'utf8');
const ICONS = [
  { file: 'icon-192.png', size: 192, inset: 0 },
  { file: 'icon-512.png', size: 512, inset: 0 },
  { file: 'icon-maskable-512.png', size: 512, inset: 0.16 },
];
const browser = await launch();
const page = await browser.newPage();
for (const { file, size, inset } of ICONS) {
  await page.setViewportSize({ width: size, height: size });
  const pad = Math.round(size * inset);
  await page.setContent(
    `<body style="margin:0;background:${inset ? '#1f2933' : 'transparent'}"><img style="display:block;margin:${pad}px;width:${size - 2 * pad}px;height:${size - 2 * pad}px" src="data:image/svg+xml;base64,${Buffer.from(svg).toString('base64')}"></body>`,
  );
  await page.screenshot({ path: fileURLToPath(new URL(`../static/icons/${file}`, import.meta.url)), omitBackground: !inset });
  console.log(`static/icons/${file}`);
}
await browser.close();
