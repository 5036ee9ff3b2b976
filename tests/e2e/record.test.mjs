// Recording: a PNG, a WebM and a GIF of the view download under names that carry the scenario, the
// seed and the steps, and decode: the PNG's size is the canvas's (or twice it), the GIF has one
// image per frame, the WebM one block per frame and a duration. The run is stepped frame by frame,
// so the frame counts are exact. Both the 2-D and the 3-D view are recorded. The frames are encoded
// in the worker: the page receives the file and no picture.
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { describe, test } from 'node:test';
import { inflateSync } from 'node:zlib';
import { loadWasm, openPage, session, settle, stepCount } from './harness.mjs';

const wasm = loadWasm();
const s = session();
const linkTo = (preset) => `${s.server.url}#${wasm.encode_link(wasm.preset_json(preset))}`;

/** Sets the dialog, records, and resolves with the download's name and bytes. */
async function recordFile(page, { format, steps = 1, every = 1, fps = 10, scale = 1, overlays = [] }) {
  await page.click('#open-record');
  await page.waitForSelector('#record[open]');
  await page.selectOption('#record-format', format);
  await page.selectOption('#record-scale', String(scale));
  for (const o of ['step', 'title', 'legend']) await page.setChecked(`#record-overlay-${o}`, overlays.includes(o));
  if (format !== 'png') {
    await page.fill('#record-steps', String(steps));
    await page.fill('#record-every', String(every));
    await page.fill('#record-fps', String(fps));
  }
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: 60000 }), page.click('#record-start')]);
  const bytes = await readFile(await download.path());
  await page.waitForFunction(() => /^Saved /.test(document.querySelector('#record-status').textContent));
  await page.click('#record-cancel');
  await page.waitForSelector('#record', { state: 'hidden' });
  return { name: download.suggestedFilename(), bytes };
}

/** The drawing buffer's size at scale `k`: the canvas's CSS size × device pixel ratio × k. */
function bufferSize(page, k) {
  return page.$eval(
    '#view',
    (c, scale) => {
      const r = c.getBoundingClientRect();
      const dpr = Math.min(2, devicePixelRatio || 1) * scale;
      return [Math.round(r.width * dpr), Math.round(r.height * dpr)];
    },
    k,
  );
}

/** A PNG's size and how many distinct byte values its pixels hold (1 or 2 for a blank picture). */
function readPng(bytes) {
  const [w, h, rgba] = pixelsOf(bytes);
  return { size: [w, h], distinct: new Set(rgba).size };
}

/** A GIF's logical screen size and its number of images, read block by block. */
function readGif(bytes) {
  assert.equal(bytes.toString('latin1', 0, 6), 'GIF89a');
  const size = [bytes.readUInt16LE(6), bytes.readUInt16LE(8)];
  let at = 13;
  if (bytes[10] & 0x80) at += 3 * 2 ** ((bytes[10] & 7) + 1);
  const skipSubBlocks = () => {
    while (bytes[at] !== 0) at += bytes[at] + 1;
    at++;
  };
  let images = 0;
  for (;;) {
    const block = bytes[at];
    if (block === 0x3b) break;
    if (block === 0x21) {
      at += 2;
      skipSubBlocks();
    } else if (block === 0x2c) {
      images++;
      const flags = bytes[at + 9];
      at += 10;
      if (flags & 0x80) at += 3 * 2 ** ((flags & 7) + 1);
      at++; // LZW minimum code size
      skipSubBlocks();
    } else {
      assert.fail(`unexpected GIF block 0x${block.toString(16)} at ${at}`);
    }
  }
  return { size, images };
}

/** EBML elements of a WebM, walked into the containers that hold what is counted. */
function readWebm(bytes) {
  const vint = (at, keepMarker) => {
    const first = bytes[at];
    let width = 1;
    while (width <= 8 && !(first & (0x80 >> (width - 1)))) width++;
    let value = keepMarker ? first : first & (0xff >> width);
    for (let i = 1; i < width; i++) value = value * 256 + bytes[at + i];
    return { value, width };
  };
  const CONTAINERS = new Set([0x18538067, 0x1549a966, 0x1f43b675, 0x1654ae6b, 0xae, 0xe0]);
  const found = { simpleBlocks: 0, blockGroups: 0, duration: null, timecodeScale: 1e6, header: false, size: null, codec: null };
  const walk = (from, to) => {
    for (let at = from; at < to; ) {
      const id = vint(at, true);
      const size = vint(at + id.width, false);
      const body = at + id.width + size.width;
      const unknown = size.value === 2 ** (7 * size.width) - 1;
      const end = unknown ? to : body + size.value;
      if (id.value === 0x1a45dfa3) found.header = true;
      else if (id.value === 0xa3) found.simpleBlocks++;
      else if (id.value === 0xa0) found.blockGroups++;
      else if (id.value === 0x4489) found.duration = size.value === 8 ? bytes.readDoubleBE(body) : bytes.readFloatBE(body);
      else if (id.value === 0x2ad7b1) found.timecodeScale = bytes.readUIntBE(body, size.value);
      else if (id.value === 0x86) found.codec = bytes.toString('latin1', body, end);
      else if (id.value === 0xb0) found.size = [bytes.readUIntBE(body, size.value), found.size?.[1]];
      else if (id.value === 0xba) found.size = [found.size?.[0], bytes.readUIntBE(body, size.value)];
      if (CONTAINERS.has(id.value)) walk(body, end);
      at = end;
    }
  };
  walk(0, bytes.length);
  return found;
}

/**
 * The browser's own decoders on the file: an image's size, or a video's size and duration. In a
 * blank page of the same browser: Kumiki's policy lets no blob: media into its own page.
 */
async function decodeInPage(page, bytes, type) {
  const blank = await page.context().newPage();
  const decoded = await blank.evaluate(
    async ([b64, mime]) => {
      const blob = new Blob([Uint8Array.from(atob(b64), (c) => c.charCodeAt(0))], { type: mime });
      if (mime.startsWith('image/')) {
        const bitmap = await createImageBitmap(blob);
        return { width: bitmap.width, height: bitmap.height };
      }
      const video = document.createElement('video');
      video.muted = true;
      video.src = URL.createObjectURL(blob);
      await new Promise((resolve, reject) => {
        video.onloadeddata = resolve;
        video.onerror = () => reject(new Error(`the video does not decode: ${video.error?.message}`));
      });
      return { width: video.videoWidth, height: video.videoHeight, duration: video.duration };
    },
    [bytes.toString('base64'), type],
  );
  await blank.close();
  return decoded;
}

describe('recording the 2-D view (amas-L)', () => {
  test('a PNG at the canvas resolution and at 2×, named after the scenario, seed and step', async () => {
    const { page, context, problems } = await openPage(s.browser, linkTo('amas-L'));
    const seed = JSON.parse(wasm.preset_json('amas-L')).seed;
    const one = await recordFile(page, { format: 'png' });
    assert.equal(one.name, `amas-L_seed${seed}_step0.png`);
    const png1 = readPng(one.bytes);
    assert.deepEqual(Object.values(await decodeInPage(page, one.bytes, 'image/png')), png1.size);
    assert.deepEqual(png1.size, await bufferSize(page, 1));
    assert.ok(png1.distinct > 8, `the picture shows something (${png1.distinct} distinct byte values)`);
    const two = await recordFile(page, { format: 'png', scale: 2 });
    assert.equal(two.name, `amas-L_seed${seed}_step0_2x.png`, 'a 2× picture never takes the 1× name');
    assert.deepEqual(readPng(two.bytes).size, await bufferSize(page, 2));
    // The worker draws the view: its next frame brings the canvas back to its own resolution.
    const own = await bufferSize(page, 1);
    await page.waitForFunction(([w, h]) => {
      const c = document.querySelector('#view');
      return c.width === w && c.height === h;
    }, own);
    assert.equal(await stepCount(page), 0, 'a picture does not step the run');
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('a WebM of 40 steps every 4: ten blocks, VP8 or VP9, a duration of one second at 10 fps', async () => {
    const { page, context, problems } = await openPage(s.browser, linkTo('amas-L'));
    const seed = JSON.parse(wasm.preset_json('amas-L')).seed;
    const { name, bytes } = await recordFile(page, { format: 'webm', steps: 40, every: 4, fps: 10 });
    assert.equal(name, `amas-L_seed${seed}_steps0-40.webm`);
    const webm = readWebm(bytes);
    assert.ok(webm.header, 'EBML header');
    assert.match(webm.codec, /^V_VP[89]$/);
    assert.equal(webm.simpleBlocks + webm.blockGroups, 10, 'one block per frame');
    assert.deepEqual(webm.size, await bufferSize(page, 1).then(([w, h]) => [w - (w % 2), h - (h % 2)]));
    assert.ok(webm.duration !== null, 'a Duration element');
    assert.ok(Math.abs((webm.duration * webm.timecodeScale) / 1e9 - 1) < 0.01, `duration ${webm.duration} × ${webm.timecodeScale} ns is one second`);
    assert.equal(await stepCount(page), 36, 'the last frame shows step 36 (it stands for steps 36 to 40)');
    const decoded = await decodeInPage(page, bytes, 'video/webm');
    assert.deepEqual([decoded.width, decoded.height], webm.size);
    assert.ok(Math.abs(decoded.duration - 1) < 0.01, `the browser reads a duration of ${decoded.duration} s`);
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('the frames are encoded in the worker: no picture crosses to the page, only the file', async () => {
    // Counts the pictures and files in what the page's workers send it.
    const watch = () => {
      const crossed = { pictures: 0, files: 0 };
      window.crossed = crossed;
      const Base = window.Worker;
      window.Worker = class extends Base {
        constructor(...args) {
          super(...args);
          this.addEventListener('message', (e) => {
            const values = e.data !== null && typeof e.data === 'object' ? Object.values(e.data) : [];
            crossed.pictures += values.filter(
              (v) => v instanceof ImageBitmap || v instanceof ImageData || (typeof VideoFrame !== 'undefined' && v instanceof VideoFrame),
            ).length;
            crossed.files += values.filter((v) => v instanceof Blob).length;
          });
        }
      };
    };
    const { page, context, problems } = await openPage(s.browser, linkTo('amas-L'), { init: watch });
    const { bytes } = await recordFile(page, { format: 'webm', steps: 40, every: 4, fps: 10 });
    const webm = readWebm(bytes);
    assert.equal(webm.simpleBlocks + webm.blockGroups, 10, 'ten frames were recorded');
    assert.deepEqual(await page.evaluate(() => window.crossed), { pictures: 0, files: 1 });
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('a GIF of 12 steps every 3: four images of the view', async () => {
    const { page, context, problems } = await openPage(s.browser, linkTo('amas-L'));
    const { name, bytes } = await recordFile(page, { format: 'gif', steps: 12, every: 3 });
    assert.match(name, /^amas-L_seed\d+_steps0-12\.gif$/);
    const gif = readGif(bytes);
    assert.equal(gif.images, 4);
    assert.deepEqual(gif.size, await bufferSize(page, 1));
    assert.deepEqual(Object.values(await decodeInPage(page, bytes, 'image/gif')), gif.size);
    assert.deepEqual(problems, []);
    await context.close();
  });

  test('a recording can be cancelled, and saves nothing; the run then takes requests again', async () => {
    const { page, context, problems } = await openPage(s.browser, linkTo('amas-L'));
    let downloads = 0;
    page.on('download', () => downloads++);
    await page.click('#open-record');
    await page.selectOption('#record-format', 'gif');
    await page.selectOption('#record-scale', '2');
    await page.fill('#record-steps', '100000');
    await page.fill('#record-every', '1');
    await page.click('#record-start');
    await page.waitForFunction(
      () =>
        Number(document.querySelector('#record-progress').getAttribute('aria-valuenow')) >= 0 &&
        /Frame [2-9]/.test(document.querySelector('#record-status').textContent),
    );
    await page.click('#record-cancel');
    await page.waitForFunction(() => /Cancelled/.test(document.querySelector('#record-status').textContent));
    assert.equal(downloads, 0);
    assert.equal(await page.isEnabled('#record-start'), true);
    // The worker held the page's resize back to 1× while it recorded, and takes it once stopped.
    await page.waitForFunction(
      ([w, h]) => {
        const c = document.querySelector('#view');
        return c.width === w && c.height === h;
      },
      await bufferSize(page, 1),
    );
    await page.click('#record-cancel');
    await settle(page);
    const before = await stepCount(page);
    await page.click('#step');
    await page.waitForFunction((n) => Number(document.querySelector('#step-count').textContent.replace(/,/g, '')) === n + 1, before);
    assert.deepEqual(problems, []);
    await context.close();
  });
});

describe('recording the 3-D view (cubes3d)', () => {
  test('a PNG and a WebM of the cubic lattice', async () => {
    const preset = 'cubes-cube8-ladder';
    const { page, context, problems } = await openPage(s.browser, linkTo(preset));
    const png = readPng((await recordFile(page, { format: 'png' })).bytes);
    assert.deepEqual(png.size, await bufferSize(page, 1));
    assert.ok(png.distinct > 8, `the picture shows the units (${png.distinct} distinct byte values)`);
    const { name, bytes } = await recordFile(page, { format: 'webm', steps: 6, every: 2, fps: 5 });
    assert.match(name, new RegExp(`^${preset}_seed\\d+_steps0-6\\.webm$`));
    const webm = readWebm(bytes);
    assert.equal(webm.simpleBlocks + webm.blockGroups, 3);
    assert.ok(Math.abs((webm.duration * webm.timecodeScale) / 1e9 - 0.6) < 0.01, `duration ${webm.duration}`);
    assert.deepEqual(problems, []);
    await context.close();
  });
});

/** A PNG's pixels in the page: [width, height, RGBA bytes as an array]. */
/**
 * A PNG's pixels, decoded here: `[width, height, rgba]`. Browsers write 8-bit RGB or RGBA without
 * interlacing; each row is unfiltered with the filter its first byte names (PNG section 9).
 */
function pixelsOf(bytes) {
  assert.deepEqual([...bytes.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a], 'PNG signature');
  const [w, h, depth, colour, interlace] = [bytes.readUInt32BE(16), bytes.readUInt32BE(20), bytes[24], bytes[25], bytes[28]];
  assert.ok(depth === 8 && (colour === 2 || colour === 6) && interlace === 0, `an 8-bit RGB(A) PNG (depth ${depth}, colour ${colour})`);
  const channels = colour === 6 ? 4 : 3;
  const idat = [];
  for (let at = 8; at < bytes.length; ) {
    const length = bytes.readUInt32BE(at);
    if (bytes.toString('latin1', at + 4, at + 8) === 'IDAT') idat.push(bytes.subarray(at + 8, at + 8 + length));
    at += 12 + length;
  }
  const raw = inflateSync(Buffer.concat(idat));
  const stride = w * channels;
  const rows = new Uint8Array(h * stride);
  for (let y = 0; y < h; y++) {
    const filter = raw[y * (stride + 1)];
    const src = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    const row = rows.subarray(y * stride, (y + 1) * stride);
    const up = y > 0 ? rows.subarray((y - 1) * stride, y * stride) : new Uint8Array(stride);
    for (let i = 0; i < stride; i++) {
      const a = i >= channels ? row[i - channels] : 0;
      const b = up[i];
      const c = i >= channels ? up[i - channels] : 0;
      let predicted = 0;
      if (filter === 1) predicted = a;
      else if (filter === 2) predicted = b;
      else if (filter === 3) predicted = (a + b) >> 1;
      else if (filter === 4) {
        const p = a + b - c;
        const [pa, pb, pc] = [Math.abs(p - a), Math.abs(p - b), Math.abs(p - c)];
        predicted = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      } else assert.equal(filter, 0, `row ${y}: filter ${filter}`);
      row[i] = (src[i] + predicted) & 0xff;
    }
  }
  const rgba = new Uint8Array(w * h * 4);
  for (let p = 0; p < w * h; p++) {
    rgba.set(rows.subarray(p * channels, p * channels + 3), 4 * p);
    rgba[4 * p + 3] = channels === 4 ? rows[p * channels + 3] : 255;
  }
  return [w, h, rgba];
}

describe('recording overlays', () => {
  test('the step counter, the title and the legend are drawn in their corners, only when asked for', async () => {
    const { page, context, problems } = await openPage(s.browser, linkTo('amas-L'));
    await page.click('#step');
    await page.waitForFunction(() => document.querySelector('#step-count').textContent === '1');
    const plain = pixelsOf((await recordFile(page, { format: 'png' })).bytes);
    const again = pixelsOf((await recordFile(page, { format: 'png' })).bytes);
    assert.deepEqual(again, plain, 'without overlays the same view gives the same picture');
    const [w, h] = plain;
    /** The share of pixels that differ from the plain picture in a region (fractions of the frame). */
    const changed = (shot, [x0, y0, x1, y1]) => {
      let n = 0;
      let all = 0;
      for (let y = Math.floor(y0 * h); y < Math.floor(y1 * h); y++) {
        for (let x = Math.floor(x0 * w); x < Math.floor(x1 * w); x++) {
          const i = 4 * (y * w + x);
          all++;
          if (shot[2][i] !== plain[2][i] || shot[2][i + 1] !== plain[2][i + 1] || shot[2][i + 2] !== plain[2][i + 2]) n++;
        }
      }
      return n / all;
    };
    const TOP_LEFT = [0, 0, 0.15, 0.06];
    const TOP_RIGHT = [0.88, 0, 1, 0.06];
    const BOTTOM_LEFT = [0, 0.94, 0.15, 1];
    const MIDDLE = [0.3, 0.3, 0.7, 0.7];
    const regions = { title: TOP_LEFT, step: TOP_RIGHT, legend: BOTTOM_LEFT };
    for (const which of ['step', 'title', 'legend']) {
      const { name, bytes } = await recordFile(page, { format: 'png', overlays: [which] });
      assert.equal(name, 'amas-L_seed1_step1.png');
      const shot = pixelsOf(bytes);
      for (const [other, region] of Object.entries(regions)) {
        const share = changed(shot, region);
        if (other === which) assert.ok(share > 0.2, `${which}: ${(share * 100).toFixed(0)} % of its corner is drawn over`);
        else assert.equal(share, 0, `${which} leaves the ${other} corner alone`);
      }
      assert.equal(changed(shot, MIDDLE), 0, `${which} leaves the middle of the view alone`);
    }
    // The step counter follows the run: the picture at step 2 differs from the one at step 1.
    const one = pixelsOf((await recordFile(page, { format: 'png', overlays: ['step'] })).bytes);
    await page.click('#step');
    await page.waitForFunction(() => document.querySelector('#step-count').textContent === '2');
    await settle(page);
    const two = pixelsOf((await recordFile(page, { format: 'png', overlays: ['step', 'title', 'legend'] })).bytes);
    assert.notDeepEqual(two[2], one[2]);
    assert.deepEqual(problems, []);
    await context.close();
  });
});

describe('recording with the Canvas 2D renderer', () => {
  for (const preset of ['amas-L', 'cubes-cube8-ladder']) {
    test(`${preset}: a PNG of the view as Canvas 2D draws it`, async () => {
      const { page, context, problems } = await openPage(s.browser, linkTo(preset));
      await page.click('#tab-about');
      await page.selectOption('#renderer-choice', 'canvas2d');
      await page.waitForSelector('body[data-renderer="canvas2d"]');
      const png = readPng((await recordFile(page, { format: 'png', scale: 2 })).bytes);
      assert.deepEqual(png.size, await bufferSize(page, 2));
      assert.ok(png.distinct > 8, `the picture shows the lattice (${png.distinct} distinct byte values)`);
      assert.deepEqual(problems, []);
      await context.close();
    });
  }
});
