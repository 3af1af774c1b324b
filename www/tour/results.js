// @ts-check
/**
 * The study's results in a newcomer's words (the page's “What our study found”): what the paper
 * asked, what our reproduction found, how sure it is, with the figures of the study panel; the
 * tests and p-values behind a fold for the statistically minded. Every number here is copied
 * from docs/RESULTS.md (the researchers' account, itself copied from the reports `vsr report`
 * writes); the browser test checks each one is there. Pure data and one function that builds
 * the section's content.
 */

import { whenNear } from '../shared/dom.js';
import { fillClaim } from './claim.js';
import { figure } from './figures.js';

/**
 * @typedef {object} Finding
 * @property {string} question  what the paper asked, in plain words
 * @property {string} paper     what the paper found
 * @property {string} ours      what our study found
 * @property {string} [figure]  a study figure (figures.js) that shows it
 * @property {boolean} [claim]  followed by the test of the paper's own claim (claim.js), read from its file
 * @property {string} [simple]  what our study found for a 14-year-old (short sentences, everyday words), shown instead of
 *   `ours` while “Simple words” is on; the same numbers
 */

/** @type {Finding[]} */
export const FINDINGS = [
  {
    question: 'Does attention make a robot walk faster than the same small brain without it?',
    paper: 'Yes: attention walked faster than a plain network (mlp).',
    ours: 'Yes, on both bodies. On ten hilly terrains no robot trained on, the middle one of ten attention bipeds walked 4.01 m/s, '
      + 'the middle plain-network biped 1.28 m/s. Comparing every attention run with every plain-network run, the typical gap is about 2.6 m/s on the biped and 1.5 m/s on the comb.',
    figure: 'validation-biped',
  },
  {
    question: 'Is attention also faster than voxels that send messages to their neighbours (mlp-comm)?',
    paper: 'Yes: attention walked faster, even though its voxels never talk.',
    ours: 'We cannot tell them apart. On the biped, ten attention runs against ten mlp-comm runs, each run\'s best robot on ten terrains no robot trained on: '
      + 'the typical gap, comparing every attention run with every mlp-comm run, was 0.70 m/s for attention, but ten runs of each are too few to rule out '
      + 'anything from attention being 0.30 m/s slower to 1.40 m/s faster (the larger test below has fresh runs of its own, so its middle speeds differ). On the comb they are closer still. Our first five runs of each on the comb (seeds 1-5, where mlp-comm was ahead overall) then went on '
      + 'to twice the evaluations (60,000): attention 3.28 m/s, mlp-comm 3.62 m/s, and still no difference detected.',
    simple: 'We cannot tell them apart. On the small walker, attention was ahead by about 0.70 m/s, but with ten tries of each brain '
      + 'that gap could be luck: attention could really be a little slower (0.30 m/s) or much faster (1.40 m/s). On the comb the two were closer still. '
      + 'Five tries of each then learned on the comb twice as long: attention 3.28 m/s, the brain with messages 3.62 m/s, and still we could not tell them apart.',
    figure: 'validation-comb',
    claim: true,
  },
  {
    question: 'Does the robot need its attention to keep changing as it walks?',
    paper: 'Yes: frozen at any moment, the robots stopped.',
    ours: 'Yes, the same: frozen from its first step and walked 30 s from standing, the middle biped of ten crawled at 0.023 m/s, against 4.23 m/s with its attention free, both on the same hilly terrain '
      + '(a robot frozen in mid-stride, as on this page, stumbles on a little faster at first; speeds on other terrains differ: see why one robot has several speeds, below).',
    figure: 'frozen-biped',
  },
  {
    question: 'Can an attention evolved on one body help another body learn to walk?',
    paper: 'Yes: transplanted and fine-tuned, it got fast much sooner than a brain evolved from scratch.',
    ours: 'Yes, early on: after 2,500 evaluations the fine-tuned robots were ahead on all four pairs of bodies we tried. '
      + 'By the end of the budget the brains evolved from scratch had caught up: no difference detected. '
      + 'On its own, before fine-tuning, a transplanted brain walks badly, as the paper found.',
    figure: 'finetune-biped-large',
  },
  {
    question: 'Can a brain evolved once, on one body, drive new bodies that a search invents?',
    paper: 'It did not try a search for bodies; it moved its brains between bodies of the same kind (a small and a large biped, a small and a large comb).',
    ours: 'Partly: the attention crosses, the rest of the brain does not. We let evolution search for bodies, starting from a 3 × 3 box, '
      + 'each search with one kind of brain and 6,000 evaluations (the 30,100 that made the module, a budget of 30,000 and the rest of its last generation, not counted). With the attention taken from our best biped and kept frozen '
      + '(four numbers that set every attention matrix; each body\'s output weights were evolved for it), the middle search of ten ended on a body walking '
      + '3.14 m/s on the unseen terrains, faster than searches that had to evolve a plain network (1.22 m/s) or a messaging one (1.96 m/s) along with the body. '
      + 'Against attention evolved from scratch with each body (2.03 m/s) no difference is detected, and that attention was already ahead of the plain network by about half as much '
      + '(a check made after the study, too few searches to be sure): much of the gain is attention itself, not the module. Every search used the same module.',
    simple: 'Partly. We let the computer invent bodies too, starting from a 3 × 3 box: each search had one kind of brain and 6,000 test walks. '
      + 'Some searches kept the attention of our best small walker, unchanged: only four numbers, while the rest of the brain still learned for each new body. '
      + 'They found bodies that walked 3.14 m/s on new ground, faster than searches with a plain brain (1.22 m/s) or a brain whose voxels send messages (1.96 m/s). '
      + 'But searches whose attention learned from nothing did about as well (2.03 m/s: we could not tell them apart), so much of the gain comes from attention itself, '
      + 'not from the brain we moved. The 30,100 test walks that made that brain are not counted in the 6,000.',
    figure: 'codesign-unseen',
  },
  {
    question: 'Can one brain, trained on many bodies, walk on a body it has never seen?',
    paper: 'It did not try: each of its brains kept weights for every voxel of its own body, so a new body needed new ones.',
    ours: 'A little. We gave every voxel the same genes and let it work out its own weights from what it knows of its place (which of its four neighbours exist), '
      + 'so that one brain fits any body, and still no voxel sends a message. We trained ten such brains on 32 random bodies, then walked each on 32 random bodies it never saw, '
      + 'each body on ten hilly terrains. The middle brain of the ten walked 0.83 m/s on a typical new body, where random brains stand still: '
      + 'below the 1 m/s we call walking, and far below brains evolved on one body. Some bodies suit it and walk fast; many barely move. '
      + 'The one in the list of modules, the one of the ten that walked best on its own training bodies, walks 1.31 m/s on a typical new body. '
      + 'It beat a brain built the same way whose voxels send messages instead of using attention; against the same brain without attention, and against attention trained on 128 bodies '
      + '(a little faster) or on the biped alone, ten runs of each were too few to tell. '
      + 'So a new drawing still starts with the phase gait, and this brain is one click away.',
    simple: 'A little. We made one brain that fits any body: every voxel runs the same genes and works out its own weights from which neighbours it has, '
      + 'and still no voxel sends a message. We trained ten of them on 32 random bodies. On new bodies, the typical one of the ten walked 0.83 m/s: '
      + 'slower than 1 m/s, which we call walking, and much slower than a brain trained on one body. Some bodies suit it and walk fast; many barely move. '
      + 'Random brains do not move at all. The one in the list of modules, the one that walked best on its training bodies, walks 1.31 m/s on a typical new body: '
      + 'try it on your own drawing. A brain whose voxels send messages did worse. 128 training bodies looked a little faster, '
      + 'and training on the small walker alone about the same, but ten tries of each are too few to be sure.',
    figure: 'any-body-heldout',
  },
];

/** What “no difference detected” means, said once. */
export const NO_DIFFERENCE = '“No difference detected” means: the runs we have are too few to be sure the two brains differ. '
  + 'It does not mean they are equal. Each run of evolution is a little lucky or unlucky (its seed), so a study runs each brain several times '
  + 'and asks whether the gap between them is larger than luck alone would often give.';

/** Why the same robot has several speeds on this page. */
export const SPEEDS = 'The same robot can show several speeds, each true for what it measures: its best walk in training (one freshly drawn '
  + 'terrain, and evolution keeps the luckiest), its mean over ten terrains it never trained on (what the figures compare, usually lower), '
  + 'and its speed on the one terrain under the robot; a brain for any body also has its speed on a typical new body (the middle of many bodies it never trained on: '
  + 'the list\'s number for it). Each speed on the page says which one it is.';

/**
 * The statistics behind the fold, as in docs/RESULTS.md (ten runs of each, the two-sided
 * Mann-Whitney test, Holm's correction within each family of six comparisons).
 * @type {{shape: string, comparison: string, p: string, holm: string, shift: string}[]}
 */
export const TESTS = [
  { shape: 'biped-4x3', comparison: 'attention vs mlp', p: '0.0029', holm: '0.017', shift: '+2.65 [+1.11, +3.32]' },
  { shape: 'biped-4x3', comparison: 'attention vs mlp-comm', p: '0.14', holm: '0.29', shift: '+0.70 [-0.30, +1.40]' },
  { shape: 'biped-4x3', comparison: 'mlp-comm vs mlp', p: '0.019', holm: '0.074', shift: '+1.71 [+0.63, +2.61]' },
  { shape: 'comb-7x2', comparison: 'attention vs mlp', p: '0.0068', holm: '0.034', shift: '+1.47 [+0.69, +2.64]' },
  { shape: 'comb-7x2', comparison: 'attention vs mlp-comm', p: '0.63', holm: '0.63', shift: '+0.34 [-0.65, +1.00]' },
  { shape: 'comb-7x2', comparison: 'mlp-comm vs mlp', p: '0.029', holm: '0.086', shift: '+1.15 [+0.17, +2.10]' },
];

/**
 * Fills `box` with the findings, the two explanations and the fold of tests.
 * @param {HTMLElement} box @param {(id: string) => void} show shows a study figure in the study panel
 */
export function fillResults(box, show) {
  const doc = box.ownerDocument;
  const add = (/** @type {string} */ tag, /** @type {string} */ text, /** @type {string} */ className = '') => {
    const el = doc.createElement(tag);
    el.textContent = text;
    if (className) el.className = className;
    return el;
  };
  box.replaceChildren(add('p', 'The paper asked four questions about robots whose voxels each run the same small brain. '
    + 'We ran its study again, on this page\'s simulator, evolving every kind of brain at least five times (ten times for every question but the fourth), '
    + 'and asked two questions of our own.', 'explain'));
  const list = doc.createElement('ol');
  list.className = 'findings';
  for (const f of FINDINGS) {
    const item = doc.createElement('li');
    item.append(add('p', f.question, 'finding-question'), add('p', `The paper: ${f.paper}`), add('p', `Our study: ${f.ours}`, f.simple ? 'expert' : ''));
    if (f.simple) item.append(add('p', `Our study: ${f.simple}`, 'simple-only'));
    if (f.claim) {
      const claim = add('p', 'A larger test of the paper\'s exact claim: reading its state…', 'claim expert');
      claim.dataset.testid = 'claim';
      // In simple words the same test told for a 14-year-old (claim.js), the exact statement hidden.
      const plain = add('p', '', 'claim simple-only');
      plain.dataset.testid = 'claim-simple';
      whenNear(item, () => void fillClaim(claim, plain), '300px'); // its file is fetched when the finding can be seen (one of the two is hidden)
      item.append(claim, plain);
    }
    if (f.figure) {
      const button = add('button', figure(f.figure).runs.length ? 'See the figure and its robots' : 'See the figure');
      /** @type {HTMLButtonElement} */ (button).type = 'button';
      button.addEventListener('click', () => show(/** @type {string} */ (f.figure)));
      item.append(button);
    }
    list.append(item);
  }
  box.append(list, add('h3', 'How sure is it?'), add('p', NO_DIFFERENCE), add('h3', 'Why one robot has several speeds'), add('p', SPEEDS));
  const fold = doc.createElement('details');
  fold.className = 'stats';
  fold.append(add('summary', 'The tests, for the statistically minded'), add('p', 'Ten runs of each brain, each best robot\'s mean speed on ten unseen terrains; '
    + 'two-sided Mann-Whitney test; p adjusted by Holm\'s method within each family of six comparisons; shift: the typical difference in m/s with its 95% interval.', 'explain'));
  const table = doc.createElement('table');
  table.className = 'tests';
  const head = table.createTHead().insertRow();
  for (const h of ['body', 'comparison', 'p', 'p (Holm)', 'shift (m/s)']) head.append(add('th', h));
  const body = table.createTBody();
  for (const t of TESTS) {
    const row = body.insertRow();
    for (const v of [t.shape, t.comparison, t.p, t.holm, t.shift]) row.append(add('td', v));
  }
  const more = doc.createElement('p');
  more.className = 'explain';
  more.append('Every number, every test and what the paper reported beside it: ');
  const link = doc.createElement('a');
  link.href = 'docs/RESULTS.html';
  link.target = '_blank';
  link.rel = 'noopener';
  link.textContent = 'the researchers\' account';
  more.append(link, '.');
  fold.append(table, more);
  box.append(fold);
}
