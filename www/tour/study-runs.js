// @ts-check
/**
 * The study's runs as data: the rows of its tables of runs (figures.js: TABLES, CLAIM_TABLE)
 * and which of them each figure is drawn from. Read by the study panel (study.js) and by
 * `make site` (scripts/site.mjs copies exactly these runs' files), so it imports nothing that
 * needs a browser.
 */
import { TABLES } from './figures.js';

/**
 * @typedef {object} StudyRun  a row of the campaign table
 * @property {string} run  its name (its run file is study/runs/<run>.json)
 * @property {string} kind @property {string} shape @property {string} controller
 * @property {number} evals  its budget @property {number} evaluations  what it took (a run finishes its last generation)
 * @property {number} seed @property {string} source
 * @property {number} unseen  mean speed of its best over the ten unseen test terrains (m/s)
 * @property {string} table  the table it is a row of (figures.js: TABLES, CLAIM_TABLE)
 */

/**
 * The runs of a campaign table (CSV with a header row; no quoted commas in it).
 * @param {string} text @param {string} table  its name @returns {StudyRun[]}
 */
export function parseCampaign(text, table) {
  const [head, ...lines] = text.trim().split('\n');
  const names = head.split(',');
  const col = (/** @type {string} */ name) => names.indexOf(name);
  const at = { run: col('run'), kind: col('kind'), shape: col('shape'), controller: col('controller'), evals: col('evals'),
    evaluations: col('evaluations'), seed: col('seed'), source: col('source'), unseen: col('unseen_mean') };
  if (Object.values(at).some((i) => i < 0)) throw new Error('the study\'s table of runs lacks a column');
  return lines.map((line) => {
    const v = line.split(',');
    return { run: v[at.run], kind: v[at.kind], shape: v[at.shape], controller: v[at.controller], evals: Number(v[at.evals]),
      evaluations: Number(v[at.evaluations]), seed: Number(v[at.seed]), source: v[at.source], unseen: Number(v[at.unseen]), table };
  });
}

/**
 * The runs a figure is drawn from (rows of its table), the fastest first within each filter.
 * @param {import('./figures.js').StudyFigure} figure @param {StudyRun[]} runs @returns {StudyRun[]}
 */
export function runsOf(figure, runs) {
  const table = figure.table ?? TABLES[0];
  return figure.runs.flatMap((f) => runs.filter((r) => r.table === table && r.kind === f.kind && r.shape === f.shape && r.evals === f.evals
    && (!f.controllers || f.controllers.includes(r.controller)) && (!f.source || r.source.startsWith(f.source)))
    .sort((a, b) => (f.controllers ? f.controllers.indexOf(a.controller) - f.controllers.indexOf(b.controller) : 0)
      || b.unseen - a.unseen));
}
