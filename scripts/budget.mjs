// The first load's budget: the kilobytes (1024 bytes) the server may send, headers and bodies as
// they go on the wire (compressed), from the navigation to interactive (the first frame drawn,
// Play acting), on a first visit with a cold cache. The one place it is stated: `npm run bench`
// measures it (scripts/bench-load.mjs) and fails when the first load is over it.
export const LOAD_BUDGET_KB = 700;

/** "within" or how far over the budget `kb` kilobytes are. */
export const loadVerdict = (kb) => (kb <= LOAD_BUDGET_KB ? 'within' : `${(kb - LOAD_BUDGET_KB).toFixed(1)} KB over`);
