// Encoding a recording, in the simulation worker: a PNG of the view as it stands, or a WebM video
// or an animated GIF made by stepping the run frame by frame. It runs where the view is drawn, so
// no picture crosses to the page: only the finished file does. Each frame is taken after the run
// has stepped and the view has drawn the result, never on a clock, so a recording is the same on
// a slow machine and a fast one. No DOM here: WebCodecs, OffscreenCanvas and the two muxers only.
import { GIFEncoder, applyPalette, quantize } from 'gifenc';
import { ArrayBufferTarget, Muxer } from 'webm-muxer';
import { Cancelled, frameCount, type Overlays, type Progress, type Recorded, type RecordSettings } from './record';

/** What the recorder needs from the worker that owns the run and its view. */
export interface RecordHost {
  /** The step the run stands at. */
  steps(): number;
  /** Steps the run `count` steps (fewer where it ends) and resolves with where it stands. */
  advance(count: number): Promise<{ steps: number; finished: boolean }>;
  /** The view drawn at the step the run stands at. */
  captureFrame(): Promise<ImageBitmap>;
}

/** Draws any captured picture onto a canvas of a fixed size (the size the encoder was set up with). */
class Canvas {
  readonly canvas: OffscreenCanvas;
  readonly ctx: OffscreenCanvasRenderingContext2D;
  constructor(
    readonly width: number,
    readonly height: number,
  ) {
    this.canvas = new OffscreenCanvas(width, height);
    this.ctx = this.canvas.getContext('2d', { willReadFrequently: true })!;
  }
  /** Draws `picture`, then the overlays asked for, with `step` as the step counter. */
  draw(picture: ImageBitmap, step: number, overlays: Overlays | undefined) {
    this.ctx.fillStyle = '#000';
    this.ctx.fillRect(0, 0, this.width, this.height);
    this.ctx.drawImage(picture, 0, 0);
    picture.close();
    if (overlays) drawOverlays(this.ctx, this.width, this.height, step, overlays);
  }
}

/**
 * The overlays, each on a dark translucent plate so it reads over any colour: the title at the
 * top left, the step counter at the top right, the legend along the bottom left. Their size
 * follows the frame's height, so a 2x recording has 2x text.
 */
function drawOverlays(ctx: OffscreenCanvasRenderingContext2D, width: number, height: number, step: number, o: Overlays) {
  const font = Math.max(11, Math.round(height / 36));
  const pad = Math.round(font * 0.5);
  const line = font + 2 * pad;
  ctx.save();
  ctx.font = `600 ${font}px system-ui, sans-serif`;
  ctx.textBaseline = 'middle';
  const plate = (x: number, y: number, w: number, h: number) => {
    ctx.fillStyle = 'rgba(15, 23, 42, 0.72)';
    ctx.fillRect(x, y, w, h);
  };
  const text = (t: string, x: number, y: number) => {
    ctx.fillStyle = '#fff';
    ctx.fillText(t, x, y);
  };
  if (o.title) {
    plate(pad, pad, Math.min(width - 2 * pad, ctx.measureText(o.title).width + 2 * pad), line);
    text(o.title, 2 * pad, pad + line / 2);
  }
  if (o.step) {
    const t = `step ${step.toLocaleString('en-US')}`;
    const w = ctx.measureText(t).width + 2 * pad;
    plate(width - pad - w, pad, w, line);
    text(t, width - w, pad + line / 2);
  }
  if (o.legend?.length) {
    ctx.font = `${Math.round(font * 0.85)}px system-ui, sans-serif`;
    const sw = Math.round(font * 0.8);
    const items = o.legend.map((e) => ({ ...e, w: sw + pad + ctx.measureText(e.name).width }));
    // As many rows as the width needs.
    const rows: (typeof items)[] = [[]];
    let used = 0;
    for (const it of items) {
      if (used && used + it.w + 2 * pad > width - 4 * pad) {
        rows.push([]);
        used = 0;
      }
      rows[rows.length - 1].push(it);
      used += it.w + 2 * pad;
    }
    const rowH = sw + pad;
    const boxH = rows.length * rowH + pad;
    const boxW = Math.max(...rows.map((r) => r.reduce((a, it) => a + it.w + 2 * pad, 0))) + pad;
    const top = height - pad - boxH;
    plate(pad, top, boxW, boxH);
    rows.forEach((row, r) => {
      let x = 2 * pad;
      const y = top + pad + r * rowH;
      for (const it of row) {
        ctx.fillStyle = it.color;
        ctx.beginPath();
        if (it.round) ctx.arc(x + sw / 2, y + sw / 2, sw / 2, 0, 2 * Math.PI);
        else ctx.rect(x, y, sw, sw);
        ctx.fill();
        ctx.strokeStyle = 'rgba(255, 255, 255, 0.8)';
        ctx.lineWidth = 1;
        ctx.stroke();
        text(it.name, x + sw + pad / 2, y + sw / 2);
        x += it.w + 2 * pad;
      }
    });
  }
  ctx.restore();
}

/** The first frame's size, made even: VP8 and VP9 encode whole 2×2 chroma blocks. */
function evenSize(picture: ImageBitmap, even: boolean): [number, number] {
  const w = Math.max(2, picture.width);
  const h = Math.max(2, picture.height);
  return even ? [w - (w % 2), h - (h % 2)] : [w, h];
}

/** The video codecs tried, best first: WebM's VP9, then VP8. */
const CODECS: { webcodecs: string; webm: string }[] = [
  { webcodecs: 'vp09.00.10.08', webm: 'V_VP9' },
  { webcodecs: 'vp8', webm: 'V_VP8' },
];

async function videoCodec(width: number, height: number, fps: number): Promise<{ config: VideoEncoderConfig; webm: string }> {
  if (typeof VideoEncoder === 'undefined') throw new Error('this browser cannot encode video (it has no WebCodecs VideoEncoder); record a GIF instead');
  for (const c of CODECS) {
    const config: VideoEncoderConfig = { codec: c.webcodecs, width, height, framerate: fps, bitrate: Math.min(20e6, width * height * fps * 0.15) };
    const support = await VideoEncoder.isConfigSupported(config).catch(() => null);
    if (support?.supported) return { config, webm: c.webm };
  }
  throw new Error(`this browser cannot encode VP8 or VP9 video at ${width} × ${height}; record a GIF instead`);
}

/**
 * Records frames: `each(picture, index)` is called for every frame, after the run was stepped and
 * drawn. Resolves with the step the recording ends at: the start plus the steps recorded, or the
 * run's last step when it ended first (its last state is then the last frame).
 */
async function eachFrame(
  host: RecordHost,
  s: RecordSettings,
  signal: AbortSignal,
  progress: Progress,
  each: (picture: ImageBitmap, index: number) => Promise<void>,
): Promise<number> {
  const total = frameCount(s.steps, s.every);
  let at = host.steps();
  const end = at + total * s.every;
  for (let i = 0; i < total; i++) {
    if (signal.aborted) throw new Cancelled();
    if (i > 0) {
      const next = await host.advance(s.every);
      // The host lets the worker's messages in while it steps: Cancel may have come meanwhile.
      if (signal.aborted) throw new Cancelled();
      if (next.steps === at) return at;
      at = next.steps;
      if (next.finished) {
        await each(await host.captureFrame(), i);
        progress(total, total);
        return at;
      }
    }
    await each(await host.captureFrame(), i);
    progress(i + 1, total);
  }
  return end;
}

async function recordPng(host: RecordHost, s: RecordSettings): Promise<Blob> {
  const picture = await host.captureFrame();
  const [w, h] = evenSize(picture, false);
  const c = new Canvas(w, h);
  c.draw(picture, host.steps(), s.overlays);
  return c.canvas.convertToBlob({ type: 'image/png' });
}

/** Reads an EBML variable-length integer: its value (the length marker kept for IDs) and width. */
function ebmlVint(bytes: Uint8Array, at: number, isId: boolean): { value: number; width: number } {
  const first = bytes[at];
  let width = 1;
  while (width < 8 && !(first & (0x80 >> (width - 1)))) width++;
  let value = isId ? first : first & (0xff >> width);
  for (let i = 1; i < width; i++) value = value * 256 + bytes[at + i];
  return { value, width };
}

/**
 * Sets the Duration of a finished WebM (Segment › Info › Duration, in the file's timecode units)
 * to `ms`. The muxer stores the last frame's start, which leaves the last frame no time on screen;
 * the right duration is the last frame's end.
 */
function setWebmDuration(buffer: ArrayBuffer, ms: number) {
  const bytes = new Uint8Array(buffer);
  const view = new DataView(buffer);
  const SEGMENT = 0x18538067;
  const INFO = 0x1549a966;
  const DURATION = 0x4489;
  const walk = (from: number, to: number): boolean => {
    for (let at = from; at < to; ) {
      const id = ebmlVint(bytes, at, true);
      const size = ebmlVint(bytes, at + id.width, false);
      const body = at + id.width + size.width;
      if (id.value === DURATION) {
        if (size.value === 8) view.setFloat64(body, ms);
        else view.setFloat32(body, ms);
        return true;
      }
      if (id.value === SEGMENT || id.value === INFO) return walk(body, Math.min(to, body + size.value));
      at = body + size.value;
    }
    return false;
  };
  if (!walk(0, bytes.length)) throw new Error('the video has no Duration to set');
}

async function recordWebm(host: RecordHost, s: RecordSettings, signal: AbortSignal, progress: Progress): Promise<{ blob: Blob; to: number }> {
  let canvas: Canvas | null = null;
  let encoder: VideoEncoder | null = null;
  let muxer: Muxer<ArrayBufferTarget> | null = null;
  let failure: Error | null = null;
  let frames = 0;
  const frameUs = 1e6 / s.fps;
  // A key frame every two seconds of video, so a player can seek.
  const keyEvery = Math.max(1, Math.round(2 * s.fps));
  try {
    const to = await eachFrame(host, s, signal, progress, async (picture, i) => {
      if (!canvas) {
        const [w, h] = evenSize(picture, true);
        canvas = new Canvas(w, h);
        const { config, webm } = await videoCodec(w, h, s.fps);
        const mux = new Muxer({ target: new ArrayBufferTarget(), video: { codec: webm, width: w, height: h, frameRate: s.fps } });
        muxer = mux;
        encoder = new VideoEncoder({
          output: (chunk, meta) => mux.addVideoChunk(chunk, meta),
          error: (e) => (failure = e),
        });
        encoder.configure(config);
      }
      canvas.draw(picture, host.steps(), s.overlays);
      frames = i + 1;
      const frame = new VideoFrame(canvas.canvas, { timestamp: Math.round(i * frameUs), duration: Math.round(frameUs) });
      encoder!.encode(frame, { keyFrame: i % keyEvery === 0 });
      frame.close();
      // Keep the encoder's queue short, so memory stays bounded on long recordings.
      while (encoder!.encodeQueueSize > 4) await new Promise((r) => setTimeout(r, 5));
      if (failure) throw failure;
    });
    await encoder!.flush();
    if (failure) throw failure;
    muxer!.finalize();
    const { buffer } = muxer!.target;
    // The muxer's timecode unit is the millisecond (its default TimecodeScale of 10^6 ns).
    setWebmDuration(buffer, frames * (1000 / s.fps));
    return { blob: new Blob([buffer], { type: 'video/webm' }), to };
  } finally {
    if (encoder && (encoder as VideoEncoder).state !== 'closed') (encoder as VideoEncoder).close();
  }
}

async function recordGif(host: RecordHost, s: RecordSettings, signal: AbortSignal, progress: Progress): Promise<{ blob: Blob; to: number }> {
  const gif = GIFEncoder();
  let canvas: Canvas | null = null;
  // GIF delays are in hundredths of a second.
  const delay = Math.max(10, Math.round(100 / s.fps) * 10);
  const to = await eachFrame(host, s, signal, progress, async (picture) => {
    if (!canvas) {
      const [w, h] = evenSize(picture, false);
      canvas = new Canvas(w, h);
    }
    canvas.draw(picture, host.steps(), s.overlays);
    const { data } = canvas.ctx.getImageData(0, 0, canvas.width, canvas.height);
    // A palette per frame: the view's colours change as fields spread and robots move.
    const palette = quantize(data, 256);
    gif.writeFrame(applyPalette(data, palette), canvas.width, canvas.height, { palette, delay, repeat: 0 });
  });
  gif.finish();
  return { blob: new Blob([gif.bytes()], { type: 'image/gif' }), to };
}

/** Records as set, and resolves with the file and the steps it shows. */
export async function encode(host: RecordHost, s: RecordSettings, signal: AbortSignal, progress: Progress): Promise<Recorded> {
  const from = host.steps();
  if (s.format === 'png') {
    const blob = await recordPng(host, s);
    progress(1, 1);
    return { blob, from, to: from };
  }
  const { blob, to } = s.format === 'webm' ? await recordWebm(host, s, signal, progress) : await recordGif(host, s, signal, progress);
  return { blob, from, to };
}
