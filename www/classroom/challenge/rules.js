// @ts-check
/**
 * A class challenge's rules: a terrain, an episode, a largest body or one fixed body, and the
 * run every student makes: its budget (the most evaluations an entry may be evolved with), seed,
 * population and training terrain, fixed for everyone (the student's run form is locked to them:
 * the same body gives the same robot on every laptop, which is what a short code relies on,
 * code.js). They travel in a challenge
 * link (`?challenge=1&terrain=...`: a query, so it never meets the share link's `#...`), are read
 * back from it, and are the one check of a body and of a budget, for the student's drawing and
 * for the teacher's ranking alike.
 */
import { count } from '../../shared/format.js';

/** The challenge link's query parameters. */
const KEYS = Object.freeze(['terrain', 'seconds', 'voxels', 'body', 'budget', 'seed', 'population', 'train']);

/**
 * The run a challenge fixes when its link does not say: the quick run's population, episode and
 * training terrains, as the teacher's form starts (index.html: 10 s, 2,000 evaluations, seed 1).
 */
export const RUN_DEFAULTS = Object.freeze({ population: 20, seconds: 10, budget: '2000', seed: '1', train: 'hilly-1-10' });

/**
 * @typedef {{terrain: string, seconds: number, voxels: number | null, body: string | null, budget: string, seed: string,
 *   population: number, train: string}} Rules
 */

/** A whole number of at least `least` as the form holds it, or null. @param {string} text @param {number} least */
function whole(text, least) {
  const n = Number(text);
  return text !== '' && Number.isSafeInteger(n) && n >= least ? String(n) : null;
}

/**
 * Rules from loose values (a link's query, a form, what was kept), each missing or wrong one the default.
 * @param {{terrain?: unknown, seconds?: unknown, voxels?: unknown, body?: unknown, budget?: unknown, seed?: unknown,
 *   population?: unknown, train?: unknown}} v
 * @returns {Rules}
 */
export function rulesFrom(v) {
  const text = (/** @type {unknown} */ x) => (typeof x === 'string' ? x.trim() : typeof x === 'number' ? String(x) : '');
  const voxels = Number(v.voxels);
  const seconds = Number(v.seconds);
  return { terrain: text(v.terrain) || 'hilly-1-10-0', seconds: Number.isFinite(seconds) && seconds > 0 ? seconds : RUN_DEFAULTS.seconds,
    voxels: Number.isInteger(voxels) && voxels > 0 ? voxels : null, body: text(v.body) || null,
    budget: whole(text(v.budget), 1) ?? RUN_DEFAULTS.budget, seed: whole(text(v.seed), 0) ?? RUN_DEFAULTS.seed,
    population: Number.isInteger(Number(v.population)) && Number(v.population) > 0 ? Number(v.population) : RUN_DEFAULTS.population,
    train: text(v.train) || RUN_DEFAULTS.train };
}

/** The run form's settings a challenge fixes, as the form holds them. @param {Rules} r @returns {Record<string, string>} */
export function runOf(r) {
  return { population: String(r.population), seconds: String(r.seconds), budget: r.budget, seed: r.seed, terrain: r.train };
}

/**
 * The run a challenge's robot of `rows` was evolved with (what a short code stands for).
 * @param {Rules} r @param {string} rows @param {string} controller @returns {import('../../workers/protocol.js').EvolveSettings}
 */
export function runSettings(r, rows, controller) {
  return { shape: rows, controller, seed: Number(r.seed), seconds: r.seconds, terrain: r.train, population: r.population, budget: Number(r.budget) };
}

/**
 * The rules a challenge link holds, or null when the address has none.
 * @param {string} search a location's query @returns {Rules | null}
 */
export function rulesOf(search) {
  const p = new URLSearchParams(search);
  if (!p.has('challenge')) return null;
  return rulesFrom(Object.fromEntries(KEYS.map((k) => [k, p.get(k) ?? undefined])));
}

/** The challenge link of `rules` on this page. @param {Rules} rules */
export function challengeLink(rules) {
  const url = new URL(location.href);
  url.search = '';
  url.hash = '';
  url.searchParams.set('challenge', '1');
  for (const k of KEYS) {
    const v = rules[/** @type {keyof Rules} */ (k)];
    if (v !== null && v !== '') url.searchParams.set(k, String(v));
  }
  return url.href;
}

/** Whether two sets of rules are the same challenge. @param {Rules} a @param {Rules} b */
export function sameRules(a, b) {
  return KEYS.every((k) => String(a[/** @type {keyof Rules} */ (k)]) === String(b[/** @type {keyof Rules} */ (k)]));
}

/**
 * Why a body breaks the rules `r` ('' when it keeps them). @param {string} rows @param {Rules} r
 */
export function bodyProblem(rows, r) {
  const voxels = rows.split('').filter((c) => c === '1').length;
  if (r.body && rows !== r.body) return `not the challenge's body (${r.body})`;
  if (r.voxels && voxels > r.voxels) return `${voxels} voxels, more than the challenge's ${r.voxels}`;
  return '';
}

/**
 * Why a run budget breaks the rules `r` ('' when it keeps them, or when there is none to read).
 * @param {string | undefined} budget the evaluations a share link's run settings say @param {Rules} r
 */
export function budgetProblem(budget, r) {
  const used = Number(budget);
  const most = Number(r.budget);
  if (budget === undefined || !Number.isFinite(used) || !Number.isFinite(most) || used <= most) return '';
  return `evolved with ${count(used)} evaluations (as its link says), more than the challenge's ${count(most)}`;
}

/** The body the rules allow, in words. @param {Rules} r */
export function bodyWords(r) {
  return r.body ? `the body ${r.body}` : r.voxels ? `any body of at most ${r.voxels} voxels` : 'any body';
}

/** The budget the rules allow, in words. @param {Rules} r */
export function budgetWords(r) {
  return `${Number.isFinite(Number(r.budget)) ? count(Number(r.budget)) : r.budget} evaluations`;
}

/**
 * The rules for the student, in parts: the goal, three short steps, and the details (folded on
 * the page: challenge.js). @param {Rules} r
 * @returns {{goal: string, steps: string[], details: string}}
 */
export function rulesParts(r) {
  return {
    goal: `Challenge: ${bodyWords(r)}, as fast as it can over ${r.seconds} s on ${r.terrain}.`,
    steps: [
      r.body ? 'Your body is drawn for you.' : 'Draw your robot.',
      'Press Evolve: the run is set for you, the same on every computer.',
      'Press “Share link” and give your teacher the short code it shows.',
    ],
    details: `The run: ${budgetWords(r)}, seed ${r.seed}, ${r.seconds}-s walks. `
      + 'Your teacher\'s page ranks your code (or your link) by its speed and can check it by making your robot again the same way. '
      + `The speed under the robot is over its own walk: ${r.seconds} s for a robot you evolve here; a brain from the list of modules walks `
      + 'as long as it trained (its details, under “3 · Give it a brain”, say how long), so its speed is not one to compare with yours.',
  };
}

/** The rules in words, in one line (the message at the top of a student's page, short: the steps are under “Class challenge”). @param {Rules} r */
export function rulesWords(r) {
  const { goal, steps } = rulesParts(r);
  return `${goal} ${steps.map((s, i) => `${i + 1} · ${s}`).join(' ')}`;
}

/** The rules in a line, for the teacher's table. @param {Rules} r */
export function rankingWords(r) {
  return `${bodyWords(r)}; speeds measured again by this page over ${r.seconds} s on ${r.terrain}; at most ${budgetWords(r)}`;
}
