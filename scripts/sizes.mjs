// Prints the gzipped size of each wasm and JavaScript file of dist/, the page's wasm module against
// its budget, and the lab module's size on a line of its own (loaded only when a panel needs it,
// so it has no budget; docs/benchmarks.md says why).
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { WASM_BUDGET_KB, budgetVerdict } from './budget.mjs';

const dir = new URL('../dist/assets/', import.meta.url).pathname;
let pageKb = 0;
let labKb = 0;
let jsKb = 0;
const lines = [];
for (const f of readdirSync(dir).sort()) {
  if (!/\.(wasm|js)$/.test(f)) continue;
  const raw = readFileSync(join(dir, f));
  const kb = gzipSync(raw, { level: 9 }).length / 1024;
  if (f.startsWith('kumiki_wasm_bg')) pageKb += kb;
  else if (f.startsWith('kumiki_lab_bg')) labKb += kb;
  else if (f.endsWith('.js')) jsKb += kb;
  else throw new Error(`dist/assets/${f}: a wasm file that is neither the page's module nor the lab's`);
  lines.push(`  ${f.padEnd(40)} ${(raw.length / 1024).toFixed(1).padStart(8)} KB  ${kb.toFixed(1).padStart(7)} KB gzipped`);
}
console.log(`dist/assets:\n${lines.join('\n')}`);
console.log(`page's wasm ${pageKb.toFixed(1)} KB gzipped (budget ${WASM_BUDGET_KB} KB: ${budgetVerdict(pageKb)}), JavaScript ${jsKb.toFixed(1)} KB gzipped`);
console.log(`lab's wasm ${labKb.toFixed(1)} KB gzipped (loaded when the experiments, a claim's re-run or grading need it)`);
if (process.argv.includes('--json')) console.log(JSON.stringify({ wasm_gzip_kb: pageKb, lab_wasm_gzip_kb: labKb, js_gzip_kb: jsKb }));
