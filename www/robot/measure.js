// @ts-check
/**
 * Measures a brain at once, off the main thread: one evaluation worker (runs/evaluator.js, the
 * very evaluation every training run uses) walks a genome on a body for an episode of a given
 * length on a given terrain, with the viewer's sensor noise, and answers its speed: the
 * fitness, the number `vsr evaluate` prints for the same genome, terrain and seconds. A
 * newer request makes an older one's answer stale (it is dropped).
 */
import { spawn } from '../workers/kit.js';
import { EvaluatorMessage } from '../workers/protocol.js';

/** @typedef {{rows: string, controller: string, genome: Float32Array, terrain: string, seconds: number}} Measured */

export class Measurer {
  /** @param {string} noiseSeed the viewer's sensor noise seed (the core's, a decimal string) */
  constructor(noiseSeed) {
    this.noiseSeed = noiseSeed;
    /** @type {import('../workers/kit.js').WorkerOf<'runs/evaluator.js'> | null} */
    this.worker = null;
    this.asked = 0;
    /** @type {Map<number, {resolve: (v: number) => void, reject: (e: Error) => void}>} */
    this.waiting = new Map();
    this.start(); // its wasm module loads with the page's, not in the middle of a run
  }

  /**
   * The speed (m/s) of `what` over its episode; rejects with a readable Error, or with null
   * reason 'stale' when a newer measure was asked meanwhile.
   * @param {Measured} what @returns {Promise<number>}
   */
  measure(what) {
    const slot = ++this.asked;
    for (const [old, waiter] of this.waiting) { waiter.reject(new Error('stale')); this.waiting.delete(old); }
    const worker = this.worker ?? this.start();
    const job = { generation: 0, index: 0, shape: what.rows, controller: what.controller, terrain: what.terrain,
      noiseSeed: this.noiseSeed, seconds: what.seconds };
    return new Promise((resolve, reject) => {
      this.waiting.set(slot, { resolve, reject });
      worker.postMessage({ type: EvaluatorMessage.JOB, slot, job, genome: Float32Array.from(what.genome) });
    });
  }

  /** @returns {import('../workers/kit.js').WorkerOf<'runs/evaluator.js'>} */
  start() {
    this.worker = spawn('runs/evaluator.js', (msg) => {
      if (msg.type === EvaluatorMessage.READY) return;
      const slot = msg.type === EvaluatorMessage.RESULT ? msg.slot : this.asked; // an error says no slot: the latest
      const waiter = this.waiting.get(slot);
      if (msg.type === EvaluatorMessage.RESULT) waiter?.resolve(msg.fitness);
      else waiter?.reject(new Error(msg.message));
      this.waiting.delete(slot);
    }, (text) => {
      for (const waiter of this.waiting.values()) waiter.reject(new Error(`the measuring worker stopped: ${text}`));
      this.waiting.clear();
      this.worker = null;
    });
    return this.worker;
  }
}
