// Prints the gzipped size of each wasm and JavaScript file of dist/, and the wasm budget check.
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { WASM_BUDGET_KB, budgetVerdict } from './budget.mjs';

const dir = new URL('../dist/assets/', import.meta.url).pathname;
let wasmKb = 0;
let jsKb = 0;
const lines = [];
for (const f of readdirSync(dir).sort()) {
  if (!/\.(wasm|js)$/.test(f)) continue;
  const raw = readFileSync(join(dir, f));
  const kb = gzipSync(raw, { level: 9 }).length / 1024;
  if (f.endsWith('.wasm')) wasmKb += kb;
  else jsKb += kb;
  lines.push(`  ${f.padEnd(40)} ${(raw.length / 1024).toFixed(1).padStart(8)} KB  ${kb.toFixed(1).padStart(7)} KB gzipped`);
}
console.log(`dist/assets:\n${lines.join('\n')}`);
console.log(`wasm ${wasmKb.toFixed(1)} KB gzipped (budget ${WASM_BUDGET_KB} KB: ${budgetVerdict(wasmKb)}), JavaScript ${jsKb.toFixed(1)} KB gzipped`);
if (process.argv.includes('--json')) console.log(JSON.stringify({ wasm_gzip_kb: wasmKb, js_gzip_kb: jsKb }));
