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
 * @returns {Promise<{text: string, generations: number, planned: number} | null>} null when the numbers are not valid
 */
export async function planWords(population, budget) {
  let plan;
  try { plan = await runPlan(population, budget); } catch { return null; }
  const extra = plan.planned > budget ? `; the last generation is finished, so the run takes ${count(plan.planned)}` : '';
  return {
    generations: plan.generations,
    planned: plan.planned,
    text: `A budget of ${count(budget)} evaluations: generation 0 measures ${count(population)} random brains, then each of `
      + `${count(plan.generations)} generations measures ${count(plan.perGeneration)} (${count(population)} new children, and the ${count(population)} `
      + `parents again on fresh terrains, so that luck on one terrain does not last)${extra}.`,
  };
}
