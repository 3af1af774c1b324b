// @ts-check
/**
 * The study's figures the page shows (written by `vsr report` into study/report/ or a
 * campaign's own report folder, served at /study/ by scripts/serve.mjs; linked, never copied),
 * each with the runs it is drawn from (rows of the tables in TABLES, whose run files are
 * study/runs/<run>.json) and the paper's figure it reproduces. The tour (chapters.js) and the study panel (study.js) read them here.
 */

/** Where the study's files are served. */
export const STUDY_DIR = 'study/';

/** The study's tables of runs (`vsr campaign merge`), in STUDY_DIR: the paper study's, then the budget campaign's. */
export const TABLES = ['campaign.csv', 'comb-budget.csv'];

/**
 * The table of the test of the paper's own claim (claim.js), read only once that test is
 * complete: its figures (those with `claim`) are listed only then.
 */
export const CLAIM_TABLE = 'noninferiority.csv';

/**
 * @typedef {object} StudyFigure
 * @property {string} id
 * @property {string} file       in the report folder
 * @property {string} [report]   the report folder in study/ (default: report/, the paper study's)
 * @property {string} title      what it shows, in a newcomer's words
 * @property {string} paper      the paper's figure it reproduces, and what the paper found
 * @property {string} read       how to read it
 * @property {RunFilter[]} runs  the campaign rows it is drawn from: those that match one filter
 * @property {string} [table]   the table those rows are in (default: TABLES[0], the paper study's)
 * @property {boolean} [claim]  a figure of the test of the paper's own claim: listed only once that test is complete
 * @property {string} [elsewhere]  where a person finds what it shows, when its runs are not listed here (no `runs`)
 */
/**
 * @typedef {{kind: string, shape: string, evals: number, controllers?: string[], source?: string}} RunFilter
 *   every field given must match; source: how the fine-tuned module's run name starts
 */

/** How to read a box plot. */
const BOX = 'Each box holds the runs of one brain (one dot per run, each with its own seed): the line in it is the median run, the box the middle half, the whiskers reach the slowest and the fastest run.';
/** How to read a box plot with the tests of each pair under it (their numbers: the glossary and "What our study found"). */
const BOXES = `${BOX} The small print under the plot compares pairs of brains, its numbers saying how sure each comparison is: "no difference detected" means the runs drawn are too few to be sure the two brains differ, `
  + 'not that they are equal (see the glossary).';
/** Where a body search's results are, since its runs are not listed in the study panel. */
const SEARCH_ELSEWHERE = 'These runs are not listed here: the fastest body each brain found is in the list of modules, in the playground above.';
/** Where the study's tests of ten runs are, in words (a heading of the page: captions hold no links). */
const FOUND = '“What our study found”, further down the page';

/** @type {StudyFigure[]} */
export const FIGURES = [
  {
    id: 'validation-biped',
    file: 'fig4-rq1-biped-4x3-30000-unseen.svg',
    title: 'Three brains on the biped, each run\'s best walking on ten unseen terrains',
    paper: 'The paper\'s Fig. 4: attention walks faster than a plain network (mlp) and than a network whose voxels send messages (mlp-comm). '
      + 'This figure shows only our first five runs of each brain: attention has the highest median, but its small print finds "no difference detected" for every pair, even attention and mlp, because five runs are too few to be sure. '
      + `We then ran ten of each (${FOUND}): with ten, attention is faster than mlp, while attention and mlp-comm still cannot be told apart.`,
    read: `${BOXES} A point is the mean speed of one run's best robot over ten hilly terrains it was not trained on; higher is faster.`,
    runs: [{ kind: 'scratch', shape: 'biped-4x3', evals: 30000, controllers: ['attention', 'mlp-comm', 'mlp'] }],
  },
  {
    id: 'validation-comb',
    file: 'fig4-rq1-comb-7x2-30000-unseen.svg',
    title: 'Three brains on the comb, each run\'s best walking on ten unseen terrains',
    paper: 'The paper\'s Fig. 4 found attention ahead on the comb too. This figure shows only our first five runs of each, too few to tell the three brains apart; '
      + `with ten runs of each (${FOUND}), attention is faster than mlp, while attention and mlp-comm cannot be told apart, `
      + 'nor when five runs of each (the five on which mlp-comm had led) go on to twice the evaluations (60,000).',
    read: `${BOXES} A point is the mean speed of one run's best robot over ten hilly terrains it was not trained on.`,
    runs: [{ kind: 'scratch', shape: 'comb-7x2', evals: 30000, controllers: ['attention', 'mlp-comm', 'mlp'] }],
  },
  {
    id: 'frozen-biped',
    file: 'fig6-rq1-biped-4x3-30000.svg',
    title: 'Freeze the attention and the biped stops',
    paper: 'The paper\'s Fig. 6: with every voxel\'s attention frozen as it was at one moment, the robots barely move.',
    read: 'Each run\'s best robot, its attention frozen as it was at the second on the horizontal axis of a walk, then walked 30 s afresh from standing, frozen from its first step: its speed. '
      + 'The frozen curve hugs zero: frozen, the robots move a few centimetres per second at most, where the same robots walk about 4 m/s unfrozen (the other line: the middle of the runs, over a whole 30-s walk). '
      + `This figure shows our first five runs; the middle of ten is in ${FOUND}.`,
    runs: [{ kind: 'scratch', shape: 'biped-4x3', evals: 30000, controllers: ['attention'] }],
  },
  {
    id: 'frozen-comb',
    file: 'fig6-rq1-comb-7x2-30000.svg',
    title: 'Freeze the attention and the comb stops',
    paper: 'The paper\'s Fig. 6, for the comb.',
    read: 'Each run\'s best robot, its attention frozen as it was at the second on the horizontal axis of a walk, then walked 30 s afresh from standing, frozen from its first step: its speed. '
      + 'The frozen curve hugs zero (a few centimetres per second), the other line is the same robots unfrozen.',
    runs: [{ kind: 'scratch', shape: 'comb-7x2', evals: 30000, controllers: ['attention'] }],
  },
  {
    id: 'budget-comb',
    report: 'report-comb-budget/',
    file: 'fig3-comb-budget-comb-7x2-60000.svg',
    title: 'Attention and mlp-comm on the comb, evolved for twice as long',
    paper: 'The paper stopped at 30,000 evaluations, saying every curve had levelled off by then. Ours were still rising, so five runs of each '
      + '(the five on which mlp-comm had led at 30,000) '
      + 'went on to 60,000: both brains got faster in every run, and their speeds on ten unseen terrains still cannot be told apart.',
    read: 'Speed of the best robot of each generation (the median run; shaded, the middle half) against evaluations, five runs of each brain; '
      + 'the first 30,000 evaluations of each run (up to the dashed line) are exactly the run the other comb figures show.',
    runs: [{ kind: 'scratch', shape: 'comb-7x2', evals: 60000, controllers: ['attention', 'mlp-comm'] }],
    table: 'comb-budget.csv',
  },
  ...claimFigures(),
  {
    id: 'codesign-unseen',
    report: 'report-codesign/',
    file: 'codesign-rq3-unseen.svg',
    title: 'Searching for a body: a frozen brain from the biped against brains evolved with the body',
    paper: 'Our own question (the paper moved brains only between bodies of the same kind). Ten searches per brain, each 6,000 evaluations from a 3 × 3 box; the 30,100 evaluations that made the biped\'s module (its budget of 30,000, passed a little because a run finishes its last generation) are not counted. '
      + 'With the biped\'s attention kept frozen, the searches ended on faster bodies than with a plain network (mlp) or a messaging one (mlp-comm) evolved along with the body; '
      + 'against attention evolved from scratch with the body, ten searches were too few to tell. '
      + 'Part of the lead over mlp is attention itself: attention evolved from scratch was ahead of mlp by about half as much, though ten searches are too few to be sure (a check made after the study). '
      + 'All twenty searches that started from a module used the same one. '
      + 'The box "finetune" sits highest of the five (the fastest median), yet ten searches were again too few to tell it apart from attention evolved from scratch. '
      + 'The fastest body of each brain is in the playground\'s list of modules.',
    read: `${BOXES} A point is one search's final best body, with its brain, walking ten hilly terrains it was not trained on. `
      + 'The boxes: frozen, the biped\'s attention kept exactly as it was evolved (as the Fine-tune button keeps it; it reaches the voxels through four numbers that set every attention matrix), only the body and the output weights evolving; '
      + 'finetune, started from the same module, every gene evolving with the body, its attention too (a name from our study\'s files: not what the Fine-tune button does); '
      + 'scratch-attention, scratch-mlp and scratch-mlp-comm, each brain evolved from scratch along with the body. The figure\'s title calls this search "rq3": only its name in our files.',
    runs: [],
    elsewhere: SEARCH_ELSEWHERE,
  },
  {
    id: 'codesign-bodies',
    report: 'report-codesign/',
    file: 'codesign-rq3-bodies.svg',
    title: 'Searching for a body: the body every search ended on',
    paper: 'Our own question. None of the fifty bodies is the biped the frozen brain was evolved on: the searches invented bodies of 5 to 20 voxels.',
    read: 'One small drawing per search (a row per brain, fastest first), with its mean speed on the ten unseen terrains; "10 of 10 runs finished": every search of that brain ended. '
      + 'The top row, for reference, is the module on the small biped it was evolved on, measured the same way: after its 30,100 evaluations on that body it walks faster than every body the searches found in 6,000. '
      + 'The fastest body of each brain is in the playground\'s list of modules: choose it there to watch it walk.',
    runs: [],
    elsewhere: SEARCH_ELSEWHERE,
  },
  {
    id: 'any-body-heldout',
    report: 'report-any-body/',
    file: 'any-body-heldout-random-unseen.svg',
    title: 'One brain for every body: speed on 32 random bodies no brain trained on',
    paper: 'Our own question: the paper moved only the attention between bodies, and the rest of each brain was drawn new for the new body. '
      + 'Here every brain is one set of genes for any body (each voxel works out its own weights from which neighbours it has), trained on random bodies, then walked on 32 random bodies it never saw. '
      + 'Attention trained on 32 bodies: its middle run walks 0.83 m/s, below the 1 m/s we call walking, while random brains stand still. '
      + 'It is faster than a brain built the same way whose voxels send messages instead of using attention (mlp-comm); against the same brain without attention (mlp), and against attention trained on 128 bodies or on the biped alone, ten runs each were too few to tell.',
    read: `${BOX} A point is one run: the middle of its 32 speeds, one per held-out body, each body's mean over ten hilly terrains it was not trained on. `
      + 'The labels: attention-any, mlp-any and mlp-comm-any are the three brains for any body; train-32 and train-128 the sets of 32 and 128 training bodies, train-biped the biped alone; grey, random brains.',
    runs: [],
    elsewhere: 'These runs are not listed here: the brain chosen from the ten of attention on 32 bodies is in the list of modules (“one brain for any body”), in the playground above: load it onto any drawing.',
  },
  {
    id: 'any-body-bodies',
    report: 'report-any-body/',
    file: 'any-body-bodies-any-train32-attention-any.svg',
    title: 'One brain for every body: the module on each body it never trained on',
    paper: 'Our own question. The brain in the playground\'s list of modules (“one brain for any body”), chosen from ten runs by its speed on its own training bodies, never by these. '
      + 'It walks the held-out random bodies at a middle speed of 1.31 m/s, 19 of the 32 above 1 m/s: better than the middle run (0.83 m/s).',
    read: 'One small drawing per body, fastest first, with its mean speed on ten hilly terrains it was not trained on; the rows are the sets of held-out bodies: '
      + 'fresh random bodies, small changes of training bodies, combs (a family kept out of training) and the paper\'s four shapes.',
    runs: [],
    elsewhere: 'The module is in the list of modules (“one brain for any body”), in the playground above: draw one of these bodies and load it, to watch it walk.',
  },
  transfer('biped', ['biped-4x3', 'small'], ['biped-6x4', 'large'], 'The paper\'s Fig. 7: a transplanted attention, '
    + 'fine-tuned, gets fast much sooner than a brain evolved from scratch. Our study agrees on all four transfers (after '
    + '2,500 evaluations); by the end of the budget no difference is detected between the two.'),
  transfer('biped', ['biped-6x4', 'large'], ['biped-4x3', 'small'], 'The paper\'s Fig. 7, from large to small.'),
  transfer('comb', ['comb-7x2', 'small'], ['comb-14x2', 'large'], 'The paper\'s Fig. 7, for the combs.'),
  transfer('comb', ['comb-14x2', 'large'], ['comb-7x2', 'small'], 'The paper\'s Fig. 7, from large to small.'),
];

/**
 * The figures of the test of the paper's own claim (attention not worse than mlp-comm, by
 * less than 0.5 m/s): the two brains' differences with their intervals, then each body's runs.
 * Their words give no result: the answer is in the line above the figure (claim.js), read
 * from the file `vsr report` writes.
 * @returns {StudyFigure[]}
 */
function claimFigures() {
  const base = { report: 'report-noninferiority/', table: CLAIM_TABLE, claim: true };
  const pair = ['attention', 'mlp-comm'];
  const bodies = /** @type {const} */ ([['biped', 'biped-4x3'], ['comb', 'comb-7x2']]);
  return [
    { ...base, id: 'claim-intervals', file: 'intervals-noninferiority-unseen.svg',
      title: 'The larger test of the paper\'s claim: is attention slower than mlp-comm, on each body?',
      paper: 'The paper says a brain with no messages (attention) performs "better or comparatively" to one whose voxels send messages (mlp-comm). '
        + 'This test asked that exactly, fixed before any of its runs began: thirty fresh runs of each brain on each body.',
      read: 'Each row is a body: the dot is how much faster attention walks than mlp-comm on ten unseen terrains (the middle estimate, m/s), the bar the range the runs still allow (95%). '
        + 'The test asks whether attention could be 0.5 m/s slower or more (the dashed line at −0.5): a bar wholly right of that line is the picture of “not slower by that much”. '
        + 'The verdict itself (and whether attention is shown faster) is the test\'s, which allows for testing two bodies, in words above the figure.',
      runs: bodies.map(([, shape]) => ({ kind: 'scratch', shape, evals: 30000, controllers: pair })) },
    ...bodies.map(([body, shape]) => ({ ...base, id: `claim-${body}`, file: `fig4-noninferiority-${shape}-30000-unseen.svg`,
      title: `The larger test of the paper's claim on the ${body}: thirty runs of each brain`,
      paper: 'The paper says attention "performs better or comparatively" to mlp-comm. The answer of this test in words is above the figure.',
      read: `${BOX} A point is the mean speed of one run's best robot over ten hilly terrains it was not trained on.`,
      runs: [{ kind: 'scratch', shape, evals: 30000, controllers: pair }] })),
  ];
}

/**
 * A fine-tuning figure (the paper's Fig. 7): the attention evolved on `from` (20,000
 * evaluations), fine-tuned on `to` (10,000), against evolving from scratch on `to` (30,000).
 * @param {string} body @param {[string, string]} from shape and size in words @param {[string, string]} to
 * @param {string} paper @returns {StudyFigure}
 */
function transfer(body, [from, fromSize], [to, toSize], paper) {
  return {
    id: `finetune-${body}-${toSize}`,
    file: `fig7-rq2-${from}-to-${to}.svg`,
    title: `The ${fromSize} ${body}'s attention, fine-tuned on the ${toSize} ${body}, against evolving from scratch`,
    paper,
    read: `Speed of the best robot so far (the median run; shaded, the middle half) against evaluations spent on the ${toSize} `
      + `${body}: fine-tuning the transplanted module (10,000 evaluations) and evolving from scratch (30,000).`,
    runs: [{ kind: 'finetune', shape: to, evals: 10000, source: `${from}-` },
      { kind: 'scratch', shape: to, evals: 30000, controllers: ['attention'] }],
  };
}

/** Where a figure's file is served. @param {StudyFigure} fig */
export function figureSrc(fig) {
  return `${STUDY_DIR}${fig.report ?? 'report/'}${fig.file}`;
}

/** @param {string} id @returns {StudyFigure} */
export function figure(id) {
  const found = FIGURES.find((f) => f.id === id);
  if (!found) throw new Error(`no study figure "${id}"`);
  return found;
}
