// The gallery's pictures: a worker that opens each built-in scenario or lesson it is sent,
// draws its first step with the page's own renderer (crate/view, Canvas 2D, on an OffscreenCanvas)
// and sends back the picture. It starts with the page's compiled module; nothing is downloaded.
import init, { Sim, Viewer } from '../../pkg/kumiki_wasm.js';

export type ToPictureWorker = { type: 'module'; module: WebAssembly.Module } | { type: 'draw'; name: string; text: string; width: number; height: number };
export type FromPictureWorker = { type: 'drawn'; name: string; picture: ImageBitmap } | { type: 'failed'; name: string; message: string };

const scope = self as unknown as DedicatedWorkerGlobalScope;
const queue: ToPictureWorker[] = [];
let ready = false;

function draw(text: string, width: number, height: number) {
  const sim = new Sim(text);
  const viewer = new Viewer(new OffscreenCanvas(width, height), undefined, 'canvas2d');
  try {
    viewer.resize(width, height, 1);
    viewer.set_layout_of(sim);
    viewer.fit();
    viewer.draw_sim(sim, undefined);
    return viewer.capture();
  } finally {
    viewer.free();
    sim.free();
  }
}

function take(msg: ToPictureWorker) {
  if (msg.type !== 'draw') return;
  try {
    const picture = draw(msg.text, msg.width, msg.height);
    scope.postMessage({ type: 'drawn', name: msg.name, picture } satisfies FromPictureWorker, [picture]);
  } catch (e) {
    scope.postMessage({ type: 'failed', name: msg.name, message: e instanceof Error ? e.message : String(e) } satisfies FromPictureWorker);
  }
}

scope.onmessage = (e: MessageEvent<ToPictureWorker>) => {
  const msg = e.data;
  if (msg.type === 'module') {
    void init({ module_or_path: msg.module }).then(() => {
      ready = true;
      for (const m of queue.splice(0)) take(m);
    });
  } else if (ready) take(msg);
  else queue.push(msg);
};
