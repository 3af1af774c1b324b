// @ts-check
/**
 * The run settings form (“Run” under “3 · Give it a brain”): population, episode seconds,
 * budget, seed, training terrain and workers, the quick and paper presets, the fresh-seed
 * dice, and the plan the population and budget make, in words. It reads the form into the
 * settings a run starts with, or says what is wrong with them: at once, as they are typed, in
 * the plan line (and Evolve is off until they are fixed; their message goes once they are).
 */
import { checkTrainingTerrain, freshSeed } from '../workers/core.js';
import { byId, make } from '../shared/dom.js';
import { messageOf } from '../workers/kit.js';
import { planWords } from './plan.js';
import { MAX_EVALUATORS } from '../workers/protocol.js';
import { RUN_KEYS } from '../keep/share.js';
import { RUN_TIME } from './time.js';
import { count, decimal } from '../shared/format.js';

export class RunSettings {
  /**
   * @param {Document} doc the page
   * @param {import('../workers/core.js').Defaults} defaults
   * @param {(text: string) => void} message shows an error about the settings ('' takes it away)
   * @param {() => void} changed the settings became valid or invalid
   */
  constructor(doc, defaults, message, changed) {
    this.defaults = defaults;
    this.message = message;
    this.changed = changed;
    /** The settings in the form are not valid (the plan line says why). */
    this.invalid = false;
    /** @type {Record<string, HTMLInputElement>} */
    this.inputs = {
      population: byId(doc, 'run-population', HTMLInputElement), seconds: byId(doc, 'run-seconds', HTMLInputElement),
      budget: byId(doc, 'run-budget', HTMLInputElement), seed: byId(doc, 'run-seed', HTMLInputElement),
      terrain: byId(doc, 'run-terrain', HTMLInputElement), workers: byId(doc, 'run-workers', HTMLInputElement),
    };
    /** @type {Record<string, HTMLButtonElement>} */
    this.buttons = {
      quick: byId(doc, 'run-quick', HTMLButtonElement), paper: byId(doc, 'run-paper', HTMLButtonElement),
      dice: byId(doc, 'run-dice', HTMLButtonElement),
    };
    this.plan = byId(doc, 'run-plan');
    /** The line at the top of the form, while a challenge fixes settings: greyed out, and why (a title is not read on a touch screen). */
    this.fixedNote = doc.createElement('p');
    this.fixedNote.className = 'explain run-fixed';
    this.fixedNote.dataset.testid = 'run-fixed';
    this.fixedNote.hidden = true;
    byId(doc, 'run-settings').querySelector('legend')?.after(this.fixedNote);
    /** Plans asked: only the latest one's words are shown. */
    this.plans = 0;
    /** Evaluations the settings in the form plan (NaN while they are not valid). */
    this.planned = NaN;
    /** The quick settings for this computer (estimate.js may make them lighter); the core's until then. */
    this.quick = (/** @type {import('../workers/core.js').RunPreset} */ p) => p;
    /** Called when the evaluations planned change (estimate.js says how long they take). */
    this.planChanged = () => {};
    /** The form holds what the page opened with: nothing typed, chosen, restored or set up since. */
    this.untouched = true;
    /** The settings a class challenge fixes (locked, kept through runs), and by what, in words ('' when none). */
    this.fixed = /** @type {Set<string>} */ (new Set());
    this.fixedBy = '';
    /** A run uses the settings (lock). */
    this.running = false;
    this.inputs.seed.value = '1';
    this.inputs.terrain.value = defaults.trainingTerrain;
    this.inputs.workers.value = String(Math.max(1, Math.min(MAX_EVALUATORS, navigator.hardwareConcurrency || 1)));
    this.inputs.workers.max = String(MAX_EVALUATORS);
    this.preset(defaults.quick); // after every input is filled: the plan checks them all
    this.buttons.quick.addEventListener('click', () => this.preset(this.quick(defaults.quick)));
    this.buttons.paper.addEventListener('click', () => this.preset(defaults.paper));
    const words = (/** @type {import('../workers/core.js').RunPreset} */ p) => `population ${count(p.population)}, ${p.seconds}-s episodes, ${count(p.budget)} evaluations`;
    this.buttons.quick.title = `Population, episodes and evaluations for a quick run, ${RUN_TIME}: ${words(defaults.quick)}`;
    this.buttons.paper.title = `The paper's settings: ${words(defaults.paper)}`;
    for (const button of [this.buttons.quick, this.buttons.paper]) button.addEventListener('click', () => { this.untouched = false; });
    this.buttons.dice.addEventListener('click', () => freshSeed().then((seed) => { this.inputs.seed.value = String(seed); },
      (error) => message(`no fresh seed: ${messageOf(error)}`)));
    for (const input of Object.values(this.inputs)) input.addEventListener('input', () => { this.untouched = false; this.describePlan(); });
  }

  /** Says what the settings in the form make, or what is wrong with them. */
  describePlan() {
    const ticket = ++this.plans;
    this.problem().then(async (problem) => {
      const words = problem ? null : await planWords(Number(this.inputs.population.value), Number(this.inputs.budget.value));
      if (ticket !== this.plans) return;
      this.planned = words?.planned ?? NaN;
      this.planChanged();
      if (problem || !words) this.plan.textContent = problem ? `Not valid yet: ${problem}. Evolve is off until it is fixed.` : '';
      else this.plan.replaceChildren(make(this.plan.ownerDocument, 'span', 'expert', words.text), make(this.plan.ownerDocument, 'span', 'simple-only', words.simple)); // one of the two shows (Simple words)
      this.plan.dataset.invalid = String(problem !== '');
      if (!problem) this.message('');
      if (this.invalid !== (problem !== '')) { this.invalid = problem !== ''; this.changed(); }
    });
  }

  /** @param {import('../workers/core.js').RunPreset} p */
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

  /** @param {Partial<Record<string, string>>} values settings to put in the form (not those a challenge fixes) */
  setValues(values) {
    this.untouched = false;
    for (const [k, value] of Object.entries(values)) if (this.inputs[k] && value !== undefined && !this.fixed.has(k)) this.inputs[k].value = String(value);
    this.describePlan();
  }

  /**
   * Fixes settings for good (a class challenge: every student's run the same): put in the form,
   * locked, and never made lighter for a slow computer (estimate.js says how long they take instead).
   * @param {Record<string, string>} values @param {string} by what fixes them, in words
   */
  fix(values, by) {
    this.fixed = new Set();
    this.setValues(values);
    this.fixed = new Set(Object.keys(values).filter((k) => this.inputs[k]));
    this.fixedBy = by;
    this.fixedNote.textContent = `Set by ${by} (greyed out): the same on every computer, so the same drawing gives the same robot everywhere. `
      + 'Workers only changes how fast it runs here.';
    this.fixedNote.hidden = this.fixed.size === 0;
    this.lock(false);
  }

  /** @param {boolean} running a run uses the settings: the form is locked (what a challenge fixes stays locked) */
  lock(running) {
    this.running = running;
    const fixed = this.fixed.size > 0;
    for (const button of Object.values(this.buttons)) button.disabled = running || (fixed && button !== this.buttons.dice);
    this.buttons.dice.disabled = running || this.fixed.has('seed');
    for (const [k, input] of Object.entries(this.inputs)) {
      input.disabled = running || this.fixed.has(k);
      input.dataset.title ??= input.title; // its own title, back when nothing fixes it
      input.title = this.fixed.has(k) ? `Set by ${this.fixedBy}: the same for everyone` : input.dataset.title;
    }
  }

  /**
   * The settings in the form for a run on `rows`, or a message saying what is wrong with them.
   * @param {string} rows @param {string} controller
   * @returns {Promise<{settings: import('../workers/protocol.js').EvolveSettings, workers: number} | {error: string}>}
   */
  async read(rows, controller) {
    const problem = await this.problem();
    if (problem) return { error: problem };
    const [population, seconds, budget, seed, workers] = ['population', 'seconds', 'budget', 'seed', 'workers'].map((k) => this.number(k));
    return { settings: { shape: rows, controller, seed, seconds, terrain: this.inputs.terrain.value.trim(), population, budget }, workers };
  }

  /** @param {string} key @returns {number} the number in that input (NaN: none) */
  number(key) { return Number(this.inputs[key].value.trim() || NaN); }

  /** '' or what is wrong with the settings in the form. @returns {Promise<string>} */
  async problem() {
    const [population, seconds, budget, seed, workers] = ['population', 'seconds', 'budget', 'seed', 'workers'].map((k) => this.number(k));
    if (!Number.isInteger(population) || population < 1) return `population must be a whole number of at least 1, not "${this.inputs.population.value}"`;
    if (!(seconds > 0) || !Number.isFinite(seconds)) return `episode seconds must be a positive number, not "${this.inputs.seconds.value}"`;
    if (!Number.isInteger(budget) || budget < population) return `the budget must be a whole number of evaluations, at least one population (${population}), not "${this.inputs.budget.value}"`;
    if (!Number.isSafeInteger(seed) || seed < 0) return `the seed must be a whole number from 0 to 2^53 - 1, not "${this.inputs.seed.value}"`;
    if (!Number.isInteger(workers) || workers < 1 || workers > MAX_EVALUATORS) return `workers must be a whole number from 1 to ${MAX_EVALUATORS}, not "${this.inputs.workers.value}"`;
    const terrainProblem = await checkTrainingTerrain(this.inputs.terrain.value.trim());
    return terrainProblem ? `training terrain: ${terrainProblem}` : '';
  }
}
