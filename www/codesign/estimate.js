// @ts-check
/**
 * The body search in the panel's form, said before it starts (under its buttons): its brain in
 * words, and how long it would take here, as the run form's estimate says (runs/estimate.js): its evaluations at this
 * computer's pace, in simulated voxel-seconds per second per worker, with the start body's
 * voxels. The bodies change size as the search goes, so the figure is a rough guide; while a
 * search runs its progress says how far it is, and the estimate is hidden.
 */
import { estimateSeconds, voxelCount } from '../runs/estimate.js';
import { durationWords } from '../runs/progress.js';

/** How often the estimate follows the form (ms). */
const REFRESH_MS = 1000;

/**
 * @typedef {object} SearchPlan  what the panel's form and the run settings say now
 * @property {number} evaluations @property {number} seconds  each walk's
 * @property {string} rows  the start body @property {number} workers @property {boolean} running
 * @property {string} brain  the brain it would search bodies for, in words
 */

export class SearchEstimate {
  /** @param {HTMLElement} out @param {() => SearchPlan} plan @param {() => number} pace this computer's (NaN: not yet known) */
  constructor(out, plan, pace) {
    this.out = out;
    this.plan = plan;
    this.pace = pace;
    this.timer = setInterval(() => this.refresh(), REFRESH_MS);
  }

  refresh() {
    const p = this.plan();
    const took = p.running ? NaN
      : estimateSeconds({ evaluations: p.evaluations, seconds: p.seconds, voxels: voxelCount(p.rows), workers: p.workers }, this.pace());
    this.out.dataset.value = String(took);
    this.out.textContent = p.running ? '' : `Brain: ${p.brain}.${Number.isFinite(took)
      ? ` At this computer's speed, about ${durationWords(took)} on ${p.workers} worker${p.workers === 1 ? '' : 's'} `
        + '(larger bodies take longer, so it depends on what the search finds).'
      : ''}`;
    this.out.hidden = !this.out.textContent;
  }
}
