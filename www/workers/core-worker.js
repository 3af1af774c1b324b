// @ts-check
/**
 * The core worker (a module worker; core.js starts one for the page): it owns the page's wasm
 * module for the core's answers that do not simulate (the defaults, the check of a drawing, a
 * run file's description, transplant, remap, the checks of terrains and genomes) and answers
 * core.js's requests (kit.js: requester / answerRequests), so that the page's main thread never
 * loads wasm. Simulating and evolving run in their own workers (simulation-worker.js, runs/coordinator.js).
 */
import init, * as wasm from '../pkg/vsr.js';
import { answerRequests, loadWasm } from './kit.js';

answerRequests(loadWasm(init, wasm.start), {
  defaults: wasm.defaults,
  runPlan: wasm.runPlan,
  checkShape: wasm.checkShape,
  describeRun: wasm.describeRun,
  runGenome: wasm.runGenome,
  transplant: wasm.transplant,
  remapGenome: wasm.remapGenome,
  checkGenome: wasm.checkGenome,
  freshSeed: wasm.freshSeed,
  checkTerrain: wasm.checkTerrain,
  checkGait: wasm.checkGait,
  checkTrainingTerrain: wasm.checkTrainingTerrain,
});
