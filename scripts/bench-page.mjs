// The page in headless Chromium: load to interactive (first frame drawn), and for workloads with
// a "page" entry ({"seconds": N}) the steps per second and frames per second while it plays at
// full speed, with where the worker's time went (stepping, uploading buffers, issuing draws), and
// then the frames per second while its view is dragged for N seconds with the run paused (panned,
// or with {"orbit": true} turned, and then not played at all): what the renderer alone keeps up
// with.
import { performance } from 'node:perf_hooks';
import { launch, serve } from '../tests/e2e/harness.mjs';

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

/** Rates between two readings, and the worker's milliseconds per frame drawn. */
function rates(a, b) {
  const dt = (b.t - a.t) / 1000;
  const frames = b.work.frames - a.work.frames;
  const per = (k) => (frames > 0 ? (b.work[k] - a.work[k]) / frames : 0);
  return {
    stepsPerSecond: (b.steps - a.steps) / dt,
    framesPerSecond: frames / dt,
    stepMsPerSecond: (b.work.stepMs - a.work.stepMs) / dt,
    uploadMsPerFrame: per('uploadMs'),
    drawMsPerFrame: per('drawMs'),
  };
}

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
      const read = () =>
        page.evaluate(() => ({
          steps: Number(document.querySelector('#step-count').textContent.replace(/,/g, '')),
          work: JSON.parse(document.body.dataset.work ?? '{}'),
          t: performance.now(),
        }));
      const renderer = await page.evaluate(() => document.body.dataset.renderer);
      if (!spec.page.orbit) {
        await page.$eval('#speed', (s) => {
          s.value = '8';
          s.dispatchEvent(new Event('input'));
        });
        await page.click('#play');
        await page.waitForTimeout(1500);
        const a = await read();
        await page.waitForTimeout(seconds * 1000);
        const b = await read();
        runs.push({ name: spec.name, seconds, renderer, moving: 'playing', ...rates(a, b) });
        // Paused by the keyboard: a click would first wait for the page's own animation frames,
        // which come slowly while the software rasteriser is busy with the view.
        await page.keyboard.press('Space');
        await page.waitForSelector('#play[aria-pressed="false"]');
      }
      // The camera dragged while the run stands still: what the renderer alone keeps up with.
      const box = await page.locator('#view').boundingBox();
      const y = box.y + box.height / 2;
      await page.mouse.move(box.x + box.width * 0.3, y);
      await page.mouse.down();
      const a = await read();
      const until = Date.now() + seconds * 1000;
      for (let k = 0; Date.now() < until; k++) {
        await page.mouse.move(box.x + box.width * (0.3 + 0.4 * Math.abs(Math.sin(k / 30))), y);
        await page.waitForTimeout(8);
      }
      await page.mouse.up();
      await page.waitForTimeout(200);
      const b = await read();
      runs.push({ name: spec.name, seconds, renderer, moving: spec.page.orbit ? 'orbiting' : 'panning', ...rates(a, b) });
      await context.close();
    }
    return { loads, loadMs: median(loads), runs };
  } finally {
    await browser.close();
    await server.close();
  }
}
