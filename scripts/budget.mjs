// The gzipped wasm budget the renderer issue sets, renderer included; build and bench check it.
export const WASM_BUDGET_KB = 350;

/** "within" or how far over the budget `kb` gzipped kilobytes are. */
export const budgetVerdict = (kb) => (kb <= WASM_BUDGET_KB ? 'within' : `${(kb - WASM_BUDGET_KB).toFixed(1)} KB over`);
