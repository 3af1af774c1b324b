// @ts-check
/**
 * A tiny evolution as the page runs it (a coordinator worker and its evaluation workers) and
 * as `vsr evolve` runs it with the same settings: shared by tests/web/evolve.test.mjs
 * (Chromium) and tests/browsers/ (Firefox, WebKit), which compare the two bit for bit.
 */
import { execFileSync } from 'node:child_process';
import { readFile } from 'node:fs/promises';
import { BIN } from './harness.mjs';

/** The page's settings: biped-4x3, 6 robots a generation, 18 evaluations of 2 s on flat ground. */
export const TINY = Object.freeze({ shape: '1111-1111-1001', controller: 'attention', seed: 3, seconds: 2, terrain: 'flat', population: 6, budget: 18 });

/**
 * Runs a whole evolution in a coordinator worker, as the page does; runs in the page (pass
 * it to the browser's evaluate with its one argument). `crash` makes worker 1 crash during
 * generation 1.
 * @param {[typeof TINY, number, boolean]} arg settings, workers, crash
 * @returns {Promise<{run: any, recovered: string[]}>}
 */
export async function evolveInPage([settings, workers, crash]) {
  const { FromCoordinator, ToCoordinator } = await import(new URL('workers/protocol.js', location.href).href);
  const coordinator = new Worker(new URL('runs/coordinator.js', location.href), { type: 'module' });
  /** @type {string[]} */
  const recovered = [];
  const text = await new Promise((resolve, reject) => {
    coordinator.onmessage = ({ data }) => {
      if (data.type === FromCoordinator.STARTED && crash) coordinator.postMessage({ type: ToCoordinator.CRASH_WORKER, index: 1 });
      if (data.type === FromCoordinator.RECOVERED) recovered.push(data.message);
      if (data.type === FromCoordinator.DONE) resolve(data.runFile);
      if (data.type === FromCoordinator.ERROR) reject(new Error(data.message));
    };
    coordinator.postMessage({ type: ToCoordinator.START, settings, workers, source: null });
  });
  coordinator.terminate();
  return { run: JSON.parse(text), recovered };
}

/** The statistics of every generation, wall time aside. @param {any} run */
export const statistics = (run) => run.generations.map((/** @type {any} */ g) => ({ ...g, wall_seconds: 0 }));

/**
 * The same evolution by `vsr evolve` on 1 thread (needs target/release/vsr; VSR_BIN).
 * @param {string} out the run file to write @returns {Promise<any>} its run
 */
export async function evolveNative(out) {
  execFileSync(BIN, ['evolve', '--shape', 'biped-4x3', '--controller', TINY.controller, '--evals', String(TINY.budget),
    '--seed', String(TINY.seed), '--seconds', String(TINY.seconds), '--terrain', TINY.terrain,
    '--population', String(TINY.population), '--threads', '1', '--out', out]);
  return JSON.parse(await readFile(out, 'utf8'));
}
