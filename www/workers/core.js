// @ts-check
/**
 * The core's answers for the page, asked of the core worker (core-worker.js, which owns the
 * wasm module: the page's main thread loads none): the defaults, the check of a drawing, a
 * module's description and the genome operations (transplant, remap). None of these
 * simulates. Each returns a promise; a problem (bad input, or the worker gone) rejects it with
 * a readable Error. `ready` resolves with the defaults once the module is loaded.
 */
import { requester } from './kit.js';

const ask = requester('workers/core-worker.js', 'the core worker');

/** Resolves with the core's defaults once the module is loaded. @type {Promise<Defaults>} */
export const ready = ask('defaults');

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
 * @returns {Promise<{planned: number, generations: number, perGeneration: number}>} rejects on a bad number
 */
export function runPlan(population, budget) { return ask('runPlan', population, budget); }

/** @param {string} rows @returns {Promise<ShapeCheck>} */
export function checkShape(rows) { return ask('checkShape', rows); }

/**
 * @param {string} runFile a run file's JSON text
 * @returns {Promise<{shape: string, controller: string, seed: number, budget: number, evaluations: number, fitness: number,
 *   genes: number, finetunedFrom: string | null, seconds: number, terrain: string,
 *   foundBySearch: boolean, anyBody: boolean, bodySet: string | null, bodies: number}>} rejects with a
 *   readable Error when malformed (anyBody: one genome drives every body; bodySet, bodies: what it was trained on,
 *   its first body `shape` when many)
 */
export function describeRun(runFile) { return ask('describeRun', runFile); }

/** @param {string} runFile @returns {Promise<Float32Array>} its best genome */
export function runGenome(runFile) { return ask('runGenome', runFile); }

/**
 * The transplant of a module onto `rows` (attention: its attention block kept).
 * @param {string} runFile @param {string} rows @param {number} seed @returns {Promise<Float32Array>}
 */
export function transplant(runFile, rows, seed) { return ask('transplant', runFile, rows, seed); }

/**
 * A genome following its body's edit: cell (x, y) of `to` is cell (x + shiftX, y + shiftY)
 * of `from`. @param {string} controller @param {Float32Array} genome @param {string} from
 * @param {string} to @param {number} shiftX @param {number} shiftY @param {number} seed
 * @param {number} edit @returns {Promise<Float32Array>}
 */
export function remapGenome(controller, genome, from, to, shiftX, shiftY, seed, edit) {
  return ask('remapGenome', controller, genome, from, to, shiftX, shiftY, seed, edit);
}

/**
 * Rejects with a readable Error unless `genome` fits.
 * @param {string} controller @param {string} rows @param {Float32Array} genome @returns {Promise<void>}
 */
export function checkGenome(controller, rows, genome) { return ask('checkGenome', controller, rows, genome); }

/** @returns {Promise<number>} a fresh seed from the operating system's randomness (getrandom) */
export function freshSeed() { return ask('freshSeed'); }

/** '' or why `name` is not a terrain. @param {string} name @returns {Promise<string>} */
export function checkTerrain(name) { return ask('checkTerrain', name); }

/** '' or why `text` is not a phase gait "F,PHI". @param {string} text @returns {Promise<string>} */
export function checkGait(text) { return ask('checkGait', text); }

/** '' or why `name` is not a training terrain (family or name). @param {string} name @returns {Promise<string>} */
export function checkTrainingTerrain(name) { return ask('checkTrainingTerrain', name); }
