// @ts-check
/**
 * The line under the viewer that puts the walking brain's speed in context: its speed on the
 * viewer's terrain over the viewer's episode, measured at once (measure.js, the fitness's own
 * evaluation), beside what training measured and why the two differ; for a module just
 * transplanted, that this one-shot speed is expected to be poor and what to do next.
 * Its raw number is in `data-value` (NaN while measuring or with no brain), the body it is
 * measured on in `data-rows`.
 */
import { checkTerrain } from '../workers/core.js';
import { messageOf } from '../workers/kit.js';
import { decimal } from '../shared/format.js';
import { hasAttention, isAnyBody } from '../shared/families.js';

export class SpeedNote {
  /** @param {HTMLElement} el @param {import('./measure.js').Measurer} measurer */
  constructor(el, measurer) {
    this.el = el;
    this.measurer = measurer;
    /** Counts the brains shown, so that a measure of an earlier one never overwrites a newer note. */
    this.shown = 0;
  }

  /**
   * @param {import('./brain.js').Brain | null} brain @param {string} terrain the viewer's
   * @param {number} seconds the viewer's episode length
   * @param {boolean} [now] measure it now (while a run uses the workers, the viewer's own measure is enough)
   */
  async show(brain, terrain, seconds, now = true) {
    const ticket = ++this.shown;
    // Its words stay until the new ones are written (below, at once or once known): an empty line,
    // even for a moment, moves everything under it (a run's Stop, each time a newer best walks).
    this.el.dataset.value = 'NaN';
    this.el.dataset.rows = brain?.rows ?? '';
    if (!brain) {
      this.set(NaN, `The phase gait has no brain: each voxel squeezes and swells on a clock. Its speed is measured as it walks, over a ${seconds}-s episode.`);
      return;
    }
    if (!now) { // the workers are the run's: the viewer's own measure, under the robot, is the speed here
      const here = `The viewer measures its speed as it walks, over a ${seconds}-s episode on ${terrain} (under the robot, once the episode is over)`;
      const trained = brain.trained && Number.isFinite(brain.trained.speed) ? brain.trained : null;
      if (!trained) { this.set(NaN, `${here}; the run goes on.`); return; }
      const said = training(trained, brain.seconds ?? seconds).then(({ where, why }) => `In training: ${decimal(trained.speed)} m/s `
        + `(${which(trained)} ${where}). ${here}. ${why}`, () => `${here}; the run goes on.`);
      const text = await said;
      if (ticket === this.shown) this.set(NaN, text);
      return;
    }
    this.set(NaN, `Measuring its speed over a ${seconds}-s episode on ${terrain}…`);
    const what = { rows: brain.rows, controller: brain.controller, genome: brain.genome, terrain, seconds };
    this.measurer.measure(what).then(async (speed) => {
      const words = await this.words(brain, speed, terrain, seconds);
      if (ticket === this.shown) this.set(speed, words);
    }).catch((error) => {
      if (ticket === this.shown && messageOf(error) !== 'stale') this.set(NaN, `Its speed could not be measured: ${messageOf(error)}`);
    });
  }

  /**
   * @param {import('./brain.js').Brain} brain @param {number} speed @param {string} terrain @param {number} seconds
   * @returns {Promise<string>}
   */
  async words(brain, speed, terrain, seconds) {
    // Measured at once, on a walk of its own: a freeze or an edit of the walk on screen changes that walk's figures, not this.
    // Your robot's speed: the one a challenge's short code and the class's ranking use (the other two are training's).
    const here = `Your robot's speed: ${decimal(speed)} m/s over a ${seconds}-s episode on ${terrain} (measured at once, on a walk with no freeze or edit; `
      + 'the short code and the class ranking use this one).';
    if (brain.oneShot && isAnyBody(brain.controller)) {
      return `${here} That is its speed on your body with no training for it: a brain for any body keeps all its genes on every body `
        + '(each voxel works out its own weights from its place in the body, such as which neighbours it has), so nothing was drawn at random for yours. '
        + (hasAttention(brain.controller) ? 'Fine-tune trains it further for this body, its attention kept.' : 'Evolve trains a new brain for this body.');
    }
    if (brain.oneShot) {
      return `${here} That is its one-shot speed, before any training for this body. Its attention fits any body, but the `
        + 'weights that turn each voxel\'s readings into a squeeze were made for the old body\'s voxels, so your robot\'s are '
        + 'drawn at random. It usually walks badly at first (the paper found the same): press Fine-tune to evolve those '
        + 'weights for this body, its attention kept.';
    }
    const trained = brain.trained;
    if (!trained || !Number.isFinite(trained.speed)) return here;
    const { where, why } = await training(trained, brain.seconds ?? seconds);
    // The run's “best so far” is a third speed: said in one sentence, for a brain from the run.
    const best = brain.run ? ' “Best so far”, under the run, is its single fastest walk in training, often a lucky one.' : '';
    return `${here} In training: ${decimal(trained.speed)} m/s (${which(trained)} ${where}). ${why}${best}`;
  }

  /** @param {number} value @param {string} text */
  set(value, text) {
    this.el.dataset.value = String(value);
    this.el.textContent = text;
  }
}

/**
 * What the training figure is, and the words that lead to where it was measured.
 * @param {import('./brain.js').Trained} trained
 */
function which(trained) {
  if (trained.walks) return trained.walks === 1 ? 'one evaluation only, on' : `the mean of its ${trained.walks} evaluations, each on`;
  return trained.single ? 'its best single evaluation, on' : 'its latest evaluation, on';
}

/**
 * Where training measured a brain (a terrain drawn fresh from a family, or one terrain) and
 * why that figure differs from the speed on the viewer's terrain.
 * @param {import('./brain.js').Trained} trained @param {number} seconds its episodes
 * @returns {Promise<{where: string, why: string}>}
 */
async function training(trained, seconds) {
  const fresh = (await checkTerrain(trained.terrain)) !== ''; // a family (hilly-1-10), not one terrain
  return fresh
    ? { where: `a ${trained.terrain} terrain drawn fresh for that evaluation, ${seconds}-s episodes`,
      why: `Training draws a fresh terrain for every evaluation${trained.walks ? ' (the body search walks each body it keeps again, every round)' : ', each generation,'} and keeps the fastest; the viewer keeps one terrain, so the two differ.` }
    : { where: `${trained.terrain}, ${seconds}-s episodes`, why: 'Training used other sensor noise (or another terrain), so the two can differ.' };
}
