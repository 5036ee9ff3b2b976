// How the page names lattice cells: which lattices have depth, and a cell index's (x, y, z) in the
// core's row-major order. Where cells are drawn, and which one a point falls in, is the view's
// (crate/view; the page asks through wasm.ts's Geometry and the worker's view).
import type { Layout } from '../contract.gen';

/** The lattice has depth: a 3-D view, where a selected unit stays selected and shows its reach. */
export const is3d = (layout: Layout): boolean => layout.lattice === 'cubic';

/** Both layouts are the same lattice of the same size (the camera and the cursor can stay). */
export const sameLattice = (a: Layout | null, b: Layout): boolean => !!a && a.lattice === b.lattice && a.dims.join() === b.dims.join();

/** A cell index's (x, y, z) in a lattice of `dims` (z is 0 in 2-D). */
export function coordOf(dims: readonly number[], i: number): [number, number, number] {
  const [w, h] = dims;
  return [i % w, Math.floor(i / w) % h, Math.floor(i / (w * h))];
}

/** A cell's coordinates as the page writes them: (x, y), and (x, y, z) in 3-D. */
export function cellCoords(layout: Layout, cell: number): string {
  const [x, y, z] = coordOf(layout.dims, cell);
  return is3d(layout) ? `(${x}, ${y}, ${z})` : `(${x}, ${y})`;
}
