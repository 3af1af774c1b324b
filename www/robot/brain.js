// @ts-check
/**
 * The brain: what drives the drawn body, a controller family and its genome for that body,
 * with where it came from. Each function here makes a new brain from what the page has (a
 * module, a finished run, a best seen during a run, an edit of the body) with the core's
 * operations (asked of the core worker: those functions return promises); none keeps state.
 * The page holds the current brain.
 */
import { describeRun, ready, remapGenome, runGenome, transplant } from '../workers/core.js';
import { decimal } from '../shared/format.js';
import { familyName, hasAttention, isAnyBody } from '../shared/families.js';

/**
 * @typedef {object} Brain
 * @property {string} controller
 * @property {Float32Array} genome   for the body `rows`
 * @property {string} rows           the body the genome fits
 * @property {{left: number, bottom: number}} origin  where that body sat on the grid
 * @property {string} label          where it came from, in words
 * @property {string | null} module  the pretrained file it came from, if any
 * @property {Source | null} source  the run file whose attention block it carries (fine-tuning), if any
 * @property {number | null} [seconds] the episode length it was trained on (s), if known
 * @property {Trained | null} [trained] its training figure, if it walks as it was trained
 * @property {boolean} [oneShot]     a module put on a body it was not trained on, not fine-tuned yet
 * @property {boolean} [run]         it comes from the run in the run panel
 * @property {boolean} [carried]     its attention came from another brain's file: transplanted, or fine-tuned from one (a link cannot bring that file)
 */

/**
 * @typedef {object} Trained  what training measured: the speed of its latest evaluation, on a
 *   terrain of the training terrain (a family draws a fresh one for every evaluation)
 * @property {number} speed   m/s
 * @property {string} terrain the training terrain (family or name)
 * @property {boolean} [single] the best single evaluation seen during a run (not the run's result)
 * @property {number} [walks]   the mean of this many evaluations, each on a fresh terrain (the body search)
 */

/** @typedef {{left: number, bottom: number}} Origin */

/** @typedef {import('../workers/protocol.js').FinetuneSource} Source  what Fine-tune starts from (as `vsr finetune --from FILE [--entry I]`) */

/**
 * A body found by the body search, with its brain (an attention brain fine-tunes from it).
 * @param {{controller: string, shape: string, genome: number[], fitness: number, index: number, source: string}} entry
 *   the body search's entry `index` and its file
 * @param {{seconds: number, terrain: string} | null} settings the search's @param {string} what what it evolved, in words
 * @param {number} [walks] how many walks its speed is the mean of
 * @returns {Brain}
 */
export function foundBody(entry, settings, what, walks) {
  return {
    controller: entry.controller, genome: new Float32Array(entry.genome), rows: entry.shape, origin: { left: 0, bottom: 0 },
    module: null, source: hasAttention(entry.controller) ? { text: entry.source, entry: entry.index } : null,
    seconds: settings?.seconds ?? null,
    trained: Number.isFinite(entry.fitness) && settings ? { speed: entry.fitness, terrain: settings.terrain, walks } : null,
    label: `a body found by the body search (${what}): ${Number.isFinite(entry.fitness) ? `${decimal(entry.fitness)} m/s in training` : 'no speed'}`,
  };
}

/**
 * A module put on the body `rows`: the core's transplant (rejects with a readable Error when
 * the module cannot go on this body). A brain for any body crosses whole: every gene as trained.
 * @param {import('../modules/modules.js').Module} module @param {string} rows @param {Origin} origin @param {number} seed
 * @returns {Promise<Brain>}
 */
export async function transplanted(module, rows, origin, seed) {
  const [info, genome, { presets }] = await Promise.all([describeRun(module.text), transplant(module.text, rows, seed), ready]);
  const own = info.shape === rows && info.bodies <= 1; // a brain trained on many bodies has no body of its own
  const from = info.bodies > 1 ? `${info.bodies} bodies` : presets.find((p) => p.rows === info.shape)?.name ?? info.shape;
  const label = isAnyBody(info.controller)
    ? `a brain for any body trained on ${from}, on your drawing, every gene as trained`
    : `a module transplanted from ${from}: its attention as evolved there, the rest of its brain new for this body, drawn with seed ${seed}`;
  return {
    controller: info.controller, genome, rows, origin, module: pretrainedKey(module), source: attentionSource(info, module.text), carried: !own,
    seconds: info.seconds, trained: own ? { speed: info.fitness, terrain: info.terrain } : null, oneShot: !own,
    label: own ? `${module.label}, on its own body` : label,
  };
}

/**
 * A module on its own body (the caller draws that body, `info.shape`).
 * @param {import('../modules/modules.js').Module} module @param {Origin} origin
 * @returns {Promise<Brain>}
 */
export async function ownBody(module, origin) {
  const [info, genome] = await Promise.all([describeRun(module.text), runGenome(module.text)]);
  // A brain trained on many bodies has none of its own: it opens on the first of them, its training speed not this body's.
  const many = info.bodies > 1;
  return {
    controller: info.controller, genome, rows: info.shape, origin, module: pretrainedKey(module),
    source: attentionSource(info, module.text),
    label: many ? `${module.label}, on the first of the ${info.bodies} bodies it was trained on` : `${module.label}, on its own body`,
    seconds: info.seconds, trained: many ? null : { speed: info.fitness, terrain: info.terrain }, oneShot: false,
  };
}

/**
 * The brain after an edit of its body, the genome following the voxels by grid position.
 * @param {Brain} brain @param {string} rows @param {Origin} origin @param {number} seed @param {number} edit
 * @returns {Promise<Brain>}
 */
export async function followEdit(brain, rows, origin, seed, edit) {
  const genome = await remapGenome(brain.controller, brain.genome, brain.rows, rows,
    origin.left - brain.origin.left, origin.bottom - brain.origin.bottom, seed, edit);
  const label = brain.label.replace(/ · edited.*$/, '');
  // A brain for any body keeps every gene through an edit (the core's remap gives it back unchanged): said, not drawn anew.
  const same = isAnyBody(brain.controller) ? ' (the same genes drive the new body)' : '';
  return { ...brain, genome, rows, origin, trained: null, label: `${label} · edited${same}${/m\/s/.test(label) ? ' since that speed was measured' : ''}` };
}

/**
 * The best single evaluation seen during a run.
 * @param {Float32Array} genome @param {number} fitness @param {import('../workers/protocol.js').EvolveSettings} settings
 * @param {string} kind @param {boolean} finetuning @param {Source | null} source @param {Origin} origin
 * @returns {Brain}
 */
export function bestSoFar(genome, fitness, settings, kind, finetuning, source, origin) {
  return {
    controller: kind, genome, rows: settings.shape, origin, module: null, source: finetuning ? source : null, carried: finetuning,
    seconds: settings.seconds, trained: { speed: fitness, terrain: settings.terrain, single: true }, run: true,
    label: `the run's best when it began walking (${finetuning ? 'fine-tuning' : 'evolving'}): ${decimal(fitness)} m/s in one evaluation, seed ${settings.seed} `
      + `(a newer best takes over once its ${settings.seconds}-s episode is over)`,
  };
}

/**
 * A finished run's result: its run file's best.
 * @param {{controller: string, genome: number[], fitness: number}} best @param {string} runFile
 * @param {import('../workers/protocol.js').EvolveSettings} settings @param {Origin} origin @param {string} label
 * @param {boolean} [carried] a fine-tune's result (its attention from another brain's file)
 * @returns {Brain}
 */
export function runResult(best, runFile, settings, origin, label, carried = false) {
  return {
    carried,
    controller: best.controller, genome: new Float32Array(best.genome), rows: settings.shape, origin, module: null,
    source: hasAttention(best.controller) ? { text: runFile, entry: null } : null, label,
    seconds: settings.seconds, trained: { speed: best.fitness, terrain: settings.terrain }, run: true,
  };
}

/** What Fine-tune does, on its button. */
export const FINETUNE_WORDS = 'Fine-tune the attention brain on your robot (a module loaded onto it, a run’s result, a body the body search found): '
  + 'its attention stays as it is and the rest of its brain is evolved anew for this body, as the paper fine-tunes a transplanted module '
  + '(that rest starts again from random, so at first it walks worse than now)';

/** What Fine-tune does to a brain for any body, on its button. */
const FINETUNE_ANY_WORDS = 'Fine-tune the brain for any body on your robot: it starts from all its genes as they are, its attention '
  + 'kept, and evolves the others (shared by every voxel) for this body';

/**
 * What Fine-tune does to the robot's brain, on its button. @param {Brain | null} brain
 * @returns {string}
 */
export function finetuneWords(brain) {
  return brain && isAnyBody(brain.controller) ? FINETUNE_ANY_WORDS : FINETUNE_WORDS;
}

/**
 * Why Fine-tune is off for the robot's brain (its button's title). @param {Brain | null} brain
 * @returns {string}
 */
export function whyNoFinetune(brain) {
  if (!brain) {
    return 'Fine-tune trains an attention brain on your robot, and none drives it yet: choose a module under “Transplant a module” '
      + 'and press “Load onto my robot” (Evolve starts a new brain, from scratch)';
  }
  if (!hasAttention(brain.controller)) {
    return `The brain driving your robot is ${familyName(brain.controller)}: it has no attention to keep, so it cannot be fine-tuned (Evolve trains a new brain for this body, from scratch)`;
  }
  return 'The file this brain’s attention came from is not in the page (a link or a reload does not bring it back): to fine-tune, '
    + 'choose a module under “Transplant a module” and press “Load onto my robot”, or Evolve a new brain, from scratch';
}

/**
 * What a link to the robot leaves behind, in a sentence ('' if nothing): said only for a brain
 * whose attention was carried over from another brain's file (transplanted, or fine-tuned from
 * one), a file a link carries only when it is a pretrained module.
 * @param {Brain | null} brain
 */
export function lostInLink(brain) {
  return brain?.source && !brain.module && brain.carried
    ? ' The robot and its brain open the same there, but Fine-tune will be off: the file its attention came from does not travel in a link.' : '';
}

/** @param {import('../modules/modules.js').Module} module */
function pretrainedKey(module) {
  return module.key.startsWith('pretrained/') ? module.key : null;
}

/** @param {{controller: string}} info @param {string} text @returns {Source | null} */
function attentionSource(info, text) {
  return hasAttention(info.controller) ? { text, entry: null } : null;
}
