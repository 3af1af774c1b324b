// @ts-check
/**
 * An evaluation worker (a module worker started by coordinator.js). It owns its own wasm
 * module and evaluates one job at a time: the job's genome drives its shape on its terrain
 * for its seconds, with its own sensor-noise seed, and the fitness goes back with the job's
 * slot. Jobs carry everything they need, so which worker runs which job never changes a
 * result. Messages: workers/protocol.js (EvaluatorMessage).
 */
import init, { evaluateJob, start as installPanicHook } from '../pkg/vsr.js';
import { loadWasm, messageOf, onReadyMessage, typeText, workerScope } from '../workers/kit.js';
import { EvaluatorMessage } from '../workers/protocol.js';

const ready = loadWasm(init, installPanicHook);
const scope = workerScope('runs/evaluator.js');

onReadyMessage(scope, ready, reportError, (msg) => {
  if (msg.type === EvaluatorMessage.CRASH) {
    setTimeout(() => { throw new Error('evaluation worker crashed on request'); });
    return;
  }
  if (msg.type !== EvaluatorMessage.JOB) {
    reportError(`unknown message type ${typeText(msg)}`);
    return;
  }
  const { slot, job, genome } = msg;
  try {
    const fitness = evaluateJob(job, genome);
    scope.postMessage({ type: EvaluatorMessage.RESULT, slot, fitness });
  } catch (error) {
    reportError(`evaluation ${job.index} of generation ${job.generation} failed: ${messageOf(error)}`);
  }
});

/** @param {string} message */
function reportError(message) {
  scope.postMessage({ type: EvaluatorMessage.ERROR, message });
}

ready.then(() => scope.postMessage({ type: EvaluatorMessage.READY }), () => {});
