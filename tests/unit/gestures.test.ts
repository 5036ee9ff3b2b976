import { describe, expect, it } from 'vitest';
import {
  type DragKind,
  type GestureHandlers,
  type GestureOptions,
  Gestures,
  type Modifiers,
  type Point,
  type PointerSample,
  type Timer,
} from '../../web/render/gestures';

/** A timer the test fires by hand. */
class FakeTimer implements Timer {
  private next = 1;
  readonly pending = new Map<number, { f: () => void; ms: number }>();
  set(f: () => void, ms: number) {
    const id = this.next++;
    this.pending.set(id, { f, ms });
    return id;
  }
  clear(id: number) {
    this.pending.delete(id);
  }
  fire() {
    const due = [...this.pending.values()];
    this.pending.clear();
    for (const { f } of due) f();
  }
}

type Call =
  | ['press', Point, number, number]
  | ['tap', Point, number, Modifiers]
  | ['drag', number, number, DragKind, Point]
  | ['zoom', number, Point]
  | ['longPress', Point]
  | ['hover', Point]
  | ['leave']
  | ['release'];

/** A machine whose every callback is recorded. */
function machine(options: Partial<GestureOptions> = {}, longPress = true) {
  const calls: Call[] = [];
  const timer = new FakeTimer();
  const on: GestureHandlers = {
    press: (at, button, _mods, pointers) => calls.push(['press', at, button, pointers]),
    tap: (at, button, mods) => calls.push(['tap', at, button, mods]),
    drag: (dx, dy, kind, at) => calls.push(['drag', dx, dy, kind, at]),
    zoom: (factor, centre) => calls.push(['zoom', factor, centre]),
    hover: (at) => calls.push(['hover', at]),
    leave: () => calls.push(['leave']),
    release: () => calls.push(['release']),
  };
  if (longPress) on.longPress = (at) => calls.push(['longPress', at]);
  const g = new Gestures(on, timer, options);
  const of = (name: Call[0]) => calls.filter((c) => c[0] === name);
  return { g, calls, timer, of };
}

const NO_MODS: Modifiers = { shiftKey: false, altKey: false, ctrlKey: false, metaKey: false };

function pointer(x: number, y: number, over: Partial<PointerSample> = {}): PointerSample {
  return { x, y, pointerId: 1, pointerType: 'mouse', button: 0, buttons: 1, ...NO_MODS, ...over };
}

describe('tap or drag', () => {
  it('a press released in place is a tap at the press, with its button and modifiers', () => {
    const { g, of } = machine();
    g.pointerDown(pointer(10, 20, { button: 2, buttons: 2 }));
    g.pointerUp(pointer(10, 20, { button: 2, buttons: 0, altKey: true }));
    expect(of('press')).toEqual([['press', { x: 10, y: 20 }, 2, 1]]);
    expect(of('tap')).toEqual([['tap', { x: 10, y: 20 }, 2, { ...NO_MODS, altKey: true }]]);
    expect(of('release')).toHaveLength(1);
  });

  it('stays a tap below 6 pixels of movement (|dx| + |dy|), and is a drag from 6', () => {
    const wobble = (moves: [number, number][]) => {
      const { g, of } = machine();
      g.pointerDown(pointer(100, 100));
      for (const [x, y] of moves) g.pointerMove(pointer(x, y));
      g.pointerUp(pointer(...(moves.at(-1) ?? [100, 100]), { buttons: 0 }));
      return of('tap');
    };
    expect(
      wobble([
        [102, 101],
        [103, 102],
      ]),
    ).toEqual([['tap', { x: 103, y: 102 }, 0, NO_MODS]]);
    // Movement adds up: there and back again is 6 pixels of movement.
    expect(
      wobble([
        [103, 100],
        [100, 100],
      ]),
    ).toEqual([]);
    expect(wobble([[103, 103]])).toEqual([]);
  });

  it('a cancelled pointer never taps', () => {
    const { g, of } = machine();
    g.pointerDown(pointer(5, 5));
    g.pointerUp(pointer(5, 5), true);
    expect(of('tap')).toEqual([]);
    expect(of('release')).toHaveLength(1);
  });

  it('drags orbit, or pan with Shift, the right or the middle button', () => {
    const kinds = (over: Partial<PointerSample>) => {
      const { g, of } = machine();
      g.pointerDown(pointer(0, 0, over));
      g.pointerMove(pointer(7, -3, over));
      return of('drag');
    };
    expect(kinds({})).toEqual([['drag', 7, -3, 'orbit', { x: 7, y: -3 }]]);
    expect(kinds({ shiftKey: true })[0][3]).toBe('pan');
    expect(kinds({ buttons: 2 })[0][3]).toBe('pan');
    expect(kinds({ buttons: 4 })[0][3]).toBe('pan');
  });

  it('with a drag slop, moves are dropped until the movement reaches it', () => {
    const { g, of } = machine({ dragSlop: 4 });
    g.pointerDown(pointer(0, 0));
    g.pointerMove(pointer(1, 1));
    g.pointerMove(pointer(2, 2));
    g.pointerMove(pointer(5, 2));
    expect(of('drag')).toEqual([
      ['drag', 1, 1, 'orbit', { x: 2, y: 2 }],
      ['drag', 3, 0, 'orbit', { x: 5, y: 2 }],
    ]);
  });

  it('moving with nothing pressed hovers; leaving says so', () => {
    const { g, of } = machine();
    g.pointerMove(pointer(3, 4, { buttons: 0 }));
    g.pointerLeave();
    expect(of('hover')).toEqual([['hover', { x: 3, y: 4 }]]);
    expect(of('leave')).toHaveLength(1);
    expect(of('drag')).toEqual([]);
  });
});

describe('pinch', () => {
  const touch = (id: number, x: number, y: number) => pointer(x, y, { pointerId: id, pointerType: 'touch' });

  it('zooms by the ratio of the spreads about the fingers, pans by the midpoint, and never taps', () => {
    const { g, of } = machine();
    g.pointerDown(touch(1, 80, 100));
    g.pointerDown(touch(2, 120, 100));
    expect(of('press').map((c) => c[3])).toEqual([1, 2]);
    // The spread goes 40, 72, 64 pixels while the midpoint moves from (100, 100) to (120, 100).
    g.pointerMove(touch(2, 152, 100));
    g.pointerMove(touch(1, 88, 100));
    const zooms = of('zoom');
    expect(zooms).toHaveLength(2);
    expect(zooms[0][1]).toBeCloseTo(72 / 40, 12);
    expect(zooms[0][2]).toEqual({ x: 100, y: 100 });
    expect(zooms[1][1]).toBeCloseTo(64 / 72, 12);
    expect(zooms[1][2]).toEqual({ x: 116, y: 100 });
    const total = zooms.reduce((f, z) => f * (z[1] as number), 1);
    expect(total).toBeCloseTo(64 / 40, 12);
    expect(of('drag')).toEqual([
      ['drag', 16, 0, 'pan', { x: 116, y: 100 }],
      ['drag', 4, 0, 'pan', { x: 120, y: 100 }],
    ]);
    g.pointerUp(touch(1, 88, 100));
    g.pointerUp(touch(2, 152, 100));
    expect(of('tap')).toEqual([]);
    expect(of('release')).toHaveLength(1);
  });

  it('after one finger lifts, the other drags on its own', () => {
    const { g, of } = machine();
    g.pointerDown(touch(1, 0, 0));
    g.pointerDown(touch(2, 50, 0));
    g.pointerUp(touch(2, 50, 0));
    g.pointerMove(touch(1, 4, 0));
    expect(of('zoom')).toEqual([]);
    expect(of('drag')).toEqual([['drag', 4, 0, 'orbit', { x: 4, y: 0 }]]);
  });
});

describe('long press', () => {
  it('a touch held still for 550 ms fires once at the press, and no tap follows', () => {
    const { g, of, timer } = machine();
    g.pointerDown(pointer(30, 40, { pointerType: 'touch' }));
    expect([...timer.pending.values()].map((t) => t.ms)).toEqual([550]);
    g.pointerMove(pointer(33, 41, { pointerType: 'touch' }));
    timer.fire();
    g.pointerUp(pointer(33, 41, { pointerType: 'touch' }));
    expect(of('longPress')).toEqual([['longPress', { x: 30, y: 40 }]]);
    expect(of('tap')).toEqual([]);
  });

  it('is called off by 8 pixels of movement, a second finger, a lift, and never comes from a mouse', () => {
    const moved = machine();
    moved.g.pointerDown(pointer(0, 0, { pointerType: 'pen' }));
    moved.g.pointerMove(pointer(5, 3, { pointerType: 'pen' }));
    moved.timer.fire();
    expect(moved.of('longPress')).toEqual([]);

    const two = machine();
    two.g.pointerDown(pointer(0, 0, { pointerType: 'touch' }));
    two.g.pointerDown(pointer(9, 0, { pointerType: 'touch', pointerId: 2 }));
    expect(two.timer.pending.size).toBe(0);

    const lifted = machine();
    lifted.g.pointerDown(pointer(0, 0, { pointerType: 'touch' }));
    lifted.g.pointerUp(pointer(0, 0, { pointerType: 'touch' }));
    expect(lifted.timer.pending.size).toBe(0);
    expect(lifted.of('tap')).toHaveLength(1);

    const mouse = machine();
    mouse.g.pointerDown(pointer(0, 0));
    expect(mouse.timer.pending.size).toBe(0);
  });

  it('is off without a handler, and destroy stops a pending one', () => {
    const off = machine({}, false);
    off.g.pointerDown(pointer(0, 0, { pointerType: 'touch' }));
    expect(off.timer.pending.size).toBe(0);
    const on = machine({ longPressMs: 300 });
    on.g.pointerDown(pointer(0, 0, { pointerType: 'touch' }));
    expect([...on.timer.pending.values()][0].ms).toBe(300);
    on.g.destroy();
    expect(on.timer.pending.size).toBe(0);
  });
});

describe('wheel', () => {
  it('zooms about the pointer: out for positive delta, lines stepping further than pixels', () => {
    const { g, of } = machine();
    g.wheel({ x: 12, y: 34, deltaY: 100, deltaMode: 0 });
    g.wheel({ x: 12, y: 34, deltaY: -3, deltaMode: 1 });
    const zooms = of('zoom');
    expect(zooms[0][1]).toBeCloseTo(Math.exp(-0.15), 12);
    expect(zooms[0][2]).toEqual({ x: 12, y: 34 });
    expect(zooms[1][1]).toBeCloseTo(Math.exp(0.15), 12);
  });
});
