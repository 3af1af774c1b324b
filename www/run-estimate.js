// @ts-check
/**
 * How long the settings in the run form would take on this computer, said before a run starts
 * (under the plan line): the planned evaluations times the episode's seconds, at the pace the
 * simulation worker steps the robot walking now (simulated seconds per second of computing,
 * the viewer's "computer can simulate"), shared by the workers. An estimate: the robots a run
 * evolves are this body with other brains of the same size, and workers sharing a computer
 * rarely add their full speed (docs/playground.md measures it).
 */
import { durationWords } from './run-progress.js';

/** How often the estimate follows the form and the pace (ms). */
const REFRESH_MS = 1000;

/**
 * Seconds of computing a run takes at `pace` (NaN when something is unknown).
 * @param {number} evaluations @param {number} episodeSeconds @param {number} workers @param {number} pace simulated s per compute s
 */
export function estimateSeconds(evaluations, episodeSeconds, workers, pace) {
  const seconds = (evaluations * episodeSeconds) / (pace * workers);
  return seconds > 0 && Number.isFinite(seconds) ? seconds : NaN;
}

export class RunEstimate {
  /**
   * @param {HTMLElement} out where the estimate is said
   * @param {import('./run-settings.js').RunSettings} form the run settings
   * @param {() => number} pace the walking robot's simulated s per compute s (NaN: not known yet)
   */
  constructor(out, form, pace) {
    this.out = out;
    this.form = form;
    this.pace = pace;
    setInterval(() => this.refresh(), REFRESH_MS);
  }

  refresh() {
    const locked = this.form.inputs.budget.disabled; // a run is going: its progress says how long it has left
    const [seconds, workers] = [this.form.number('seconds'), this.form.number('workers')];
    const pace = this.pace();
    const took = locked ? NaN : estimateSeconds(this.form.planned, seconds, workers, pace);
    this.out.dataset.value = String(took);
    this.out.textContent = Number.isFinite(took)
      ? `On this computer that is about ${durationWords(took)} on ${workers} worker${workers === 1 ? '' : 's'} `
        + `(at ${Math.round(pace)}x real time, the pace it simulates the robot walking now).`
      : '';
    this.out.hidden = !this.out.textContent;
  }
}
