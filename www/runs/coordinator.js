// @ts-check
/**
 * The GA coordinator (a module worker; the page starts one per run). It owns the wasm
 * `Evolution` (ask/tell: from scratch as `vsr evolve`, or fine-tuning as `vsr finetune`) and
 * a pool of evaluation workers (pool.js). Each generation it asks for the jobs, the pool hands
 * them out one at a time to whichever worker is idle and stores each fitness at its job's
 * index, and the GA is told once all are back: the result is the same for any number of
 * workers, and when a worker dies, a new one re-runs its job with the same result. Pausing
 * stops handing out jobs (the run holds once the jobs under way are back, which may finish a
 * generation); a step runs one generation; stopping drops the unfinished generation. Messages: workers/protocol.js (ToCoordinator, FromCoordinator, EvaluatorMessage).
 */
import init, { Evolution, start as installPanicHook } from '../pkg/vsr.js';
import { loadWasm, messageOf, onReadyMessage, typeText, workerScope } from '../workers/kit.js';
import { EvaluatorPool, workerCount } from './pool.js';
import { FromCoordinator, ToCoordinator } from '../workers/protocol.js';

const ready = loadWasm(init, installPanicHook);
const scope = workerScope('runs/coordinator.js');

/** @type {Evolution | null} */
let evolution = null;
/** @type {EvaluatorPool | null} */
let pool = null;
/** The generation under evaluation: its jobs and genomes. @type {{jobs: import('../workers/protocol.js').EvolveJob[], genomes: Float32Array} | null} */
let batch = null;
let paused = false;
/** Pause again after the generation under way (a step). */
let stepping = false;
/** Wall time of the run so far, pauses excluded: ms accumulated, and when the clock last ran. */
let clock = { ms: 0, since: 0 };
let bestSoFar = -Infinity;

onReadyMessage(scope, ready, fail, (msg) => {
  switch (msg.type) {
    case ToCoordinator.START: start(msg.settings, msg.workers, msg.source ?? null); break;
    case ToCoordinator.PAUSE: setPaused(true); break;
    case ToCoordinator.RESUME: setPaused(false); break;
    case ToCoordinator.STEP: step(); break;
    case ToCoordinator.STOP: finish(true); break;
    case ToCoordinator.RUN_FILE: scope.postMessage({ type: FromCoordinator.RUN_FILE, runFile: currentRunFile() }); break;
    case ToCoordinator.CRASH_WORKER: pool?.crash(Number(msg.index) || 0); break;
    default: fail(`unknown message type ${typeText(msg)}`);
  }
});

/**
 * Starts the run; bad settings answer 'error' before any worker starts.
 * @param {import('../workers/protocol.js').EvolveSettings} settings
 * @param {number} workers
 * @param {import('../workers/protocol.js').FinetuneSource | null} source the run file to fine-tune from (and its body, for a body search's file), or null
 */
function start(settings, workers, source) {
  if (evolution) { fail('this coordinator already runs an evolution'); return; }
  try {
    evolution = source === null ? new Evolution(settings) : Evolution.finetune(source.text, settings, source.entry ?? undefined);
  } catch (error) {
    fail(messageOf(error));
    return;
  }
  const count = workerCount(workers);
  pool = new EvaluatorPool(count, {
    done: tellGeneration, failed: fail, settled: postState,
    recovered: (message) => scope.postMessage({ type: FromCoordinator.RECOVERED, message }),
  });
  clock = { ms: 0, since: performance.now() };
  scope.postMessage({ type: FromCoordinator.STARTED, planned: evolution.plannedEvaluations, workers: count });
  nextGeneration();
}

/** Asks for the next generation and hands out its jobs, or ends the run. */
function nextGeneration() {
  if (!evolution) return;
  const jobs = evolution.ask();
  if (jobs.length === 0) { finish(false); return; }
  const genomes = evolution.genomes();
  const len = evolution.genomeLength;
  batch = { jobs, genomes };
  pool?.run(jobs, (slot) => genomes.slice(slot * len, (slot + 1) * len));
}

/** Tells the GA the finished generation, reports it, and goes on (or pauses after a step). @param {Float64Array} fitness */
function tellGeneration(fitness) {
  if (!evolution || !batch) return;
  const seconds = wallSeconds();
  const record = evolution.tell(fitness, seconds);
  const generation = { ...batch, fitness };
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
  scope.postMessage({
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
  pool?.setPaused(pause);
}

/** Tells the page the pause state and the evaluations still under way (a pause holds once they are back). */
function postState() {
  scope.postMessage({ type: FromCoordinator.STATE, paused, stepping, underWay: pool?.underWay ?? 0 });
}

/** @returns {number} wall seconds of the run, pauses excluded */
function wallSeconds() {
  return (clock.ms + (paused ? 0 : performance.now() - clock.since)) / 1000;
}

/** @returns {string | null} the run so far as a run file, or null before generation 0 */
function currentRunFile() {
  return evolution && evolution.evaluations > 0 ? evolution.runFile(pool?.workers.length ?? 1, wallSeconds()) : null;
}

/**
 * Ends the run: stops the workers and reports the run file of the generations told.
 * @param {boolean} stopped true when stopped before the budget was spent
 */
function finish(stopped) {
  if (!evolution) return;
  const runFile = currentRunFile();
  pool?.terminate();
  pool = null;
  batch = null;
  evolution.free();
  evolution = null;
  scope.postMessage({ type: FromCoordinator.DONE, stopped, runFile });
}

/** Reports an error and ends the run. @param {string} message */
function fail(message) {
  scope.postMessage({ type: FromCoordinator.ERROR, message });
  finish(true);
}
