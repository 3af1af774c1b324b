// @ts-check
/**
 * The body-search coordinator (a module worker; the page starts one per search). It owns the
 * wasm `Codesign` (ask/tell, as `vsr codesign`) and a pool of evaluation workers (runs/pool.js).
 * Each iteration it asks for the jobs (new bodies and the archive's bodies measured again,
 * each job with its own shape), the pool evaluates them in any order on any worker, and the
 * fitness values are told in job order: the archive is the same for any number of workers, and
 * a dying worker is replaced and its job run again. After each iteration the page gets the
 * record and the gallery (every archive cell's best body); once the search ends, its archive
 * stays here to answer for any entry until the page ends this worker. Messages:
 * workers/codesign-protocol.js (ToCodesign, FromCodesign).
 */
import init, { Codesign, start as installPanicHook } from '../pkg/vsr.js';
import { loadWasm, messageOf, onReadyMessage, typeText, workerScope } from '../workers/kit.js';
import { EvaluatorPool, workerCount } from '../runs/pool.js';
import { FromCodesign, ToCodesign } from '../workers/codesign-protocol.js';

const ready = loadWasm(init, installPanicHook);
const scope = workerScope('codesign/coordinator.js');

/** @type {Codesign | null} */
let search = null;
/** @type {EvaluatorPool | null} */
let pool = null;
let started = 0;
/** The search ended: its archive stays to answer 'entry' until the page ends this worker. */
let over = false;

onReadyMessage(scope, ready, fail, (msg) => {
  switch (msg.type) {
    case ToCodesign.START: start(msg.settings, msg.workers, msg.module ?? null); break;
    case ToCodesign.STOP: finish(true); break;
    case ToCodesign.ENTRY: sendEntry(msg.cell, msg.ticket); break;
    case ToCodesign.CRASH_WORKER: pool?.crash(Number(msg.index) || 0); break;
    default: fail(`unknown message type ${typeText(msg)}`);
  }
});

/**
 * Starts the search; bad settings or a wrong module answer 'error' before any worker starts.
 * @param {import('../workers/codesign-protocol.js').CodesignSettings} settings @param {number} workers
 * @param {string | null} module the module's run file (frozen, finetune)
 */
function start(settings, workers, module) {
  if (search) { scope.postMessage({ type: FromCodesign.ERROR, message: 'this coordinator already ran a body search' }); return; }
  try {
    search = new Codesign(settings, module);
  } catch (error) {
    fail(messageOf(error));
    return;
  }
  const count = workerCount(workers);
  pool = new EvaluatorPool(count, {
    done: tellIteration, failed: fail, settled: () => {},
    recovered: (message) => scope.postMessage({ type: FromCodesign.RECOVERED, message }),
  });
  started = performance.now();
  scope.postMessage({ type: FromCodesign.STARTED, planned: search.budget, workers: count,
    layout: search.layout() });
  nextIteration();
}

/** Asks for the next iteration's jobs and hands them out, or ends the search. */
function nextIteration() {
  if (!search || over) return;
  const jobs = search.ask();
  if (jobs.length === 0) { finish(false); return; }
  const codesign = search;
  const genomes = jobs.map((/** @type {unknown} */ _, /** @type {number} */ i) => codesign.genome(i));
  pool?.run(jobs, (slot) => genomes[slot].slice());
}

/** Tells the search the iteration's fitness values (job order), reports it and goes on. @param {Float64Array} fitness */
function tellIteration(fitness) {
  if (!search || over) return;
  const seconds = wallSeconds();
  const record = search.tell(fitness, seconds);
  scope.postMessage({
    type: FromCodesign.ITERATION, record, evaluations: search.evaluations, planned: search.budget,
    gallery: search.gallery(), seconds,
  });
  nextIteration();
}

/**
 * Sends the archive's body in `cell` with its brain (null, with a message, when that cell is empty).
 * @param {[number, number]} cell @param {number} ticket
 */
function sendEntry(cell, ticket) {
  if (!search) return;
  try {
    const index = search.gallery().findIndex((/** @type {{cell: number[]}} */ e) => e.cell[0] === cell[0] && e.cell[1] === cell[1]);
    if (index < 0) throw new Error('no body in that cell yet');
    // with the search's file so far (entry `index` in it): what Fine-tune starts from
    const source = search.runFile(pool?.workers.length ?? 1, wallSeconds());
    scope.postMessage({ type: FromCodesign.ENTRY, cell, ticket, entry: { ...search.entry(index), index, source } });
  } catch (error) {
    scope.postMessage({ type: FromCodesign.ENTRY, cell, ticket, entry: null, message: messageOf(error) });
  }
}

/** @returns {number} wall seconds since the start */
function wallSeconds() {
  return (performance.now() - started) / 1000;
}

/**
 * Ends the search: stops the workers and reports the run file of the iterations told.
 * @param {boolean} stopped true when stopped before the budget was spent
 */
function finish(stopped) {
  if (!search || over) return;
  over = true;
  const runFile = search.evaluations > 0 ? search.runFile(pool?.workers.length ?? 1, wallSeconds()) : null;
  pool?.terminate();
  pool = null;
  scope.postMessage({ type: FromCodesign.DONE, stopped, runFile });
}

/** Reports an error and ends the search. @param {string} message */
function fail(message) {
  if (over) return;
  scope.postMessage({ type: FromCodesign.ERROR, message });
  finish(true);
}
