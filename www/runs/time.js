// @ts-check
/**
 * How long a quick run takes, in words: one phrase for every place that says it (the quick
 * preset's button, chapter 8, the lesson plan; docs/teaching.md says the same, and the browser
 * test checks it). The page measures this computer and says how long before a run starts
 * (estimate.js); this is what to expect before that.
 */
export const RUN_TIME = 'under a minute on most computers (the page says how long before it starts)';
