// Prints the gzipped size of each wasm and JavaScript file of dist/: the page's wasm module, the
// rules module (the simulation with the rule scripts' engine, fetched only for a scenario with
// rules or when the Rules tab opens) and the lab module (when a panel needs it; neither has a
// budget, docs/benchmarks.md says why); the page's script (what index.html's scripts import
// statically), the workers (`new URL(…, import.meta.url)`: the simulation's starts with the page,
// the others when a dialog or tab needs them) and the chunks a dynamic import() loads later. Which
// of them the first load fetches, and its bytes on the wire against the budget (scripts/budget.mjs),
// `npm run bench` measures in a browser (scripts/bench-load.mjs): a static reading cannot tell a
// worker started at once from one started on demand.
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';

const dist = new URL('../dist/', import.meta.url).pathname;
const dir = join(dist, 'assets');

/** The JavaScript of dist/assets/ that index.html's scripts import statically, and the workers any file names. */
function pageScript() {
  const html = readFileSync(join(dist, 'index.html'), 'utf8');
  const todo = [...html.matchAll(/(?:src|href)="\.\/assets\/([^"]+\.js)"/g)].map((m) => m[1]);
  const seen = new Set();
  while (todo.length > 0) {
    const f = todo.pop();
    if (seen.has(f)) continue;
    seen.add(f);
    const code = readFileSync(join(dir, f), 'utf8');
    // Static imports (`import{a}from"./x.js"`, `import"./x.js"`, `export{a}from"./x.js"`); never `import("./x.js")`.
    todo.push(...[...code.matchAll(/(?:\bfrom|\bimport)\s*["'`]\.\/([\w.-]+\.js)["'`]/g)].map((m) => m[1]));
  }
  const workers = new Set();
  for (const f of readdirSync(dir).filter((f) => f.endsWith('.js'))) {
    const code = readFileSync(join(dir, f), 'utf8');
    for (const m of code.matchAll(/new URL\(\s*["'`](?:\.\/)?([\w.-]+\.js)["'`]\s*,\s*import\.meta\.url/g)) workers.add(m[1]);
  }
  return { page: seen, workers };
}

const { page: script, workers } = pageScript();
const kb = { page: 0, rules: 0, lab: 0, js: 0, workers: 0, jsLater: 0 };
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
  else if (script.has(f)) kb.js += gz;
  else if (workers.has(f)) {
    kb.workers += gz;
    when = '  (a worker)';
  } else {
    kb.jsLater += gz;
    when = '  (loaded later)';
    later.push(f);
  }
  lines.push(`  ${f.padEnd(40)} ${(raw.length / 1024).toFixed(1).padStart(8)} KB  ${gz.toFixed(1).padStart(7)} KB gzipped${when}`);
}
const f1 = (n) => n.toFixed(1);
console.log(`dist/assets:\n${lines.join('\n')}`);
console.log(
  `page's wasm ${f1(kb.page)} KB gzipped, the page's script ${f1(kb.js)} KB gzipped (npm run bench measures what the first load fetches, against scripts/budget.mjs)`,
);
console.log(`workers ${f1(kb.workers)} KB gzipped (${workers.size}: the simulation's starts with the page, the others on demand)`);
console.log(`rules module's wasm ${f1(kb.rules)} KB gzipped (loaded for a scenario with rules, or when the Rules tab opens)`);
console.log(`lab's wasm ${f1(kb.lab)} KB gzipped (loaded when the experiments, a claim's re-run or grading need it)`);
console.log(
  `JavaScript loaded later ${f1(kb.jsLater)} KB gzipped (${later.length} files: the rule editor, the lab's code and other chunks a tab or dialog imports)`,
);
if (process.argv.includes('--json'))
  console.log(
    JSON.stringify({
      wasm_gzip_kb: kb.page,
      rules_wasm_gzip_kb: kb.rules,
      lab_wasm_gzip_kb: kb.lab,
      js_gzip_kb: kb.js,
      worker_js_gzip_kb: kb.workers,
      later_js_gzip_kb: kb.jsLater,
    }),
  );
