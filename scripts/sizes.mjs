// Prints the gzipped size of each wasm and JavaScript file of dist/, the page's wasm module (the
// first load's budget is npm run bench's, scripts/budget.mjs), and on lines of their own what the
// first load never fetches: the rules module (the simulation with the rule scripts' engine,
// fetched only for a scenario with rules or when the Rules tab opens), the lab module (when a panel needs it; neither has a budget, docs/benchmarks.md says
// why), and the JavaScript loaded later (the rule editor's CodeMirror chunk, the lab's code). The
// first load's JavaScript is what index.html's scripts import statically, with every worker they
// name (`new URL(…, import.meta.url)`: counted as first load, whether it starts at once or on
// demand); a dynamic import() starts a chunk loaded later.
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';

const dist = new URL('../dist/', import.meta.url).pathname;
const dir = join(dist, 'assets');

/** The JavaScript files of dist/assets/ the first load fetches: index.html's, and all they reach without import(). */
function firstLoad() {
  const html = readFileSync(join(dist, 'index.html'), 'utf8');
  const todo = [...html.matchAll(/(?:src|href)="\.\/assets\/([^"]+\.js)"/g)].map((m) => m[1]);
  const seen = new Set();
  while (todo.length > 0) {
    const f = todo.pop();
    if (seen.has(f)) continue;
    seen.add(f);
    const code = readFileSync(join(dir, f), 'utf8');
    // Static imports (`import{a}from"./x.js"`, `import"./x.js"`, `export{a}from"./x.js"`) and workers
    // (`new URL("x.js", import.meta.url)`); never `import("./x.js")`.
    const found = [
      ...[...code.matchAll(/(?:\bfrom|\bimport)\s*["'`]\.\/([\w.-]+\.js)["'`]/g)].map((m) => m[1]),
      ...[...code.matchAll(/new URL\(\s*["'`](?:\.\/)?([\w.-]+\.js)["'`]\s*,\s*import\.meta\.url/g)].map((m) => m[1]),
    ];
    todo.push(...found);
  }
  return seen;
}

const first = firstLoad();
const kb = { page: 0, rules: 0, lab: 0, js: 0, jsLater: 0 };
const lines = [];
const later = [];
for (const f of readdirSync(dir).sort()) {
  if (!/\.(wasm|js)$/.test(f)) continue;
  const raw = readFileSync(join(dir, f));
  const gz = gzipSync(raw, { level: 9 }).length / 1024;
  let when = '';
  if (f.startsWith('kumiki_wasm_rules_bg')) kb.rules += gz;
  else if (f.startsWith('kumiki_wasm_bg')) kb.page += gz;
  else if (f.startsWith('kumiki_lab_bg')) kb.lab += gz;
  else if (f.endsWith('.wasm')) throw new Error(`dist/assets/${f}: a wasm file that is neither the page's module, its rules module nor the lab's`);
  else if (first.has(f)) kb.js += gz;
  else {
    kb.jsLater += gz;
    when = '  (loaded later)';
    later.push(f);
  }
  lines.push(`  ${f.padEnd(40)} ${(raw.length / 1024).toFixed(1).padStart(8)} KB  ${gz.toFixed(1).padStart(7)} KB gzipped${when}`);
}
const f1 = (n) => n.toFixed(1);
console.log(`dist/assets:\n${lines.join('\n')}`);
console.log(
  `page's wasm ${f1(kb.page)} KB gzipped, first load's JavaScript ${f1(kb.js)} KB gzipped (npm run bench checks the first load's bytes against scripts/budget.mjs)`,
);
console.log(`rules module's wasm ${f1(kb.rules)} KB gzipped (loaded for a scenario with rules, or when the Rules tab opens)`);
console.log(`lab's wasm ${f1(kb.lab)} KB gzipped (loaded when the experiments, a claim's re-run or grading need it)`);
console.log(
  `JavaScript loaded later ${f1(kb.jsLater)} KB gzipped (${later.length} files: the rule editor, the lab's code and other chunks a tab or dialog imports)`,
);
if (process.argv.includes('--json'))
  console.log(
    JSON.stringify({ wasm_gzip_kb: kb.page, rules_wasm_gzip_kb: kb.rules, lab_wasm_gzip_kb: kb.lab, js_gzip_kb: kb.js, later_js_gzip_kb: kb.jsLater }),
  );
