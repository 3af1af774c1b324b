// @ts-check
/**
 * Two or more wasm builds compared in one Node process (a benchmark that prints figures, not
 * a test): each build's `benchEpisode` (a 30-s episode of the phase gait f = 1 Hz, phi = 1.5
 * on hilly-1-10-0) in turn, ROUNDS rounds after 3 warm-ups each, so the host's drift hits
 * every build alike. Prints, per build, the CPU time of the process (user + system, steadier
 * than wall time on a shared machine) and the wall time per episode, min and median over the
 * rounds, and the displacements seen (one value per build if the builds agree).
 *
 *   node tests/bench/wasm_alternate.mjs ROUNDS SHAPE PKG_DIR [PKG_DIR ...]
 * Each PKG_DIR is a `wasm-pack build --target web --out-name vsr` output (vsr.js, vsr_bg.wasm).
 */
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { performance } from 'node:perf_hooks';

const [rounds = '10', shape = 'biped-4x3', ...pkgs] = process.argv.slice(2);
if (!pkgs.length) {
  console.error('usage: node tests/bench/wasm_alternate.mjs ROUNDS SHAPE PKG_DIR [PKG_DIR ...]');
  process.exit(2);
}
const mods = [];
for (const p of pkgs) {
  const m = await import(path.resolve(p, 'vsr.js'));
  m.initSync({ module: readFileSync(path.resolve(p, 'vsr_bg.wasm')) });
  mods.push(m);
}
const cpu = () => { const u = process.cpuUsage(); return (u.user + u.system) / 1000; };
const run = (/** @type {any} */ m) => m.benchEpisode(shape, 'hilly-1-10-0', 1, 1.5, 1801);
/** @type {number[][][]} */
const times = mods.map(() => []);
const dxs = mods.map(() => new Set());
for (const m of mods) for (let i = 0; i < 3; i++) run(m);
for (let r = 0; r < Number(rounds); r++) {
  mods.forEach((m, i) => {
    const [c0, w0] = [cpu(), performance.now()];
    dxs[i].add(run(m));
    times[i].push([cpu() - c0, performance.now() - w0]);
  });
}
const median = (/** @type {number[]} */ xs) => [...xs].sort((a, b) => a - b)[xs.length >> 1];
const fmt = (/** @type {number[]} */ xs) => `min ${Math.min(...xs).toFixed(2)} median ${median(xs).toFixed(2)}`;
pkgs.forEach((p, i) => {
  const cpuMs = times[i].map((t) => t[0]);
  const wallMs = times[i].map((t) => t[1]);
  console.log(`${p} ${shape}: cpu ms ${fmt(cpuMs)} | wall ms ${fmt(wallMs)} | dx ${[...dxs[i]].join(' ')}`);
});
