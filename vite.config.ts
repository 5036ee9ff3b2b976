import { readFileSync } from 'node:fs';
import { type Plugin, defineConfig } from 'vite';
import { compress } from './vite.compress.ts';
import { pwa } from './vite.pwa.ts';

// One Content-Security-Policy: the page's meta tag. Wherever Kumiki serves the page it also sends
// it as a header, with what a meta tag cannot carry: frame-ancestors. Kumiki is meant to be
// embedded in course pages on any site (?embed), and holds no accounts or private data, so any
// https page (and a teacher's own machine) may frame it; plain-http and file pages may not.
const metaPolicy = /http-equiv="Content-Security-Policy" content="([^"]+)"/.exec(readFileSync('static/index.html', 'utf8'))?.[1];
if (!metaPolicy) throw new Error('static/index.html has no Content-Security-Policy meta tag');
export const HEADERS: Record<string, string> = {
  'Content-Security-Policy': `${metaPolicy}; frame-ancestors 'self' https: http://localhost:* http://127.0.0.1:*`,
  'X-Content-Type-Options': 'nosniff',
  'Referrer-Policy': 'no-referrer',
};

/** Writes dist/_headers, the header file static hosts such as Netlify and Cloudflare Pages read. */
function headersFile(): Plugin {
  return {
    name: 'kumiki-headers',
    generateBundle() {
      const lines = Object.entries(HEADERS).map(([k, v]) => `  ${k}: ${v}`);
      this.emitFile({ type: 'asset', fileName: '_headers', source: `/*\n${lines.join('\n')}\n` });
    },
  };
}

/**
 * Starts the page's wasm module downloading with the page itself: a preload in index.html, which
 * web/wasm.ts's fetch then takes (same URL, same CORS mode). Without it the module, the largest
 * part of the first load, is asked for only once the page's script has arrived and run.
 */
function preloadWasm(): Plugin {
  return {
    name: 'kumiki-preload-wasm',
    apply: 'build',
    transformIndexHtml: {
      order: 'post',
      handler(_html, ctx) {
        const wasm = Object.keys(ctx.bundle ?? {}).filter((f) => /(^|\/)kumiki_wasm_bg-[\w-]+\.wasm$/.test(f));
        if (wasm.length !== 1) throw new Error(`expected one page wasm module in the build, found ${wasm.length}`);
        return [{ tag: 'link', attrs: { rel: 'preload', href: `./${wasm[0]}`, as: 'fetch', type: 'application/wasm', crossorigin: '' }, injectTo: 'head' }];
      },
    },
  };
}

// The page lives in static/ (index.html, CSS, icons) and imports its code from web/.
// Relative base: the built site in dist/ works from any sub-path.
export default defineConfig({
  root: 'static',
  base: './',
  publicDir: false,
  plugins: [headersFile(), preloadWasm(), pwa(), compress()],
  build: {
    outDir: '../dist',
    emptyOutDir: true,
    target: 'es2022',
    // Never inline assets as data: URLs; the Content-Security-Policy only allows 'self'.
    assetsInlineLimit: 0,
    chunkSizeWarningLimit: 1024,
    // The precompression after the build (vite.compress.ts) takes seconds by design: no warning
    // about slow plugin callbacks on every build.
    rolldownOptions: { checks: { bundlerTimings: false } },
  },
  worker: { format: 'es' },
  server: { port: 8080, strictPort: true, fs: { allow: ['..'] }, headers: HEADERS },
  preview: { port: 8080, strictPort: true, host: 'localhost', headers: HEADERS },
});
