// @ts-check
/**
 * Speed of the wasm build in Node (single thread), for the README's speed table next to
 * `vsr bench`: for each benchmark robot, one 30-s episode (1801 steps at dt = 1/60) of
 * the phase gait f = 1 Hz, phi = 1.5 on hilly-1-10-0, construction included. The whole
 * episode runs inside one wasm call (`benchEpisode`), so JS boundary costs stay out;
 * timing is `performance.now()` around that call.
 *
 * Reports the MEDIAN of REPS timed runs after one warm-up run (and the best, for
 * reference). Run with `make bench-wasm` (it builds www/pkg first).
 *
 *   node tests/bench/wasm_bench.mjs [--json] [--reps N]
 */
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { performance } from 'node:perf_hooks';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
/** The wasm-pack output to measure (`--target web`); VSR_WASM_PKG overrides it. */
const PKG = path.resolve(process.env.VSR_WASM_PKG ?? path.join(ROOT, 'www', 'pkg'));
const SHAPES = ['biped-4x3', 'comb-7x2', 'biped-6x4', 'comb-14x2'];
const TERRAIN = 'hilly-1-10-0';
const FREQUENCY = 1;
const PHASE = 1.5;
/** Steps in a 30-s episode as the reference counts them (SPEC 1). */
const STEPS = 1801;
const DT = 1 / 60;

const args = process.argv.slice(2);
const json = args.includes('--json');
const repsAt = args.indexOf('--reps');
const REPS = repsAt >= 0 ? Number(args[repsAt + 1]) : 11;
if (!Number.isInteger(REPS) || REPS < 1) {
  console.error('--reps needs a positive integer');
  process.exit(2);
}

const wasm = await import(path.join(PKG, 'vsr.js')).catch(() => {
  console.error(`cannot load ${PKG}/vsr.js: build it first with \`make wasm\``);
  process.exit(2);
});
wasm.initSync({ module: readFileSync(path.join(PKG, 'vsr_bg.wasm')) });

/** @param {string} shape @returns {{ms: number, dx: number}} one timed episode */
function timeOne(shape) {
  const begin = performance.now();
  const dx = wasm.benchEpisode(shape, TERRAIN, FREQUENCY, PHASE, STEPS);
  return { ms: performance.now() - begin, dx };
}

/** @param {number[]} xs */
function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
}

const rows = SHAPES.map((shape) => {
  timeOne(shape);
  const runs = Array.from({ length: REPS }, () => timeOne(shape));
  const ms = median(runs.map((r) => r.ms));
  return {
    shape,
    steps_per_second: STEPS / (ms / 1000),
    ms_per_evaluation: ms,
    realtime_factor: (STEPS * DT) / (ms / 1000),
    best_ms_per_evaluation: Math.min(...runs.map((r) => r.ms)),
    displacement_m: runs[0].dx,
  };
});

if (json) {
  console.log(JSON.stringify({ build: 'wasm (node ' + process.version + ')', terrain: TERRAIN,
    gait: [FREQUENCY, PHASE], steps: STEPS, statistic: `median of ${REPS}`, results: rows }, null, 2));
} else {
  console.log(`wasm build in Node ${process.version}: ${STEPS} steps (30 s) of gait f=${FREQUENCY} phi=${PHASE} on ${TERRAIN}, median of ${REPS} runs after 1 warm-up`);
  console.log('shape        steps/s   ms/eval (median)  ms/eval (best)  sim s/wall s  dx (m)');
  for (const r of rows) {
    console.log(`${r.shape.padEnd(11)} ${r.steps_per_second.toFixed(0).padStart(8)}  ${r.ms_per_evaluation.toFixed(2).padStart(16)}  ${r.best_ms_per_evaluation.toFixed(2).padStart(14)}  ${r.realtime_factor.toFixed(0).padStart(12)}  ${r.displacement_m.toFixed(2).padStart(6)}`);
  }
}
