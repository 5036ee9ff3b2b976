// Tooltips that stay on the screen: a tip drawn beside its anchor (a metric card's explanation)
// opens below it and to the right, and flips to the left or above when that side has no room.

export interface Box {
  left: number;
  top: number;
  right: number;
  bottom: number;
}

/**
 * Where a tip of `width` × `height` goes against an anchor in a viewport of `viewport` (all in
 * CSS pixels): its offsets from the anchor's left and top edges, below the anchor unless only
 * above it has room, and starting at its left edge unless that runs off the right of the screen.
 * A gap of `gap` pixels is kept from the anchor and from the screen's edges.
 */
export function tipPlace(anchor: Box, width: number, height: number, viewport: { width: number; height: number }, gap = 4): { x: number; y: number } {
  let x = 0;
  const right = viewport.width - gap;
  if (anchor.left + width > right) x = Math.max(gap, right - width) - anchor.left;
  const below = anchor.bottom + gap + height <= viewport.height - gap;
  const above = anchor.top - gap - height >= gap;
  const y = !below && above ? -(gap + height) : anchor.bottom - anchor.top + gap;
  return { x, y };
}

/**
 * Keeps the tips of the anchors in `root` (those matching `anchors`, each with its `.tip` child) on
 * the screen: placed as they open, on hover and on focus.
 */
export function keepTipsInside(root: HTMLElement, anchors: string, tip: string) {
  const place = (e: Event) => {
    const anchor = e.target instanceof Element ? e.target.closest<HTMLElement>(anchors) : null;
    const box = anchor?.querySelector<HTMLElement>(tip);
    if (!anchor || !box) return;
    // Measured where it opens by default, then moved.
    box.style.left = '0px';
    box.style.top = '';
    requestAnimationFrame(() => {
      const rect = box.getBoundingClientRect();
      const at = tipPlace(anchor.getBoundingClientRect(), rect.width, rect.height, { width: window.innerWidth, height: window.innerHeight });
      box.style.left = `${at.x}px`;
      box.style.top = `${at.y}px`;
    });
  };
  root.addEventListener('pointerover', place);
  root.addEventListener('focusin', place);
}
