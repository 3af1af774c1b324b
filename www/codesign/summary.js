// @ts-check
/**
 * The body search in words: its summary line (its brain, the kinds of body found, the fastest,
 * and how long it has searched, or once it ended how long it took) and its exported file's name.
 */
import { decimal } from '../shared/format.js';

/** The fastest entry of a gallery, or null. @param {import('../workers/codesign-protocol.js').GalleryEntry[]} gallery */
export function bestEntry(gallery) {
  let best = null;
  for (const e of gallery) if (e.fitness !== null && (best === null || e.fitness > /** @type {number} */ (best.fitness))) best = e;
  return best;
}

/**
 * The summary after the round `round` of a search of `what` (its brain and bodies, in words).
 * @param {string} what
 * @param {{record: {iteration: number}, evaluations: number, gallery: import('../workers/codesign-protocol.js').GalleryEntry[], seconds: number}} round
 * @param {boolean} ended whether the search has ended (it says how long it took)
 */
export function summaryWords(what, { record, evaluations, gallery, seconds }, ended) {
  const best = bestEntry(gallery);
  const rate = seconds > 0 ? `, ${decimal(evaluations / seconds, 1)} evaluations a second` : '';
  const rounds = record.iteration + 1;
  return `Brain: ${what} · ${gallery.length} kind${gallery.length === 1 ? '' : 's'} of body found (cells filled) in ${rounds} round${rounds === 1 ? '' : 's'}`
    + (best?.fitness != null ? ` · fastest: ${decimal(best.fitness)} m/s in training (${best.measurements === 1 ? 'one walk so far' : `the mean of ${best.measurements} walks`}), `
      + `${best.voxels} voxels with ${best.feet} ${best.feet === 1 ? 'foot' : 'feet'}` : '')
    + ` · ${ended ? 'searched' : 'searching'} for ${seconds < 1 ? 'under a second' : `${decimal(seconds, 0)} s`}${rate}`;
}

/**
 * The exported search's file name, in the panel's words: `body-search-frozen-seed1.json`.
 * @param {{brain?: string, seed?: number}} config the run file's
 */
export function exportName(config) {
  return `body-search-${config.brain ?? 'run'}${config.seed === undefined ? '' : `-seed${config.seed}`}.json`;
}
