// The annotation layer, drawn with Canvas 2D over either renderer: events of the last step,
// gradient arrows, cell labels, the hovered cell, highlighted cells and the keyboard cursor. Only
// what is visible and large enough to read is drawn.
import type { Camera2D, Camera3D } from './camera';
import { HEX_RADIUS, cellCentre, hexCorners, neighbours } from './geometry';
import type { Scene } from './renderer';

export interface Marks {
  arrows: boolean;
  labels: boolean;
  hover: number;
  highlight: number[];
  /** A value per highlighted cell (the difference at a reachable position), labelled in 3-D. */
  highlightValues?: number[];
  /** The cell picked with the inspector, outlined. */
  selected?: number;
  /** An editing cursor in 3-D (where a unit would be added or removed), or the keyboard cursor. */
  cursor?: { cell: number; kind: 'add' | 'remove' | 'cursor' } | null;
  /** One slot's signals: pairs (cell, lit faces as a mask of lattice directions); a sender
   * with no face bit (a signal along a route or a line) is ringed. */
  signals?: number[];
  /** Units drawn displaced over the view: triples (cell, dx, dy) in cells, y down. */
  displaced?: number[];
  /** 3-D view options (default on). */
  ghost?: boolean;
  bonds?: boolean;
}

const MAX_VISIBLE = 40000;

export function annotate(ctx: CanvasRenderingContext2D, dpr: number, scene: Scene, marks: Marks) {
  const { canvas } = ctx;
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  if (scene.camera.kind !== '2d') {
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    labelReach(ctx, scene, scene.camera, marks);
    return;
  }
  const cam = scene.camera;
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  const { layout, frame } = scene;
  const [w, h] = layout.dims;
  const vis = cam.visible();
  const x0 = Math.max(0, Math.floor(vis.x0) - 1);
  const x1 = Math.min(w - 1, Math.ceil(vis.x1));
  const yScale = layout.lattice === 'hex' ? Math.sqrt(3) / 2 : 1;
  const y0 = Math.max(0, Math.floor(vis.y0 / yScale) - 1);
  const y1 = Math.min(h - 1, Math.ceil(vis.y1 / yScale));
  const visibleCount = Math.max(0, x1 - x0 + 1) * Math.max(0, y1 - y0 + 1);
  const centre = (i: number) => cam.toScreen(...cellCentre(layout.lattice, i % w, Math.floor(i / w)));

  const bonds = frame.bonds;
  if (bonds && cam.scale >= 7 && visibleCount <= MAX_VISIBLE) {
    // Each bond once, from the cell whose neighbour lies in direction 0..half.
    ctx.strokeStyle = 'rgba(20,26,33,0.85)';
    ctx.lineWidth = Math.max(1.5, cam.scale * 0.14);
    ctx.lineCap = 'round';
    ctx.beginPath();
    for (let y = y0; y <= y1; y++) {
      for (let x = x0; x <= x1; x++) {
        const i = y * w + x;
        const mask = bonds[i];
        if (!mask) continue;
        const around = neighbours(layout, i, true);
        const [ax, ay] = centre(i);
        for (let d = 0; d < around.length; d++) {
          const j = around[d];
          if (j < 0 || j < i || !(mask & (1 << d))) continue;
          const [bx, by] = centre(j);
          // A connector across the shared edge, clear of the labels at the centres.
          ctx.moveTo(ax + (bx - ax) * 0.34, ay + (by - ay) * 0.34);
          ctx.lineTo(bx - (bx - ax) * 0.34, by - (by - ay) * 0.34);
        }
      }
    }
    ctx.stroke();
    ctx.lineCap = 'butt';
  }

  const field = scene.overlay;
  const info = field ? layout.fields.find((f) => f.name === field.name) : undefined;
  if (marks.arrows && field && info?.arrows && cam.scale >= 12 && visibleCount <= MAX_VISIBLE) {
    ctx.strokeStyle = 'rgba(255,255,255,0.85)';
    ctx.fillStyle = 'rgba(255,255,255,0.85)';
    ctx.lineWidth = Math.max(1, cam.scale * 0.06);
    for (let y = y0; y <= y1; y++) {
      for (let x = x0; x <= x1; x++) {
        const i = y * w + x;
        const v = field.data[i];
        if (Number.isNaN(v)) continue;
        let best = -1;
        let bestV = v;
        for (const j of neighbours(layout, i)) {
          const u = field.data[j];
          if (!Number.isNaN(u) && u < bestV) {
            bestV = u;
            best = j;
          }
        }
        if (best < 0) continue;
        arrow(ctx, centre(i), centre(best), cam.scale);
      }
    }
  }

  if (marks.labels && layout.cell_labels === true && cam.scale >= 22 && visibleCount <= MAX_VISIBLE) {
    const names = new Map(layout.cells.map((c) => [c.code, c.name]));
    ctx.font = `600 ${Math.min(16, cam.scale * 0.32)}px system-ui, sans-serif`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.lineWidth = 3;
    ctx.strokeStyle = 'rgba(0,0,0,0.6)';
    ctx.fillStyle = '#fff';
    for (let y = y0; y <= y1; y++) {
      for (let x = x0; x <= x1; x++) {
        const i = y * w + x;
        const name = names.get(frame.cells[i]);
        if (!frame.cells[i] || !name) continue;
        const [sx, sy] = centre(i);
        ctx.strokeText(name, sx, sy);
        ctx.fillText(name, sx, sy);
      }
    }
  }

  const events = frame.events;
  if (events.length) {
    // One path per kind: a large run has hundreds of events a step.
    const radius = Math.max(4, cam.scale * 0.48);
    ctx.lineWidth = Math.max(1.5, cam.scale * 0.1);
    for (const kind of layout.events) {
      ctx.strokeStyle = kind.color;
      ctx.beginPath();
      for (let k = 0; k + 1 < events.length; k += 2) {
        if (events[k + 1] !== kind.code) continue;
        const [sx, sy] = centre(events[k]);
        if (sx < -radius || sy < -radius || sx > cam.width + radius || sy > cam.height + radius) continue;
        ctx.moveTo(sx + radius, sy);
        ctx.arc(sx, sy, radius, 0, Math.PI * 2);
      }
      ctx.stroke();
    }
  }

  const displaced = marks.displaced;
  if (displaced?.length && layout.lattice === 'square') {
    // The deflected shape: each unit's square moved by its (scaled) displacement.
    ctx.fillStyle = 'rgba(43,149,214,0.28)';
    ctx.strokeStyle = 'rgba(16,107,163,0.9)';
    ctx.lineWidth = 1;
    const side = cam.scale * 0.9;
    for (let k = 0; k + 2 < displaced.length; k += 3) {
      const i = displaced[k];
      const [wx, wy] = cellCentre(layout.lattice, i % w, Math.floor(i / w));
      const [sx, sy] = cam.toScreen(wx + displaced[k + 1], wy + displaced[k + 2]);
      ctx.fillRect(sx - side / 2, sy - side / 2, side, side);
      ctx.strokeRect(sx - side / 2, sy - side / 2, side, side);
    }
  }

  const signals = marks.signals;
  if (signals?.length) {
    ctx.strokeStyle = 'rgba(240,180,41,0.95)';
    ctx.fillStyle = 'rgba(240,180,41,0.95)';
    ctx.lineWidth = Math.max(1.5, cam.scale * 0.08);
    const radius = Math.max(3, cam.scale * 0.3);
    for (let k = 0; k + 1 < signals.length; k += 2) {
      const i = signals[k];
      const faces = signals[k + 1];
      const from = centre(i);
      if (!faces) {
        ctx.beginPath();
        ctx.arc(from[0], from[1], radius, 0, Math.PI * 2);
        ctx.stroke();
        continue;
      }
      const around = neighbours(layout, i, true);
      for (let d = 0; d < around.length; d++) {
        if (!(faces & (1 << d)) || around[d] < 0) continue;
        // An arrow from the sender's centre toward the face it lights.
        const to = centre(around[d]);
        arrow(ctx, [(from[0] * 2 + to[0]) / 3, (from[1] * 2 + to[1]) / 3], to, cam.scale);
      }
    }
  }

  for (const i of marks.highlight) outline(ctx, scene, cam, i, 'rgba(240,180,41,0.95)');
  if (marks.hover >= 0) outline(ctx, scene, cam, marks.hover, 'rgba(255,255,255,0.9)');
  // The keyboard cursor: dark and light, so it shows on any cell colour.
  const cursor = marks.cursor;
  if (cursor && cursor.kind === 'cursor' && cursor.cell >= 0) {
    outline(ctx, scene, cam, cursor.cell, 'rgba(0,0,0,0.9)', 5);
    outline(ctx, scene, cam, cursor.cell, '#ffd166', 2.5);
  }
}

function outline(ctx: CanvasRenderingContext2D, scene: Scene, cam: Camera2D, i: number, color: string, width = 2) {
  const { layout } = scene;
  const w = layout.dims[0];
  const [wx, wy] = cellCentre(layout.lattice, i % w, Math.floor(i / w));
  const [sx, sy] = cam.toScreen(wx, wy);
  ctx.strokeStyle = color;
  ctx.lineWidth = width;
  ctx.beginPath();
  if (layout.lattice === 'hex') {
    const c = hexCorners(sx, sy, HEX_RADIUS * cam.scale);
    ctx.moveTo(c[0][0], c[0][1]);
    for (let k = 1; k < 6; k++) ctx.lineTo(c[k][0], c[k][1]);
    ctx.closePath();
  } else {
    ctx.rect(sx - cam.scale / 2, sy - cam.scale / 2, cam.scale, cam.scale);
  }
  ctx.stroke();
}

function arrow(ctx: CanvasRenderingContext2D, [ax, ay]: [number, number], [bx, by]: [number, number], scale: number) {
  const dx = bx - ax;
  const dy = by - ay;
  const len = Math.hypot(dx, dy) || 1;
  const ux = dx / len;
  const uy = dy / len;
  const half = scale * 0.3;
  const sx = ax - ux * half;
  const sy = ay - uy * half;
  const ex = ax + ux * half;
  const ey = ay + uy * half;
  ctx.beginPath();
  ctx.moveTo(sx, sy);
  ctx.lineTo(ex, ey);
  ctx.stroke();
  const head = scale * 0.14;
  ctx.beginPath();
  ctx.moveTo(ex, ey);
  ctx.lineTo(ex - ux * head - uy * head * 0.7, ey - uy * head + ux * head * 0.7);
  ctx.lineTo(ex - ux * head + uy * head * 0.7, ey - uy * head - ux * head * 0.7);
  ctx.closePath();
  ctx.fill();
}

/** In 3-D: the difference a unit would have at each highlighted (reachable) cell. */
function labelReach(ctx: CanvasRenderingContext2D, scene: Scene, cam: Camera3D, marks: Marks) {
  const values = marks.highlightValues;
  if (!marks.labels || !values?.length || marks.highlight.length > 64) return;
  const [w, h] = scene.layout.dims;
  ctx.font = '600 12px system-ui, sans-serif';
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  marks.highlight.forEach((i, k) => {
    const v = values[k];
    if (!Number.isFinite(v)) return;
    const p = cam.project((i % w) + 0.5, (Math.floor(i / w) % h) + 0.5, Math.floor(i / (w * h)) + 0.5);
    if (!p) return;
    const text = `D ${Number(v.toPrecision(3))}`;
    const width = ctx.measureText(text).width + 8;
    ctx.fillStyle = 'rgba(27,35,44,0.82)';
    ctx.beginPath();
    ctx.roundRect(p[0] - width / 2, p[1] - 9, width, 18, 4);
    ctx.fill();
    ctx.fillStyle = '#f0b429';
    ctx.fillText(text, p[0], p[1]);
  });
}
