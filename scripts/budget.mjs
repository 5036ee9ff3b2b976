// The gzipped wasm budget, renderer included: the one place it is stated. The build prints the
// size against it and `npm run bench` fails when the wasm is over it.
export const WASM_BUDGET_KB = 400;

/** "within" or how far over the budget `kb` gzipped kilobytes are. */
export const budgetVerdict = (kb) => (kb <= WASM_BUDGET_KB ? 'within' : `${(kb - WASM_BUDGET_KB).toFixed(1)} KB over`);

/** True when `kb` gzipped kilobytes are over the budget. */
export const overBudget = (kb) => kb > WASM_BUDGET_KB;
