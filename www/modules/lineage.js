// @ts-check
/**
 * One run of the study stopped at two budgets. The campaign plan continues a shorter run from
 * scratch when a longer one has the same shape, controller and seed (a run's draws never
 * depend on its budget), so the study's 20,000- and 30,000-evaluation runs of one seed are one
 * run, each stop with its own best robot. A longer run is not always better on terrains it
 * never saw: said beside a run (the study panel) and a module (the module list), so that the
 * biped-6x4 module, stopped at 20,100 evaluations, walking faster than the 30,000-evaluation
 * runs of its body is explained where both numbers are.
 */
import { count, decimal } from '../shared/format.js';

/**
 * A run of the study as this file reads it: a row of the campaign table (the study panel's
 * rows, tour/study-runs.js, hold these and more).
 * @typedef {object} Stop
 * @property {string} run  its name (study/runs/<run>.json)
 * @property {string} kind @property {string} shape @property {string} controller @property {number} seed
 * @property {number} evals  its budget @property {number} evaluations  what it took
 * @property {number} unseen  mean speed of its best over the ten unseen test terrains (m/s)
 */

/** Why the same run's later best can walk slower on new terrains. */
export const LATER_NOT_FASTER = 'A run keeps as its best the robot that walked fastest in training, each walk on one freshly '
  + 'drawn terrain, so a longer run can end on a robot that walks worse on terrains it never saw.';

/**
 * The other stops of the study run `run` (the same run from scratch, another budget, measured
 * on the unseen terrains), the shortest first.
 * @param {Stop[]} runs @param {Stop} run
 */
export function otherStops(runs, run) {
  if (run.kind !== 'scratch') return [];
  return runs.filter((r) => r !== run && r.kind === 'scratch' && r.shape === run.shape && r.controller === run.controller
    && r.seed === run.seed && r.evals !== run.evals && Number.isFinite(r.unseen)).sort((a, b) => a.evals - b.evals);
}

/**
 * Beside a module or a run: the same run stopped at each budget of the study, its best's mean
 * speed on the unseen terrains at each, and, when a later best is slower, why ('' when the run
 * has no other stop).
 * @param {Stop[]} runs @param {string} name the run's name (study/runs/<name>.json)
 */
export function lineageNote(runs, name) {
  const run = runs.find((r) => r.run === name);
  const others = run ? otherStops(runs, run) : [];
  if (!run || others.length === 0) return '';
  const stops = [run, ...others].sort((a, b) => a.evals - b.evals);
  const at = stops.map((r) => count(r.evaluations));
  const speeds = stops.map((r) => `${decimal(r.unseen)} m/s${r === run ? ' (this one)' : ''}`);
  const slower = stops.some((r, i) => i > 0 && r.unseen < stops[i - 1].unseen);
  const budgets = stops.map((r) => count(r.evals));
  const passed = stops.some((r) => r.evaluations !== r.evals)
    ? ` (budgets of ${budgets.slice(0, -1).join(', ')} and ${budgets[budgets.length - 1]}: a run finishes its last generation)` : '';
  return `The study ran this seed once, its best kept at ${at.slice(0, -1).join(', ')} and ${at[at.length - 1]} evaluations${passed}: `
    + `on ten terrains it never trained on, these bests average ${speeds.slice(0, -1).join(', ')} and ${speeds[speeds.length - 1]}.`
    + (slower ? ` ${LATER_NOT_FASTER}` : '');
}
