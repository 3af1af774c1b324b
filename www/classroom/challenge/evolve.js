// @ts-check
/**
 * A short code's robot evolved again on the teacher's page with the challenge's run
 * (code.js says why that gives the student's robot, to the bit), stoppable.
 */
import { runGenome } from '../../workers/core.js';
import { spawn } from '../../workers/kit.js';
import { FromCoordinator, MAX_EVALUATORS, ToCoordinator } from '../../workers/protocol.js';

/**
 * Evolves a robot again with a challenge's run, as the student's page did (the page's GA
 * coordinator, all this computer's cores: the same bits for any number of workers), and gives
 * its best genome. An abort stops it at once (its workers ended) and rejects with an AbortError.
 * @param {import('../../workers/protocol.js').EvolveSettings} settings @param {AbortSignal} [signal]
 * @returns {Promise<Float32Array>}
 */
export function evolveAgain(settings, signal) {
  const workers = Math.max(1, Math.min(MAX_EVALUATORS, navigator.hardwareConcurrency || 1));
  return new Promise((resolve, reject) => {
    if (signal?.aborted) { reject(new DOMException('stopped', 'AbortError')); return; }
    const worker = spawn('runs/coordinator.js', (msg) => {
      if (msg.type === FromCoordinator.ERROR) { done(); reject(new Error(msg.message)); }
      if (msg.type === FromCoordinator.DONE) {
        done();
        if (msg.runFile === null || msg.stopped) reject(new Error('the run did not finish'));
        else runGenome(msg.runFile).then(resolve, reject);
      }
    }, (text) => { done(); reject(new Error(`the run stopped: ${text}`)); });
    const stop = () => { worker.terminate(); reject(new DOMException('stopped', 'AbortError')); };
    const done = () => { worker.terminate(); signal?.removeEventListener('abort', stop); };
    signal?.addEventListener('abort', stop, { once: true });
    worker.postMessage({ type: ToCoordinator.START, settings, workers, source: null });
  });
}
