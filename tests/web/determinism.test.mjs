// @ts-check
/**
 * Native vs wasm determinism (node --test): the same 30-s episode (biped-4x3 on
 * hilly-1-10-0, phase gait f = 1 Hz, phi = 1.5) must give the bit-identical distance in
 * the wasm build (through the page's `Episode` export) and in the native CLI
 * (`vsr simulate --json`). Both builds use only IEEE +, -, *, /, sqrt and libm, so any
 * difference is a bug (FMA contraction, fast-math, an approximate intrinsic).
 * Needs `make wasm` (www/pkg) and `cargo build --release` (target/release/vsr);
 * VSR_WASM_PKG and VSR_BIN override those paths.
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const PKG = path.resolve(process.env.VSR_WASM_PKG ?? path.join(ROOT, 'www', 'pkg'));
const TARGET = process.env.CARGO_TARGET_DIR ?? path.join(ROOT, 'target');
const BIN = path.resolve(process.env.VSR_BIN ?? path.join(TARGET, 'release', 'vsr'));
/** Steps in a 30-s episode (SPEC 1); fitness runs from after step 1 to after the last. */
const STEPS = 1801;

test('wasm and native give the bit-identical 30-s distance', async () => {
  const wasm = await import(path.join(PKG, 'vsr.js'));
  wasm.initSync({ module: readFileSync(path.join(PKG, 'vsr_bg.wasm')) });
  const episode = new wasm.Episode('biped-4x3', 'hilly-1-10-0', 1, 1.5);
  episode.step(1);
  const first = episode.centreX;
  episode.step(STEPS - 1);
  const inWasm = episode.centreX - first;
  episode.free();

  const out = execFileSync(BIN, ['simulate', '--shape', 'biped-4x3', '--terrain', 'hilly-1-10-0',
    '--gait', '1,1.5', '--json'], { encoding: 'utf8' });
  const native = JSON.parse(out).distance;
  assert.ok(Number.isFinite(native) && Math.abs(native) > 0.1, `native distance ${native}`);
  assert.equal(inWasm, native, `wasm ${inWasm} vs native ${native}`);
});

/** A run file without what depends on the machine (timing, wall seconds). @param {string} text */
function withoutTiming(text) {
  const run = JSON.parse(text);
  run.timing = null;
  for (const r of run.history) r.wall_seconds = 0;
  return run;
}

test('a body search in wasm (Node, jobs in reverse order) gives the file of vsr codesign', async (t) => {
  const wasm = await import(path.join(PKG, 'vsr.js'));
  wasm.initSync({ module: readFileSync(path.join(PKG, 'vsr_bg.wasm')) });
  const module = readFileSync(path.join(ROOT, 'pretrained', 'biped-4x3-attention.json'), 'utf8');
  const search = new wasm.Codesign({ brain: 'frozen', start: '111-111-111', seed: 9, seconds: 2,
    terrain: 'hilly-1-10', budget: 80, batch: 12 }, module);
  while (!search.isDone) {
    const jobs = search.ask();
    const fitness = new Float64Array(jobs.length);
    for (let i = jobs.length - 1; i >= 0; i--) fitness[i] = wasm.evaluateJob(jobs[i], search.genome(i));
    search.tell(fitness, 0);
  }
  const inWasm = withoutTiming(search.runFile(1, 0));
  search.free();

  const out = path.join(ROOT, 'target', `codesign-node-${process.pid}.json`);
  execFileSync(BIN, ['codesign', '--brain', 'frozen', '--from',
    path.join(ROOT, 'pretrained', 'biped-4x3-attention.json'), '--start', '111-111-111', '--seed', '9',
    '--seconds', '2', '--evals', '80', '--batch', '12', '--threads', '2', '--out', out]);
  const native = withoutTiming(readFileSync(out, 'utf8'));
  t.diagnostic(`${native.archive.length} bodies, best ${native.best.fitness} m/s`);
  assert.ok(native.archive.length >= 2, 'the archive holds several bodies');
  assert.deepEqual(inWasm, native);
});
