// Precompressed copies of the built site for static hosts and `npm start` (scripts/serve.mjs): a
// build-only Vite plugin that writes, once the build has written its files, a .br (Brotli, best
// quality) and a .gz (gzip, level 9) beside each text or wasm file, so that no server compresses
// on the fly and the wasm, which servers rarely compress (vite preview does not), goes compressed.
// The service worker's list (vite.pwa.ts) is the build's own files: the copies are not in it.
import { readFile, readdir, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { brotliCompress, constants, gzip } from 'node:zlib';
import type { Plugin } from 'vite';

const COMPRESSIBLE = /\.(html|js|css|wasm|svg|json|webmanifest)$/;
/** Smaller files go as they are: a compressed copy would save less than its headers cost. */
const MIN_BYTES = 1024;
const brotli = promisify(brotliCompress);
const gz = promisify(gzip);

/** Every file under `dir`, relative to it. */
async function files(dir: string, under = ''): Promise<string[]> {
  const out: string[] = [];
  for (const entry of await readdir(join(dir, under), { withFileTypes: true })) {
    const rel = join(under, entry.name);
    if (entry.isDirectory()) out.push(...(await files(dir, rel)));
    else out.push(rel);
  }
  return out;
}

/** Writes `file.br` and `file.gz` beside each compressible file of `dir` that compression makes smaller. */
export async function compressDir(dir: string) {
  const todo = (await files(dir)).filter((f) => COMPRESSIBLE.test(f));
  await Promise.all(
    todo.map(async (f) => {
      const raw = await readFile(join(dir, f));
      if (raw.length < MIN_BYTES) return;
      const [br, gzipped] = await Promise.all([
        brotli(raw, {
          params: {
            [constants.BROTLI_PARAM_QUALITY]: constants.BROTLI_MAX_QUALITY,
            [constants.BROTLI_PARAM_SIZE_HINT]: raw.length,
            [constants.BROTLI_PARAM_LGWIN]: 24,
          },
        }),
        gz(raw, { level: 9 }),
      ]);
      if (br.length < raw.length) await writeFile(join(dir, `${f}.br`), br);
      if (gzipped.length < raw.length) await writeFile(join(dir, `${f}.gz`), gzipped);
    }),
  );
}

export function compress(): Plugin {
  let outDir = 'dist';
  return {
    name: 'kumiki-compress',
    apply: 'build',
    // After the offline plugin's writeBundle (it writes sw.js): the service worker is compressed too.
    enforce: 'post',
    configResolved(config) {
      outDir = config.build.outDir.startsWith('/') ? config.build.outDir : join(config.root, config.build.outDir);
    },
    async closeBundle() {
      await compressDir(outDir);
    },
  };
}
