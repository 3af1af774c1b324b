// @ts-check
/**
 * A module's names, as the module list and the study panel write them: its body in words, how
 * a body search's brain was evolved, and its short name with its speed.
 */
import { decimal } from '../shared/format.js';

/**
 * The search's brains in words (the menu's, the estimate's and the gallery's): `frozen` keeps the
 * module's attention as the Fine-tune button does; `finetune` starts from the module and lets
 * every gene change (`vsr codesign --brain`'s names).
 */
export const BRAIN_WORDS = Object.freeze({
  frozen: { menu: 'the chosen module, its attention kept', short: 'attention kept' },
  finetune: { menu: 'the chosen module as a start, every gene evolving, its attention too', short: 'every gene evolving' },
  scratch: { menu: 'a new brain, from scratch', short: 'from scratch' },
});

/** What separates a module's name from its speed in the list (see {@link shortLabel}). */
export const SPEED_MARK = ' · ';
/** Which measurement the list's speed is, said after it: its mean over the study's ten unseen terrains. */
export const LIST_SPEED = 'average over 10 new terrains';

/**
 * A body in words: its preset's name with its rows (as “Rows” in “1 · Draw” writes them), else
 * its voxels and rows.
 * @param {string} rows @param {{name: string, rows: string}[]} presets
 */
export function bodyWords(rows, presets) {
  const name = presets.find((p) => p.rows === rows)?.name;
  return name ? `${name} (rows ${rows})` : `a body of ${rows.split('').filter((c) => c === '1').length} voxels (rows ${rows})`;
}

/**
 * A module's name as the list shows it, short enough for a phone's width: what it is, then its
 * mean speed on the unseen terrains, said in a few words beside it (the speed under the robot,
 * a race's and training's are other measurements of the same brain; the list's title and the
 * details say more).
 * @param {string} what @param {number} mean m/s (NaN: not known)
 * @param {string} [after] words after the speed, which measurement it is (by default the unseen terrains' mean)
 */
export function shortLabel(what, mean, after = ` ${LIST_SPEED}`) {
  return Number.isFinite(mean) ? `${what}${SPEED_MARK}${decimal(mean)} m/s${after}` : what;
}

/**
 * A best robot's speed on the study's unseen terrains, in the words every list of the page uses.
 * @param {number} mean m/s, the mean over the ten terrains
 */
export function unseenWords(mean) {
  return `on average ${decimal(mean)} m/s on ten terrains it never trained on`;
}

/**
 * How a body search's brain was evolved, in words (long, and short for the list), from its
 * condition in the campaign (`frozen`, `finetune`, `scratch-CONTROLLER`). @param {string} condition
 */
export function brainWords(condition) {
  const kind = condition.startsWith('scratch-') ? 'scratch' : condition;
  if (!(kind in BRAIN_WORDS)) return { long: `brain (${condition})`, short: condition };
  const { short } = BRAIN_WORDS[/** @type {keyof typeof BRAIN_WORDS} */ (kind)];
  return kind === 'scratch' ? { long: 'brain from scratch', short } : { long: `module, ${short}`, short: `module, ${short}` };
}

/** The study's bodies in everyday words, for the module list in simple words. @type {Record<string, string>} */
const BODY_SIMPLE = {
  'biped-4x3': 'the small walker', 'biped-6x4': 'the big walker', 'comb-7x2': 'the small comb', 'comb-14x2': 'the big comb',
};
/** The brains in everyday words. @type {Record<string, string>} */
const BRAIN_SIMPLE = { attention: 'an attention brain', mlp: 'a plain brain', 'mlp-comm': 'a brain whose voxels send messages' };
/** The list's speed in simple words: the mean over the study's ten unseen terrains. */
export const LIST_SPEED_SIMPLE = 'on new ground';
/** Which measurement a brain for any body's list speed is: the median over held-out bodies (shared/held-out.js). */
export const HELDOUT_SHORT = 'median on new bodies';
/** The same in simple words. */
export const HELDOUT_SIMPLE = 'on a typical new body';

/**
 * A brain for any body's speed on the bodies it never trained on, in the module list's details.
 * @param {import('../shared/held-out.js').HeldOut} set
 */
export function heldOutLong(set) {
  return `a median of ${decimal(set.median)} m/s over ${set.bodies} bodies it never trained on (each body's mean on ${set.terrains}), `
    + `${set.above} of the ${set.bodies} above 1 m/s`;
}

/** A body's name in everyday words (its own name when it has none). @param {string} shape */
export function bodySimple(shape) {
  return BODY_SIMPLE[shape] ?? shape;
}

/**
 * A study module's name in simple words, with its speed (the list's, in simple words: the
 * unseen terrains' mean), separated as {@link shortLabel} separates it.
 * @param {{controller: string, shape: string, finetuned_from?: string}} m @param {number} mean
 */
export function simpleLabel(m, mean) {
  const what = m.finetuned_from
    ? `a brain trained on ${bodySimple(m.finetuned_from)}, moved to ${bodySimple(m.shape)}`
    : `${BRAIN_SIMPLE[m.controller] ?? m.controller}, trained on ${bodySimple(m.shape)}`;
  return shortLabel(what, mean, ` ${LIST_SPEED_SIMPLE}`).replace(SPEED_MARK, ': ');
}

