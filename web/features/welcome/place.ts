// Where the tour's box goes: beside the part of the page it points at, never over it. Below it,
// else above, else to its right, else to its left, whichever first has room for the box; the box
// narrows (to MIN_WIDTH) to fit a side. Only when no side has room does it overlap, on the side
// with the most room.

export interface Rect {
  left: number;
  top: number;
  right: number;
  bottom: number;
}

/** The narrowest the box may get to fit beside its target. */
export const MIN_WIDTH = 260;

/**
 * The box's place and width beside `target` in a viewport of `view` (CSS pixels): `width` is its
 * preferred width, `heightAt(w)` its height at width `w`; `gap` is kept from the target and from
 * the viewport's edges.
 */
export function placeBeside(
  target: Rect,
  width: number,
  heightAt: (width: number) => number,
  view: { width: number; height: number },
  gap = 12,
): { left: number; top: number; width: number; overlaps: boolean } {
  const edge = 8;
  const sides: { room: Rect; along: 'x' | 'y' }[] = [
    { room: { left: edge, top: target.bottom + gap, right: view.width - edge, bottom: view.height - edge }, along: 'x' },
    { room: { left: edge, top: edge, right: view.width - edge, bottom: target.top - gap }, along: 'x' },
    { room: { left: target.right + gap, top: edge, right: view.width - edge, bottom: view.height - edge }, along: 'y' },
    { room: { left: edge, top: edge, right: target.left - gap, bottom: view.height - edge }, along: 'y' },
  ];
  const centre = { x: (target.left + target.right) / 2, y: (target.top + target.bottom) / 2 };
  const place = ({ room, along }: (typeof sides)[number]) => {
    const w = Math.max(0, Math.min(width, room.right - room.left));
    const h = heightAt(Math.max(w, MIN_WIDTH));
    const clamp = (v: number, lo: number, hi: number) => Math.max(lo, Math.min(v, Math.max(lo, hi)));
    const left = along === 'x' ? clamp(centre.x - w / 2, room.left, room.right - w) : room.left;
    const top = along === 'y' ? clamp(centre.y - h / 2, room.top, room.bottom - h) : room.top;
    const fits = w >= MIN_WIDTH && h <= room.bottom - room.top;
    return { left, top, width: Math.max(w, MIN_WIDTH), fits, area: (room.right - room.left) * (room.bottom - room.top) };
  };
  const placed = sides.map(place);
  const chosen = placed.find((p) => p.fits) ?? placed.reduce((a, b) => (b.area > a.area ? b : a));
  // A box that does not fit its side keeps inside the viewport.
  const height = heightAt(chosen.width);
  const left = Math.max(edge, Math.min(chosen.left, view.width - edge - chosen.width));
  const top = Math.max(edge, Math.min(chosen.top, view.height - edge - height));
  return { left, top, width: chosen.width, overlaps: !chosen.fits };
}
