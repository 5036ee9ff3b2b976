// The installable, offline Kumiki: a build-only Vite plugin that adds the web app manifest and its
// icons, and writes the service worker (web/sw.ts, compiled) with the list of every built file
// and a version made from their contents. Only the built site has them: the dev server registers
// no service worker.
import { createHash } from 'node:crypto';
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import ts from 'typescript';
import type { Plugin } from 'vite';

const ICONS = [
  { file: 'icon-192.png', sizes: '192x192', purpose: 'any' },
  { file: 'icon-512.png', sizes: '512x512', purpose: 'any' },
  { file: 'icon-maskable-512.png', sizes: '512x512', purpose: 'maskable' },
];
const THEME = '#1f2933';
const PLACEHOLDER = "'__KUMIKI_PRECACHE__'";

export const MANIFEST = {
  name: 'Kumiki · modular robots playground',
  short_name: 'Kumiki',
  description: 'A playground for self-assembling and self-reconfiguring modular robots.',
  start_url: './',
  scope: './',
  display: 'standalone',
  background_color: '#f5f7fa',
  theme_color: THEME,
  icons: ICONS.map((i) => ({ src: `icons/${i.file}`, sizes: i.sizes, type: 'image/png', purpose: i.purpose })),
};

/** Files of the build that a service worker should not keep: host configuration and source maps. */
const notKept = (file: string) => file === '_headers' || file.endsWith('.map');

export function pwa(): Plugin {
  let outDir = 'dist';
  return {
    name: 'kumiki-pwa',
    apply: 'build',
    configResolved(config) {
      outDir = config.build.outDir.startsWith('/') ? config.build.outDir : join(config.root, config.build.outDir);
    },
    transformIndexHtml() {
      return [
        { tag: 'link', attrs: { rel: 'manifest', href: './manifest.webmanifest' }, injectTo: 'head' },
        { tag: 'meta', attrs: { name: 'theme-color', content: THEME }, injectTo: 'head' },
        { tag: 'link', attrs: { rel: 'apple-touch-icon', href: './icons/icon-192.png' }, injectTo: 'head' },
      ];
    },
    generateBundle() {
      for (const icon of ICONS) this.emitFile({ type: 'asset', fileName: `icons/${icon.file}`, source: readFileSync(`static/icons/${icon.file}`) });
      this.emitFile({ type: 'asset', fileName: 'manifest.webmanifest', source: `${JSON.stringify(MANIFEST, null, 2)}\n` });
    },
    writeBundle(_options, bundle) {
      // Every file the build wrote, in a fixed order; the version changes when any of them does.
      const files = Object.keys(bundle)
        .filter((f) => !notKept(f))
        .sort();
      const hash = createHash('sha256');
      for (const f of files) {
        const item = bundle[f];
        hash.update(f);
        hash.update(item.type === 'chunk' ? item.code : item.source);
      }
      const version = hash.digest('hex').slice(0, 16);
      const source = readFileSync('web/sw.ts', 'utf8');
      const { outputText } = ts.transpileModule(source, { compilerOptions: { target: ts.ScriptTarget.ES2022, module: ts.ModuleKind.ESNext } });
      if (!outputText.includes(PLACEHOLDER)) throw new Error(`web/sw.ts has no ${PLACEHOLDER} for the list of files`);
      const code = outputText.replace(PLACEHOLDER, JSON.stringify(JSON.stringify({ version, files })));
      writeFileSync(join(outDir, 'sw.js'), code);
    },
  };
}
