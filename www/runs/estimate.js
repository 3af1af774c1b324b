// @ts-check
/**
 * How long the settings in the run form would take on this computer, said before a run starts
 * (under the plan line). A run's cost grows with its evaluations, its episodes' seconds and its
 * body's voxels, and shrinks with its workers, so a pace is kept as simulated voxel-seconds per
 * second per worker: the latest run's here (panel.js measures it at every generation,
 * pauses excluded), or, before any run, the page's own measure as it opens (pace.js: a few
 * seconds of evaluations of random brains in evaluation workers of its own, the very evaluation
 * a run makes). The quick settings are made lighter where they would take well over a minute,
 * never those a class challenge fixes (settings.js: fix): a computer too slow for them says so
 * beside the estimate, and runs them all.
 * With the from-scratch comparison switched on, a fine-tune is two runs of the same budget on
 * the same body, one after the other: the estimate says both.
 * The viewer's simulation pace was tried first and missed by 1.5 to 6 times (it
 * warms up, and it steps a few frames at a time).
 */
import { measurePace } from './pace.js';
import { durationWords } from './progress.js';
import { count } from '../shared/format.js';

/** How often the estimate follows the form and the drawing (ms). */
const REFRESH_MS = 1000;

/**
 * The quick settings should take about a minute: above {@link QUICK_MOST_S} here, the Quick
 * settings lighten the budget to the largest of {@link LIGHTER} that takes at most
 * {@link QUICK_AIM_S} (the population and episodes stay, so a run starts as any quick run).
 */
const QUICK_MOST_S = 90;
const QUICK_AIM_S = 70;
const LIGHTER = [1000, 500, 200];

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
   * @param {import('./settings.js').RunSettings} form the run settings
   * @param {() => number} pace the latest run's pace (NaN: none yet)
   * @param {() => string} rows the body drawn now
   * @param {import('../workers/core.js').RunPreset} quick the core's quick settings
   * @param {() => boolean} [compare] whether a fine-tune is followed by a run from scratch (the form's box)
   */
  constructor(out, form, pace, rows, quick, compare = () => false) {
    this.out = out;
    this.form = form;
    this.pace = pace;
    this.rows = rows;
    this.quick = quick;
    this.compare = compare;
    /** This computer's pace as measured when the page opened (NaN until then, or if it failed). */
    this.measured = NaN;
    /** The quick budget made lighter for this computer, and the core's (null: not lighter). @type {{budget: number, from: number} | null} */
    this.lighter = null;
    form.quick = (p) => this.fitQuick(p);
    form.planChanged = () => this.refresh(); // at once: the estimate never stands beside another budget's
    this.timer = setInterval(() => this.refresh(), REFRESH_MS);
  }

  /**
   * Measures this computer's pace (once, as the page opens) on the drawn body, checked (the
   * core's check, with its gene counts), with the workers the form says.
   * @param {string} rows @param {import('../workers/core.js').ShapeCheck} check @param {number} seconds @param {string} terrain a terrain family
   */
  async measure(rows, check, seconds, terrain) {
    const genes = check.params.find(([kind]) => kind === 'attention')?.[1];
    if (!check.ok || !genes) return; // no robot drawn: the first run's pace will say
    try {
      this.measured = await measurePace({ rows, voxels: check.voxels, controller: 'attention', genes, seconds, terrain,
        workers: this.form.number('workers') });
      if (this.form.untouched) this.form.preset(this.fitQuick(this.quick)); // a fresh visitor's quick settings, fitted
    } catch (error) {
      console.warn('the page could not measure this computer\'s speed', error);
    }
    this.refresh();
  }

  /** This computer's pace: the last run's here, else the one measured as the page opened (NaN: neither). */
  currentPace() {
    const last = this.pace();
    return Number.isFinite(last) ? last : this.measured;
  }

  /**
   * The quick settings `p` for this computer: lighter if they would take well over a minute
   * here (the drawing's voxels, the form's workers). @param {import('../workers/core.js').RunPreset} p
   * @returns {import('../workers/core.js').RunPreset}
   */
  fitQuick(p) {
    const run = (/** @type {number} */ budget) => estimateSeconds({ evaluations: budget + p.population, seconds: p.seconds,
      voxels: voxelCount(this.rows()), workers: this.form.number('workers') }, this.currentPace());
    const took = run(p.budget);
    this.lighter = null;
    if (!(took > QUICK_MOST_S) || this.form.fixed.size > 0) return p; // a challenge's run is everyone's: never lighter
    const budget = LIGHTER.find((b) => b < p.budget && run(b) <= QUICK_AIM_S) ?? LIGHTER[LIGHTER.length - 1];
    this.lighter = { budget, from: p.budget };
    return { ...p, budget };
  }

  refresh() {
    const locked = this.form.running; // a run is going: its progress says how long it has left
    const run = { evaluations: this.form.planned, seconds: this.form.number('seconds'), voxels: voxelCount(this.rows()),
      workers: this.form.number('workers') };
    const last = this.pace();
    const took = locked ? NaN : estimateSeconds(run, this.currentPace());
    this.out.dataset.value = String(took); // one run
    const two = this.compare() ? 2 * took : NaN; // a fine-tune and its comparison
    this.out.dataset.total = String(Number.isFinite(two) ? two : took);
    this.out.dataset.from = Number.isFinite(last) ? 'last-run' : 'measured';
    const pace = Number.isFinite(last) ? 'At the pace of the last run here' : 'At this computer\'s speed, measured as the page opened';
    const lighter = this.lighter && this.form.number('budget') === this.lighter.budget
      ? ` The quick settings are lighter on this computer: ${count(this.lighter.budget)} evaluations, not `
        + `${count(this.lighter.from)} (about ${durationWords(estimateSeconds({ ...run, evaluations: this.lighter.from + this.form.number('population') }, this.currentPace()))} here).` : '';
    // A run a challenge fixes is never made lighter: a computer too slow for it is told so, and how long it takes.
    const slow = this.form.fixed.size > 0 && took > QUICK_MOST_S
      ? ` This computer is slow for ${this.form.fixedBy}'s run: it runs all ${count(this.form.number('budget'))} evaluations all the same (the run must be the same as everyone's), `
        + 'so start it now and let it finish, or use a faster computer.' : '';
    this.out.dataset.slow = String(slow !== '');
    this.out.textContent = Number.isFinite(took)
      ? `${pace}, that is about ${durationWords(took)}${Number.isFinite(two) ? ' a run' : ''} on ${run.workers} worker${run.workers === 1 ? '' : 's'}`
        + `${Number.isFinite(two) ? `; Fine-tune with the from-scratch comparison makes two runs, about ${durationWords(two)} in all` : ''}.${lighter}${slow}`
      : '';
    this.out.hidden = !this.out.textContent;
  }
}
