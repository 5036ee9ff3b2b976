// The gzipped budget of the page's wasm module (kumiki_wasm, renderer included), the one the page
// loads to open: the one place it is stated. The build prints the size against it and `npm run
// bench` fails when the module is over it. The lab module (kumiki_lab), loaded only when a panel
// needs it, is printed beside it without a budget.
export const WASM_BUDGET_KB = 400;

/** "within" or how far over the budget `kb` gzipped kilobytes are. */
export const budgetVerdict = (kb) => (kb <= WASM_BUDGET_KB ? 'within' : `${(kb - WASM_BUDGET_KB).toFixed(1)} KB over`);

/** True when `kb` gzipped kilobytes are over the budget. */
export const overBudget = (kb) => kb > WASM_BUDGET_KB;
