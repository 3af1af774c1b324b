// @ts-check
/**
 * The run settings form (“Run” under “3 · Give it a brain”): population, episode seconds,
 * budget, seed, training terrain and workers, the quick and paper presets, the fresh-seed
 * dice, and the plan the population and budget make, in words. It reads the form into the
 * settings a run starts with, or says what is wrong with them.
 */
import { checkTrainingTerrain, freshSeed } from './core.js';
import { messageOf } from './kit.js';
import { planWords } from './run-plan.js';
import { MAX_EVALUATORS } from './protocol.js';
import { RUN_KEYS } from './share.js';

export class RunSettings {
  /**
   * @param {(id: string) => any} el the page's element by id
   * @param {import('./core.js').Defaults} defaults
   * @param {(text: string) => void} message shows an error
   */
  constructor(el, defaults, message) {
    this.defaults = defaults;
    /** @type {Record<string, HTMLInputElement>} */
    this.inputs = {
      population: el('run-population'), seconds: el('run-seconds'), budget: el('run-budget'),
      seed: el('run-seed'), terrain: el('run-terrain'), workers: el('run-workers'),
    };
    /** @type {Record<string, HTMLButtonElement>} */
    this.buttons = { quick: el('run-quick'), paper: el('run-paper'), dice: el('run-dice') };
    this.plan = /** @type {HTMLElement} */ (el('run-plan'));
    /** Plans asked: only the latest one's words are shown. */
    this.plans = 0;
    this.preset(defaults.quick);
    this.inputs.seed.value = '1';
    this.inputs.terrain.value = defaults.trainingTerrain;
    this.inputs.workers.value = String(Math.max(1, Math.min(MAX_EVALUATORS, navigator.hardwareConcurrency || 1)));
    this.inputs.workers.max = String(MAX_EVALUATORS);
    this.buttons.quick.addEventListener('click', () => this.preset(defaults.quick));
    this.buttons.paper.addEventListener('click', () => this.preset(defaults.paper));
    this.buttons.dice.addEventListener('click', () => freshSeed().then((seed) => { this.inputs.seed.value = String(seed); },
      (error) => message(`no fresh seed: ${messageOf(error)}`)));
    for (const input of [this.inputs.population, this.inputs.budget]) input.addEventListener('input', () => this.describePlan());
  }

  /** Says what the population and budget in the form make. */
  describePlan() {
    const ticket = ++this.plans;
    planWords(Number(this.inputs.population.value), Number(this.inputs.budget.value)).then((words) => {
      if (ticket === this.plans) this.plan.textContent = words?.text ?? '';
    });
  }

  /** @param {import('./core.js').RunPreset} p */
  preset(p) {
    this.inputs.population.value = String(p.population);
    this.inputs.seconds.value = String(p.seconds);
    this.inputs.budget.value = String(p.budget);
    this.describePlan();
  }

  /** The settings in the form as the page stores and shares them. @returns {Record<string, string>} */
  values() {
    return Object.fromEntries(RUN_KEYS.map((k) => [k, this.inputs[k].value]));
  }

  /** @param {Partial<Record<string, string>>} values settings to put in the form */
  setValues(values) {
    for (const [k, value] of Object.entries(values)) if (this.inputs[k] && value !== undefined) this.inputs[k].value = String(value);
    this.describePlan();
  }

  /** @param {boolean} running a run uses the settings: the form is locked */
  lock(running) {
    for (const button of Object.values(this.buttons)) button.disabled = running;
    for (const input of Object.values(this.inputs)) input.disabled = running;
  }

  /**
   * The settings in the form for a run on `rows`, or a message saying what is wrong with them.
   * @param {string} rows @param {string} controller
   * @returns {Promise<{settings: import('./protocol.js').EvolveSettings, workers: number} | {error: string}>}
   */
  async read(rows, controller) {
    const number = (/** @type {string} */ key) => Number(this.inputs[key].value.trim() || NaN);
    const [population, seconds, budget, seed, workers] = ['population', 'seconds', 'budget', 'seed', 'workers'].map(number);
    if (!Number.isInteger(population) || population < 1) return { error: `population must be a whole number of at least 1, not "${this.inputs.population.value}"` };
    if (!(seconds > 0) || !Number.isFinite(seconds)) return { error: `episode seconds must be a positive number, not "${this.inputs.seconds.value}"` };
    if (!Number.isInteger(budget) || budget < population) return { error: `the budget must be a whole number of evaluations, at least one population (${population}), not "${this.inputs.budget.value}"` };
    if (!Number.isSafeInteger(seed) || seed < 0) return { error: `the seed must be a whole number from 0 to 2^53 - 1, not "${this.inputs.seed.value}"` };
    if (!Number.isInteger(workers) || workers < 1 || workers > MAX_EVALUATORS) return { error: `workers must be a whole number from 1 to ${MAX_EVALUATORS}, not "${this.inputs.workers.value}"` };
    const terrain = this.inputs.terrain.value.trim();
    const terrainProblem = await checkTrainingTerrain(terrain);
    if (terrainProblem) return { error: `training terrain: ${terrainProblem}` };
    return { settings: { shape: rows, controller, seed, seconds, terrain, population, budget }, workers };
  }
}
