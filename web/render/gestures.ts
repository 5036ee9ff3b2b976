// Gestures: one state machine turns pointer input (mouse, pen, touch with a two-finger pinch, a
// long press) and the wheel into what they mean (a tap, a drag that orbits or pans, a zoom about a
// point, a long press, hovering) for the lattice view and every editor. The machine is pure: it
// takes plain event records and an injected timer, so unit tests drive it with synthetic events;
// `bindGestures` wires it to an element, with pointer capture.

export interface Point {
  x: number;
  y: number;
}

export interface Modifiers {
  shiftKey: boolean;
  altKey: boolean;
  ctrlKey: boolean;
  metaKey: boolean;
}

/** A one-pointer drag turns a 3-D view (orbit) unless Shift, the right or the middle button pans. */
export type DragKind = 'orbit' | 'pan';

/** What the machine reads of a pointer event: its fields, with the position in element pixels. */
export interface PointerSample extends Point, Modifiers {
  pointerId: number;
  pointerType: string;
  /** The button that changed (0 main, 1 middle, 2 right). */
  button: number;
  /** The buttons held (1 main, 2 right, 4 middle). */
  buttons: number;
}

export interface WheelSample extends Point {
  deltaY: number;
  /** 0 pixels, 1 lines. */
  deltaMode: number;
}

export interface GestureHandlers {
  /** A pointer went down; `pointers` counts those down now, this one included. */
  press?(at: Point, button: number, mods: Modifiers, pointers: number): void;
  /** The last pointer lifted where it went down (within the tap slop), and no long press fired. */
  tap?(at: Point, button: number, mods: Modifiers): void;
  /** One pointer moved, or the midpoint of a pinch moved (then always a pan); `at` is where it is now. */
  drag?(dx: number, dy: number, kind: DragKind, at: Point): void;
  /**
   * Zoom by `factor` (above 1 closer) about `centre`: the pointer for the wheel; for a pinch, the
   * fingers' midpoint before the move (a pan to the new midpoint follows), so what is between the
   * fingers stays between them.
   */
  zoom?(factor: number, centre: Point): void;
  /** A touch or pen held still for `longPressMs`; a tap no longer follows. Off without a handler. */
  longPress?(at: Point): void;
  /** A pointer moved with nothing pressed (a mouse or a hovering pen). */
  hover?(at: Point, mods: Modifiers): void;
  /** The pointer left the element. */
  leave?(): void;
  /** The last pointer lifted or was cancelled. */
  release?(): void;
}

export interface GestureOptions {
  /** A press is a tap while its movement (|dx| + |dy| summed, 10 per pinch move) stays below this. */
  tapSlop: number;
  /** One-pointer moves are dropped until the movement reaches this. */
  dragSlop: number;
  longPressMs: number;
  /** A long press is called off once the pointer has moved this far. */
  longPressSlop: number;
}

const DEFAULT_GESTURES: GestureOptions = { tapSlop: 6, dragSlop: 0, longPressMs: 550, longPressSlop: 8 };

/** Movement a pinch step counts towards the tap slop: any pinch is a gesture, never a tap. */
const PINCH_MOVE = 10;

export interface Timer {
  set(f: () => void, ms: number): number;
  clear(id: number): void;
}

/** Zoom factor of one wheel event: lines (Firefox) step further than pixels. */
function wheelFactor(deltaY: number, deltaMode: number): number {
  return Math.exp(-deltaY * (deltaMode === 1 ? 0.05 : 0.0015));
}

const modifiers = (e: Modifiers): Modifiers => ({ shiftKey: e.shiftKey, altKey: e.altKey, ctrlKey: e.ctrlKey, metaKey: e.metaKey });

export class Gestures {
  private readonly opts: GestureOptions;
  private readonly pointers = new Map<number, Point>();
  private moved = 0;
  private pinch = 0;
  private mid: Point | null = null;
  private timer = 0;
  private longPressed = false;

  constructor(
    private readonly on: GestureHandlers,
    private readonly clock: Timer,
    options: Partial<GestureOptions> = {},
  ) {
    this.opts = { ...DEFAULT_GESTURES, ...options };
  }

  pointerDown(e: PointerSample) {
    const at = { x: e.x, y: e.y };
    this.pointers.set(e.pointerId, at);
    this.moved = 0;
    this.longPressed = false;
    this.pinchReset();
    this.clock.clear(this.timer);
    const longPress = this.on.longPress;
    if (longPress && e.pointerType !== 'mouse' && this.pointers.size === 1) {
      this.timer = this.clock.set(() => {
        if (this.moved >= this.opts.longPressSlop || this.pointers.size !== 1) return;
        this.longPressed = true;
        longPress(at);
      }, this.opts.longPressMs);
    }
    this.on.press?.(at, e.button, modifiers(e), this.pointers.size);
  }

  pointerMove(e: PointerSample) {
    const p = { x: e.x, y: e.y };
    const prev = this.pointers.get(e.pointerId);
    if (!prev) {
      this.on.hover?.(p, modifiers(e));
      return;
    }
    this.pointers.set(e.pointerId, p);
    if (this.pointers.size === 2) {
      // Two fingers: the spread zooms about where they were, then the midpoint's move pans.
      const d = this.spread();
      const mid = this.middle();
      if (this.pinch > 0 && d > 0 && this.mid) this.on.zoom?.(d / this.pinch, this.mid);
      if (this.mid && mid) this.on.drag?.(mid.x - this.mid.x, mid.y - this.mid.y, 'pan', mid);
      this.pinch = d;
      this.mid = mid;
      this.moved += PINCH_MOVE;
      return;
    }
    const dx = p.x - prev.x;
    const dy = p.y - prev.y;
    this.moved += Math.abs(dx) + Math.abs(dy);
    if (this.moved < this.opts.dragSlop) return;
    const pan = e.shiftKey || e.buttons === 2 || e.buttons === 4;
    this.on.drag?.(dx, dy, pan ? 'pan' : 'orbit', p);
  }

  /** A pointer lifted (`cancelled` false) or was taken away by the browser. */
  pointerUp(e: PointerSample, cancelled = false) {
    const p = this.pointers.get(e.pointerId);
    this.pointers.delete(e.pointerId);
    this.clock.clear(this.timer);
    if (!cancelled && p && this.moved < this.opts.tapSlop && this.pointers.size === 0 && !this.longPressed) {
      this.on.tap?.(p, e.button, modifiers(e));
    }
    this.pinchReset();
    if (p && this.pointers.size === 0) this.on.release?.();
  }

  pointerLeave() {
    this.on.leave?.();
  }

  wheel(e: WheelSample) {
    this.on.zoom?.(wheelFactor(e.deltaY, e.deltaMode), { x: e.x, y: e.y });
  }

  /** Stops a pending long press. */
  destroy() {
    this.clock.clear(this.timer);
  }

  private pinchReset() {
    this.pinch = this.spread();
    this.mid = this.middle();
  }

  private middle(): Point | null {
    if (this.pointers.size !== 2) return null;
    const [a, b] = [...this.pointers.values()];
    return { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
  }

  private spread(): number {
    if (this.pointers.size !== 2) return 0;
    const [a, b] = [...this.pointers.values()];
    return Math.hypot(a.x - b.x, a.y - b.y);
  }
}

/**
 * Wires the gesture machine to an element: captures each pointer that goes down, keeps the
 * context menu away (right-drag pans, right-click removes), and takes the wheel from the page only
 * when there is a zoom handler. `destroy` removes every listener.
 */
export function bindGestures(el: HTMLElement, on: GestureHandlers, options: Partial<GestureOptions> = {}): { destroy(): void } {
  const gestures = new Gestures(on, { set: (f, ms) => window.setTimeout(f, ms), clear: (id) => window.clearTimeout(id) }, options);
  const abort = new AbortController();
  const signal = abort.signal;
  const sample = (e: PointerEvent): PointerSample => {
    const r = el.getBoundingClientRect();
    const { pointerId, pointerType, button, buttons, shiftKey, altKey, ctrlKey, metaKey } = e;
    return { x: e.clientX - r.left, y: e.clientY - r.top, pointerId, pointerType, button, buttons, shiftKey, altKey, ctrlKey, metaKey };
  };
  el.addEventListener(
    'pointerdown',
    (e) => {
      el.setPointerCapture(e.pointerId);
      gestures.pointerDown(sample(e));
    },
    { signal },
  );
  el.addEventListener('pointermove', (e) => gestures.pointerMove(sample(e)), { signal });
  el.addEventListener('pointerup', (e) => gestures.pointerUp(sample(e)), { signal });
  el.addEventListener('pointercancel', (e) => gestures.pointerUp(sample(e), true), { signal });
  el.addEventListener('pointerleave', () => gestures.pointerLeave(), { signal });
  el.addEventListener('contextmenu', (e) => e.preventDefault(), { signal });
  if (on.zoom) {
    el.addEventListener(
      'wheel',
      (e) => {
        e.preventDefault();
        const r = el.getBoundingClientRect();
        gestures.wheel({ x: e.clientX - r.left, y: e.clientY - r.top, deltaY: e.deltaY, deltaMode: e.deltaMode });
      },
      { passive: false, signal },
    );
  }
  return {
    destroy() {
      abort.abort();
      gestures.destroy();
    },
  };
}
