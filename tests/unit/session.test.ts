import { describe, expect, it } from 'vitest';
import { cellCoords, is3d, sameLattice } from '../../web/render/geometry';
import { Session } from '../../web/session';
import type { Frame } from '../../web/types';
import { layout } from './helpers';

/** A session with a record of every event it emitted, in order. */
function recorded() {
  const session = new Session();
  const events: string[] = [];
  session.on('loaded', ({ shapeChanged }) => events.push(`loaded ${shapeChanged}`));
  session.on('frame', (f) => events.push(`frame ${f.steps}`));
  session.on('recorded', () => events.push('recorded'));
  session.on('history', () => events.push(`history ${session.canUndo} ${session.canRedo}`));
  return { session, events };
}

describe('the session store', () => {
  it('says when a loaded run changes the lattice or its size, and keeps the scenario it runs', () => {
    const { session, events } = recorded();
    session.loaded(layout('square', 4, 3), '{"seed":1}');
    session.loaded(layout('square', 4, 3), '{"seed":2}');
    session.loaded(layout('hex', 4, 3), '{"seed":3}');
    session.loaded(layout('hex', 5, 3), '{"seed":4}');
    expect(events).toEqual(['loaded true', 'loaded false', 'loaded true', 'loaded true']);
    expect(session.scenario).toBe('{"seed":4}');
    expect(session.doc().seed).toBe(4);
  });

  it('parses the scenario once per text', () => {
    const session = new Session();
    expect(session.doc()).toEqual({});
    session.scenario = '{"name":"a"}';
    const first = session.doc();
    expect(session.doc()).toBe(first);
    session.scenario = '{"name":"b"}';
    expect(session.doc()).not.toBe(first);
    expect(session.doc().name).toBe('b');
  });

  it('keeps the latest frame', () => {
    const { session, events } = recorded();
    session.setFrame({ steps: 7 } as Frame);
    expect(session.frame?.steps).toBe(7);
    expect(events).toEqual(['frame 7']);
  });

  it('remembers replaced scenarios for undo, not unchanged ones or the first', () => {
    const { session, events } = recorded();
    session.remember('', 'a');
    session.scenario = 'a';
    session.remember('a', 'a');
    expect(session.canUndo).toBe(false);
    session.remember('a', 'b');
    session.scenario = 'b';
    expect(session.undo()).toBe('a');
    session.scenario = 'a';
    expect(session.redo()).toBe('b');
    expect(events).toEqual(['history false false', 'history false false', 'history true false', 'history false true', 'history true false']);
  });

  it('a recorded disturbance replaces the scenario and can be undone', () => {
    const { session, events } = recorded();
    session.scenario = 'a';
    session.recorded('a+click');
    expect(session.scenario).toBe('a+click');
    expect(events).toEqual(['history true false', 'recorded']);
    expect(session.undo()).toBe('a');
  });
});

describe('what generic code asks of a lattice', () => {
  it('only the cubic lattice is 3-D, and its coordinates have three parts', () => {
    expect([is3d(layout('square', 4, 3)), is3d(layout('hex', 4, 3)), is3d(layout('cubic', 4, 3, 2))]).toEqual([false, false, true]);
    expect(cellCoords(layout('square', 4, 3), 6)).toBe('(2, 1)');
    expect(cellCoords(layout('hex', 4, 3), 11)).toBe('(3, 2)');
    expect(cellCoords(layout('cubic', 4, 3, 2), 4 * 3 + 4 + 2)).toBe('(2, 1, 1)');
  });

  it('the same lattice means the same kind and size', () => {
    expect(sameLattice(null, layout('square', 4, 3))).toBe(false);
    expect(sameLattice(layout('square', 4, 3), layout('square', 4, 3))).toBe(true);
    expect(sameLattice(layout('square', 4, 3), layout('hex', 4, 3))).toBe(false);
    expect(sameLattice(layout('cubic', 4, 3, 2), layout('cubic', 4, 3, 3))).toBe(false);
  });
});
