// One renderer interface with two implementations, WebGL2 first and Canvas 2D as the fallback.
import type { Frame, Layout, SceneInfo } from '../types';
import type { Marks } from './annotate';
import type { Camera } from './camera';

export type RendererKind = 'webgl2' | 'canvas2d';

export interface Overlay {
  name: string;
  data: Float32Array;
  min: number;
  max: number;
}

export interface Scene {
  layout: Layout;
  frame: Frame;
  overlay: Overlay | null;
  camera: Camera;
  /** 3-D extras from the model (ghost, light, ground, bonds), when it has any. */
  world?: SceneInfo | null;
  /** Hover, selection, highlighted cells and view options; the 3-D paths draw them in depth. */
  marks?: Marks;
}

export interface Renderer {
  readonly kind: RendererKind;
  /** Called when a new run starts; rebuilds per-layout resources. */
  setLayout(layout: Layout): void;
  /** Resizes the drawing buffer to css size × device pixel ratio. */
  resize(cssWidth: number, cssHeight: number, dpr: number): void;
  draw(scene: Scene): void;
  destroy(): void;
}

export async function createRenderer(canvas: HTMLCanvasElement, prefer: RendererKind | 'auto'): Promise<Renderer> {
  if (prefer !== 'canvas2d') {
    const { WebGL2Renderer } = await import('./webgl2');
    const gl = WebGL2Renderer.create(canvas);
    if (gl) return gl;
  }
  const { Canvas2DRenderer } = await import('./canvas2d');
  const ctx = Canvas2DRenderer.create(canvas);
  if (!ctx) throw new Error('this browser offers neither WebGL2 nor Canvas 2D');
  return ctx;
}
