// @ts-check
/**
 * This computer's speed at a run's work, measured in the first seconds the page is open: a
 * few evaluation workers of its own (evaluator.js, the very evaluation a run makes) evaluate
 * random brains one after the other for about a second, after a warm-up; estimate.js
 * turns the pace into how long a run will take before the first run here.
 */
import { spawn } from '../workers/kit.js';
import { EvaluatorMessage } from '../workers/protocol.js';

/** Evaluations, and wall time (s), before the measure starts: the wasm warms up (a browser compiles it better as it runs). */
const WARM_UP = 4;
const WARM_UP_S = 0.75;
/** The most evaluations measured, and the wall time (s) after which the measure stops. */
const MEASURED = 40;
const MEASURE_FOR_S = 1;

/**
 * This computer's pace (simulated voxel-seconds per second per worker), measured as a run
 * measures: `workers` evaluation workers of its own (terminated after) at once, so that they
 * share the cores as a run's do, each evaluating random brains of the chosen family for `rows`
 * one after the other, each episode `seconds` long on a terrain of `terrain`; the first
 * {@link WARM_UP} of each not counted. Rejects with a readable Error.
 * @param {{rows: string, voxels: number, controller: string, genes: number, seconds: number, terrain: string, workers: number}} what
 *   the body (its rows and voxels, checked) and its brain family's gene count (the core's check)
 * @returns {Promise<number>}
 */
export async function measurePace({ rows, voxels, controller, genes, seconds, terrain, workers }) {
  const rates = await Promise.all(Array.from({ length: Math.max(1, workers) }, (_, w) => evaluationsPerSecond(w, (index) => ({
    job: { generation: 0, index, shape: rows, controller, terrain: `${terrain}-${1000 * w + index}`, noiseSeed: String(1000 * w + index + 1), seconds },
    genome: Float32Array.from({ length: genes }, () => Math.random() * 2 - 1),
  }))));
  return (rates.reduce((a, b) => a + b, 0) / rates.length) * seconds * voxels;
}

/**
 * Evaluations per second of one evaluation worker of its own, on the jobs `make` gives.
 * @param {number} w which worker (for its error message)
 * @param {(index: number) => {job: import('../workers/protocol.js').EvolveJob, genome: Float32Array}} make
 * @returns {Promise<number>}
 */
function evaluationsPerSecond(w, make) {
  return new Promise((resolve, reject) => {
    let done = 0;
    const began = performance.now();
    let asked = began;
    /** How long each counted evaluation took (ms). @type {number[]} */
    const took = [];
    let since = NaN;
    const next = () => {
      const { job, genome } = make(done);
      asked = performance.now();
      worker.postMessage({ type: EvaluatorMessage.JOB, slot: done, job, genome }, [genome.buffer]);
    };
    const worker = spawn('runs/evaluator.js', (msg) => {
      if (msg.type === EvaluatorMessage.ERROR) { worker.terminate(); reject(new Error(msg.message)); return; }
      if (msg.type !== EvaluatorMessage.RESULT) return;
      done += 1;
      const now = performance.now();
      if (Number.isNaN(since)) { // warming up
        if (done >= WARM_UP && now - began >= WARM_UP_S * 1000) since = now;
      } else {
        took.push(now - asked);
        if (took.length >= MEASURED || now - since >= MEASURE_FOR_S * 1000) {
          worker.terminate();
          // The median evaluation: a stall of the machine (another program's burst) does not count for all.
          const sorted = took.sort((a, b) => a - b);
          resolve(1000 / sorted[Math.floor((sorted.length - 1) / 2)]);
          return;
        }
      }
      next();
    }, (text) => reject(new Error(`measuring worker ${w + 1}: ${text}`)));
    next();
  });
}
