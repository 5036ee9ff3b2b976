// Recording the view: a PNG of the view as it stands, or a WebM video or an animated GIF made by
// stepping the run frame by frame. Each video frame is taken after the worker has stepped and the
// page has drawn the result, never on a clock, so a recording is the same on a slow machine and a
// fast one. Where the picture comes from is one function, `captureFrame`, so the capture can move
// with the renderer (for example into the worker) without touching the encoders.
import { GIFEncoder, applyPalette, quantize } from 'gifenc';
import { ArrayBufferTarget, Muxer } from 'webm-muxer';
import { byId, download } from './dom';

export type RecordFormat = 'png' | 'webm' | 'gif';

export interface RecordSettings {
  format: RecordFormat;
  /** Steps to record, from the step in view. */
  steps: number;
  /** Steps between two frames. */
  every: number;
  /** Drawing-buffer multiple: 1 (the canvas's own resolution) or 2. */
  scale: number;
  /** Frames per second of the video or GIF. */
  fps: number;
}

/** What the recorder needs from the page. */
export interface RecordHost {
  /** The scenario's name, its seed, and the step in view. */
  describe(): { name: string; seed: number; steps: number };
  pause(): void;
  /** Steps the run and resolves once the frame at the new step has been drawn. */
  advance(count: number): Promise<{ steps: number; finished: boolean }>;
  /** Draws at `scale` times the usual resolution (1 restores it). */
  setScale(scale: number): void;
  /** The view as drawn now. */
  captureFrame(): Promise<ImageBitmap | ImageData>;
}

/** A file name: letters, digits, dot, dash and underscore only, never empty. */
export function sanitizeName(name: string): string {
  const clean = name
    .normalize('NFKD')
    .replace(/[\u0300-\u036f]/g, '')
    .replace(/[^A-Za-z0-9._-]+/g, '-')
    .replace(/[-.]{2,}/g, '-')
    .replace(/^[-.]+|[-.]+$/g, '')
    .slice(0, 60);
  return clean || 'kumiki';
}

/** `amas-L_seed1_steps0-400.webm`: the scenario, the seed and the steps the file shows. */
export function recordingName(name: string, seed: number, from: number, to: number, format: RecordFormat): string {
  const range = from === to ? `step${from}` : `steps${from}-${to}`;
  return `${sanitizeName(name)}_seed${seed}_${range}.${format}`;
}

/**
 * The frames of a recording of `steps` steps every `every`: one per interval, the first showing the
 * step in view. A video frame stands for the time until the next, so frame i shows step
 * from + i·every and the video's duration covers the `steps` steps (the file name's range).
 */
export function frameCount(steps: number, every: number): number {
  return Math.max(1, Math.floor(steps / every));
}

/** Raised by the recorder when the user cancels. */
class Cancelled extends Error {}

/** `promise`, or Cancelled as soon as the signal aborts (a step that never comes back stays cancellable). */
function untilAborted<T>(signal: AbortSignal, promise: Promise<T>): Promise<T> {
  if (signal.aborted) return Promise.reject(new Cancelled());
  return new Promise((resolve, reject) => {
    const abort = () => reject(new Cancelled());
    signal.addEventListener('abort', abort, { once: true });
    promise.then(
      (v) => {
        signal.removeEventListener('abort', abort);
        resolve(v);
      },
      (e: unknown) => {
        signal.removeEventListener('abort', abort);
        reject(e);
      },
    );
  });
}

type Progress = (done: number, total: number) => void;

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
  draw(picture: ImageBitmap | ImageData) {
    if (picture instanceof ImageData) {
      this.ctx.putImageData(picture, 0, 0);
      return;
    }
    this.ctx.fillStyle = '#000';
    this.ctx.fillRect(0, 0, this.width, this.height);
    this.ctx.drawImage(picture, 0, 0);
    picture.close();
  }
}

/** The first frame's size, made even: VP8 and VP9 encode whole 2×2 chroma blocks. */
function evenSize(picture: ImageBitmap | ImageData, even: boolean): [number, number] {
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
async function eachFrame(host: RecordHost, s: RecordSettings, signal: AbortSignal, progress: Progress, each: (picture: ImageBitmap | ImageData, index: number) => Promise<void>): Promise<number> {
  const total = frameCount(s.steps, s.every);
  let at = host.describe().steps;
  const end = at + total * s.every;
  for (let i = 0; i < total; i++) {
    if (signal.aborted) throw new Cancelled();
    if (i > 0) {
      const next = await untilAborted(signal, host.advance(s.every));
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

async function recordPng(host: RecordHost): Promise<Blob> {
  const picture = await host.captureFrame();
  const [w, h] = evenSize(picture, false);
  const c = new Canvas(w, h);
  c.draw(picture);
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
      canvas.draw(picture);
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
    canvas.draw(picture);
    const { data } = canvas.ctx.getImageData(0, 0, canvas.width, canvas.height);
    // A palette per frame: the view's colours change as fields spread and robots move.
    const palette = quantize(data, 256);
    gif.writeFrame(applyPalette(data, palette), canvas.width, canvas.height, { palette, delay, repeat: 0 });
  });
  gif.finish();
  return { blob: new Blob([gif.bytes()], { type: 'image/gif' }), to };
}

/** Records as set, offers the file for download, and resolves with its name. */
export async function record(host: RecordHost, s: RecordSettings, signal: AbortSignal, progress: Progress): Promise<string> {
  host.pause();
  const { name, seed, steps: from } = host.describe();
  host.setScale(s.scale);
  try {
    if (s.format === 'png') {
      const file = recordingName(name, seed, from, from, 'png');
      download(file, await recordPng(host), 'image/png');
      progress(1, 1);
      return file;
    }
    const { blob, to } = s.format === 'webm' ? await recordWebm(host, s, signal, progress) : await recordGif(host, s, signal, progress);
    const file = recordingName(name, seed, from, to, s.format);
    download(file, blob, blob.type);
    return file;
  } finally {
    host.setScale(1);
  }
}

/** The "Record…" dialog: its form, its progress bar and its Cancel button. */
export function setupRecordDialog(host: RecordHost) {
  const dialog = byId<HTMLDialogElement>('record');
  const form = byId<HTMLFormElement>('record-form');
  const format = byId<HTMLSelectElement>('record-format');
  const steps = byId<HTMLInputElement>('record-steps');
  const every = byId<HTMLInputElement>('record-every');
  const scale = byId<HTMLSelectElement>('record-scale');
  const fps = byId<HTMLInputElement>('record-fps');
  const start = byId<HTMLButtonElement>('record-start');
  const cancel = byId<HTMLButtonElement>('record-cancel');
  const bar = byId('record-progress');
  const status = byId('record-status');
  let running: AbortController | null = null;

  const showProgress = (done: number, total: number) => {
    const pct = Math.round((100 * done) / Math.max(1, total));
    (bar.firstElementChild as HTMLElement).style.width = `${pct}%`;
    bar.setAttribute('aria-valuenow', String(pct));
    status.textContent = total > 1 ? `Frame ${done} of ${total}` : '';
  };
  const syncFields = () => {
    const still = format.value === 'png';
    byId('record-motion').hidden = still;
    for (const f of [steps, every, fps]) f.disabled = still || running !== null;
    cancel.textContent = running ? 'Cancel' : 'Close';
    const n = Math.max(1, Number(steps.value) || 1);
    const k = Math.max(1, Number(every.value) || 1);
    byId('record-summary').textContent = still ? 'One picture of the view as it stands.' : `${frameCount(n, k)} frames, ${(frameCount(n, k) / Math.max(1, Number(fps.value) || 1)).toFixed(1)} s long.`;
  };
  for (const f of [format, steps, every, fps]) f.addEventListener('input', syncFields);

  byId('open-record').addEventListener('click', () => {
    showProgress(0, 1);
    status.textContent = '';
    syncFields();
    dialog.showModal();
  });
  dialog.addEventListener('cancel', (e) => {
    // Escape during a recording cancels the recording first.
    if (running) {
      e.preventDefault();
      running.abort();
    }
  });
  cancel.addEventListener('click', () => {
    if (running) running.abort();
    else dialog.close();
  });
  form.addEventListener('submit', async (e) => {
    e.preventDefault();
    if (running || !form.reportValidity()) return;
    const settings: RecordSettings = {
      format: format.value as RecordFormat,
      steps: Math.max(1, Math.floor(Number(steps.value))),
      every: Math.max(1, Math.floor(Number(every.value))),
      scale: Number(scale.value) === 2 ? 2 : 1,
      fps: Math.min(60, Math.max(1, Number(fps.value))),
    };
    running = new AbortController();
    start.disabled = true;
    scale.disabled = format.disabled = true;
    syncFields();
    status.textContent = 'Recording…';
    try {
      const file = await record(host, settings, running.signal, showProgress);
      status.textContent = `Saved ${file}`;
    } catch (err) {
      status.textContent = err instanceof Cancelled ? 'Cancelled: nothing was saved.' : `The recording failed: ${err instanceof Error ? err.message : String(err)}`;
    } finally {
      running = null;
      start.disabled = false;
      scale.disabled = format.disabled = false;
      syncFields();
    }
  });
}
