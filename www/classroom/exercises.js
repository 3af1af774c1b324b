// @ts-check
/**
 * Predict, then try: one task per tour chapter (tied to its chapter by title), as data. A
 * task asks before it shows: choices, or a number to guess. Its key is never written here: it
 * is computed when asked (`key(lab)`, lab.js), by walking the chapter's robots in the page, by
 * the core's checks, or from committed run files, and it says where its numbers come from. The
 * tour shows a task under its chapter, the worksheet prints them all, the teacher view lists
 * every key (classroom.js).
 */
import { CHAPTERS } from '../tour/chapters.js';
import { count, decimal, plainNumber, size } from '../shared/format.js';
import { NOT_YET } from '../shared/families.js';
import { HELDOUT_RANDOM, heldOut } from '../shared/held-out.js';

/** A value of an attention matrix beyond ±this counts as "at +1 or −1". */
export const SATURATED = 0.9;

/**
 * @typedef {object} Key  a task's answer, computed
 * @property {number} answer   the right choice's index, or the number
 * @property {string} shown    the answer in words
 * @property {string} why      why, with the numbers the page just ran and where they come from
 * @property {string} [simpleWhy] the same in simple words (shown instead while “Simple words” is on)
 */
/**
 * @typedef {object} Exercise
 * @property {string} chapter        its chapter's title
 * @property {string} ask            the question
 * @property {string} [simple]       the question in simple words (shown instead while “Simple words” is on)
 * @property {string[]} [choices]    choices (else a number to guess)
 * @property {string} [unit]         the number's unit
 * @property {string} [try]          what to do after answering, to see it happen
 * @property {(lab: import('./lab.js').Lab) => string} [wait]  why Reveal must wait (its answer is still being made), or ''
 * @property {boolean} [speedsShown]  its question is not about speeds: the page's speeds are not held back until Reveal
 * @property {(lab: import('./lab.js').Lab) => string} [unavailable]  why the task cannot be asked now ('' when it can): its module
 *   is not in pretrained/ yet; then the tour, the worksheet and the keys say so in its place
 * @property {(lab: import('./lab.js').Lab) => object | null} [lock]  what shows the answer now (a run), or null: a guess given before a new one comes is locked (guess-lock.js)
 * @property {(lab: import('./lab.js').Lab) => Promise<Key>} key
 */

/** @param {number} v @param {number} [digits] */
const ms = (v, digits = 2) => `${decimal(v, digits)} m/s`;
/** A set-up's phase gait in words, or '' (the page's default). @param {{gait?: {frequency: number, phase: number}}} s */
const clock = (s) => (s.gait ? `f ${plainNumber(s.gait.frequency)} Hz, φ ${plainNumber(s.gait.phase)}` : '');
/** @param {string} rows */
const voxels = (rows) => rows.split('').filter((c) => c === '1').length;
/** The chapters the tasks belong to, by title (a task follows its chapter wherever it moves). */
const GAIT = 'A voxel and its colours';
const BODY = 'A body';
const BRAIN = 'One small brain in every voxel';
const ATTENTION = 'Attention, read on one voxel';
const EVOLUTION = 'Evolution';
const THREE = 'Three brains, side by side';
const FREEZE = 'Freeze the attention';
const TRANSPLANT = 'Transplant a module';
const BODIES = 'Which body for this brain?';
const YOURS = 'Your turn';
const ANY_BODY = 'One brain for every body';

/** @typedef {import('../tour/chapters.js').Chapter['setup']} Setup */
/** @type {Setup} a chapter that is not there (its task is left out, see EXERCISES) */
const MISSING = { rows: '', brain: null, terrain: 'flat' };
/** A chapter's set-up. @param {string} title @returns {Setup} */
const setup = (title) => CHAPTERS.find((c) => c.title === title)?.setup ?? MISSING;
/** The chapter's own module (a run file served with the page). @param {string} title */
const moduleOf = (title) => setup(title).brain?.module ?? '';

/** Whether the page's latest run is chapter 5's (evolving its brain on its body). @param {import('./lab.js').LatestRun} run */
function ownRun(run) {
  const { rows, controller } = setup(EVOLUTION);
  return run.mode === 'evolve' && run.shape === rows && run.controller === controller;
}

/**
 * Why chapter 5's Reveal must wait, or '': its question is about the class's own run, so it
 * answers only from a run of this chapter that has ended. Each message stays true once the run
 * ends (the page does not rewrite it then): it says to press Reveal again, not that the run is going.
 */
export const EVOLVE_FIRST = 'Press Evolve first: the question is about your own run. Once it has ended, press Reveal again.';
export const RUN_GOING = 'Reveal waits for the end of your run (the question is about its last generation): once the run has ended, press Reveal again.';
/** @param {import('./lab.js').Lab} lab */
function evolutionWait(lab) {
  const run = lab.latestRun();
  if (run.running) return RUN_GOING; // (the latest run is this one only from its generation 0 on)
  // A run stopped before its second generation has no last generation to compare.
  return ownRun(run) && run.bests.length >= 2 ? '' : EVOLVE_FIRST;
}

/**
 * The index of the choice a ratio falls in: faster than 1, from a half to 1, under a half.
 * @param {number} ratio
 */
const third = (ratio) => (ratio > 1 ? 0 : ratio >= 0.5 ? 1 : 2);
/** The three choices {@link third} tells apart. @param {string} than what the speed is compared with */
const thirds = (than) => [`faster than ${than}`, 'slower, but at least half as fast', 'less than half as fast'];
const GAIT_CHOICES = thirds(`at φ ${setup(GAIT).gait?.phase}`);
const FREEZE_CHOICES = ['at least half as fast as before', 'between a tenth and half as fast', 'less than a tenth as fast: it nearly stops'];
/** The freeze's choice a ratio falls in. @param {number} ratio */
const freezeChoice = (ratio) => (ratio >= 0.5 ? 0 : ratio >= 0.1 ? 1 : 2);
const TRANSPLANT_CHOICES = thirds('on its own body');
const ANY_BODY_CHOICES = ['faster than 1 m/s', 'from 0.5 to 1 m/s', 'slower than 0.5 m/s'];
/** The choice of {@link ANY_BODY_CHOICES} a speed (m/s) falls in. @param {number} speed */
const anyBodyChoice = (speed) => (speed > 1 ? 0 : speed >= 0.5 ? 1 : 2);
/**
 * What the study measured of its brain for any body on bodies it never trained on (shared/held-out.js), in words and in
 * simple words: the median of the bodies' mean speeds and the share of them above 1 m/s, then, where the manifest gives
 * it, the typical run's median beside this module's (it is the best of its runs); null when the manifest gives none.
 * @param {any} entry the manifest's entry of the module
 */
function heldOutWords(entry) {
  const set = heldOut(entry?.any_body);
  if (!set) return null;
  const { bodies: n, above } = set;
  const bodies = set.name === HELDOUT_RANDOM ? `${count(n)} random bodies` : `the ${count(n)} bodies of the set ${set.name}`;
  const runs = Number.isInteger(entry?.chosen_from) && entry.chosen_from > 1 ? entry.chosen_from : 0;
  const typical = runs > 0 && Number.isFinite(set.typical);
  const slow = typical && set.typical < 1 ? ', below the 1 m/s the study calls walking' : '';
  return {
    words: `The study walked it on ${bodies} it never trained on, each on ${set.terrains}: the median of those bodies' mean speeds is `
      + `${ms(set.median)}, and ${count(above)} of the ${count(n)} (${Math.round(100 * set.share)}%) averaged more than 1 m/s.`
      + (typical ? ` This brain is the one the study chose of its ${count(runs)} runs of this kind (by their speed on their own training bodies); `
        + `the middle run's brain walked ${ms(set.typical)} there${slow}.` : ''),
    simple: `The study tried it on ${bodies} it never saw. The middle speed of those bodies was ${ms(set.median)}. `
      + `${count(above)} of the ${count(n)} walked faster than 1 m/s.`
      + (typical ? ` It is the best of the ${count(runs)} brains the study trained this way: the typical one walked ${ms(set.typical)}.` : ''),
  };
}

/** Rows with column `col` (0-based from the left) erased. @param {string} rows @param {number} col */
const erase = (rows, col) => rows.split('-').map((r) => `${r.slice(0, col)}0${r.slice(col + 1)}`).join('-');

/** @type {Exercise[]} */
export const TASKS = [
  {
    chapter: GAIT,
    ask: `The robot walks with φ ${setup(GAIT).gait?.phase} (each column a little later than the one on its left). If every column beats together (φ 0), how fast will it walk?`,
    choices: GAIT_CHOICES,
    try: 'Change φ to 0 under the robot and read its speed.',
    async key(lab) {
      const { rows, terrain, gait } = setup(GAIT);
      const f = gait?.frequency ?? lab.defaults.gait.frequency;
      const seconds = lab.defaults.quick.seconds;
      const wave = await lab.walk({ rows: /** @type {string} */ (rows), terrain, seconds, gait: { frequency: f, phase: gait?.phase ?? 0 } });
      const together = await lab.walk({ rows: /** @type {string} */ (rows), terrain, seconds, gait: { frequency: f, phase: 0 } });
      const answer = third(together.speed / wave.speed);
      return { answer, shown: `${GAIT_CHOICES[answer]}: ${ms(together.speed)} against ${ms(wave.speed)}`,
        why: `The page just walked both for ${seconds} s on ${terrain} ground: ${ms(wave.speed)} at φ ${gait?.phase}, ${ms(together.speed)} at φ 0. `
          + 'When every column squeezes at the same moment the body bounces on the spot: no wave runs along it to push it forward.' };
    },
  },
  {
    chapter: BODY,
    ask: 'Erase the third column of the biped, so that it falls into two pieces. What will the page do?', // the chapter's Do says the same
    choices: ['both pieces walk, each on its own', 'the bigger piece walks, the other one is dropped', 'neither piece walks: the robot before the cut walks on'],
    try: 'Erase that column (drag with the right mouse button, or press Erase first) and watch.',
    async key(lab) {
      const cut = erase(/** @type {string} */ (setup(BODY).rows), 2);
      const check = await lab.check(cut);
      const answer = check.ok ? 0 : 2;
      return { answer, shown: answer === 2 ? 'neither piece walks: the robot before the cut walks on until the drawing is one piece again' : 'it walks',
        why: `The page's check of the cut drawing (${cut}) finds ${check.pieces.length} pieces${check.ok ? '' : ` and says: “${check.message}”`}. `
          + 'Voxels only push and pull on the voxels they touch, so a piece on its own would be a second robot.' };
    },
  },
  {
    chapter: BRAIN,
    ask: `This biped has ${voxels(/** @type {string} */ (setup(BRAIN).rows))} voxels. Give it one more voxel: how many genes (the numbers evolution tunes) does its attention brain gain?`,
    unit: 'genes',
    try: 'Click an empty square right next to the robot and read the gene count under “3 · Give it a brain”.',
    async key(lab) {
      const rows = /** @type {string} */ (setup(BRAIN).rows);
      const bigger = rows.replace(/0(?=[01]*$)/, '1'); // one more voxel in the bottom row, next to a leg
      const [a, b] = await Promise.all([lab.check(rows), lab.check(bigger)]);
      const genes = (/** @type {import('../workers/core.js').ShapeCheck} */ c) => c.params.find(([k]) => k === 'attention')?.[1] ?? NaN;
      const gain = genes(b) - genes(a);
      return { answer: gain, shown: `${gain} genes`,
        why: `The page counts ${genes(a)} genes for ${a.voxels} voxels and ${genes(b)} for ${b.voxels}. The new voxel runs the same network as `
          + `every other; only its own output weights are new, one for each of the ${gain} things a voxel feels (area, vx, vy, touch).` };
    },
  },
  {
    chapter: ATTENTION,
    ask: 'A voxel\'s attention matrix holds 16 values, each between −1 and +1. At any moment of this walk, how many of the 16 do you expect to sit at +1 or −1 (beyond ±0.9)?',
    simple: 'A voxel\'s table has 16 squares. Each holds a number from −1 to +1. At any moment of this walk, how many of the 16 do you think are fully on (+1) or fully turned around (−1)?',
    unit: 'of 16',
    try: 'Click a voxel\'s map beside the robot and count the darkest squares.',
    async key(lab) {
      const { rows, controller, genome } = await lab.module(moduleOf(ATTENTION));
      const seconds = lab.defaults.quick.seconds;
      const walk = await lab.walk({ rows, terrain: setup(ATTENTION).terrain, seconds, brain: { controller, genome }, saturated: SATURATED });
      const n = /** @type {number} */ (walk.saturatedPer16);
      const moved = /** @type {number[]} */ (walk.movedByRow).map((m, i) => `${['area', 'vx', 'vy', 'touch'][i]} ${Math.round(100 * m)}%`);
      return { answer: Math.round(n), shown: `about ${decimal(n, 1)} of 16`,
        why: `The page just walked this robot for ${seconds} s and read every voxel's matrix at every decision (three a second): on average `
          + `${decimal(n, 1)} of the 16 values sat beyond ±${SATURATED}. Each value is a tanh (a squashing into −1 to +1) of numbers evolution made large, so it sits at −1 or +1 `
          + `unless they nearly cancel. Share of each row's values that swung by more than 0.5 during the walk: ${moved.join(', ')}.`,
        simpleWhy: `The page just walked this robot for ${seconds} s and looked at every voxel's table three times a second. `
          + `On average ${decimal(n, 1)} of the 16 squares were fully on or fully turned around (nearly +1 or −1). `
          + 'The brain\'s numbers are large, so most squares get pushed all the way to one end. When the foot lands or lifts, whole rows flip.' };
    },
  },
  {
    chapter: EVOLUTION,
    ask: 'Press Evolve. When this quick run ends, how many times faster will the last generation\'s best brain walk than generation 0\'s best (random brains)? '
      + 'Each is the fastest of its own generation, as the run measured it (not the best so far).',
    choices: ['less than 2 times', '2 to 10 times', 'more than 10 times'],
    try: 'Press Evolve, and when it ends press “Race first, middle and last” under “Side by side”.',
    // Revealed during the run, its answer would be a generation's, not the run's end; before it, another run's.
    wait: evolutionWait,
    // The run prints each generation's best as it goes: a guess given before it is kept as it was.
    lock: (lab) => { const run = lab.latestRun(); return ownRun(run) ? run.bests : null; },
    async key(lab) {
      // The page's own run counts only if it is this chapter's (a later chapter's run is another question). A
      // student's Reveal waits for one (evolutionWait); the teacher's keys, without one, answer from the study's run.
      const run = lab.latestRun();
      const own = ownRun(run) ? run.bests : [];
      const bests = own.length >= 2 ? own : await lab.history(moduleOf(BRAIN));
      const source = own.length >= 2 ? 'this page\'s latest run'
        : `the study's best run of this brain on this body (${count(bests[bests.length - 1].evaluations ?? NaN)} evaluations)`;
      const first = bests[0];
      const last = bests[bests.length - 1];
      const ratio = last.fitness / first.fitness;
      const answer = first.fitness <= 0 || ratio > 10 ? 2 : ratio >= 2 ? 1 : 0;
      const times = first.fitness > 0 ? `${decimal(ratio, 1)} times` : 'beyond any ratio (generation 0 went nowhere)';
      // Which run the ratio is of, where it is said: the study's long run climbs far higher than a class's quick one.
      const whose = own.length >= 2 ? ', in your own run'
        : `, in the study's run of ${count(last.evaluations ?? NaN)} evaluations, not a class's quick run of ${count(Number(setup(EVOLUTION).run?.budget))}`;
      // Beside the study's number, what a class's quick run gets to: the study's run after as many evaluations.
      const budget = Number(setup(EVOLUTION).run?.budget);
      const upTo = bests.filter((b) => (b.evaluations ?? Infinity) <= budget);
      const soon = upTo[upTo.length - 1];
      const early = soon && first.fitness > 0 ? soon.fitness / first.fitness : NaN;
      const band = early > 10 ? 2 : early >= 2 ? 1 : 0;
      const quick = own.length >= 2 || !Number.isFinite(early) ? ''
        : `; what the class will see is nearer ${decimal(early, 1)} times (${['less than 2 times', '2 to 10 times', 'more than 10 times'][band]}), as the study's run stood after its first ${count(soon.evaluations ?? NaN)} evaluations, as many as the class's quick run: each student's Reveal says their own run's number`;
      return { answer, shown: `${['less than 2 times', '2 to 10 times', 'more than 10 times'][answer]} (${times})${whose}${quick}`,
        why: `From ${source}: generation 0's best walked ${ms(first.fitness)} in training, the last generation's best (generation ${last.generation}) ${ms(last.fitness)}. `
          + 'Random brains barely move; each generation keeps the fastest and tries changed copies of them, and small gains pile up.'
          + (own.length >= 2 ? '' : ` A student's Reveal answers from their own quick run of ${count(Number(setup(EVOLUTION).run?.budget))} evaluations, which gets less far (it asks them to press Evolve first).`) };
    },
  },
  {
    chapter: THREE,
    ask: 'Three brains on the same body race for 30 s on the same ground. Which one will be fastest?',
    choices: ['attention', 'mlp-comm (voxels that send messages)', 'mlp (no attention)'],
    try: 'Watch the race under “Side by side” to the end.',
    async key(lab) {
      const keys = /** @type {string[]} */ (setup(THREE).race);
      const seconds = lab.raceSeconds();
      const speeds = [];
      for (const key of keys) {
        const { rows, controller, genome } = await lab.module(key);
        speeds.push({ controller, speed: (await lab.walk({ rows, terrain: setup(THREE).terrain, seconds, brain: { controller, genome } })).speed });
      }
      const win = speeds.reduce((a, b) => (b.speed > a.speed ? b : a));
      const answer = ['attention', 'mlp-comm', 'mlp'].indexOf(win.controller);
      return { answer, shown: win.controller,
        why: `The page has just run this race to its end on its own (${seconds} s on ${setup(THREE).terrain}): ${speeds.map((s) => `${s.controller} ${ms(s.speed)}`).join(', ')}; `
          + 'watch it below: its finish shows these speeds. One race is one terrain and one run of each brain: the figure below compares every run on ten terrains.' };
    },
  },
  {
    chapter: FREEZE,
    ask: 'After 5 s of walking, the attention is frozen: every voxel keeps its matrix as it is. How fast will the robot walk from then on?',
    choices: FREEZE_CHOICES,
    try: 'Let it walk about 5 s, press “Freeze the attention” and read the line under it.',
    async key(lab) {
      const { rows, controller, genome, seconds } = await lab.module(moduleOf(FREEZE));
      const at = 5;
      const walk = await lab.walk({ rows, terrain: setup(FREEZE).terrain, seconds, brain: { controller, genome }, freezeAt: at });
      const [before, frozen] = [/** @type {number} */ (walk.before), /** @type {number} */ (walk.frozen)];
      const answer = freezeChoice(frozen / before);
      return { answer, shown: `${FREEZE_CHOICES[answer]}: ${ms(frozen)} frozen (its mean speed from second ${at} to ${seconds}) `
          + `against ${ms(before)} before (its mean over the first ${at} s)`,
        why: `The page just walked this robot ${at} s (${ms(before)}), froze its attention and walked on to ${seconds} s: ${ms(frozen)} frozen. `
          + 'The changing attention is how each voxel re-weighs its readings as it moves; fixed, it can no longer, and the stride falls apart (the paper\'s Fig. 6 and our study found the same for every best robot). '
          + 'Frozen in mid-stride it still stumbles on a little way; the study\'s figure starts each frozen walk from standing, hence its few centimetres per second.' };
    },
  },
  {
    chapter: TRANSPLANT,
    ask: `This brain walks fast on its own small biped. Put on this larger biped (${voxels(/** @type {string} */ (setup(TRANSPLANT).rows))} voxels) before any training, how fast will it walk?`,
    choices: TRANSPLANT_CHOICES,
    try: 'Read the one-shot speed under the robot, then press Fine-tune.',
    async key(lab) {
      const path = moduleOf(TRANSPLANT);
      const own = await lab.module(path);
      const rows = /** @type {string} */ (setup(TRANSPLANT).rows);
      const seed = Number(setup(TRANSPLANT).run?.seed ?? 0);
      const genome = await lab.transplant(path, rows, seed);
      const terrain = setup(TRANSPLANT).terrain;
      const home = await lab.walk({ rows: own.rows, terrain, seconds: own.seconds, brain: { controller: own.controller, genome: own.genome } });
      const away = await lab.walk({ rows, terrain, seconds: own.seconds, brain: { controller: own.controller, genome } });
      const answer = third(away.speed / home.speed);
      return { answer, shown: `${TRANSPLANT_CHOICES[answer]}: ${ms(away.speed)} against ${ms(home.speed)}`,
        why: `The page just walked both for ${own.seconds} s on ${terrain}: ${ms(home.speed)} on its own body, ${ms(away.speed)} transplanted (its new voxels' weights drawn with seed ${seed}). `
          + 'The attention fits any body, but the last step, the weights of each voxel\'s place, was made for the old body: a brain is made for its body.' };
    },
  },
  {
    chapter: BODIES,
    ask: 'The body search keeps the brain\'s attention module exactly as it is while it changes the body. Of the brain\'s numbers (its genes), how many stay exactly the same on every body it tries?',
    unit: 'genes',
    try: 'Press “Search bodies”, click a body in the gallery to watch it walk, and read its gene count under “3 · Give it a brain”.',
    speedsShown: true, // a question about genes; the gallery shows every body's speed anyway
    async key(lab) {
      const box = '111-111-111'; // the search's start, a 3 × 3 box
      const biped = /** @type {string} */ (setup(GAIT).rows);
      const [a, b] = await Promise.all([lab.check(box), lab.check(biped)]);
      const genes = (/** @type {import('../workers/core.js').ShapeCheck} */ c) => c.params.find(([k]) => k === 'attention')?.[1] ?? NaN;
      const shared = lab.defaults.attentionGenes;
      return { answer: shared, shown: `${shared} genes`,
        why: `The page counts ${genes(a)} genes for the ${size(3, 3)} box (${a.voxels} voxels) and ${genes(b)} for the biped (${b.voxels} voxels). `
          + `${shared} of them are the attention block, the same for any body; the rest (four weights for each voxel's place, and one bias) depend on the body or may change with it. `
          + `Those ${shared} genes reach the robot only through four numbers (a, b, c and d) that set every voxel's attention matrix: that is all a kept module brings to a new body.` };
    },
  },
  {
    chapter: YOURS,
    ask: `This table (${voxels(/** @type {string} */ (setup(YOURS).rows))} voxels) has no brain: the phase gait drives it on hilly ground, on this chapter's clock (its f and φ are under the robot, in “Phase gait”; chapter 1's were ${clock(setup(GAIT))}). `
      + `Put chapter 1's biped of ${voxels(/** @type {string} */ (setup(GAIT).rows))} voxels here, on this hilly ground with this same clock: will the table be faster or slower than the biped?`,
    choices: ['faster', 'slower'],
    try: `Read the table's speed under the robot, then type the biped's rows (${setup(GAIT).rows}) in “Rows” and read its speed on the same clock; then draw your own.`,
    async key(lab) {
      const terrain = setup(YOURS).terrain;
      const seconds = lab.defaults.quick.seconds;
      const gait = setup(YOURS).gait ?? lab.defaults.gait; // this chapter's clock, the one the question names
      const mine = await lab.walk({ rows: /** @type {string} */ (setup(YOURS).rows), terrain, seconds, gait });
      const biped = await lab.walk({ rows: /** @type {string} */ (setup(GAIT).rows), terrain, seconds, gait });
      const answer = mine.speed > biped.speed ? 0 : 1;
      return { answer, shown: `${['faster', 'slower'][answer]}: ${ms(mine.speed)} against ${ms(biped.speed)}`,
        why: `The page just walked both with the phase gait (${clock({ gait })}) for ${seconds} s on ${terrain}: this robot ${ms(mine.speed)}, the biped ${ms(biped.speed)}. `
          + 'The same clock moves different bodies differently: that is why evolution tunes a brain for one body.' };
    },
  },
  {
    chapter: ANY_BODY,
    ask: 'This brain was trained on other bodies, never on yours. Walked on the body you keep or draw, how fast will it go?',
    simple: 'This brain learned on other bodies. It never saw yours. How fast will it walk on the body you keep or draw?',
    choices: ANY_BODY_CHOICES,
    try: 'Draw another body (the brain keeps walking as you draw) and read “Your robot\'s speed” under the robot.',
    unavailable: (lab) => (lab.studyAnyBody() ? '' : `The study's brain for any body: ${NOT_YET}.`),
    async key(lab) {
      const key = lab.studyAnyBody();
      if (!key) throw new Error(`the study's brain for any body: ${NOT_YET}`);
      const [module, entry] = await Promise.all([lab.module(key), lab.manifestEntry(key)]);
      const { rows, terrain } = lab.walkingBody();
      const seconds = module.seconds;
      const speed = await lab.measure({ rows, controller: module.controller, genome: module.genome, terrain, seconds });
      const answer = anyBodyChoice(speed);
      const study = heldOutWords(entry);
      return { answer, shown: `${ANY_BODY_CHOICES[answer]}: ${ms(speed)} on your body (${rows}, ${voxels(rows)} voxels)`,
        why: `The page just walked the study's brain for any body, all its genes as trained, on your body for ${seconds} s on ${terrain}, `
          + `as “Your robot's speed” under the robot measures it: ${ms(speed)}. `
          + (study?.words ?? 'The manifest gives no figure of the study\'s for bodies it never trained on.')
          + ' Your body is one body: another may walk faster or slower.',
        simpleWhy: `The page just walked this brain on your body for ${seconds} s: ${ms(speed)}. Nothing was changed for your body. `
          + `${study ? `${study.simple} ` : ''}Your body is one try: another body may walk faster or slower.` };
    },
  },
];

/** The tasks whose chapter is in the tour (all of them, unless a chapter was renamed: the browser test checks). */
export const EXERCISES = TASKS.filter((t) => CHAPTERS.some((c) => c.title === t.chapter));

/** Chapter `index`'s task (0-based), or null when it has none. @param {number} index @returns {Exercise | null} */
export function exerciseOf(index) {
  return EXERCISES.find((t) => t.chapter === CHAPTERS[index]?.title) ?? null;
}
