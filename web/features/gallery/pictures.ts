// The gallery's pictures, drawn on demand: the first time the gallery opens, a worker
// (picture-worker.ts) draws each card's scenario as it comes into view, and the pictures are kept
// for the next time.
import { wasmModule } from '../../wasm';
import type { FromPictureWorker, ToPictureWorker } from './picture-worker';

/** A picture's size in CSS pixels (drawn at twice that for sharp screens). */
export const PICTURE = { width: 160, height: 100 };

export class Pictures {
  private worker: Worker | null = null;
  private readonly drawn = new Map<string, ImageBitmap>();
  private readonly asked = new Set<string>();
  /** Canvases waiting for their picture, by scenario name. */
  private readonly waiting = new Map<string, HTMLCanvasElement[]>();
  private readonly seen = new IntersectionObserver((entries) => {
    for (const entry of entries) {
      if (!entry.isIntersecting) continue;
      this.seen.unobserve(entry.target);
      const canvas = entry.target as HTMLCanvasElement;
      this.ask(canvas.dataset.picture ?? '');
    }
  });

  /** The text of each scenario asked for, by name. */
  private readonly texts = new Map<string, string>();

  /** A canvas that shows the picture of the scenario `name` (its text `text`) once drawn. */
  canvas(name: string, text: string, lesson: boolean): HTMLCanvasElement {
    this.texts.set(name, text);
    const canvas = document.createElement('canvas');
    canvas.className = 'card-picture';
    canvas.width = PICTURE.width * 2;
    canvas.height = PICTURE.height * 2;
    canvas.setAttribute('aria-hidden', 'true');
    canvas.dataset.picture = name;
    canvas.dataset.of = lesson ? 'lesson' : 'preset';
    const picture = this.drawn.get(name);
    if (picture) paint(canvas, picture);
    else {
      this.waiting.set(name, [...(this.waiting.get(name) ?? []), canvas]);
      this.seen.observe(canvas);
    }
    return canvas;
  }

  private ask(name: string) {
    const text = this.texts.get(name);
    if (!name || text === undefined || this.asked.has(name)) return;
    this.asked.add(name);
    this.start().postMessage({ type: 'draw', name, text, width: PICTURE.width * 2, height: PICTURE.height * 2 } satisfies ToPictureWorker);
  }

  private start(): Worker {
    if (this.worker) return this.worker;
    const worker = new Worker(new URL('./picture-worker.ts', import.meta.url), { type: 'module', name: 'kumiki-pictures' });
    worker.onmessage = (e: MessageEvent<FromPictureWorker>) => {
      const msg = e.data;
      const canvases = this.waiting.get(msg.name) ?? [];
      this.waiting.delete(msg.name);
      if (msg.type !== 'drawn') return;
      this.drawn.set(msg.name, msg.picture);
      for (const c of canvases) paint(c, msg.picture);
    };
    void wasmModule().then((module) => worker.postMessage({ type: 'module', module } satisfies ToPictureWorker));
    this.worker = worker;
    return worker;
  }
}

function paint(canvas: HTMLCanvasElement, picture: ImageBitmap) {
  canvas.getContext('2d')?.drawImage(picture, 0, 0, canvas.width, canvas.height);
  canvas.dataset.drawn = 'true';
}
