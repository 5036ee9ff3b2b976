import { defineConfig } from 'vite';

// The page lives in static/ (index.html, CSS, icons) and imports its code from web/.
// Relative base: the built site in dist/ works from any sub-path.
export default defineConfig({
  root: 'static',
  base: './',
  publicDir: false,
  build: {
    outDir: '../dist',
    emptyOutDir: true,
    target: 'es2022',
    // Never inline assets as data: URLs; the Content-Security-Policy only allows 'self'.
    assetsInlineLimit: 0,
    chunkSizeWarningLimit: 1024,
  },
  worker: { format: 'es' },
  server: { port: 8080, strictPort: true, fs: { allow: ['..'] } },
  preview: { port: 8080, strictPort: true, host: 'localhost' },
});
