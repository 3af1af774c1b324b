// @ts-check
/**
 * The lesson plan: two lessons of 45 minutes, one device for every two students, chapter by
 * chapter with time to start and to compare. The answer keys' sheet prints it and
 * docs/teaching.md gives it as a table (the browser test checks that both say the same).
 */
import { CHAPTERS, RUN_TIME } from '../tour/chapters.js';

/** @typedef {{what: string, minutes: number}} Step  a chapter (by title) or a step of the lesson (START, WRAP) */

/** The steps that are not chapters. */
export const START = 'Open the page in pairs, press Learn';
export const WRAP = 'Compare predictions: who was right, and why?';

/** The two lessons. @type {{name: string, steps: Step[]}[]} */
export const LESSONS = [
  { name: 'First lesson', steps: [
    { what: START, minutes: 5 },
    { what: 'A voxel and its colours', minutes: 5 },
    { what: 'A body', minutes: 5 },
    { what: 'One small brain in every voxel', minutes: 5 },
    { what: 'Attention, read on one voxel', minutes: 10 },
    { what: 'Evolution', minutes: 10 },
    { what: WRAP, minutes: 5 },
  ] },
  { name: 'Second lesson', steps: [
    { what: START, minutes: 5 },
    { what: 'Three brains, side by side', minutes: 7 },
    { what: 'Freeze the attention', minutes: 5 },
    { what: 'Transplant a module', minutes: 8 },
    { what: 'Which body for this brain?', minutes: 8 },
    { what: 'Your turn', minutes: 7 },
    { what: WRAP, minutes: 5 },
  ] },
];

/** A step in words: a chapter with its number. @param {Step} step */
export function stepWords(step) {
  const n = CHAPTERS.findIndex((c) => c.title === step.what) + 1;
  return `${n > 0 ? `chapter ${n} (${step.what})` : step.what}, ${step.minutes} min`;
}

/**
 * The teachers' guide, docs/teaching.md as a web page (rendered by `make site`, and by
 * scripts/serve.mjs for /docs/teaching.html), relative to the page, and its words.
 */
export const GUIDE = { href: 'docs/teaching.html', text: 'The teachers\' guide (teaching.md)', after: ' has this plan with what students see in each chapter.' };

/** The plan in one paragraph, for the answer keys' sheet, up to the guide. */
function planWords() {
  const lessons = LESSONS.map((l) => `${l.name} (${l.steps.reduce((sum, s) => sum + s.minutes, 0)} min): ${l.steps.map(stepWords).join('; ')}.`);
  return `A plan, if you want one: one device for every two students. ${lessons.join(' ')} `
    + `The quick evolution, the fine-tuning and the body search each take ${RUN_TIME}: start them, then talk. `
    + 'Print the worksheet before the first lesson (one per student). ';
}

/** The plan as text, the guide named. */
export function lessonPlan() {
  return `${planWords()}${GUIDE.text}${GUIDE.after}`;
}

/**
 * The plan as nodes, the guide a link (opening in a new tab): what the answer keys' sheet is to
 * show, `make(doc, 'p', 'sheet-plan')` then `.append(...lessonPlanNodes(doc))`. @param {Document} doc
 * @returns {(string | HTMLElement)[]}
 */
export function lessonPlanNodes(doc) {
  const a = doc.createElement('a');
  a.href = GUIDE.href;
  a.target = '_blank';
  a.rel = 'noopener';
  a.textContent = GUIDE.text;
  return [planWords(), a, GUIDE.after];
}
