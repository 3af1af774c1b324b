// @ts-check
/**
 * What a run's settings mean, in words, from the core's rule (workers/core.js runPlan): a budget
 * becomes whole generations, each of which measures two populations (the parents again, on
 * fresh terrains, and as many new children), so a run can pass its budget.
 */
import { runPlan } from '../workers/core.js';
import { count } from '../shared/format.js';

/**
 * @param {number} population @param {number} budget
 * @returns {Promise<{text: string, simple: string, generations: number, planned: number} | null>} null when the numbers
 *   are not valid; `simple`: the same for a 14-year-old (shown instead of `text` in simple words)
 */
export async function planWords(population, budget) {
  let plan;
  try { plan = await runPlan(population, budget); } catch { return null; }
  const over = plan.planned > budget;
  const extra = over ? `; the last generation is finished, so the run takes ${count(plan.planned)}` : '';
  return {
    generations: plan.generations,
    planned: plan.planned,
    text: `A budget of ${count(budget)} evaluations: generation 0 measures ${count(population)} random brains, then each of `
      + `${count(plan.generations)} generations measures ${count(plan.perGeneration)} (${count(population)} new children, and the ${count(population)} `
      + `parents again on fresh terrains, so that luck on one terrain does not last)${extra}.`,
    simple: `The run may use ${count(budget)} test walks. First ${count(population)} random brains walk; then come ${count(plan.generations)} rounds. `
      + `In each round ${count(population)} new brains (children of the best) walk, and the ${count(population)} best so far walk again on new hills, `
      + `so one lucky walk does not keep a brain on top${over ? `. The last round is finished, so the run uses ${count(plan.planned)}` : ''}.`,
  };
}
