import { describe, expect, it } from 'vitest';
import { cellCoords, is3d, sameLattice } from '../../web/render/geometry';
import { type ScenarioOwner, Session, type SessionHost } from '../../web/page/session';
import type { Proposed } from '../../web/sim/protocol';
import type { Frame } from '../../web/contract.gen';
import { layout } from './helpers';

const NONE = { kind: 'none' } as const;

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
    session.loaded(0, layout('square', 4, 3), '{"seed":1}', NONE);
    session.loaded(0, layout('square', 4, 3), '{"seed":2}', NONE);
    session.loaded(0, layout('hex', 4, 3), '{"seed":3}', NONE);
    session.loaded(0, layout('hex', 5, 3), '{"seed":4}', NONE);
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
    session.recorded('a+click', NONE);
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

describe('the session owns the scenario through the worker', () => {
  /** A session whose worker answers each request with `answer(kind)`, recording every call. */
  function owned(answer: (kind: string) => Partial<Proposed> = () => ({})) {
    const calls: unknown[][] = [];
    let id = 0;
    const propose = async (kind: string): Promise<Proposed> => ({ id: ++id, problem: null, in_full: null, large_cells: 0, text: null, ...answer(kind) });
    const owner: ScenarioOwner = {
      async open(text, keepLocks, ask) {
        calls.push(['open', text, keepLocks, ask]);
        return propose('open');
      },
      async edit(changes) {
        calls.push(['edit', changes]);
        return propose('edit');
      },
      build: (request) => calls.push(['build', request]),
      reset: () => calls.push(['reset']),
      link: async (name) => `k1.${name ?? ''}`,
      goalProblem: async () => null,
    };
    const host: SessionHost = {
      refused: (brief, full) => calls.push(['refused', brief, full]),
      large: (cells, build) => {
        calls.push(['large', cells]);
        build();
      },
    };
    return { session: new Session(owner, host), calls };
  }

  it('an edit crosses to the worker once, as the changes alone, its number as typed', async () => {
    const { session, calls } = owned();
    expect(await session.set('seed', '9007199254740993')).toBeNull();
    expect(await session.edit({ robots: 6, collision: 'token' })).toBeNull();
    expect(await session.set('name', 'an L, not JSON')).toBeNull();
    expect(calls).toEqual([
      ['edit', '{"seed":9007199254740993}'],
      ['edit', '{"robots":6,"collision":"token"}'],
      ['edit', '{"name":"an L, not JSON"}'],
    ]);
  });

  it("a refused edit is the caller's to show; a refused opening goes to the banner, brief and whole", async () => {
    const { session, calls } = owned(() => ({ problem: 'robots: at least one robot is needed', in_full: 'robots: at least one robot is needed (all of it)' }));
    const told: string[] = [];
    expect(await session.set('robots', '0', { onProblem: (brief) => told.push(brief) })).toBe('robots: at least one robot is needed');
    expect(told).toEqual(['robots: at least one robot is needed']);
    expect(await session.open('{}')).toBe(false);
    expect(calls.slice(1)).toEqual([
      ['open', '{}', true, true],
      ['refused', 'robots: at least one robot is needed', 'robots: at least one robot is needed (all of it)'],
    ]);
  });

  it('the run of a request comes back with its number: then, and only then, it can be undone', async () => {
    const { session } = owned();
    const history: boolean[] = [];
    session.on('history', () => history.push(session.canUndo));
    session.loaded(0, layout('square', 4, 3), 'first', NONE);
    expect(await session.open('second', { opens: true })).toBe(true);
    // A reset of the first loads with no number: nothing to undo yet.
    session.loaded(0, layout('square', 4, 3), 'first', NONE);
    expect(session.canUndo).toBe(false);
    session.loaded(1, layout('square', 4, 3), 'second', NONE);
    expect([session.scenario, session.canUndo, session.undo()]).toEqual(['second', true, 'first']);
  });

  it('a large scenario is built only once the page agreed, with the number it was proposed under', async () => {
    const { session, calls } = owned(() => ({ large_cells: 1 << 20, text: 'large' }));
    const replaced: null[] = [];
    session.on('replaced', (v) => replaced.push(v));
    expect(await session.open('large', { opens: true })).toBe(true);
    expect(calls).toEqual([
      ['open', 'large', false, true],
      ['large', 1 << 20],
      ['build', 1],
    ]);
    session.loaded(1, layout('square', 1024, 1024), 'large', NONE);
    expect(replaced).toEqual([null]);
  });
});
