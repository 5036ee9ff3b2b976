// Writes the built-in scenarios and lessons for the page: web/pkg/catalog.json (their lists, as
// the gallery shows them, and each one's text) and web/pkg/default-scenario.json (the text of the
// scenario a first visit opens). The page's first-load module is built without them (the
// `catalog` feature of crate/wasm; about 86 KB of text): the page imports the catalogue when it
// first needs it (the gallery, a lesson, a shared edited preset), and the default scenario with
// its script. Both are read from the rules module, which has them, so they are exactly the text
// the core's preset_json() and lesson_json() give. Run by scripts/build-wasm.sh; the scripts that
// need a built-in scenario's text read it here (readCatalogue), as the page does.
import { readFileSync, writeFileSync } from 'node:fs';

/** The scenario a first visit opens (web/page/start.ts). */
const DEFAULT_PRESET = 'amas-L';

const pkg = new URL('../web/pkg/', import.meta.url);

/** The catalogue as written: { presets, lessons, presetText: {name: JSON}, lessonText: {name: JSON} }. */
export function readCatalogue() {
  return JSON.parse(readFileSync(new URL('catalog.json', pkg), 'utf8'));
}

if (process.argv[1] === new URL(import.meta.url).pathname) {
  const wasm = await import('../web/pkg/kumiki_wasm_rules.js');
  wasm.initSync({ module: readFileSync(new URL('kumiki_wasm_rules_bg.wasm', pkg)) });
  const presets = wasm.presets();
  const lessons = wasm.lessons();
  const catalog = {
    presets,
    lessons,
    presetText: Object.fromEntries(presets.map((p) => [p.name, wasm.preset_json(p.name)])),
    lessonText: Object.fromEntries(lessons.map((l) => [l.name, wasm.lesson_json(l.name)])),
  };
  writeFileSync(new URL('catalog.json', pkg), JSON.stringify(catalog));
  writeFileSync(new URL('default-scenario.json', pkg), wasm.preset_json(DEFAULT_PRESET));
  console.log(`catalog: web/pkg/catalog.json (${presets.length} presets, ${lessons.length} lessons), web/pkg/default-scenario.json (${DEFAULT_PRESET})`);
}
