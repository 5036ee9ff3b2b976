import type { Layout } from '../../web/contract.gen';

/** A layout with only what geometry and cameras read. */
export function layout(lattice: Layout['lattice'], w: number, h: number, d = 1): Layout {
  return { lattice, dims: [w, h, d], cells: [], agents: [], events: [], fields: [], tools: [] } as unknown as Layout;
}
