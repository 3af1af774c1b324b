// @ts-check
/**
 * The tour's chapters, as data: the paper's story told with the live playground. Each
 * chapter has a title, 2 to 5 plain sentences, one thing to do and what to notice, and the
 * playground it sets up (stage.js does it with the page's own functions):
 *
 * - rows: the body (rows of 1 and 0, top first), or null to keep the body;
 * - brain: null (the phase gait), or a module: a run file served with the page, either on its
 *   own body (`own`) or transplanted onto `rows` (`drawn`);
 * - terrain: the viewer's terrain; gait: the phase gait if not the page's default; run: the run settings (and `compare`: run from scratch after
 *   fine-tuning); controller: the family Evolve uses; race: the modules racing side by side;
 * - codesign: the body search's brain (frozen, finetune, scratch) and start body (box, drawing, module);
 * - anyBody: the study's brain for any body goes onto `rows` with all its genes, once pretrained/ has one; until then
 *   the chapter says it is not there yet (`pending`), its task is not offered, and the body walks on the phase gait;
 * - target: the control the visitor is asked to use (scrolled to and outlined);
 * - figure: a study figure shown beside the chapter (figures.js).
 *
 * Pure data with no page in it: the browser tests read it to check each chapter's set-up.
 */
import { count, plainNumber, size } from '../shared/format.js';
import { RUN_TIME } from '../runs/time.js';
import { STUDY_ANY_BODY } from '../shared/held-out.js';

const BIPED = '1111-1111-1001';
const BIPED_LARGE = '111111-111111-100011-100011';
const TABLE = '11111-10101';
/** The last chapter's body: a taller table, none of the bodies the brain for any body was trained on. */
const TALL_TABLE = '11111-11111-10101';
/** How many bodies the study's brain for any body was trained on (shared/held-out.js: its group of campaigns/any-body.toml). */
const TRAINING_BODIES = STUDY_ANY_BODY.bodies;
const ATTENTION = 'pretrained/biped-4x3-attention.json';
const QUICK = { population: '20', seconds: '10', budget: '2000', seed: '1', terrain: 'hilly-1-10' };
const VIEW = 'hilly-1-10-0';
/** Chapter 1's phase gait (chapter 10's is the page's default, which its question says). */
const CLOCK = { frequency: 1, phase: 1.5 };
/** How long a quick run takes (one phrase for chapter 8, the lesson plan and the quick preset). */
export { RUN_TIME };
/** The voxels of a drawing's rows. @param {string} rows */
const voxels = (rows) => rows.split('').filter((c) => c === '1').length;

/**
 * @typedef {object} Chapter
 * @property {string} title
 * @property {string[]} text      2 to 5 plain sentences (a paragraph each)
 * @property {string} task        the one thing to do
 * @property {string} notice      what to notice
 * @property {{rows: string | null, brain: {module: string, on: 'own' | 'drawn'} | null, terrain: string,
 *   gait?: {frequency: number, phase: number}, run?: Record<string, string>, compare?: boolean, controller?: string, race?: string[],
 *   codesign?: {brain: string, from: string}, anyBody?: boolean}} setup
 * @property {string} target      CSS selector of the control the task is about
 * @property {string} [figure]    a study figure's id (figures.js)
 * @property {{text: string[], task: string, notice: string, pending?: string}} [simple]  the same facts for a 14-year-old: short
 *   sentences, everyday words, shown instead of text, task and notice while “Simple words” is on (tour.js)
 * @property {string} [pending]   for a chapter whose brain the study has not finished (`setup.anyBody`): what to do meanwhile,
 *   said after “not yet: the study is still training it” in place of the task and the notice (tour.js)
 */

/** @type {Chapter[]} */
export const CHAPTERS = [
  {
    title: 'A voxel and its colours',
    text: [
      'This robot is made of ten voxels: soft squares, each joined to its neighbours. A voxel can squeeze (red) and swell (green); yellow is at rest.',
      'No brain drives it yet. Every voxel squeezes and swells on a clock, each column a little later than the one on its left, so a wave runs along the body: this is the phase gait.',
      'Its speed is measured over an episode: one walk of a fixed length (here 10 s), from the start line.',
    ],
    task: `Under the robot, in “Phase gait”, change φ, the delay from one column to the next, from ${plainNumber(CLOCK.phase)} to 0, then to ${plainNumber(-CLOCK.phase)}.`,
    notice: `At φ ${plainNumber(CLOCK.phase)} (and f ${plainNumber(CLOCK.frequency)} Hz) it walks about 2 m/s. At 0 every column beats together and it only shuffles, well under 1 m/s. At ${plainNumber(-CLOCK.phase)} the wave runs the other way, yet this biped still goes forwards, only slower (about 1 m/s): which way a body goes is not simply the way its wave runs (its squeezes change only three times a second, so ${plainNumber(-CLOCK.phase)} is not the exact mirror of ${plainNumber(CLOCK.phase)}, and a wall just behind the start stops a robot walking backwards). Only the timing changed. The speed under the robot says how fast.`,
    setup: { rows: BIPED, brain: null, terrain: 'flat', gait: CLOCK },
    target: '#scene, details.gait',
  },
  {
    title: 'A body',
    text: [
      'You can draw any body on the grid of “1 · Draw”: every filled square is a voxel, and the robot walks as soon as you lift the mouse or your finger.',
      'A robot must be one piece, every voxel sharing a side with another: voxels only push and pull on the voxels they touch, so a piece on its own would be a second robot.',
    ],
    task: 'Erase the third column of the biped (drag down it with the right mouse button, or press Erase first on a phone) and watch what the page does with the two pieces. Then draw voxels (drag on the grid) until it is one piece again, and a few more.',
    notice: 'A new body walks at once on the phase gait. Cut in two, each piece gets its own colour, and the last whole robot walks on until the drawing is one piece again.',
    setup: { rows: BIPED, brain: null, terrain: VIEW },
    target: '#editor',
  },
  {
    title: 'One small brain in every voxel',
    text: [
      'Now each voxel gets a brain. A voxel feels four things, all about itself: its area (squeezed or stretched), its speed sideways (vx) and up or down (vy), and touch (whether it is on the ground).',
      'Three times a second, its brain turns these four readings into one number: how much to squeeze. Every voxel runs the same small network; only its very last step has numbers of the voxel\'s own, which belong to its place in the body.',
      'No voxel sends anything to another. They walk together only because they share one body and one ground. This brain was evolved in our study (chapter 5 shows how; the lines under the robot say with what).',
    ],
    task: 'Click an empty square right next to the walking robot to give it one more voxel.',
    notice: 'The brain grows by 4 genes (the numbers evolution tunes; the count is under “3 · Give it a brain”), not by a whole new brain: the new voxel runs the same network, with its own four weights.',
    setup: { rows: BIPED, brain: { module: ATTENTION, on: 'own' }, terrain: VIEW },
    target: '#scene',
  },
  {
    title: 'Attention, read on one voxel',
    text: [
      'Before it decides, a voxel\'s brain lets each of its four readings ask how much to listen to each of the four. The answers form a 4 × 4 table, its attention matrix, new at every step.',
      'The small maps next to the robot (“Attention of each voxel”) show every voxel\'s matrix in its place: red +1 (listen), blue −1 (listen, reversed), white 0 (ignore). A row is the reading that asks (the query); the columns are the readings it listens to (the keys).',
    ],
    task: 'Click one voxel\'s map (a foot is a good choice) to read its matrix enlarged, with the voxel outlined on the robot.',
    notice: 'Most values sit at +1 or −1 at any moment; as the foot lands and lifts, whole rows flip from one side to the other (the reveal above counts, for this very walk, how many values sit at ±1 and which rows move). The robot reads its own motion and touch through them.',
    setup: { rows: BIPED, brain: { module: ATTENTION, on: 'own' }, terrain: VIEW },
    target: '#scene, #attention',
    simple: {
      text: [
        'Before a voxel decides how much to squeeze, it looks at the four things it feels. Each of the four asks: how much should I listen to each of the four?',
        'The answers make a small table: 4 rows and 4 columns. The voxel makes a new table three times a second.',
        'The small maps next to the robot show the table of every voxel, in its place on the body. Red means listen. Blue means listen, but turned around. White means ignore. '
          + 'Each row is one thing the voxel feels, asking. Each column is one thing it listens to.',
      ],
      task: 'Click the map of one voxel (a foot is a good choice). It opens big, and that voxel gets an outline on the robot.',
      notice: 'At any moment most squares are dark red or dark blue: fully on, or fully turned around. When the foot lands or lifts, whole rows flip from red to blue or back. '
        + 'The box above counts this for the walk you are watching. This is how the robot uses what it feels about its own movement and touch.',
    },
  },
  {
    title: 'Evolution',
    text: [
      'Nobody wrote these brains: evolution found them. It starts with a population of random brains (here 20) and walks each one for an episode (10 s) on hilly ground. Its fitness is its speed: the distance walked divided by the time.',
      'The fastest become parents; their children are copies with small random changes, or mixes of two parents. Each round is a generation; each walk measured is an evaluation.',
      `The study gave every run 30,000 evaluations with 100 brains and 30-s episodes; this quick run has ${count(Number(QUICK.budget))}.`,
      'Its seed (under “Run”) fixes every random draw: the same seed gives the same run, on any computer, so a class can all watch the same evolution; another seed, another one.',
    ],
    task: 'Press Evolve. When the run ends, press “Race first, middle and last” under “Side by side”: generation 0\'s best, the middle generation\'s and the last one\'s walk side by side.',
    notice: 'The chart climbs as generations pass, and the robot switches to the best brain so far every few seconds. Each evaluation is on freshly drawn hills, so a lucky walk can score high once: the line wobbles.',
    setup: { rows: BIPED, brain: null, terrain: VIEW, run: QUICK, controller: 'attention' },
    target: '#run-evolve',
  },
  {
    title: 'Three brains, side by side',
    text: [
      'Three kinds of brain on the same body: attention (the paper\'s); mlp, the same small network without attention; and mlp-comm, a network whose voxels do send messages to their neighbours.',
      'Each was evolved in our study with 30,000 evaluations. Below, they race on one terrain for 30 s, all started together.',
    ],
    task: 'Answer first: the race under “Side by side” starts when you reveal your answer. Then watch it to the end.',
    notice: 'The paper found attention the fastest, even against voxels that talk. Our study, with ten runs of each brain, finds attention faster than mlp, on this biped and on the comb, but could not tell attention and mlp-comm apart. '
      + 'A larger test, planned in advance with thirty fresh runs of each brain on each body, then asked the paper\'s own claim: attention is not slower than mlp-comm by 0.5 m/s or more on either body, though not shown faster. '
      + 'One race is one terrain and one run of each: the figure is the fair comparison, every run of each brain on ten terrains it never trained on (it shows our first five runs of each).',
    setup: { rows: BIPED, brain: { module: ATTENTION, on: 'own' }, terrain: VIEW,
      race: ['pretrained/biped-4x3-mlp.json', 'pretrained/biped-4x3-mlp-comm.json', ATTENTION] }, // not in the order they finish
    target: '#race-status, #race-lanes', // the lanes the class watches, above the sheet on a phone
    figure: 'validation-biped',
    simple: {
      text: [
        'Here are three kinds of brain on the same body. Attention is the brain from the paper. mlp is the same small brain without attention. '
          + 'mlp-comm is a brain whose voxels send messages to their neighbours.',
        'Our study trained each brain with 30,000 test walks. Now they race on the same ground for 30 seconds. They all start together.',
      ],
      task: 'Choose your answer first. The race under “Side by side” starts when you press Reveal. Then watch it to the end.',
      notice: 'The paper found attention the fastest, even against voxels that send messages. We trained ten brains of each kind to check. Attention was faster than mlp. '
        + 'But we could not tell attention and mlp-comm apart. Then a bigger test, planned before it started, trained thirty new brains of each kind on each body. '
        + 'It showed that attention is not much slower than mlp-comm: not 0.5 m/s slower or more. It did not show that attention is faster. '
        + 'One race is one piece of ground and one brain of each kind, so it can surprise you. The picture below is the fair test: '
        + 'many brains of each kind, each on ten pieces of ground it never walked on before (it shows five brains of each kind).',
    },
  },
  {
    title: 'Freeze the attention',
    text: [
      'Is the changing attention needed, or would one fixed table do? Freeze every voxel\'s matrix as it is at one moment, and let the robot walk on with it.',
      'Nothing else changes: the same sensors, the same weights, the same ground.',
    ],
    task: 'Let the robot walk for about 5 s, then press “Freeze the attention”.',
    notice: 'Within seconds it stumbles and nearly stops; the line under the button gives its speed before and frozen, and says what they mean. The paper (its Fig. 6) and our study froze every best robot at every second of a walk: they all stop. The figure\'s robots walk about 4 m/s unfrozen (the middle one of the study\'s runs); this one is the fastest, so it walks faster before you freeze it.',
    setup: { rows: BIPED, brain: { module: ATTENTION, on: 'own' }, terrain: VIEW },
    target: '#freeze-attention',
    figure: 'frozen-biped',
  },
  {
    title: 'Transplant a module',
    text: [
      `A module is a brain evolved before, kept in a file. Here the small biped's brain is transplanted onto a larger biped of ${voxels(BIPED_LARGE)} voxels: its attention, the same for any body, is kept.`,
      'Its last step, the four weights of each voxel\'s place, belonged to the old body, so they are drawn at random for the new one. Walking at once with them, before any training, is a one-shot transplant.',
      'Fine-tuning evolves only those weights and keeps the attention. In the paper (its Fig. 7) and our study it gets fast sooner than a brain evolved from scratch: in our study it was ahead after 2,500 evaluations on all four bodies we tried, and by the end of their budgets (10,000 evaluations of fine-tuning, 30,000 from scratch) no difference between the two was detected.',
    ],
    task: 'Read its one-shot speed on the line under the robot, then press Fine-tune: a run from scratch with the same budget follows by itself.',
    notice: `One-shot, the robot hardly moves: a brain is made for its body. What crossed to this body is only the attention, and it acts through four numbers that set every voxel's attention matrix; the weights that drive each voxel were drawn anew. Each run takes ${RUN_TIME}; the numbers above the chart say which one is running and how long it has left. The chart draws fine-tuning, then from scratch as a dashed line: compare them over the first few hundred evaluations, where fine-tuning starts from a brain that already works. By the end of this short run either may lead: one run is one sample; the study's figure has five runs of each.`,
    setup: { rows: BIPED_LARGE, brain: { module: ATTENTION, on: 'drawn' }, terrain: VIEW, run: QUICK, compare: true },
    target: '#scene, #run-finetune',
    figure: 'finetune-biped-large',
  },
  {
    title: 'Which body for this brain?',
    text: [
      'So far you chose a body and evolved a brain for it. Now turn it around: keep the brain and let evolution search the body.',
      `The brain is the small biped's attention module, its attention kept exactly as it was evolved, as the Fine-tune button keeps it; only the body and each voxel's four output weights evolve. The search starts from a plain ${size(3, 3)} box, adds and removes voxels, and keeps the fastest body of each size and each number of feet.`,
      'The attention is the same for any body, so it can be carried to many bodies, while each body gets output weights evolved for it: this is what the paper means by a brain that can be taken apart and put together in other forms.',
    ],
    task: 'Under “Search bodies for this brain”, press “Search bodies”. When the gallery fills, click a green body to watch it walk.',
    notice: 'The gallery fills round by round: small bodies first, then larger ones and more feet. Green bodies are the fastest; an outline marks bodies new in the last round. The fastest body is often not the biped the brain was evolved on. Each body\'s speed is measured again every round on new hills, so a lucky walk does not stay on top. A quick search is short: its bodies walk slower than the biped this brain had 30,000 evaluations to master. '
      + 'What the bodies share is not a whole brain: the kept attention reaches every voxel through just four numbers (a, b, c and d, which set every attention matrix), and each body\'s output weights are evolved for it. '
      + 'In our study of this search (ten long searches per brain, 6,000 walks each, on hills the robots never trained on; the 30,100 walks that made the module, its budget of 30,000 and the rest of its last generation, are not counted), the kept attention found faster bodies than searches that had to evolve a plain network or a messaging network together with the body; against an attention brain evolved from scratch with the body, the searches were too few to tell. '
      + 'Part of that lead is attention itself, not the module: attention evolved from scratch was also ahead of the plain network, by about half as much, though ten searches are too few to be sure (a check made after the study). And every one of these searches used the same module, so whether other modules do as well is not known.',
    setup: { rows: null, brain: { module: ATTENTION, on: 'own' }, terrain: VIEW, run: QUICK, codesign: { brain: 'frozen', from: 'box' } },
    figure: 'codesign-unseen',
    target: '#codesign-panel',
  },
  {
    title: 'Your turn',
    text: [
      `This table of ${voxels(TABLE)} voxels has no brain: the phase gait drives it, on this chapter's clock (f and φ under the robot, in “Phase gait”). Now draw a robot of your own: a long worm, a taller table, a creature with three legs.`,
      'Give it a brain: evolve one, or choose a module under “3 · Give it a brain”, load it onto your robot and fine-tune it. Every figure of the study is under “The study”, further down the page, each with its robots to watch.',
    ],
    task: `Read the table's speed under the robot. Then put chapter 1's biped here: type ${BIPED} in “Rows” under the grid; the same clock drives it on the same hills: compare its speed. Then draw a robot of your own; when it walks, press “Share link” and send the link: it opens your robot, its brain and its settings.`,
    notice: 'This tour has a link for every chapter too (the address bar shows it), to send one chapter to a class.',
    setup: { rows: TABLE, brain: null, terrain: VIEW, run: QUICK, controller: 'attention' },
    target: '#share',
  },
  {
    title: 'One brain for every body',
    text: [
      'Every brain so far had genes tied to each voxel, to its place in one body: a new drawing had to wait for evolution before it walked well.',
      'This brain\'s genes are the same for every voxel, whatever the body. Each voxel runs the same network on its four readings, with the paper\'s attention, '
        + 'and also feels which of its four neighbours are there.',
      `It was trained on ${TRAINING_BODIES} random bodies at once, never on yours. As before, no voxel sends messages to another.`,
    ],
    task: 'Keep this body, or draw your own on the grid of “1 · Draw”: the brain walks on it at once. Answer the question, then press Reveal: the page walks this brain on the body you drew.',
    notice: 'Nothing was drawn at random for your body: every gene is the one training found. Bodies differ: some suit this brain and walk fast, many barely move. '
      + 'Draw another body and read “Your robot\'s speed” under the robot.',
    pending: 'Until it is, this chapter has no brain to walk: its body walks on the phase gait. Evolve can train a brain of the same kind on your drawing '
      + '(choose “attention, any body” in “Brain (controller)”, under “3 · Give it a brain”).',
    setup: { rows: TALL_TABLE, brain: null, anyBody: true, terrain: VIEW },
    target: '#scene, #editor',
    simple: {
      text: [
        'Until now, every brain had numbers (genes) that belong to the voxels of one body. A new body had to wait for evolution before it could walk well.',
        'This brain is different. Every voxel uses the very same numbers, on any body. Each voxel feels the same four things as before. It also feels which of its four sides touch another voxel.',
        `It learned on ${TRAINING_BODIES} random bodies. It never saw yours. The voxels do not send messages to each other.`,
      ],
      task: 'Keep this body or draw your own. The brain walks on it at once. Choose your answer, then press Reveal. The page walks this brain on your body.',
      notice: 'Nothing was changed for your body: every number is the one training found. Some bodies suit this brain and walk fast; many barely move. '
        + 'Draw another and read “Your robot\'s speed” under the robot.',
      pending: 'Until then, there is no brain to try here: the body moves on the clock. You can train a brain like it on your own drawing with Evolve '
        + '(choose “attention, any body” in “Brain (controller)”, under “3 · Give it a brain”).',
    },
  },
];
