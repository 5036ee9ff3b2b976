import { describe, expect, it } from 'vitest';
import schema from '../../docs/schema/scenario.schema.json';
import { choices } from '../../web/ui/params';
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
