// @ts-check
/**
 * How long the settings in the run form would take on this computer, said before a run starts
 * (under the plan line), from the pace of the latest run here: a run's cost grows with its
 * evaluations, its episodes' seconds and its body's voxels, and shrinks with its workers, so
 * the pace is kept as simulated voxel-seconds per second per worker (run-panel.js measures it
 * at every generation, pauses excluded). Before the first run there is no estimate: the
 * viewer's simulation pace was tried and missed by 1.5 to 6 times (it warms up, and it steps a
 * few frames at a time).
 */
import { durationWords } from './run-progress.js';

/** How often the estimate follows the form and the drawing (ms). */
const REFRESH_MS = 1000;

/** The voxels of a body given as rows ('1111-1111-1001': 10). @param {string} rows */
export function voxelCount(rows) {
  return [...rows].filter((c) => c === '1').length;
}

/**
 * Seconds a run takes at `pace` (NaN when something is unknown).
 * @param {{evaluations: number, seconds: number, voxels: number, workers: number}} run
 * @param {number} pace simulated voxel-seconds per second per worker
 */
export function estimateSeconds({ evaluations, seconds, voxels, workers }, pace) {
  const took = (evaluations * seconds * voxels) / (pace * workers);
  return took > 0 && Number.isFinite(took) ? took : NaN;
}

export class RunEstimate {
  /**
   * @param {HTMLElement} out where the estimate is said
   * @param {import('./run-settings.js').RunSettings} form the run settings
   * @param {() => number} pace the latest run's pace (NaN: none yet)
   * @param {() => string} rows the body drawn now
   */
  constructor(out, form, pace, rows) {
    this.out = out;
    this.form = form;
    this.pace = pace;
    this.rows = rows;
    setInterval(() => this.refresh(), REFRESH_MS);
  }

  refresh() {
    const locked = this.form.inputs.budget.disabled; // a run is going: its progress says how long it has left
    const run = { evaluations: this.form.planned, seconds: this.form.number('seconds'), voxels: voxelCount(this.rows()),
      workers: this.form.number('workers') };
    const took = locked ? NaN : estimateSeconds(run, this.pace());
    this.out.dataset.value = String(took);
    this.out.textContent = Number.isFinite(took)
      ? `At the pace of the last run here, that is about ${durationWords(took)} on ${run.workers} worker${run.workers === 1 ? '' : 's'}.`
      : '';
    this.out.hidden = !this.out.textContent;
  }
}
