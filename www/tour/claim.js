// @ts-check
/**
 * The test of the paper's own claim, that attention "performs better or comparatively" to
 * mlp-comm (not worse), in a newcomer's words. Read from the file `vsr report` writes for it
 * (study/report-noninferiority/noninferiority.json; crate/study/src/report/
 * noninferiority/summary.rs), never copied by hand: until every planned run is in, the file
 * holds only how many have finished, and the page says so; the answer appears once the test
 * is complete.
 */
import { count, decimal, signed } from '../shared/format.js';
import { fetchOk, messageOf } from '../workers/kit.js';
import { STUDY_DIR } from './figures.js';

/** Where the page reads the test's state. */
export const CLAIM_FILE = `${STUDY_DIR}report-noninferiority/noninferiority.json`;

/**
 * @typedef {object} ClaimAnswer
 * @property {[number, number]} medians @property {number} shift @property {[number, number]} interval
 * @property {number} p @property {number} holm_p
 * @property {'not worse' | 'worse' | 'not shown'} verdict @property {'better' | 'not shown better' | null} superiority
 */
/**
 * @typedef {object} ClaimSummary
 * @property {string} treatment @property {string} control @property {number} margin
 * @property {number} planned_runs @property {number} finished_runs @property {boolean} complete
 * @property {{shape: string, planned: number, finished: [number, number], answer: ClaimAnswer | null}[]} shapes
 */

/** A body's name in words. @param {string} shape */
function bodyWords(shape) {
  return shape.startsWith('biped') ? `the biped (${shape})` : shape.startsWith('comb') ? `the comb (${shape})` : shape;
}

/** One shape's answer in words. @param {ClaimSummary} s @param {ClaimSummary['shapes'][number]} shape */
function answerWords(s, shape) {
  const a = shape.answer;
  if (!a) return '';
  const verdict = {
    'not worse': `${s.treatment} is not slower than ${s.control} by ${decimal(s.margin, 1)} m/s or more${a.superiority === 'better' ? ', and is faster'
      : a.superiority === 'not shown better' ? ', though these runs do not show it faster either' : ''}`,
    worse: `${s.treatment} is worse, by more than ${decimal(s.margin, 1)} m/s: the paper's claim does not hold here`,
    'not shown': `not settled: the runs still allow ${s.treatment} being more than ${decimal(s.margin, 1)} m/s slower`,
  }[a.verdict];
  return `On ${bodyWords(shape.shape)}, ${verdict} (median speeds ${decimal(a.medians[0])} against ${decimal(a.medians[1])} m/s, the middle ones of this test's own runs; `
    + `the runs allow a difference between ${signed(a.interval[0])} and ${signed(a.interval[1])} m/s, with 95% confidence).`;
}

/**
 * The test in words: what it asks, then either how far it has come or its answer on each body.
 * @param {ClaimSummary} s @returns {string}
 */
export function claimWords(s) {
  const perArm = count(s.planned_runs / (2 * s.shapes.length));
  const asks = `The paper's own words are that ${s.treatment} "performs better or comparatively" to ${s.control}: that it is at least about as fast. `
    + `Ten runs of each cannot settle that, so a larger test asks it exactly: is ${s.treatment} slower by ${decimal(s.margin, 1)} m/s or more `
    + `(a margin fixed in advance: chosen before any run, so that nobody could pick it to suit the answer; less than half of ${s.control}'s estimated lead over mlp on either body)? `
    + `Everything about it was written down before any of its runs began: ${perArm} fresh runs of each brain on each body, ${count(s.planned_runs)} in all.`;
  if (!s.complete) {
    return `${asks} It is under way: ${count(s.finished_runs)} of the ${count(s.planned_runs)} runs have finished. `
      + 'Its answer will be here when all are in: it is worked out only then, so that nobody can stop at a convenient moment.';
  }
  return `${asks} ${s.shapes.map((shape) => answerWords(s, shape)).join(' ')}`;
}

/**
 * The test in words for a 14-year-old (“Simple words”): the same facts, no interval or confidence,
 * the margin as a rule chosen before the runs. @param {ClaimSummary} s @returns {string}
 */
export function claimSimpleWords(s) {
  const perArm = count(s.planned_runs / (2 * s.shapes.length));
  const margin = `${decimal(s.margin, 1)} m/s`;
  const asks = `The paper says ${s.treatment} is at least about as fast as ${s.control}. To check this fairly, we wrote down a rule before we ran anything: `
    + `${s.treatment} passes if it is not slower than ${s.control} by ${margin} or more. Then we trained ${perArm} new brains of each kind on each body.`;
  if (!s.complete) return `${asks} The test is still running: ${count(s.finished_runs)} of ${count(s.planned_runs)} brains are done. The answer comes when all are in.`;
  const each = s.shapes.map((shape) => {
    const a = shape.answer;
    if (!a) return '';
    const body = bodyWords(shape.shape);
    if (a.verdict === 'worse') return `On ${body}, ${s.treatment} failed: it was more than ${margin} slower.`;
    if (a.verdict === 'not shown') return `On ${body}, there is no answer yet: ${s.treatment} might still be ${margin} slower or more.`;
    return `On ${body}, ${s.treatment} passed: it is not ${margin} slower. `
      + (a.superiority === 'better' ? 'It was even faster.' : 'It may be a little faster, but the test cannot be sure.');
  });
  return `${asks} ${each.filter(Boolean).join(' ')}`;
}

/** @type {Promise<ClaimSummary> | undefined} */
let loaded;

/** The test's state, fetched once for every place that says it. @returns {Promise<ClaimSummary>} */
export function loadClaim() {
  loaded ??= fetchOk(CLAIM_FILE).then((response) => response.json());
  return loaded;
}

/**
 * Writes the test's state into `box` (a line that says why, if it cannot be read): in “What
 * our study found” and in the study panel.
 * @param {HTMLElement} box @param {HTMLElement | null} [simple] where its simple words go (shown instead in simple words), if anywhere
 */
export async function fillClaim(box, simple = null) {
  try {
    const s = await loadClaim();
    box.textContent = claimWords(s);
    if (simple) simple.textContent = claimSimpleWords(s);
  } catch (error) {
    box.textContent = `A larger test of the paper's own claim is under way; how far it has come could not be read (${messageOf(error)}).`;
  }
}
