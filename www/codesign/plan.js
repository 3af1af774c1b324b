// @ts-check
/**
 * The body search the panel's form describes (as `vsr codesign`'s options), or what is wrong
 * with it, in words that name the fix.
 */
import { describeRun } from '../workers/core.js';
import { plain } from '../shared/message.js';
import { size } from '../shared/format.js';
import { hasAttention, isAnyBody } from '../shared/families.js';
import { BRAIN_WORDS } from '../modules/names.js';

/** The quick body search: finishes in about a minute in Chromium on 2 workers (docs/playground.md). */
export const QUICK = Object.freeze({ budget: 1000, seconds: 10, batch: 20 });
/** The seed body, a box of 3 × 3 voxels, and its name in words. */
export const BOX = '111-111-111';
export const BOX_WORDS = `a ${size(3, 3)} box`;

/**
 * The search's brains in words for a module of the family `kind` (the core's rule,
 * `CodesignConfig::frozen_shared`): a brain for any body has no gene of its own per voxel, so
 * kept it is kept whole and only the bodies evolve; as a start, the genes its voxels share
 * evolve, its attention (if it has one) kept. Other modules: {@link BRAIN_WORDS}.
 * @param {'frozen' | 'finetune' | 'scratch'} brain @param {string} kind the module's family ('' when none is known)
 * @returns {{menu: string, short: string}}
 */
export function searchWords(brain, kind) {
  if (brain === 'scratch' || !isAnyBody(kind)) return BRAIN_WORDS[brain];
  if (brain === 'frozen') return { menu: 'the chosen module, kept whole: only the bodies evolve', short: 'kept whole (only the bodies evolve)' };
  return hasAttention(kind)
    ? { menu: 'the chosen module as a start, its attention kept, its other genes evolving', short: 'attention kept, its other genes evolving' }
    : { menu: 'the chosen module as a start, every gene evolving', short: 'every gene evolving' };
}

/**
 * The search the panel's form describes, or what is wrong, in words.
 * @param {{brain: string, from: string, budget: string, seconds: string}} form  the panel's fields
 * @param {import('./panel.js').CodesignHooks} hooks
 * @returns {Promise<{settings: import('../workers/codesign-protocol.js').CodesignSettings, module: import('../modules/modules.js').Module | null,
 *   kind: string, workers: number} | {error: string}>} `kind`: the module's family ('' without one)
 */
export async function planSearch(form, hooks) {
  const brain = /** @type {'frozen' | 'finetune' | 'scratch'} */ (form.brain);
  const from = form.from;
  const budget = Number(form.budget);
  const seconds = Number(form.seconds);
  const run = hooks.run();
  if (!Number.isInteger(budget) || budget < 1) return { error: `evaluations must be a whole number of at least 1, not "${form.budget}"` };
  if (!(seconds > 0 && seconds <= 3600)) return { error: `the episode must last from a fraction of a second to 3600 s, not "${form.seconds}"` };
  const seed = Number(run.seed);
  if (!Number.isSafeInteger(seed) || seed < 0) return { error: `the seed (Run, under 3 · Give it a brain) must be a whole number from 0, not "${run.seed}"` };
  let start;
  if (from === 'drawing') {
    const body = hooks.body();
    if (!body.ok) {
      return { error: `Your drawing is not a body the search can start from${body.message ? `: ${plain(body.message)}` : ''}. `
        + `Draw one piece of touching voxels, or start from the module's own body or ${BOX_WORDS}.` };
    }
    start = body.rows;
  } else if (from === 'box') {
    start = BOX;
  }
  const chosen = brain !== 'scratch' || from === 'module' ? await hooks.module() : null;
  if (!chosen && brain !== 'scratch') return { error: 'choose a module first (Transplant a module, under 3 · Give it a brain): its brain is the one the bodies are searched for' };
  if (!chosen && from === 'module') return { error: 'choose a module first (Transplant a module, under 3 · Give it a brain): the search starts from its body' };
  const info = chosen ? await describeRun(chosen.text) : null;
  if (info && brain === 'scratch' && from === 'module') start = info.shape; // a new brain on the module's body
  const module = brain === 'scratch' ? null : chosen;
  /** @type {import('../workers/codesign-protocol.js').CodesignSettings} */
  const settings = { brain, seed, seconds, terrain: run.terrain.trim(), budget, batch: QUICK.batch };
  if (brain === 'scratch') settings.controller = hooks.controller();
  if (start !== undefined) settings.start = start;
  return { settings, module, kind: module && info ? info.controller : '', workers: Number(run.workers) || 1 };
}
