// @ts-check
/**
 * A pool of evaluation workers (evaluator.js), shared by the coordinators (coordinator.js for
 * an evolution, codesign/coordinator.js for a body search). A batch of jobs is handed out one
 * job at a time to whichever worker is idle; each fitness is stored at its job's index, so the
 * batch's result is the same for any number of workers. When a worker dies, a new one takes
 * its place and re-runs its job (same job, same result). While paused, no job is handed out;
 * the jobs under way finish. Messages: workers/protocol.js (EvaluatorMessage).
 */
import { spawn, typeText } from '../workers/kit.js';
import { EvaluatorMessage, MAX_EVALUATORS } from '../workers/protocol.js';

/** @typedef {import('../workers/kit.js').WorkerOf<'runs/evaluator.js'>} Evaluator */
/** @typedef {import('../workers/protocol.js').EvolveJob} EvolveJob */

/** Replacements of dead evaluation workers before the run gives up. */
const MAX_REPLACEMENTS = 8;

/**
 * @typedef {object} PoolHooks
 * @property {(fitness: Float64Array) => void} done  every job of the batch is back (fitness in job order)
 * @property {(message: string) => void} failed       an evaluation failed, or workers keep dying: the run must end
 * @property {(message: string) => void} recovered    a worker died; a new one re-runs its job
 * @property {() => void} settled                      paused, and the last job under way came back
 */

/** The number of workers a run may start from what the page asked. @param {unknown} workers */
export function workerCount(workers) {
  return Math.max(1, Math.min(MAX_EVALUATORS, Math.floor(Number(workers)) || 1));
}

export class EvaluatorPool {
  /** @param {number} count workers to start @param {PoolHooks} hooks */
  constructor(count, hooks) {
    this.hooks = hooks;
    /** @type {Evaluator[]} every evaluation worker */
    this.workers = Array.from({ length: count }, () => this.startEvaluator());
    /** @type {Evaluator[]} workers without a job */
    this.idle = [...this.workers];
    /** The job slot each busy worker holds. @type {Map<Evaluator, number>} */
    this.busy = new Map();
    /** Job slots handed back by dead workers, to hand out again first. @type {number[]} */
    this.orphans = [];
    this.replacements = 0;
    this.paused = false;
    /**
     * The batch under evaluation.
     * @type {{jobs: EvolveJob[], genome: (slot: number) => Float32Array, fitness: Float64Array, next: number, left: number} | null}
     */
    this.batch = null;
  }

  /** Evaluations under way. */
  get underWay() { return this.busy.size; }

  /**
   * Hands out a batch: job `slot` is evaluated with `genome(slot)`; `done` gets the fitness values.
   * @param {EvolveJob[]} jobs @param {(slot: number) => Float32Array} genome
   */
  run(jobs, genome) {
    this.batch = { jobs, genome, fitness: new Float64Array(jobs.length).fill(NaN), next: 0, left: jobs.length };
    this.orphans = [];
    this.dispatch();
  }

  /** @param {boolean} paused */
  setPaused(paused) {
    this.paused = paused;
    this.dispatch();
  }

  /** Makes worker `index` fail as if it crashed (tests, demonstrations). @param {number} index */
  crash(index) {
    this.workers[index]?.postMessage({ type: EvaluatorMessage.CRASH });
  }

  /** Ends every worker; the batch is dropped. */
  terminate() {
    for (const w of this.workers) w.terminate();
    this.workers = [];
    this.idle = [];
    this.busy.clear();
    this.batch = null;
  }

  /** @returns {Evaluator} an evaluation worker wired to this pool */
  startEvaluator() {
    const w = spawn('runs/evaluator.js', (msg) => this.onMessage(w, msg), (text) => this.replace(w, text));
    return w;
  }

  /** A worker died: a new one takes its place and its job goes out again. @param {Evaluator} dead @param {string} why */
  replace(dead, why) {
    const index = this.workers.indexOf(dead);
    if (index < 0) return;
    dead.terminate();
    if (++this.replacements > MAX_REPLACEMENTS) {
      this.hooks.failed(`evaluation workers keep failing (${why}); the run ended`);
      return;
    }
    const slot = this.busy.get(dead);
    this.busy.delete(dead);
    this.idle = this.idle.filter((w) => w !== dead);
    if (slot !== undefined) this.orphans.push(slot);
    const fresh = this.startEvaluator();
    this.workers[index] = fresh;
    this.idle.push(fresh);
    this.hooks.recovered(`evaluation worker ${index + 1} stopped (${why}); a new one re-runs its job`);
    this.dispatch();
    if (this.paused && slot !== undefined && this.busy.size === 0) this.hooks.settled();
  }

  /** @param {Evaluator} w @param {import('../workers/protocol.js').FromEvaluatorMessage} msg */
  onMessage(w, msg) {
    switch (msg.type) {
      case EvaluatorMessage.READY: break;
      case EvaluatorMessage.RESULT: this.onResult(w, Number(msg.slot), Number(msg.fitness)); break;
      case EvaluatorMessage.ERROR: this.hooks.failed(String(msg.message)); break;
      default: this.hooks.failed(`unknown message from an evaluation worker: ${typeText(msg)}`);
    }
  }

  /** Gives idle workers the next jobs (orphaned ones first) while not paused. */
  dispatch() {
    const batch = this.batch;
    if (!batch) return;
    while (!this.paused && this.idle.length > 0 && (this.orphans.length > 0 || batch.next < batch.jobs.length)) {
      const w = /** @type {Evaluator} */ (this.idle.pop());
      const slot = this.orphans.length > 0 ? /** @type {number} */ (this.orphans.shift()) : batch.next++;
      const genome = batch.genome(slot);
      this.busy.set(w, slot);
      w.postMessage({ type: EvaluatorMessage.JOB, slot, job: batch.jobs[slot], genome }, [genome.buffer]);
    }
  }

  /** @param {Evaluator} w @param {number} slot @param {number} fitness */
  onResult(w, slot, fitness) {
    const batch = this.batch;
    if (!batch || this.busy.get(w) !== slot) return;
    this.busy.delete(w);
    this.idle.push(w);
    batch.fitness[slot] = fitness;
    batch.left -= 1;
    const settled = this.paused && this.busy.size === 0; // the last evaluation under way when paused came back
    if (batch.left === 0) {
      this.batch = null;
      this.hooks.done(batch.fitness);
    } else {
      this.dispatch();
    }
    if (settled) this.hooks.settled();
  }
}
