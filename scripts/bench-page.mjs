// The page in headless Chromium: load to interactive (first frame drawn), and for workloads with
// a "page" entry ({"seconds": N}) the steps per second and frames per second while it plays at
// full speed.
import { performance } from 'node:perf_hooks';
import { launch, serve } from '../tests/e2e/harness.mjs';

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

export async function benchPage(pageSpecs, linkFor) {
  const server = await serve('/');
  const browser = await launch();
  try {
    const loads = [];
    for (let i = 0; i < 5; i++) {
      const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
      const page = await context.newPage();
      const t = performance.now();
      await page.goto(server.url);
      await page.waitForSelector('body[data-ready="true"]', { timeout: 60000 });
      loads.push(performance.now() - t);
      await context.close();
    }
    const runs = [];
    for (const spec of pageSpecs) {
      const seconds = spec.page.seconds ?? 10;
      const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
      const page = await context.newPage();
      await page.goto(`${server.url}#${linkFor(spec)}`);
      await page.waitForSelector('body[data-ready="true"]', { timeout: 60000 });
      // A shared link opens with its introduction, which would take the click on Play.
      if (await page.isVisible('#intro')) {
        await page.click('#intro button.primary');
        await page.waitForSelector('#intro', { state: 'hidden' });
      }
      await page.$eval('#speed', (s) => {
        s.value = '8';
        s.dispatchEvent(new Event('input'));
      });
      await page.click('#play');
      await page.waitForTimeout(1500);
      const read = () => page.evaluate(() => ({ steps: Number(document.querySelector('#step-count').textContent.replace(/,/g, '')), frames: Number(document.body.dataset.frames ?? 0), t: performance.now() }));
      const a = await read();
      await page.waitForTimeout(seconds * 1000);
      const b = await read();
      const renderer = await page.evaluate(() => document.body.dataset.renderer);
      runs.push({ name: spec.name, seconds, renderer, stepsPerSecond: ((b.steps - a.steps) * 1000) / (b.t - a.t), framesPerSecond: ((b.frames - a.frames) * 1000) / (b.t - a.t) });
      await context.close();
    }
    return { loads, loadMs: median(loads), runs };
  } finally {
    await browser.close();
    await server.close();
  }
}
