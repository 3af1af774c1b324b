// @ts-check
/**
 * The page's folders point one way (node --test, no browser): a file of www/ imports files of
 * its own folder or of a folder below its own in FOLDERS, never one above it, so no two folders
 * import each other. Every import counts: static, dynamic, and the JSDoc type imports
 * (`import('../x.js').T`) that tsc follows. main.js, at the top of www/, may import any folder.
 * The order is docs/playground.md's ("The code behind the page"); a new folder is placed in it.
 */
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';

const WWW = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', 'www');

/** The folders of www/, top down (embed/ and offline/ are entry points of their own: none imports them). */
const FOLDERS = ['classroom', 'tour', 'codesign', 'embed', 'robot', 'viewer', 'runs', 'modules', 'keep', 'workers', 'shared', 'offline'];
/** Not the page's own code: wasm-pack's output and the vendored libraries' types. */
const NOT_OURS = ['pkg', 'vendor'];

/** Every import of a file: `from '...'`, `import '...'`, `import('...')`, as paths relative to www/. @param {string} file */
function importsOf(file) {
  const text = readFileSync(path.join(WWW, file), 'utf8');
  return [...text.matchAll(/(?:\bfrom\s*|\bimport\s*\(\s*|\bimport\s+)'(\.{1,2}\/[^']+)'/g)]
    .map((m) => path.posix.normalize(path.posix.join(path.posix.dirname(file), m[1])));
}

/** The folder a path of www/ is in ('' at the top). @param {string} file */
const folderOf = (file) => (file.includes('/') ? file.split('/')[0] : '');

test('every folder of www/ has its place in the order', () => {
  const folders = readdirSync(WWW, { withFileTypes: true }).filter((e) => e.isDirectory() && !NOT_OURS.includes(e.name)).map((e) => e.name);
  assert.deepEqual(folders.sort(), [...FOLDERS].sort());
});

test('a file imports its own folder or a folder below it, never one above', () => {
  const files = readdirSync(WWW, { recursive: true, encoding: 'utf8' })
    .map((f) => f.split(path.sep).join('/'))
    .filter((f) => f.endsWith('.js') && !NOT_OURS.includes(folderOf(f)));
  assert.ok(files.length > 80, `the page's files are read (${files.length})`);
  /** @type {string[]} */
  const upward = [];
  for (const file of files) {
    const from = folderOf(file);
    if (from === '') continue; // main.js wires every part
    for (const target of importsOf(file)) {
      const to = folderOf(target);
      if (to === from || NOT_OURS.includes(to)) continue;
      if (to === '' || FOLDERS.indexOf(to) < FOLDERS.indexOf(from)) upward.push(`${file} -> ${target}`);
    }
  }
  assert.deepEqual(upward, [], 'imports that run back up');
});
