// @ts-check
/**
 * The Evolve panel: reads the run's settings (controller, population, episode seconds,
 * evaluation budget, seed, training terrain; the shape comes from the Shape field), starts
 * one GA coordinator worker per run (coordinator.js), shows its progress live (generation,
 * evaluations / budget, best and median fitness, evaluations per second, a chart), pauses
 * and stops it, offers the current best to watch (as a run file, the path of "Run file from
 * disk") and exports the run file. Bad settings show a message; the last run's file stays.
 */
import { EVOLVE_CONTROLLERS, FromCoordinator, MAX_EVALUATORS, PAPER_EVOLVE, QUICK_EVOLVE,
  ToCoordinator } from './protocol.js';
import { FitnessChart } from './fitness-chart.js';

/** Least wall time between two automatic switches to a new best (ms), so each walks a while. */
const FOLLOW_INTERVAL_MS = 6000;

/**
 * @typedef {object} EvolveHooks
 * @property {() => string} shape   the shape typed in the Shape field
 * @property {(runFile: string, label: string) => void} watch  drive the robot with a run file
 * @property {(text: string) => void} message  shows an error ('' clears it)
 */

export class EvolvePanel {
  /** @param {Document} doc @param {EvolveHooks} hooks */
  constructor(doc, hooks) {
    this.hooks = hooks;
    const el = (/** @type {string} */ id) => {
      const found = doc.getElementById(`evolve-${id}`);
      if (!found) throw new Error(`the page has no #evolve-${id}`);
      return /** @type {any} */ (found);
    };
    /** @type {Record<string, HTMLInputElement | HTMLSelectElement>} */
    this.inputs = {
      controller: el('controller'), population: el('population'), seconds: el('seconds'),
      budget: el('budget'), seed: el('seed'), terrain: el('terrain'),
    };
    /** @type {Record<string, HTMLButtonElement>} */
    this.buttons = {
      quick: el('quick'), paper: el('paper'), start: el('start'), pause: el('pause'),
      stop: el('stop'), watch: el('watch'), export: el('export'),
    };
    this.follow = /** @type {HTMLInputElement} */ (el('follow'));
    /** @type {Record<string, HTMLElement>} */
    this.out = {
      generation: el('generation'), evaluations: el('evaluations'), best: el('best'),
      median: el('median'), rate: el('rate'), status: el('status'),
    };
    this.chart = new FitnessChart(el('chart'));
    /** @type {Worker | null} */
    this.coordinator = null;
    this.paused = false;
    /** The latest run file (JSON text) and the settings of its run, kept after the run ends. */
    this.runFile = /** @type {string | null} */ (null);
    this.runSettings = /** @type {import('./protocol.js').EvolveSettings | null} */ (null);
    /** Whether a better individual is not yet shown (follow mode), and when the view last switched. */
    this.pendingBest = false;
    this.lastSwitch = -Infinity;
    this.followTimer = 0;
    this.planned = 0;
    for (const c of EVOLVE_CONTROLLERS) this.inputs.controller.append(new Option(c));
    this.preset(QUICK_EVOLVE);
    this.inputs.seed.value = '1';
    this.inputs.terrain.value = 'hilly-1-10';
    this.wire();
    this.update();
  }

  wire() {
    const b = this.buttons;
    b.quick.addEventListener('click', () => this.preset(QUICK_EVOLVE));
    b.paper.addEventListener('click', () => this.preset(PAPER_EVOLVE));
    b.start.addEventListener('click', () => this.start());
    b.pause.addEventListener('click', () => this.coordinator?.postMessage({
      type: this.paused ? ToCoordinator.RESUME : ToCoordinator.PAUSE }));
    b.stop.addEventListener('click', () => this.coordinator?.postMessage({ type: ToCoordinator.STOP }));
    b.watch.addEventListener('click', () => this.watchBest());
    b.export.addEventListener('click', () => this.exportRunFile());
  }

  /** @param {{population: number, seconds: number, budget: number}} p */
  preset(p) {
    this.inputs.population.value = String(p.population);
    this.inputs.seconds.value = String(p.seconds);
    this.inputs.budget.value = String(p.budget);
  }

  /**
   * The settings in the form, or a message saying what is wrong with them.
   * @returns {{settings: import('./protocol.js').EvolveSettings} | {error: string}}
   */
  readSettings() {
    const shape = this.hooks.shape();
    if (shape === '') return { error: 'type a shape in the Shape field to evolve its controller' };
    const number = (/** @type {string} */ key) => Number(this.inputs[key].value.trim() || NaN);
    const population = number('population');
    const seconds = number('seconds');
    const budget = number('budget');
    const seed = number('seed');
    if (!Number.isInteger(population) || population < 1) return { error: `population must be a whole number of at least 1, not "${this.inputs.population.value}"` };
    if (!(seconds > 0) || !Number.isFinite(seconds)) return { error: `episode seconds must be a positive number, not "${this.inputs.seconds.value}"` };
    if (!Number.isInteger(budget) || budget < population) return { error: `the budget must be a whole number of evaluations, at least one population (${population}), not "${this.inputs.budget.value}"` };
    if (!Number.isSafeInteger(seed) || seed < 0) return { error: `the seed must be a whole number from 0 to 2^53 - 1, not "${this.inputs.seed.value}"` };
    const terrain = this.inputs.terrain.value.trim();
    const controller = this.inputs.controller.value;
    return { settings: { shape, controller, seed, seconds, terrain, ga: { population, budget_evals: budget } } };
  }

  /** Starts a run with the settings in the form (a bad setting only shows a message). */
  start() {
    if (this.coordinator) return;
    const read = this.readSettings();
    if ('error' in read) { this.hooks.message(read.error); return; }
    this.hooks.message('');
    const workers = Math.max(1, Math.min(MAX_EVALUATORS, navigator.hardwareConcurrency || 1));
    const coordinator = new Worker(new URL('./coordinator.js', import.meta.url), { type: 'module' });
    coordinator.onmessage = (event) => this.onMessage(event.data, read.settings);
    coordinator.onerror = (event) => this.end(`the evolution worker failed: ${event.message || 'see the console'}`);
    coordinator.postMessage({ type: ToCoordinator.START, settings: read.settings, workers });
    this.coordinator = coordinator;
    this.paused = false;
    this.setStatus('starting…');
    this.update();
  }

  /** @param {any} msg a coordinator message @param {import('./protocol.js').EvolveSettings} settings */
  onMessage(msg, settings) {
    switch (msg.type) {
      case FromCoordinator.STARTED:
        this.chart.clear();
        this.runSettings = settings;
        this.planned = msg.planned;
        this.setStatus(`running on ${msg.workers} worker${msg.workers === 1 ? '' : 's'}`);
        show(this.out.evaluations, 0, `0 / ${msg.planned}`);
        break;
      case FromCoordinator.GENERATION: this.onGeneration(msg); break;
      case FromCoordinator.STATE:
        this.paused = msg.paused;
        this.setStatus(msg.paused ? 'paused' : 'running');
        this.update();
        break;
      case FromCoordinator.DONE:
        if (msg.runFile) this.runFile = msg.runFile;
        window.clearTimeout(this.followTimer);
        this.followTimer = 0;
        this.end('', msg.stopped ? 'stopped' : 'finished');
        if (this.follow.checked && msg.runFile) this.watchBest();
        break;
      case FromCoordinator.ERROR: this.end(msg.message); break;
      default: console.warn('unknown message from the coordinator', msg);
    }
  }

  /** @param {{record: any, evaluations: number, planned: number, evalsPerSecond: number, improved: boolean, runFile: string}} msg */
  onGeneration(msg) {
    const { record } = msg;
    this.runFile = msg.runFile;
    show(this.out.generation, record.generation, String(record.generation));
    show(this.out.evaluations, msg.evaluations, `${msg.evaluations} / ${msg.planned}`);
    show(this.out.best, record.best ?? NaN, `${fixed(record.best)} m/s`);
    show(this.out.median, record.median ?? NaN, `${fixed(record.median)} m/s`);
    show(this.out.rate, msg.evalsPerSecond, `${fixed(msg.evalsPerSecond, 1)} evaluations/s`);
    this.chart.add(record.best, record.median);
    if (msg.improved) this.offerBest();
    this.update();
  }

  /** A generation improved the best: switch the view to it (follow mode), at most every few s. */
  offerBest() {
    this.pendingBest = true;
    if (!this.follow.checked || this.followTimer) return;
    const wait = this.lastSwitch + FOLLOW_INTERVAL_MS - performance.now();
    if (wait <= 0) { this.watchBest(); return; }
    this.followTimer = window.setTimeout(() => {
      this.followTimer = 0;
      if (this.follow.checked && this.pendingBest) this.watchBest();
    }, wait);
  }

  /** Drives the robot with the current best (the latest run file's). */
  watchBest() {
    const text = this.runFile;
    if (!text) return;
    const best = JSON.parse(text).best;
    this.pendingBest = false;
    this.lastSwitch = performance.now();
    this.hooks.watch(text, `evolved best (${best.controller}, ${fixed(best.fitness)} m/s)`);
  }

  /** Downloads the latest run file. */
  exportRunFile() {
    if (!this.runFile || !this.runSettings) return;
    const { controller, seed } = this.runSettings;
    const url = URL.createObjectURL(new Blob([this.runFile], { type: 'application/json' }));
    const link = document.createElement('a');
    link.href = url;
    link.download = `evolved-${controller}-seed${seed}.json`;
    link.click();
    setTimeout(() => URL.revokeObjectURL(url), 1000);
  }

  /** The run ended: an error message (or ''), and the status to show. @param {string} error @param {string} [status] */
  end(error, status = 'failed') {
    this.coordinator?.terminate();
    this.coordinator = null;
    this.paused = false;
    if (error) this.hooks.message(error);
    this.setStatus(status);
    this.update();
  }

  /** @param {string} text */
  setStatus(text) {
    this.out.status.textContent = text;
    document.body.dataset.evolve = text.split(' ')[0].replace('…', '');
  }

  /** Enables the buttons that apply now. */
  update() {
    const running = this.coordinator !== null;
    const b = this.buttons;
    for (const key of ['start', 'quick', 'paper']) b[key].disabled = running;
    for (const input of Object.values(this.inputs)) input.disabled = running;
    b.pause.disabled = !running;
    b.stop.disabled = !running;
    b.pause.textContent = this.paused ? 'Resume' : 'Pause';
    b.watch.disabled = this.runFile === null;
    b.export.disabled = this.runFile === null;
  }
}

/** @param {number | null} v @param {number} [digits] */
function fixed(v, digits = 2) {
  return v === null || !Number.isFinite(v) ? '–' : v.toFixed(digits);
}

/** Shows a figure, with its raw number in data-value for tests. @param {HTMLElement} el @param {number} value @param {string} text */
function show(el, value, text) {
  el.dataset.value = String(value);
  el.textContent = text;
}
