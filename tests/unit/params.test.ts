import { describe, expect, it } from 'vitest';
import schema from '../../web/scenario.schema.gen.json';
import { choices, otherNumber } from '../../web/widgets/params';
import type { SchemaNode } from '../../web/wasm';

const defs = (schema as { $defs: Record<string, SchemaNode> }).$defs;

describe('the parameter form reads choices from the schema', () => {
  it('offers the constants of a oneOf or an enum, and nothing for other kinds', () => {
    expect(choices({ oneOf: [{ const: 'a' }, { const: 'b' }] })).toEqual(['a', 'b']);
    expect(choices({ enum: [1, 2] })).toEqual([1, 2]);
    expect(choices({ oneOf: [{ type: 'integer' }, { type: 'array' }] })).toBeUndefined();
    expect(choices({ type: 'string' })).toBeUndefined();
  });

  it('finds every enum of every model as a list of choices', () => {
    for (const name of ['Collision', 'Communication', 'FieldKind', 'Priorities', 'Selection', 'Ground', 'Task', 'Leader', 'Method']) {
      expect(choices(defs[name])?.length, name).toBeGreaterThan(1);
    }
    expect(choices(defs.Collision)).toEqual(['token', 'relay', 'blackboard']);
  });
});

describe("a compared number starts from a value other than the run's own", () => {
  it('moves a whole number by one and another number by a factor of two, within its bounds', () => {
    expect(otherNumber(5, { min: 1, max: 100, integer: true })).toBe(6);
    expect(otherNumber(100, { min: 1, max: 100, integer: true })).toBe(99);
    expect(otherNumber(2, { min: 0, max: 10, integer: false })).toBe(4);
    expect(otherNumber(0.8, { min: 0, max: 1, integer: false })).toBe(0.4);
    expect(otherNumber(0, { min: 0, max: 1, integer: false })).toBe(1);
    // A number with a single allowed value keeps it (the core then says the runs would be the same).
    expect(otherNumber(3, { min: 3, max: 3, integer: true })).toBe(3);
  });
});
