// @ts-check
/**
 * The npm-ready web package: the wasm core as `wasm-pack build --target web` wrote it into
 * www/pkg (`make wasm`), plus `<vsr-robot>` (www/embed/vsr-robot.js) and the playground
 * modules it imports, laid out as in www/ so that every relative import holds. The
 * package.json extends the one wasm-pack wrote (version and licence come from the workspace's
 * Cargo.toml; the name is the product's, `vsr-playground`, not the wasm crate's); the README is
 * docs/embed.md. Prints the package's size.
 *
 *   node scripts/web-package.mjs [OUT]    # default target/web-package; then `npm pack` there
 *
 * Also importable: `assemble(out)` returns the package's file list and package.json.
 */
import { execFileSync } from 'node:child_process';
import { copyFile, mkdir, readFile, rm, stat, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { gzipSync } from 'node:zlib';
import { fileURLToPath, pathToFileURL } from 'node:url';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const ROOT = path.resolve(HERE, '..');
const WWW = path.join(ROOT, 'www');
/** The element, the one entry point besides the wasm core's JS API. */
const ELEMENT = 'embed/vsr-robot.js';
/** Relative imports, and workers started by their path in www/ through workers/kit.js's `spawn('workers/simulation-worker.js', ...)`. */
const IMPORT = /(?:from|import)\s*\(?\s*'(\.{1,2}\/[^']+)'|spawn\(\s*'([^']+)'/g;

/**
 * The www/ files `entry` needs: itself and, transitively, what it imports or starts as a
 * worker (kit.js names a worker by its path in www/). The wasm core (pkg/) is listed separately.
 * @param {string} entry a path relative to www/
 * @returns {Promise<string[]>} paths relative to www/, sorted
 */
export async function closure(entry) {
  const seen = new Set();
  const todo = [entry];
  while (todo.length > 0) {
    const file = /** @type {string} */ (todo.pop());
    if (seen.has(file) || file.startsWith('pkg/')) continue;
    seen.add(file);
    const text = await readFile(path.join(WWW, file), 'utf8');
    for (const [, imported, worker] of text.matchAll(IMPORT)) {
      todo.push(imported ? path.posix.join(path.posix.dirname(file), imported) : worker);
    }
  }
  return [...seen].sort();
}

/**
 * Writes the package into `out` (emptied first).
 * @param {string} out
 * @returns {Promise<{files: string[], manifest: Record<string, any>}>}
 */
export async function assemble(out) {
  const generated = JSON.parse(await readFile(path.join(WWW, 'pkg', 'package.json'), 'utf8').catch(() => {
    throw new Error('www/pkg/package.json is missing: run `make wasm` first');
  }));
  const core = [...generated.files, 'vsr_bg.wasm.d.ts'].map((f) => `pkg/${f}`);
  const files = [...core, ...await closure(ELEMENT)];
  await rm(out, { recursive: true, force: true });
  for (const file of files) {
    await mkdir(path.join(out, path.dirname(file)), { recursive: true });
    await copyFile(path.join(WWW, file), path.join(out, file));
  }
  await copyFile(path.join(ROOT, 'docs', 'embed.md'), path.join(out, 'README.md'));
  const manifest = {
    name: 'vsr-playground',
    version: generated.version,
    description: 'Voxel-based soft robots with local self-attention, simulated in WebAssembly; <vsr-robot>, a walking robot for any web page',
    license: generated.license,
    type: 'module',
    files,
    main: `pkg/${generated.main}`,
    module: `pkg/${generated.main}`,
    types: `pkg/${generated.types}`,
    exports: {
      '.': { types: `./pkg/${generated.types}`, default: `./pkg/${generated.main}` },
      './vsr-robot': `./${ELEMENT}`,
      './*': './*',
    },
    sideEffects: [`./${ELEMENT}`],
    keywords: ['soft robots', 'voxel', 'webassembly', 'custom element', 'evolution', 'attention'],
  };
  await writeFile(path.join(out, 'package.json'), `${JSON.stringify(manifest, null, 2)}\n`);
  return { files, manifest };
}

/**
 * Sizes in bytes: the packed tarball, unpacked, the wasm binary raw and gzipped, its JS glue and
 * the element's JS (everything outside pkg/). Runs `npm pack` in `out`.
 * @param {string} out
 */
export async function sizes(out) {
  const [packed] = JSON.parse(execFileSync('npm', ['pack', '--json', '--pack-destination', out], { cwd: out, encoding: 'utf8' }));
  const wasm = await readFile(path.join(out, 'pkg', 'vsr_bg.wasm'));
  const tarball = path.join(out, packed.filename);
  const listed = /** @type {{path: string, size: number}[]} */ (packed.files);
  const element = listed.filter((f) => f.path.endsWith('.js') && !f.path.startsWith('pkg/'));
  return { tarball, packed: (await stat(tarball)).size, unpacked: packed.unpackedSize, entries: packed.entryCount,
    wasm: wasm.length, wasmGzip: gzipSync(wasm, { level: 9 }).length,
    glue: listed.find((f) => f.path === 'pkg/vsr.js')?.size ?? NaN, element: element.reduce((sum, f) => sum + f.size, 0) };
}

if (process.argv[1] && import.meta.url === pathToFileURL(path.resolve(process.argv[1])).href) {
  const out = path.resolve(process.argv[2] ?? path.join(ROOT, 'target', 'web-package'));
  const { files, manifest } = await assemble(out);
  const s = await sizes(out);
  const kb = (/** @type {number} */ n) => `${(n / 1024).toFixed(0)} KiB`;
  console.log(`${manifest.name}@${manifest.version} in ${out}: ${files.length} files + package.json, README.md`);
  console.log(`  ${path.relative(ROOT, s.tarball)}: ${kb(s.packed)} packed, ${kb(s.unpacked)} unpacked (${s.entries} entries); `
    + `vsr_bg.wasm ${kb(s.wasm)} (${kb(s.wasmGzip)} gzipped), its JS glue ${kb(s.glue)}, the element's JS ${kb(s.element)}`);
}
