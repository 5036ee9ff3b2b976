import { defineConfig } from 'vitest/config';

// Unit tests of the page: its pure modules (geometry, gestures, plots' statistics, the store) in
// Node, and its features in a DOM library's document on the real core (tests/unit/page.ts; files
// that name `@vitest-environment happy-dom`). No browser. The page's own build is vite.config.ts.
export default defineConfig({
  test: {
    root: '.',
    include: ['tests/unit/**/*.test.ts'],
    environment: 'node',
    // A feature test opens scenarios through the real core: seconds each on a busy machine.
    testTimeout: 60_000,
  },
});
