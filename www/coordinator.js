// @ts-check
/**
 * The GA coordinator (a module worker; the page starts one per run). It owns the wasm
 * `Evolution` (ask/tell) and a pool of evaluation workers (evaluator.js). Each generation it
 * asks for the jobs, hands them out one at a time to whichever worker is idle, stores each
 * fitness at its job's index, and tells the GA once all are back: the result is the same
 * for any number of workers. Pausing stops handing out jobs; stopping drops the unfinished
 * generation. Messages: protocol.js (ToCoordinator, FromCoordinator, EvaluatorMessage).
 */
import init, { Evolution, start as installPanicHook } from './pkg/vsr.js';
import { EvaluatorMessage, FromCoordinator, MAX_EVALUATORS, ToCoordinator } from './protocol.js';

const ready = init().then(() => installPanicHook());

/** @type {Evolution | null} */
let evolution = null;
/** @type {Worker[]} every evaluation worker */
let pool = [];
/** @type {Worker[]} workers without a job */
let idle = [];
/**
 * The generation under evaluation.
 * @type {{jobs: import('./protocol.js').EvolveJob[], genomes: Float32Array,
 *   fitness: Float64Array, next: number, left: number} | null}
 */
let batch = null;
let paused = false;
/** Wall time of the run so far, pauses excluded: ms accumulated, and when the clock last ran. */
let clock = { ms: 0, since: 0 };
let bestSoFar = -Infinity;

/** @param {MessageEvent} event */
self.onmessage = async (event) => {
  try {
    await ready;
  } catch (error) {
    fail(`could not load the simulator (wasm): ${messageOf(error)}`);
    return;
  }
  const msg = event.data;
  switch (msg.type) {
    case ToCoordinator.START: start(msg.settings, msg.workers); break;
    case ToCoordinator.PAUSE: setPaused(true); break;
    case ToCoordinator.RESUME: setPaused(false); break;
    case ToCoordinator.STOP: finish(true); break;
    default: fail(`unknown message type ${JSON.stringify(msg.type)}`);
  }
};

/**
 * Starts the run; bad settings answer 'error' before any worker starts.
 * @param {import('./protocol.js').EvolveSettings} settings
 * @param {number} workers
 */
function start(settings, workers) {
  if (evolution) { fail('this coordinator already runs an evolution'); return; }
  try {
    evolution = new Evolution(JSON.stringify(settings));
  } catch (error) {
    fail(messageOf(error));
    return;
  }
  const count = Math.max(1, Math.min(MAX_EVALUATORS, Math.floor(Number(workers)) || 1));
  pool = Array.from({ length: count }, startEvaluator);
  idle = [...pool];
  clock = { ms: 0, since: performance.now() };
  self.postMessage({ type: FromCoordinator.STARTED, planned: evolution.plannedEvaluations, workers: count });
  nextGeneration();
}

/** @returns {Worker} an evaluation worker wired to this coordinator */
function startEvaluator() {
  const w = new Worker(new URL('./evaluator.js', import.meta.url), { type: 'module' });
  w.onmessage = (event) => onEvaluatorMessage(w, event.data);
  w.onerror = (event) => fail(`an evaluation worker failed: ${event.message || 'see the console'}`);
  return w;
}

/** @param {Worker} w @param {{type: string, slot?: number, fitness?: number, message?: string}} msg */
function onEvaluatorMessage(w, msg) {
  switch (msg.type) {
    case EvaluatorMessage.READY: break;
    case EvaluatorMessage.RESULT: onResult(w, Number(msg.slot), Number(msg.fitness)); break;
    case EvaluatorMessage.ERROR: fail(String(msg.message)); break;
    default: fail(`unknown message from an evaluation worker: ${JSON.stringify(msg.type)}`);
  }
}

/** Asks for the next generation and hands out its jobs, or ends the run. */
function nextGeneration() {
  if (!evolution) return;
  const jobs = JSON.parse(evolution.ask());
  if (jobs.length === 0) { finish(false); return; }
  const genomes = evolution.genomes();
  batch = { jobs, genomes, fitness: new Float64Array(jobs.length).fill(NaN), next: 0, left: jobs.length };
  dispatch();
}

/** Gives idle workers the next jobs while not paused. */
function dispatch() {
  if (!evolution || !batch) return;
  const len = evolution.genomeLength;
  while (!paused && batch.next < batch.jobs.length && idle.length > 0) {
    const w = /** @type {Worker} */ (idle.pop());
    const slot = batch.next++;
    const genome = batch.genomes.slice(slot * len, (slot + 1) * len);
    w.postMessage({ type: EvaluatorMessage.JOB, slot, job: batch.jobs[slot], genome }, [genome.buffer]);
  }
}

/** @param {Worker} w @param {number} slot @param {number} fitness */
function onResult(w, slot, fitness) {
  if (!batch) return;
  idle.push(w);
  batch.fitness[slot] = fitness;
  batch.left -= 1;
  if (batch.left === 0) tellGeneration(); else dispatch();
}

/** Tells the GA the finished generation, reports it, and goes on. */
function tellGeneration() {
  if (!evolution || !batch) return;
  const seconds = wallSeconds();
  const record = JSON.parse(evolution.tell(batch.fitness, seconds));
  batch = null;
  const improved = record.best !== null && record.best > bestSoFar;
  if (improved) bestSoFar = record.best;
  const evaluations = evolution.evaluations;
  self.postMessage({
    type: FromCoordinator.GENERATION, record, evaluations, planned: evolution.plannedEvaluations,
    evalsPerSecond: seconds > 0 ? evaluations / seconds : NaN, improved,
    runFile: evolution.runFile(pool.length, seconds),
  });
  nextGeneration();
}

/** @param {boolean} pause */
function setPaused(pause) {
  if (!evolution || pause === paused) return;
  const now = performance.now();
  if (pause) clock.ms += now - clock.since; else clock.since = now;
  paused = pause;
  self.postMessage({ type: FromCoordinator.STATE, paused });
  dispatch();
}

/** @returns {number} wall seconds of the run, pauses excluded */
function wallSeconds() {
  return (clock.ms + (paused ? 0 : performance.now() - clock.since)) / 1000;
}

/**
 * Ends the run: stops the workers and reports the run file of the generations told.
 * @param {boolean} stopped true when stopped before the budget was spent
 */
function finish(stopped) {
  if (!evolution) return;
  const workers = pool.length;
  for (const w of pool) w.terminate();
  pool = [];
  idle = [];
  batch = null;
  const runFile = evolution.evaluations > 0 ? evolution.runFile(workers, wallSeconds()) : null;
  evolution.free();
  evolution = null;
  self.postMessage({ type: FromCoordinator.DONE, stopped, runFile });
}

/** Reports an error and ends the run. @param {string} message */
function fail(message) {
  self.postMessage({ type: FromCoordinator.ERROR, message });
  finish(true);
}

/** @param {unknown} error */
function messageOf(error) {
  return error instanceof Error ? error.message : String(error);
}
