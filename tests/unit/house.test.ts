// The page's house rules, read from its sources: a room per feature that imports no other, the
// features mounted from one list, no file over 400 lines, only model plugins in web/models/, and
// no runtime data imported from docs/.
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

const WEB = resolve(__dirname, '../../web');

/** Every TypeScript file under `dir`, but the wasm packages' and the generated ones. */
function sources(dir = WEB): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return name === 'pkg' ? [] : sources(path);
    return name.endsWith('.ts') && !name.endsWith('.gen.ts') && !name.endsWith('.d.ts') ? [path] : [];
  });
}

/** The files a source imports (relative imports only), resolved against its folder. */
function imports(file: string): string[] {
  const text = readFileSync(file, 'utf8');
  return [...text.matchAll(/(?:import|export)[^'";]*?from\s+'(\.[^']+)'|import\('(\.[^']+)'\)|new URL\('(\.[^']+)'/g)].map((m) =>
    resolve(dirname(file), m[1] ?? m[2] ?? m[3]),
  );
}

const feature = (path: string): string | null => {
  const rel = relative(join(WEB, 'features'), path);
  return rel.startsWith('..') ? null : rel.split('/')[0];
};

describe("the page's rooms", () => {
  it('no feature imports another', () => {
    const crossings: string[] = [];
    for (const file of sources(join(WEB, 'features'))) {
      const own = feature(file);
      for (const target of imports(file)) {
        const other = feature(target);
        if (other && other !== own && own !== 'index.ts') crossings.push(`${relative(WEB, file)} imports ${relative(WEB, target)}`);
      }
    }
    expect(crossings).toEqual([]);
  });

  it('nothing outside the features imports one, but the list and the shell that mounts it', () => {
    const reaching = sources()
      .filter((file) => feature(file) === null)
      .flatMap((file) =>
        imports(file)
          .filter((t) => feature(t) && !t.endsWith('features/index'))
          .map((t) => `${relative(WEB, file)} imports ${relative(WEB, t)}`),
      );
    expect(reaching).toEqual([]);
  });

  it('every feature folder is in the one list, once', () => {
    const list = readFileSync(join(WEB, 'features/index.ts'), 'utf8');
    const folders = readdirSync(join(WEB, 'features')).filter((n) => statSync(join(WEB, 'features', n)).isDirectory());
    for (const name of folders) expect(list, name).toMatch(new RegExp(`from '\\./${name}'`));
    const listed = [...list.matchAll(/^ {2}(\w+),$/gm)].map((m) => m[1]);
    expect(new Set(listed).size).toBe(listed.length);
    expect(listed.length).toBe(folders.length);
  });

  it('web/models/ holds the model plugins only: one file a model, and the index that finds them', () => {
    const files = readdirSync(join(WEB, 'models')).sort();
    const models = readdirSync(resolve(WEB, '../crate/models')).sort();
    expect(files).toEqual(['index.ts', ...models.filter((m) => files.includes(`${m}.ts`)).map((m) => `${m}.ts`)].sort());
    for (const f of files.filter((f) => f !== 'index.ts')) expect(models).toContain(f.slice(0, -3));
  });

  it('no TypeScript file is over 400 lines', () => {
    const long = sources()
      .map((f) => [relative(WEB, f), readFileSync(f, 'utf8').split('\n').length - 1] as const)
      .filter(([, n]) => n > 400);
    expect(long).toEqual([]);
  });

  it('no runtime data is imported from docs/', () => {
    const fromDocs = sources().flatMap((f) =>
      imports(f)
        .filter((t) => t.includes('/docs/'))
        .map((t) => `${relative(WEB, f)} imports ${t}`),
    );
    expect(fromDocs).toEqual([]);
  });
});
