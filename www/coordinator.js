// @ts-check
/**
 * The GA coordinator (a module worker; the page starts one per run). It owns the wasm
 * `Evolution` (ask/tell: from scratch as `vsr evolve`, or fine-tuning as `vsr finetune`) and
 * a pool of evaluation workers (evaluator.js). Each generation it asks for the jobs, hands
 * them out one at a time to whichever worker is idle, stores each fitness at its job's
 * index, and tells the GA once all are back: the result is the same for any number of
 * workers, and when a worker dies, a new one re-runs its job with the same result. Pausing
 * stops handing out jobs (the run holds once the jobs under way are back, which may finish a
 * generation); a step runs one generation; stopping drops the unfinished generation. Messages: protocol.js (ToCoordinator, FromCoordinator, EvaluatorMessage).
 */
import init, { Evolution, start as installPanicHook } from './pkg/vsr.js';
import { loadWasm, messageOf, spawn } from './kit.js';
import { EvaluatorMessage, FromCoordinator, MAX_EVALUATORS, ToCoordinator } from './protocol.js';

const ready = loadWasm(init, installPanicHook);
/** Replacements of dead evaluation workers before the run gives up. */
const MAX_REPLACEMENTS = 8;

/** @type {Evolution | null} */
let evolution = null;
/** @type {Worker[]} every evaluation worker */
let pool = [];
/** @type {Worker[]} workers without a job */
let idle = [];
/** The job slot each busy worker holds. @type {Map<Worker, number>} */
const busy = new Map();
/** Job slots handed back by dead workers, to hand out again first. @type {number[]} */
let orphans = [];
let replacements = 0;
/**
 * The generation under evaluation.
 * @type {{jobs: import('./protocol.js').EvolveJob[], genomes: Float32Array,
 *   fitness: Float64Array, next: number, left: number} | null}
 */
let batch = null;
let paused = false;
/** Pause again after the generation under way (a step). */
let stepping = false;
/** Wall time of the run so far, pauses excluded: ms accumulated, and when the clock last ran. */
let clock = { ms: 0, since: 0 };
let bestSoFar = -Infinity;

/** @param {MessageEvent} event */
self.onmessage = async (event) => {
  try {
    await ready;
  } catch (error) {
    fail(messageOf(error));
    return;
  }
  const msg = event.data;
  switch (msg.type) {
    case ToCoordinator.START: start(msg.settings, msg.workers, msg.source ?? null); break;
    case ToCoordinator.PAUSE: setPaused(true); break;
    case ToCoordinator.RESUME: setPaused(false); break;
    case ToCoordinator.STEP: step(); break;
    case ToCoordinator.STOP: finish(true); break;
    case ToCoordinator.RUN_FILE: self.postMessage({ type: FromCoordinator.RUN_FILE, runFile: currentRunFile() }); break;
    case ToCoordinator.CRASH_WORKER: pool[Number(msg.index) || 0]?.postMessage({ type: EvaluatorMessage.CRASH }); break;
    default: fail(`unknown message type ${JSON.stringify(msg.type)}`);
  }
};

/**
 * Starts the run; bad settings answer 'error' before any worker starts.
 * @param {import('./protocol.js').EvolveSettings} settings
 * @param {number} workers
 * @param {string | null} source the run file to fine-tune from, or null
 */
function start(settings, workers, source) {
  if (evolution) { fail('this coordinator already runs an evolution'); return; }
  try {
    evolution = source === null ? new Evolution(settings) : Evolution.finetune(source, settings);
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
  const w = spawn('evaluator.js', (msg) => onEvaluatorMessage(w, msg), (text) => replace(w, text));
  return w;
}

/**
 * A worker died: a new one takes its place and its job goes out again.
 * @param {Worker} dead @param {string} why
 */
function replace(dead, why) {
  const index = pool.indexOf(dead);
  if (!evolution || index < 0) return;
  dead.terminate();
  if (++replacements > MAX_REPLACEMENTS) {
    fail(`evaluation workers keep failing (${why}); the run ended`);
    return;
  }
  const slot = busy.get(dead);
  busy.delete(dead);
  idle = idle.filter((w) => w !== dead);
  if (slot !== undefined) orphans.push(slot);
  const fresh = startEvaluator();
  pool[index] = fresh;
  idle.push(fresh);
  self.postMessage({ type: FromCoordinator.RECOVERED,
    message: `evaluation worker ${index + 1} stopped (${why}); a new one re-runs its job` });
  dispatch();
  if (paused && slot !== undefined && busy.size === 0) postState();
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
  const jobs = evolution.ask();
  if (jobs.length === 0) { finish(false); return; }
  const genomes = evolution.genomes();
  batch = { jobs, genomes, fitness: new Float64Array(jobs.length).fill(NaN), next: 0, left: jobs.length };
  orphans = [];
  dispatch();
}

/** Gives idle workers the next jobs (orphaned ones first) while not paused. */
function dispatch() {
  if (!evolution || !batch) return;
  const len = evolution.genomeLength;
  while (!paused && idle.length > 0 && (orphans.length > 0 || batch.next < batch.jobs.length)) {
    const w = /** @type {Worker} */ (idle.pop());
    const slot = orphans.length > 0 ? /** @type {number} */ (orphans.shift()) : batch.next++;
    const genome = batch.genomes.slice(slot * len, (slot + 1) * len);
    busy.set(w, slot);
    w.postMessage({ type: EvaluatorMessage.JOB, slot, job: batch.jobs[slot], genome }, [genome.buffer]);
  }
}

/** @param {Worker} w @param {number} slot @param {number} fitness */
function onResult(w, slot, fitness) {
  if (!batch || busy.get(w) !== slot) return;
  busy.delete(w);
  idle.push(w);
  batch.fitness[slot] = fitness;
  batch.left -= 1;
  const settled = paused && busy.size === 0; // the last evaluation under way when paused came back
  if (batch.left === 0) tellGeneration(); else dispatch();
  if (settled) postState();
}

/** Tells the GA the finished generation, reports it, and goes on (or pauses after a step). */
function tellGeneration() {
  if (!evolution || !batch) return;
  const seconds = wallSeconds();
  const record = evolution.tell(batch.fitness, seconds);
  const generation = batch;
  batch = null;
  let best = null;
  const i = bestIndex(generation.fitness);
  const len = evolution.genomeLength;
  const top = { fitness: generation.fitness[i], genome: generation.genomes.slice(i * len, (i + 1) * len) };
  if (record.best !== null && record.best !== undefined && record.best > bestSoFar) {
    bestSoFar = record.best;
    best = { fitness: record.best, genome: top.genome.slice() };
  }
  const evaluations = evolution.evaluations;
  self.postMessage({
    type: FromCoordinator.GENERATION, record, evaluations, planned: evolution.plannedEvaluations,
    evalsPerSecond: seconds > 0 ? evaluations / seconds : NaN, best, top,
  });
  if (stepping) { stepping = false; setPaused(true); }
  nextGeneration();
}

/** Index of the largest finite fitness. @param {Float64Array} fitness */
function bestIndex(fitness) {
  let best = 0;
  fitness.forEach((f, i) => { if (Number.isFinite(f) && !(fitness[best] >= f)) best = i; });
  return best;
}

/** While paused: run one generation, then pause again. */
function step() {
  if (!evolution || !paused) return;
  stepping = true;
  setPaused(false);
}

/** @param {boolean} pause */
function setPaused(pause) {
  if (!evolution || pause === paused) return;
  const now = performance.now();
  if (pause) clock.ms += now - clock.since; else clock.since = now;
  paused = pause;
  postState();
  dispatch();
}

/** Tells the page the pause state and the evaluations still under way (a pause holds once they are back). */
function postState() {
  self.postMessage({ type: FromCoordinator.STATE, paused, stepping, underWay: busy.size });
}

/** @returns {number} wall seconds of the run, pauses excluded */
function wallSeconds() {
  return (clock.ms + (paused ? 0 : performance.now() - clock.since)) / 1000;
}

/** @returns {string | null} the run so far as a run file, or null before generation 0 */
function currentRunFile() {
  return evolution && evolution.evaluations > 0 ? evolution.runFile(pool.length, wallSeconds()) : null;
}

/**
 * Ends the run: stops the workers and reports the run file of the generations told.
 * @param {boolean} stopped true when stopped before the budget was spent
 */
function finish(stopped) {
  if (!evolution) return;
  const runFile = currentRunFile();
  for (const w of pool) w.terminate();
  pool = [];
  idle = [];
  busy.clear();
  batch = null;
  evolution.free();
  evolution = null;
  self.postMessage({ type: FromCoordinator.DONE, stopped, runFile });
}

/** Reports an error and ends the run. @param {string} message */
function fail(message) {
  self.postMessage({ type: FromCoordinator.ERROR, message });
  finish(true);
}
