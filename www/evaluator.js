// @ts-check
/**
 * An evaluation worker (a module worker started by coordinator.js). It owns its own wasm
 * module and evaluates one job at a time: the job's genome drives its shape on its terrain
 * for its seconds, with its own sensor-noise seed, and the fitness goes back with the job's
 * slot. Jobs carry everything they need, so which worker runs which job never changes a
 * result. Messages: protocol.js (EvaluatorMessage).
 */
import init, { evaluateJob, start as installPanicHook } from './pkg/vsr.js';
import { loadWasm, messageOf, onReadyMessage } from './kit.js';
import { EvaluatorMessage } from './protocol.js';

const ready = loadWasm(init, installPanicHook);

onReadyMessage(ready, reportError, (/** @type {{type: string, slot: number, job: import('./protocol.js').EvolveJob, genome: Float32Array}} */ msg) => {
  const { type, slot, job, genome } = msg;
  if (type === EvaluatorMessage.CRASH) {
    setTimeout(() => { throw new Error('evaluation worker crashed on request'); });
    return;
  }
  if (type !== EvaluatorMessage.JOB) {
    reportError(`unknown message type ${JSON.stringify(type)}`);
    return;
  }
  try {
    const fitness = evaluateJob(job, genome);
    self.postMessage({ type: EvaluatorMessage.RESULT, slot, fitness });
  } catch (error) {
    reportError(`evaluation ${job.index} of generation ${job.generation} failed: ${messageOf(error)}`);
  }
});

/** @param {string} message */
function reportError(message) {
  self.postMessage({ type: EvaluatorMessage.ERROR, message });
}

ready.then(() => self.postMessage({ type: EvaluatorMessage.READY }), () => {});
