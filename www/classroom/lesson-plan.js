// @ts-check
/**
 * The lesson plan. LESSON is THE plan: one lesson of 50 minutes for a class of 30 (a laptop
 * each, or one per pair), minute by minute, what the teacher projects and what the students do,
 * chapters 1 to 7 and then the class challenge; the teacher's “The 50-minute lesson” sheet shows
 * it (classroom.js, opened by “For teachers” in the page's header) and docs/teaching.md gives it
 * as a table. LESSONS is its alternative if you have two lessons of 45 minutes: the same chapters
 * and the same challenge, with time for chapters 8 to 11; the answer keys' sheet names both and
 * docs/teaching.md gives it as a second table. The browser tests check that the page and the
 * guide say the same.
 */
import { CHAPTERS, RUN_TIME } from '../tour/chapters.js';

/**
 * @typedef {object} LessonStep  a few minutes of the 50-minute lesson
 * @property {number} minutes
 * @property {string} what  a chapter (by title) or a step of the lesson
 * @property {string} projects  what the teacher shows on the projector
 * @property {string} students  what the students do
 */

/** The 50-minute lesson. */
export const LESSON = Object.freeze({
  name: 'One lesson of 50 minutes',
  who: 'a class of 30, a laptop each or one per pair',
  /** @type {LessonStep[]} */
  steps: [
    { minutes: 4, what: 'Open the page', projects: 'this sheet\'s QR code of the page\'s address, and the address in words',
      students: 'open it (the camera on the QR code, or type the address), then press Learn: chapter 1' },
    { minutes: 5, what: 'A voxel and its colours', projects: 'chapter 1: read its question aloud',
      students: 'tick an answer, press Reveal, then change the delay between columns and watch the speed' },
    { minutes: 4, what: 'A body', projects: 'a drawing cut in two: the page refuses it, in words',
      students: 'answer, Reveal, then draw a body of their own' },
    { minutes: 3, what: 'One small brain in every voxel', projects: 'the gene count under the brain',
      students: 'add voxels and watch the count grow by four for each' },
    { minutes: 5, what: 'Attention, read on one voxel', projects: 'one voxel\'s attention map, enlarged (click it)',
      students: 'answer, Reveal, then click the maps of two voxels and compare them' },
    { minutes: 8, what: 'Evolution', projects: 'your own quick run: the chart climbing',
      students: `answer before pressing Evolve, then watch: the run takes ${RUN_TIME}; then race generation 0 against the last` },
    { minutes: 3, what: 'Three brains, side by side', projects: 'the race of three brains, after a show of hands: which wins?',
      students: 'vote, then watch on the screen' },
    { minutes: 3, what: 'Freeze the attention', projects: 'the walking robot, frozen',
      students: 'answer, Reveal, then press Freeze the attention on their own robot' },
    { minutes: 10, what: 'Class challenge', projects: 'the challenge link\'s QR code (made before the lesson: Class challenge, For the teacher)',
      students: 'open it, draw a body within its rules, press Evolve (the same run on every laptop), then Share link: hand in the short code or the link' },
    { minutes: 5, what: 'Rank, race, compare', projects: 'Rank the class, then Race the best four',
      students: 'watch the best four race; who predicted right, and why?' },
  ],
});

/** When each step of the 50-minute lesson starts and ends, "0-4", "4-9", ... @returns {string[]} */
export function lessonTimes() {
  let at = 0;
  return LESSON.steps.map((s) => `${at}–${(at += s.minutes)}`);
}

/** A step of the 50-minute lesson in words: a chapter with its number. @param {LessonStep} step */
export function lessonStepWords(step) {
  const n = CHAPTERS.findIndex((c) => c.title === step.what) + 1;
  return n > 0 ? `Chapter ${n}: ${step.what}` : step.what;
}

/**
 * The chapters the 50-minute lesson uses (0-based, in order): what its worksheet prints.
 * @returns {number[]}
 */
export function lessonChapters() {
  return LESSON.steps.map((s) => CHAPTERS.findIndex((c) => c.title === s.what)).filter((i) => i >= 0);
}

/** The lesson's chapters in words, "chapters 1 to 7". */
export function lessonChaptersWords() {
  const n = lessonChapters().map((i) => i + 1);
  const run = n.every((v, i) => i === 0 || v === n[i - 1] + 1);
  return run ? `chapters ${n[0]} to ${n[n.length - 1]}` : `chapters ${n.join(', ')}`;
}

/** @typedef {{what: string, minutes: number}} Step  a chapter (by title) or a step of the lesson (START, CHALLENGE, RANK, WRAP) */

/** The steps that are not chapters. */
export const START = 'Open the page, press Learn';
export const AGAIN = 'Open the page again, at chapter 8 (its link)';
export const CHALLENGE = 'Class challenge';
export const RANK = 'Rank, race, compare';
export const WRAP = 'Compare predictions: who was right, and why?';

/**
 * If you have two lessons of 45 minutes instead: the 50-minute lesson's chapters 1 to 7 in the
 * first, with a little more time each; chapters 8 to 11 and the same class challenge in the second.
 * @type {{name: string, steps: Step[]}[]}
 */
export const LESSONS = [
  { name: 'First lesson', steps: [
    { what: START, minutes: 5 },
    { what: 'A voxel and its colours', minutes: 5 },
    { what: 'A body', minutes: 4 },
    { what: 'One small brain in every voxel', minutes: 3 },
    { what: 'Attention, read on one voxel', minutes: 5 },
    { what: 'Evolution', minutes: 9 },
    { what: 'Three brains, side by side', minutes: 4 },
    { what: 'Freeze the attention', minutes: 4 },
    { what: WRAP, minutes: 6 },
  ] },
  { name: 'Second lesson', steps: [
    { what: AGAIN, minutes: 3 },
    { what: 'Transplant a module', minutes: 6 },
    { what: 'Which body for this brain?', minutes: 5 },
    { what: 'Your turn', minutes: 3 },
    { what: 'One brain for every body', minutes: 5 },
    { what: CHALLENGE, minutes: 14 },
    { what: RANK, minutes: 9 },
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
export const GUIDE = { href: 'docs/teaching.html', text: 'The teachers\' guide (teaching.md)', after: ' has these plans with what students see in each chapter.' };

/** The name of the teacher's sheet with THE plan. */
export const LESSON_SHEET = 'The 50-minute lesson';

/** The plan in one paragraph, for the answer keys' sheet, up to the guide. */
function planWords() {
  const lessons = LESSONS.map((l) => `${l.name} (${l.steps.reduce((sum, s) => sum + s.minutes, 0)} min): ${l.steps.map(stepWords).join('; ')}.`);
  return `The plan: ${LESSON.name.toLowerCase()} (“${LESSON_SHEET}”, under “For teachers” at the top of the page), ${lessonChaptersWords()} and then the class challenge, for ${LESSON.who}. `
    + `If you have two lessons of 45 minutes instead, the same chapters and the same challenge: ${lessons.join(' ')} `
    + `The quick evolution, the fine-tuning and the body search each take ${RUN_TIME}: start them, then talk. `
    + 'Print the worksheet before the lesson (one per student). ';
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
