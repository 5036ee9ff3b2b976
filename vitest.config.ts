import { defineConfig } from 'vitest/config';

// Unit tests of the page's pure modules (geometry, cameras, colours, plots' statistics, the
// store), in Node: no browser, no wasm. The page's own build is vite.config.ts.
export default defineConfig({
  test: {
    root: '.',
    include: ['tests/unit/**/*.test.ts'],
    environment: 'node',
  },
});
