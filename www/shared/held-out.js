// @ts-check
/**
 * What the study measured of a brain for any body on bodies it never trained on: the manifest's
 * `any_body` record (`vsr campaign export` of an `[[any_body]]` group: every body set's
 * per-body means, their median and the share above 1 m/s), read in one place for the module
 * list and the tour. The figure the plan makes primary is the held-out random bodies'
 * (docs/ANALYSIS-PLAN.md, the fourth question); another held-out set only when it is missing.
 * And which module of the manifest is the study's brain for any body: attention for any body
 * of the plan's primary group (campaigns/any-body.toml). No imports.
 */

/** The study's brain for any body: its campaign group and how many bodies that group trains on (campaigns/any-body.toml). */
export const STUDY_ANY_BODY = Object.freeze({ group: 'any-train32', controller: 'attention-any', bodies: 32 });

/** The held-out body set the plan's primary measure is on: random bodies. */
export const HELDOUT_RANDOM = 'heldout-random';

/**
 * @typedef {object} HeldOut  a held-out body set's figures
 * @property {string} name       the set (its file's stem)
 * @property {string} terrains   the terrain set its bodies walked, in words (e.g. “10 new terrains”)
 * @property {number} median     the median of the bodies' mean speeds (m/s)
 * @property {number} share      the share of the bodies above 1 m/s (0 to 1)
 * @property {number} bodies     how many bodies
 * @property {number} above      how many of them averaged more than 1 m/s
 * @property {number} typical    the typical run's figure beside this module's: the median over the runs it was chosen
 *   from of each run's median on the same set (m/s; NaN when the manifest does not give it)
 */

/**
 * The held-out random bodies' figures of a manifest entry's `any_body` record (else its first
 * held-out set's), or null when it gives none. @param {any} record @returns {HeldOut | null}
 */
export function heldOut(record) {
  const sets = /** @type {{name: string, heldout: boolean, set: string, median: number, walking_share: number, means: number[], median_of_runs?: number}[]} */ (
    Array.isArray(record?.sets) ? record.sets : []);
  const set = sets.find((s) => s.heldout && s.name === HELDOUT_RANDOM) ?? sets.find((s) => s.heldout);
  if (!set || !Number.isFinite(set.median) || !Array.isArray(set.means)) return null;
  const bodies = set.means.length;
  const typical = Number.isFinite(set.median_of_runs) ? Number(set.median_of_runs) : NaN;
  return { name: set.name, terrains: terrainWords(set.set), median: set.median, share: set.walking_share, bodies, above: Math.round(set.walking_share * bodies), typical };
}

/** Whether a manifest entry is the study's brain for any body ({@link STUDY_ANY_BODY}). @param {any} entry */
export function isStudyAnyBody(entry) {
  return entry?.controller === STUDY_ANY_BODY.controller && entry?.any_body?.group === STUDY_ANY_BODY.group;
}

/** The study's terrain sets in a newcomer's words (its own name for another). @param {string} set */
function terrainWords(set) {
  return { unseen: '10 new terrains', paper: 'the paper\'s 10 test terrains' }[set] ?? `the terrains ${set}`;
}
