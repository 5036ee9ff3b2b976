// Generated from the view's records (crate/view/src/contract.rs): do not edit.

/** An editing cursor in 3-D (where a unit would be added or removed), or the keyboard cursor. */
export interface Cursor {
  cell: number;
  kind: CursorKind;
}

/** What kind of editing cursor a 3-D view shows, or the keyboard cursor. */
export type CursorKind = "add" | "remove" | "cursor";

/** A 3-D pick: the occupied cell hit, and the empty cell in front of the face hit. */
export interface Hit {
  cell: number;
  /** The empty cell in front of the hit face, or -1 when that is off the lattice. */
  front: number;
}

/** The page's marks over the lattice (its hover, selection, cursor and view options). */
export interface Marks {
  /** Gradient arrows over a field that has them. */
  arrows: boolean;
  bonds: boolean;
  cursor?: Cursor | null;
  /** Units drawn displaced: triples (cell, dx, dy) in cells, y down. */
  displaced: number[];
  /** 3-D view options. */
  ghost: boolean;
  /** Highlighted cells (reachable positions). */
  highlight: number[];
  /** A value per highlighted cell (a difference), labelled in 3-D. */
  highlightValues: number[];
  hover: number | null;
  /** Cell labels when cells are large enough. */
  labels: boolean;
  /** The cell picked with the inspector, outlined. */
  selected: number | null;
  /**
   * One slot's signals: pairs (cell, lit faces as a mask of lattice directions); a sender
   * with no face bit is ringed.
   */
  signals: number[];
}

/** What is under the pointer: a cell (or none), its code, and in 3-D the face hit. */
export interface Picked {
  /** The cell, or -1 off the lattice. */
  cell: number;
  /** The cell's code in the frame drawn (0: empty). */
  code: number;
  /** In 3-D, the face hit. */
  hit?: Hit | null;
}

/** What a 3-D frame drew, for the page (and its tests) to read. */
export interface RenderStats {
  bonds: number;
  ghost: number;
  ground: boolean;
  highlight: number;
  light: boolean;
  units: number;
}
