// @ts-check
/**
 * The classroom's lab (a module worker; lab.js asks it): walks a robot for an episode with the
 * core's own episode, off the page's main thread, so that every number a task's reveal quotes
 * is one the page has just run: the speed of the phase gait or of a genome (the fitness's
 * measure, as `vsr evaluate` prints it), the speed before and after freezing the attention,
 * and how the attention matrices sit during the walk.
 */
import init, * as wasm from '../pkg/vsr.js';
import { answerRequests, loadWasm } from '../workers/kit.js';

/** Steps of the brain's one decision (the core's ACTUATION_HOLD_STEPS): attention is sampled once per decision. */
const SAMPLE_STEPS = 20;

/**
 * @typedef {object} Walk
 * @property {string} rows @property {string} terrain @property {number} seconds
 * @property {{frequency: number, phase: number}} [gait]  without a brain
 * @property {{controller: string, genome: Float32Array}} [brain]
 * @property {number} [freezeAt]  freeze the attention at this second
 * @property {number} [saturated] sample the attention matrices: a value beyond ±saturated counts as saturated
 */

/** @param {Walk} walk */
function episodeOf(walk) {
  if (walk.brain) return wasm.Episode.fromGenome(walk.rows, walk.terrain, walk.brain.controller, Float32Array.from(walk.brain.genome), NaN);
  const gait = walk.gait ?? { frequency: 1, phase: 0 };
  return new wasm.Episode(walk.rows, walk.terrain, gait.frequency, gait.phase);
}

/**
 * Walks `walk` and answers its speed (m/s over the episode); with freezeAt, also the speed
 * before it and the speed frozen (from that second to the end); with saturated, per sensor
 * row: the mean share of saturated values and of values that moved by more than 0.5 over the
 * walk, and the mean number of saturated values of a 16-value matrix.
 * @param {Walk} walk
 */
function run(walk) {
  const ep = episodeOf(walk);
  try {
    /** @type {Record<string, any>} */
    const out = {};
    if (walk.freezeAt !== undefined) {
      ep.step(ep.stepsLeft(walk.freezeAt));
      out.before = ep.velocity;
      const [x0, t0] = [ep.centreX, ep.time];
      ep.freezeAttention(true);
      ep.step(ep.stepsLeft(walk.seconds));
      out.frozen = (ep.centreX - x0) / (ep.time - t0);
      out.speed = ep.velocity;
      return out;
    }
    if (walk.saturated === undefined) {
      ep.step(ep.stepsLeft(walk.seconds));
      out.speed = ep.velocity;
      return out;
    }
    const limit = walk.saturated;
    let samples = 0;
    let saturated = 0;
    /** @type {Float32Array | null} */ let low = null;
    /** @type {Float32Array | null} */ let high = null;
    while (ep.stepsLeft(walk.seconds) > 0) {
      ep.step(Math.min(SAMPLE_STEPS, ep.stepsLeft(walk.seconds)));
      const a = ep.attention();
      if (a.length === 0) throw new Error('this brain has no attention');
      low ??= Float32Array.from(a);
      high ??= Float32Array.from(a);
      for (let i = 0; i < a.length; i++) {
        if (Math.abs(a[i]) > limit) saturated++;
        low[i] = Math.min(low[i], a[i]);
        high[i] = Math.max(high[i], a[i]);
      }
      samples += a.length / 16;
    }
    out.speed = ep.velocity;
    out.saturatedPer16 = (16 * saturated) / (16 * samples);
    const moved = [0, 0, 0, 0];
    if (low && high) for (let i = 0; i < low.length; i++) if (high[i] - low[i] > 0.5) moved[Math.floor((i % 16) / 4)]++;
    const matrices = (low?.length ?? 0) / 16;
    out.movedByRow = moved.map((m) => m / (4 * matrices)); // share of a row's values that moved, over every voxel
    out.voxels = matrices;
    return out;
  } finally {
    ep.free();
  }
}

answerRequests(loadWasm(init, wasm.start), { walk: run });
