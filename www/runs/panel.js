// @ts-check
/**
 * The run panel: evolves a controller for the drawn body (as `vsr evolve`) or fine-tunes a
 * transplanted attention module on it (as `vsr finetune`), in a GA coordinator worker with
 * a pool of evaluation workers (coordinator.js), with the settings of the form
 * (settings.js). It shows the run live (progress.js), pauses, steps one generation,
 * stops, exports the run file, and hands each new best to the page to watch. A fine-tuning
 * run can be followed by a from-scratch run with the same budget, drawn as a second line.
 */
import { byId } from '../shared/dom.js';
import { messageOf, spawn } from '../workers/kit.js';
import { download, downloadCsv, runFileName } from '../shared/export.js';
import { planWords } from './plan.js';
import { FromCoordinator, ToCoordinator } from '../workers/protocol.js';
import { RunProgress, TABLE_HEADER } from './progress.js';
import { voxelCount } from './estimate.js';
import { RunSettings } from './settings.js';

/**
 * @typedef {object} RunHooks
 * @property {() => {rows: string, ok: boolean, why?: string}} body   the drawing now (why: what keeps it from a run, if not its check)
 * @property {() => string} controller                   the family chosen for Evolve
 * @property {() => import('../workers/protocol.js').FinetuneSource | null} source  the run file of the module on the robot, if any
 * @property {() => string} sourceKind                  the family of the brain on the robot (a fine-tune keeps it)
 * @property {() => string} whyNoFinetune               why Fine-tune is off when there is none
 * @property {() => string} finetuneWords               what Fine-tune does to the brain on the robot
 * @property {(genome: Float32Array, fitness: number, settings: import('../workers/protocol.js').EvolveSettings, kind: string) => void} best
 *   a new best seen during a run (with "walk the best so far")
 * @property {(run: FinishedRun) => void} finished     a run ended with a run file
 * @property {(top: {fitness: number, genome: Float32Array}, generation: number,
 *   settings: import('../workers/protocol.js').EvolveSettings, kind: string, mode: string) => void} [generation]
 *   each generation's best evaluation (kept to race generations)
 * @property {(running: boolean) => void} running        a run started or ended
 * @property {(text: string, source?: string) => void} message  shows an error (about `source`: '' takes it away)
 * @property {(text: string) => void} note               shows a note
 */

/**
 * @typedef {object} FinishedRun
 * @property {string} runFile     its run file (JSON text)
 * @property {import('../workers/protocol.js').EvolveSettings} settings
 * @property {'evolve' | 'finetune' | 'scratch'} mode
 * @property {number} peak        the best single evaluation seen (m/s)
 * @property {boolean} stopped    ended by Stop
 * @property {boolean} follow     "walk the best so far" is on
 */

export class RunPanel {
  /** @param {Document} doc @param {import('../workers/core.js').Defaults} defaults @param {RunHooks} hooks */
  constructor(doc, defaults, hooks) {
    this.hooks = hooks;
    this.form = new RunSettings(doc, defaults, (text) => hooks.message(text, 'run-settings'), () => this.update());
    this.inputs = this.form.inputs;
    /** @type {Record<string, HTMLButtonElement>} */
    this.buttons = {
      evolve: byId(doc, 'run-evolve', HTMLButtonElement), finetune: byId(doc, 'run-finetune', HTMLButtonElement),
      pause: byId(doc, 'run-pause', HTMLButtonElement), step: byId(doc, 'run-step', HTMLButtonElement),
      stop: byId(doc, 'run-stop', HTMLButtonElement), export: byId(doc, 'run-export', HTMLButtonElement),
      csv: byId(doc, 'run-csv', HTMLButtonElement),
    };
    this.compare = byId(doc, 'run-compare', HTMLInputElement);
    this.follow = byId(doc, 'run-follow', HTMLInputElement);
    this.status = byId(doc, 'run-status');
    this.progress = new RunProgress(doc);
    /** Generations after generation 0 that the running run takes. */
    this.generations = NaN;
    /** @type {import('../workers/kit.js').WorkerOf<'runs/coordinator.js'> | null} */
    this.coordinator = null;
    /** A run's settings are being checked (by the core) before it starts. */
    this.starting = false;
    this.paused = false;
    /** The latest finished run's file and settings. */
    this.runFile = /** @type {string | null} */ (null);
    this.runSettings = /** @type {import('../workers/protocol.js').EvolveSettings | null} */ (null);
    /** What runs now: 'evolve', 'finetune' or 'scratch' (the comparison), and its series key. @type {'evolve' | 'finetune' | 'scratch'} */
    this.mode = 'evolve';
    this.bestSoFar = -Infinity;
    /** Workers of the running run. */
    this.workers = 1;
    /** The pace of the latest run here: simulated voxel-seconds per second per worker (NaN: no run yet; estimate.js). */
    this.pace = NaN;
    /** Whether the coordinator reported the run started (errors before that: 'not started'). */
    this.started = false;
    /** Start a from-scratch run when this fine-tuning run finishes. */
    this.compareNext = false;
    /** The family of the latest fine-tune (its source's): its from-scratch comparison evolves the same family. */
    this.finetuneKind = 'attention';
    /** A download asked for while running, waiting for the coordinator's run file. */
    this.exportWanted = false;
    this.wire();
    this.update();
  }

  wire() {
    const b = this.buttons;
    b.evolve.addEventListener('click', () => this.start('evolve'));
    b.finetune.addEventListener('click', () => this.start('finetune'));
    b.pause.addEventListener('click', () => this.send(this.paused ? ToCoordinator.RESUME : ToCoordinator.PAUSE));
    b.step.addEventListener('click', () => this.send(ToCoordinator.STEP));
    b.stop.addEventListener('click', () => { this.compareNext = false; this.send(ToCoordinator.STOP); });
    b.export.addEventListener('click', () => this.exportRunFile());
    b.csv.addEventListener('click', () => this.exportCsv());
  }

  /** Downloads the latest run's generations (and its comparison's) as a CSV table, so far if it is running. */
  exportCsv() {
    const first = this.progress.table[0];
    if (!first || !this.runSettings) return;
    const { controller, seed } = this.runSettings;
    const name = first[0] === 'evolve' ? `evolved-${controller}-seed${seed}` : `finetuned-${controller}-seed${seed}`;
    downloadCsv(`${name}-generations.csv`, TABLE_HEADER, this.progress.table);
  }

  /**
   * Whether the robot walking now has a brain from a run of this panel: if not, its figures
   * are said to be the last run's, not the walking robot's. @param {boolean} fromRun
   */
  showWalking(fromRun) {
    this.progress.otherBrain(!fromRun && this.started);
  }

  /**
   * Sends the coordinator a message that is only its type.
   * @param {typeof ToCoordinator.PAUSE | typeof ToCoordinator.RESUME | typeof ToCoordinator.STEP
   *   | typeof ToCoordinator.STOP | typeof ToCoordinator.RUN_FILE} type
   */
  send(type) { this.coordinator?.postMessage({ type }); }

  /** The settings in the form as the page stores and shares them. */
  values() { return this.form.values(); }

  /** @param {Partial<Record<string, string>>} values settings to put in the form */
  setValues(values) { this.form.setValues(values); }

  /**
   * The settings in the form, or a message saying what is wrong with them.
   * @param {string} controller
   * @returns {Promise<{settings: import('../workers/protocol.js').EvolveSettings, workers: number} | {error: string}>}
   */
  async readSettings(controller) {
    const body = this.hooks.body();
    if (!body.ok) return { error: body.why || 'draw a valid robot first (see the message under the grid)' };
    return this.form.read(body.rows, controller);
  }

  /**
   * Starts a run: 'evolve' (the chosen family from scratch), 'finetune' (the module on the
   * robot) or 'scratch' (attention from scratch, the comparison after a fine-tune).
   * @param {'evolve' | 'finetune' | 'scratch'} mode
   */
  async start(mode) {
    if (this.coordinator || this.starting) return;
    const source = mode === 'finetune' ? this.hooks.source() : null;
    if (mode === 'finetune' && !source) { this.refuse('load an attention module onto your robot first (Load onto my robot)', 'run-start'); return; }
    if (mode === 'finetune') this.finetuneKind = this.hooks.sourceKind(); // attention, or attention for any body (its whole genome the start)
    this.starting = true;
    this.update();
    let read;
    let plan;
    try {
      read = await this.readSettings(mode === 'evolve' ? this.hooks.controller() : this.finetuneKind);
      plan = 'error' in read ? null : await planWords(read.settings.population, read.settings.budget);
    } catch (error) {
      read = { error: `the settings could not be checked: ${messageOf(error)}` };
    } finally {
      this.starting = false;
    }
    if ('error' in read) { this.refuse(read.error); this.update(); return; }
    this.mode = mode;
    this.compareNext = mode === 'finetune' && this.compare.checked;
    this.bestSoFar = -Infinity;
    this.showWalking(true);
    this.generations = plan?.generations ?? NaN;
    const settings = read.settings;
    const coordinator = spawn('runs/coordinator.js', (msg) => this.onMessage(msg, settings),
      (text) => this.end(`the evolution stopped: ${text}`, 'failed'));
    coordinator.postMessage({ type: ToCoordinator.START, settings, workers: read.workers, source });
    this.coordinator = coordinator;
    this.workers = read.workers;
    this.paused = false;
    this.started = false;
    this.progress.reset();
    this.setStatus('starting…');
    this.hooks.running(true);
    this.update();
  }

  /** @param {import('../workers/protocol.js').FromCoordinatorMessage} msg @param {import('../workers/protocol.js').EvolveSettings} settings */
  onMessage(msg, settings) {
    switch (msg.type) {
      case FromCoordinator.STARTED:
        this.started = true;
        this.progress.started(msg.planned, this.mode);
        this.runSettings = settings;
        this.setStatus(`${this.verb()} on ${msg.workers} worker${msg.workers === 1 ? '' : 's'}`);
        break;
      case FromCoordinator.GENERATION: this.onGeneration(msg, settings); break;
      case FromCoordinator.STATE:
        this.paused = msg.paused;
        this.setStatus(msg.paused ? (msg.underWay > 0 ? 'pausing (the evaluations under way finish)' : 'paused')
          : msg.stepping ? 'stepping' : this.verb());
        this.update();
        break;
      case FromCoordinator.RUN_FILE:
        if (this.exportWanted && msg.runFile) download(msg.runFile, runFileName(msg.runFile));
        this.exportWanted = false;
        break;
      case FromCoordinator.RECOVERED: this.hooks.message(msg.message); break;
      case FromCoordinator.DONE: this.onDone(msg, settings); break;
      case FromCoordinator.ERROR: this.end(msg.message, this.started ? 'failed' : 'not started'); break;
      default: console.warn('unknown message from the coordinator', msg);
    }
  }

  verb() {
    return { evolve: 'evolving', finetune: 'fine-tuning', scratch: 'from scratch: evolving' }[this.mode] ?? 'running';
  }

  /** A run that cannot start: the message, and the status says so. @param {string} why @param {string} [source] */
  refuse(why, source = 'run-settings') {
    this.hooks.message(why, source);
    this.setStatus('not started');
  }

  /**
   * @param {Extract<import('../workers/protocol.js').FromCoordinatorMessage, {type: 'generation'}>} msg
   * @param {import('../workers/protocol.js').EvolveSettings} settings
   */
  onGeneration(msg, settings) {
    const { record } = msg;
    if (record.best !== null && record.best > this.bestSoFar) this.bestSoFar = record.best;
    this.progress.generation(msg, this.generations, this.bestSoFar, this.mode);
    this.buttons.csv.disabled = false;
    const pace = (msg.evalsPerSecond * settings.seconds * voxelCount(settings.shape)) / this.workers;
    if (pace > 0 && Number.isFinite(pace)) this.pace = pace;
    this.hooks.generation?.(msg.top, record.generation, settings, this.kind(settings), this.mode);
    if (msg.best && this.follow.checked && this.mode !== 'scratch') {
      this.hooks.best(msg.best.genome, msg.best.fitness, settings, this.kind(settings));
    }
  }

  /** @param {import('../workers/protocol.js').EvolveSettings} settings */
  kind(settings) {
    return settings.controller; // a fine-tune's is its source's family, and so is its comparison's
  }

  /** @param {{stopped: boolean, runFile: string | null}} msg @param {import('../workers/protocol.js').EvolveSettings} settings */
  onDone(msg, settings) {
    const compare = this.compareNext && !msg.stopped;
    if (msg.runFile) {
      if (this.mode !== 'scratch') { this.runFile = msg.runFile; this.runSettings = settings; }
      this.hooks.finished({ runFile: msg.runFile, settings, mode: this.mode, peak: this.bestSoFar,
        stopped: msg.stopped, follow: this.follow.checked });
    }
    this.progress.ended();
    const how = msg.stopped ? 'stopped' : 'finished';
    this.end('', this.mode === 'scratch' ? `from scratch: ${how}` : how);
    if (compare) this.start('scratch');
  }

  /** Downloads the run file: the running one's so far, or the last finished one. */
  exportRunFile() {
    if (this.coordinator && this.mode !== 'scratch') {
      this.exportWanted = true;
      this.send(ToCoordinator.RUN_FILE);
      return;
    }
    if (this.runFile) download(this.runFile, runFileName(this.runFile));
  }

  /** The run ended: an error message (or ''), and the status to show. @param {string} error @param {string} status */
  end(error, status) {
    this.coordinator?.terminate();
    this.coordinator = null;
    this.paused = false;
    if (error) this.hooks.message(error);
    this.setStatus(status);
    this.hooks.running(false);
    this.update();
  }

  /** @param {string} text */
  setStatus(text) {
    this.status.textContent = text;
    document.body.dataset.run = text.replace(/^from scratch: /, '').split(' ')[0].replace('…', '');
  }

  /** Enables the buttons that apply now. */
  update() {
    const running = this.coordinator !== null;
    const b = this.buttons;
    const body = this.hooks.body();
    const off = running || this.starting || !body.ok || this.form.invalid;
    b.evolve.disabled = off;
    b.evolve.title = !running && body.why ? `Evolve is off: ${body.why}` : '';
    b.finetune.disabled = off || this.hooks.source() === null;
    b.finetune.title = b.finetune.disabled && !running && this.hooks.source() === null ? this.hooks.whyNoFinetune() : this.hooks.finetuneWords();
    this.form.lock(running);
    b.pause.disabled = !running;
    b.step.disabled = !running || !this.paused;
    b.stop.disabled = !running;
    b.pause.textContent = this.paused ? 'Resume' : 'Pause';
    b.export.disabled = !running && this.runFile === null;
    b.csv.disabled = this.progress.table.length === 0;
  }
}
