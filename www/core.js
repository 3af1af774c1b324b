// @ts-check
/**
 * The core's answers on the main thread: the defaults, the check of a drawing, a module's
 * description and the genome operations (transplant, remap). None of these simulates; the
 * simulation stays in the workers. `ready` resolves once the wasm module is loaded.
 */
import init, * as wasm from './pkg/vsr.js';
import { loadWasm } from './kit.js';

/** Resolves with the core's defaults once the module is loaded. */
export const ready = loadWasm(init, wasm.start).then(() => /** @type {Defaults} */ (wasm.defaults()));

/**
 * @typedef {object} Defaults
 * @property {{width: number, height: number}} grid   the editor's grid (cells)
 * @property {{name: string, rows: string}[]} presets
 * @property {string[]} controllers                     families the page evolves
 * @property {RunPreset} quick
 * @property {RunPreset} paper
 * @property {string} trainingTerrain
 * @property {string} viewTerrain
 * @property {{frequency: number, phase: number}} gait
 * @property {number} maxSeed
 * @property {number} attentionGenes
 * @property {string} viewNoiseSeed   the viewer's sensor noise seed (decimal)
 */
/** @typedef {{population: number, seconds: number, budget: number}} RunPreset */
/**
 * @typedef {object} ShapeCheck
 * @property {boolean} ok
 * @property {string} message          why not, in words ('' when ok)
 * @property {number} voxels
 * @property {[number, number][][]} pieces   cells (x, y from the bottom-left) per piece
 * @property {[string, number][]} params      genes per controller family
 */

/**
 * What a run of `population` and `budget` evaluations takes (the core's rule).
 * @param {number} population @param {number} budget
 * @returns {{planned: number, generations: number, perGeneration: number}} throws on a bad number
 */
export function runPlan(population, budget) { return wasm.runPlan(population, budget); }

/** @param {string} rows @returns {ShapeCheck} */
export function checkShape(rows) { return wasm.checkShape(rows); }

/**
 * @param {string} runFile a run file's JSON text
 * @returns {{shape: string, controller: string, seed: number, budget: number, evaluations: number, fitness: number,
 *   genes: number, finetunedFrom: string | null, seconds: number, terrain: string}} throws a
 *   readable Error when malformed
 */
export function describeRun(runFile) { return wasm.describeRun(runFile); }

/** @param {string} runFile @returns {Float32Array} its best genome */
export function runGenome(runFile) { return wasm.runGenome(runFile); }

/** The transplant of a module onto `rows` (attention: its attention block kept). @param {string} runFile @param {string} rows @param {number} seed */
export function transplant(runFile, rows, seed) { return wasm.transplant(runFile, rows, seed); }

/**
 * A genome following its body's edit: cell (x, y) of `to` is cell (x + shiftX, y + shiftY)
 * of `from`. @param {string} controller @param {Float32Array} genome @param {string} from
 * @param {string} to @param {number} shiftX @param {number} shiftY @param {number} seed
 * @param {number} edit @returns {Float32Array}
 */
export function remapGenome(controller, genome, from, to, shiftX, shiftY, seed, edit) {
  return wasm.remapGenome(controller, genome, from, to, shiftX, shiftY, seed, edit);
}

/** Throws a readable Error unless `genome` fits. @param {string} controller @param {string} rows @param {Float32Array} genome */
export function checkGenome(controller, rows, genome) { wasm.checkGenome(controller, rows, genome); }

/** @returns {number} a fresh seed from the operating system's randomness (getrandom) */
export function freshSeed() { return wasm.freshSeed(); }

/** '' or why `name` is not a terrain. @param {string} name @returns {string} */
export function checkTerrain(name) { return wasm.checkTerrain(name); }

/** '' or why `name` is not a training terrain (family or name). @param {string} name @returns {string} */
export function checkTrainingTerrain(name) { return wasm.checkTrainingTerrain(name); }

/**
 * The four numbers a, b, c, d of an attention genome that fix its matrices:
 * A[r][c] = tanh(a s_r s_c + b s_r + c s_c + d). @param {Float32Array} genome @returns {number[]}
 */
export function attentionTerms(genome) { return Array.from(wasm.attentionTerms(genome)); }
