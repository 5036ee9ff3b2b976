// Reading the page's cell labels back off its annotation layer, for the browser tests.

/**
 * Runs in the page (`page.evaluate(readLabels, names)`). Reads the cell labels off the annotation layer: groups its white label pixels into one glyph
 * group per label, reads each group by matching it against every legend name drawn the way the
 * page draws labels, and takes the colour the renderer filled that cell with. Returns one
 * { read, score, runnerUp, colour } per label: the best-matching name, its overlap (1 is a
 * pixel-perfect match), the next name's overlap, and the fill colour under the label.
 */
export async function readLabels(names) {
  const ann = document.querySelector('#annotations');
  const view = document.querySelector('#view');
  // The canvases are drawn by the worker: their pixels are read from what they show.
  const bitmap = await createImageBitmap(ann);
  const W = bitmap.width;
  const H = bitmap.height;
  const dpr = W / ann.clientWidth;
  const shown = new OffscreenCanvas(W, H).getContext('2d');
  shown.drawImage(bitmap, 0, 0);
  const data = shown.getImageData(0, 0, W, H).data;
  // Label text is filled pure white; bonds are dark and arrows translucent.
  const white = (i) => data[i * 4] >= 200 && data[i * 4 + 1] >= 200 && data[i * 4 + 2] >= 200 && data[i * 4 + 3] >= 250;
  const label = new Int32Array(W * H).fill(-1);
  const parts = [];
  for (let i = 0; i < W * H; i++) {
    if (!white(i) || label[i] >= 0) continue;
    const pixels = [];
    const stack = [i];
    label[i] = parts.length;
    while (stack.length) {
      const j = stack.pop();
      pixels.push(j);
      const x = j % W;
      const y = (j - x) / W;
      for (let dy = -1; dy <= 1; dy++) {
        for (let dx = -1; dx <= 1; dx++) {
          const nx = x + dx;
          const ny = y + dy;
          const k = ny * W + nx;
          if (nx >= 0 && ny >= 0 && nx < W && ny < H && label[k] < 0 && white(k)) {
            label[k] = parts.length;
            stack.push(k);
          }
        }
      }
    }
    parts.push(pixels);
  }
  const centre = (pixels) => {
    let sx = 0;
    let sy = 0;
    for (const j of pixels) {
      sx += j % W;
      sy += Math.floor(j / W);
    }
    return [sx / pixels.length, sy / pixels.length];
  };
  // Pieces of one label (the dot of an i) lie closer together than labels of neighbouring cells.
  const groups = [];
  for (const p of parts) {
    const c = centre(p);
    const near = groups.find((g) => Math.hypot(g.c[0] - c[0], g.c[1] - c[1]) < 10 * dpr);
    if (near) {
      near.pixels.push(...p);
      near.c = centre(near.pixels);
    } else groups.push({ pixels: p, c });
  }
  // Neighbouring cell centres are one world unit apart: the camera's scale, in CSS pixels.
  let scale = Infinity;
  for (const a of groups) for (const b of groups) if (a !== b) scale = Math.min(scale, Math.hypot(a.c[0] - b.c[0], a.c[1] - b.c[1]) / dpr);
  const fontPx = Math.min(16, scale * 0.32);

  // Each name drawn as the page draws labels, as a set of white pixel offsets from its centroid.
  const R = Math.ceil(fontPx * dpr * 2);
  const scratch = document.createElement('canvas');
  scratch.width = 2 * R;
  scratch.height = 2 * R;
  const sctx = scratch.getContext('2d', { willReadFrequently: true });
  const shapeOf = (pixels, width) => {
    const set = new Set();
    let sx = 0;
    let sy = 0;
    for (const j of pixels) {
      sx += j % width;
      sy += Math.floor(j / width);
    }
    const cx = Math.round(sx / pixels.length);
    const cy = Math.round(sy / pixels.length);
    for (const j of pixels) set.add(`${(j % width) - cx},${Math.floor(j / width) - cy}`);
    return set;
  };
  // Text lands on the pixel grid wherever the cell centre falls: draw each name at sixteen
  // sub-pixel offsets.
  const templates = [];
  for (const name of names) {
    for (let k = 0; k < 16; k++) {
      const ox = (k % 4) / 4;
      const oy = Math.floor(k / 4) / 4;
      sctx.setTransform(1, 0, 0, 1, 0, 0);
      sctx.clearRect(0, 0, 2 * R, 2 * R);
      sctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      sctx.font = `600 ${fontPx}px system-ui, sans-serif`;
      sctx.textAlign = 'center';
      sctx.textBaseline = 'middle';
      sctx.lineWidth = 3;
      sctx.strokeStyle = 'rgba(0,0,0,0.6)';
      sctx.fillStyle = '#fff';
      sctx.strokeText(name, R / dpr + ox, R / dpr + oy);
      sctx.fillText(name, R / dpr + ox, R / dpr + oy);
      const d = sctx.getImageData(0, 0, 2 * R, 2 * R).data;
      const pixels = [];
      for (let i = 0; i < 4 * R * R; i++) if (d[i * 4] >= 200 && d[i * 4 + 1] >= 200 && d[i * 4 + 2] >= 200 && d[i * 4 + 3] >= 250) pixels.push(i);
      if (pixels.length) templates.push({ name, shape: shapeOf(pixels, 2 * R) });
    }
  }
  // Intersection over union of two pixel sets, the best over shifts of a pixel either way.
  const overlap = (a, b) => {
    let best = 0;
    for (let dy = -1; dy <= 1; dy++) {
      for (let dx = -1; dx <= 1; dx++) {
        let both = 0;
        for (const k of a) {
          const [x, y] = k.split(',').map(Number);
          if (b.has(`${x + dx},${y + dy}`)) both++;
        }
        best = Math.max(best, both / (a.size + b.size - both));
      }
    }
    return best;
  };

  // The renderer's fill under each label, from the main canvas.
  const probe = document.createElement('canvas');
  probe.width = W;
  probe.height = H;
  const pctx = probe.getContext('2d', { willReadFrequently: true });
  pctx.drawImage(view, 0, 0, W, H);
  return groups.map((g) => {
    const shape = shapeOf(g.pixels, W);
    const best = new Map();
    for (const t of templates) best.set(t.name, Math.max(best.get(t.name) ?? 0, overlap(shape, t.shape)));
    const scored = [...best].sort((a, b) => b[1] - a[1]);
    const [x, y] = g.c.map(Math.round);
    const colour = Array.from(pctx.getImageData(x, y, 1, 1).data.slice(0, 3));
    return { read: scored[0][0], score: scored[0][1], runnerUp: scored[1]?.[1] ?? 0, colour };
  });
}
