// @ts-check
/**
 * Test of the tour's words, without a browser (node --test): no text a pair reads before a
 * chapter's Reveal states its answer (the chapter's sentences and Do, its question, the sentences
 * of the chapter before, the glossary); the body search's `finetune` is never called fine-tuned
 * (the Fine-tune button's word: it keeps the attention); the study figures' captions hold no
 * statistics; chapter 5's Reveal answers only from the pair's own finished run, in words that stay
 * true once it ends, and its question names what the key divides; chapter 10's question names the
 * clock its key walks both robots with; chapter 2's Do does what its question asks; the lesson
 * plan, chapter 8 and docs/teaching.md say the same about how long a run takes, and the plan
 * links the teachers' guide. The browser tests check the page itself (classroom, reveal, tour).
 */
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { EVOLVE_FIRST, RUN_GOING, TASKS } from '../../www/classroom/exercises.js';
import { GUIDE, lessonPlan, lessonPlanNodes } from '../../www/classroom/lesson-plan.js';
import { SENSOR_NAMES } from '../../www/workers/protocol.js';
import { CHAPTERS, RUN_TIME } from '../../www/tour/chapters.js';
import { FIGURES, figure } from '../../www/tour/figures.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const ENTITIES = { minus: '−', ldquo: '“', rdquo: '”', rsquo: '’', lsquo: '‘', middot: '·', phi: 'φ', deg: '°', radic: '√', times: '×', amp: '&' };
/** The glossary's words, as the page shows them (index.html's `#glossary`, tags out). */
const GLOSSARY = (/<details id="glossary"[\s\S]*?<\/details>/.exec(readFileSync(path.join(ROOT, 'www/index.html'), 'utf8'))?.[0] ?? '')
  .replace(/<[^>]+>/g, ' ').replace(/&(\w+);/g, (m, e) => ENTITIES[/** @type {keyof ENTITIES} */ (e)] ?? m).replace(/\s+/g, ' ');
/** @param {string} title */
const chapterIndex = (title) => CHAPTERS.findIndex((c) => c.title === title);
/** @param {string} title */
const taskOf = (title) => /** @type {import('../../www/classroom/exercises.js').Exercise} */ (TASKS.find((t) => t.chapter === title));

/** What a pair can read before chapter `title`'s Reveal, by where it is. @param {string} title */
function before(title) {
  const i = chapterIndex(title);
  const { text, task } = CHAPTERS[i];
  const ex = taskOf(title);
  return { [`chapter ${i + 1}'s sentences and Do`]: [...text, task].join(' '),
    [`chapter ${i + 1}'s question`]: [ex.ask, ...(ex.choices ?? [])].join(' '),
    [`chapter ${i}'s sentences`]: i > 0 ? CHAPTERS[i - 1].text.join(' ') : '',
    glossary: GLOSSARY };
}

/** The number in words too (the texts spell small numbers out). @param {number} n */
const spelled = (n) => [String(n), ['zero', 'one', 'two', 'three', 'four', 'five', 'six', 'seven', 'eight', 'nine', 'ten'][n]].filter(Boolean).join('|');

/** What would give each answer away, by chapter (the newcomer's review found each of these in the page). */
const GIVEAWAYS = {
  // 4 genes: one output weight per sensor.
  'One small brain in every voxel': new RegExp(`\\b(${spelled(SENSOR_NAMES.length)})\\s+(genes|weights|output weights)\\b`, 'i'),
  // Most values at −1 or +1.
  'Attention, read on one voxel': /\bmost\b[^.]*\b(sit|are|lie|stay)\b[^.]*(±\s*1|[−-]1 or \+1|\+1 or [−-]1)/i,
  // One-shot, it barely walks.
  'Transplant a module': /walks? badly|(hardly|barely) walks|hardly moves|robots? barely moves?|nearly stops/i,
  // The attention block's 32 genes.
  'Which body for this brain?': /\b32\b|thirty-two/i,
};

test('no text a pair reads before a Reveal states its answer', () => {
  for (const [title, giveaway] of Object.entries(GIVEAWAYS)) {
    assert.ok(chapterIndex(title) >= 0 && taskOf(title), `a chapter "${title}" with a task`);
    for (const [where, text] of Object.entries(before(title))) {
      const found = giveaway.exec(text);
      assert.equal(found, null, `${title}: ${where} gives the answer away: “${found?.[0]}” in “${text.slice(Math.max(0, (found?.index ?? 0) - 80), (found?.index ?? 0) + 80)}”`);
    }
  }
  // The facts stay taught: after the Reveal, in the chapter's Notice.
  assert.match(CHAPTERS[chapterIndex('One small brain in every voxel')].notice, /4 genes/);
  assert.match(CHAPTERS[chapterIndex('Attention, read on one voxel')].notice, /Most values sit at \+1 or −1/);
  assert.match(CHAPTERS[chapterIndex('Transplant a module')].notice, /One-shot, the robot hardly moves/);
});

test('the body search\'s "finetune" is every gene evolving, never "fine-tuned"; captions hold no statistics', () => {
  const bodies = figure('codesign-unseen');
  const caption = `${bodies.title}. ${bodies.read} ${bodies.paper}`;
  assert.match(caption, /finetune, started from the same module, every gene evolving with the body, its attention too/);
  assert.equal(caption.match(/\bfinetune,/g)?.length, 1, 'the label explained once');
  const chapter9 = CHAPTERS[chapterIndex('Which body for this brain?')];
  for (const [where, text] of [['the body search figure', caption], ['chapter 9', [...chapter9.text, chapter9.notice].join(' ')], ['the glossary', GLOSSARY]]) {
    assert.doesNotMatch(text, /fine-tuned along|\bfine-tuned with the body|finetune[^.;]*fine-tuned/i, `${where} calls the body search's finetune fine-tuned`);
  }
  assert.match(GLOSSARY, /fine-tune [^.]*the attention stays as it is/, 'the glossary\'s fine-tune is the button\'s');
  for (const f of FIGURES) {
    const words = `${f.title}. ${f.read} ${f.paper}`;
    assert.doesNotMatch(words, /\bHolm\b|\bp\s*(=\s*)?\d*\.\d|p-value|results page|middle body|\bseeds? \d/, `${f.id}: a caption in a newcomer's words`);
  }
  // Chapter 6's figure: its small print tests five runs, the claim is from ten; the caption says so.
  assert.match(figure('validation-biped').paper, /first five runs[^.]*"no difference detected" for every pair[^.]*too few[^.]*\. We then ran ten of each/);
});

test('chapter 5: Reveal waits for the pair\'s own finished run, in words that stay true; the question names what the key divides', async () => {
  const ex = taskOf('Evolution');
  const { rows, controller } = CHAPTERS[chapterIndex('Evolution')].setup;
  const bests = [{ generation: 0, fitness: 0.5 }, { generation: 1, fitness: 1 }, { generation: 2, fitness: 2 }];
  /** @param {object} run */
  const lab = (run) => /** @type {any} */ ({ latestRun: () => ({ bests: [], shape: '', controller: '', mode: '', running: false, ...run }) });
  const own = { shape: rows, controller, mode: 'evolve' };
  assert.equal(ex.wait?.(lab({})), EVOLVE_FIRST, 'no run yet: press Evolve first');
  assert.equal(ex.wait?.(lab({ ...own, mode: 'finetune', bests })), EVOLVE_FIRST, 'another chapter\'s run: press Evolve first');
  assert.equal(ex.wait?.(lab({ ...own, bests: bests.slice(0, 1), running: true })), RUN_GOING, 'its run going: wait');
  assert.equal(ex.wait?.(lab({ running: true })), RUN_GOING, 'a run going, before its generation 0 is in: wait');
  assert.equal(ex.wait?.(lab({ ...own, bests: bests.slice(0, 1) })), EVOLVE_FIRST, 'a run stopped at generation 0: evolve again');
  assert.equal(ex.wait?.(lab({ ...own, bests })), '', 'its run ended: reveal');
  for (const text of [EVOLVE_FIRST, RUN_GOING]) {
    assert.doesNotMatch(text, /still going|is running/, 'the message does not say the run is going: it stays on screen after the run ends');
    assert.match(text, /press Reveal again/);
  }
  assert.match(ex.ask, /the last generation's best brain walk than generation 0's best[^?]*\? Each is the fastest of its own generation[^.]*not the best so far/);
  const key = await ex.key(lab({ ...own, bests }));
  assert.match(key.shown, /\(4\.0 times\)/, 'the key divides the last generation\'s best by generation 0\'s');
});

test('chapter 10\'s question names the clock its key walks both robots with; chapter 2\'s Do does what its question asks', async () => {
  const yours = CHAPTERS[chapterIndex('Your turn')].setup;
  const first = CHAPTERS[0].setup;
  const ex = taskOf('Your turn');
  const gait1 = /** @type {{frequency: number, phase: number}} */ (first.gait);
  // The question says the biped is put on this chapter's clock, and what chapter 1's was.
  assert.match(ex.ask, /on this chapter's clock \(its f and φ are under the robot[^)]*\)\. Put chapter 1's biped [^:]*with this same clock:/);
  assert.ok(ex.ask.includes(`chapter 1's were f ${gait1.frequency} Hz, φ ${gait1.phase}`), ex.ask);
  /** @type {any[]} */ const walks = [];
  const page = { frequency: 0.5, phase: 0.25 }; // the page's default clock, this chapter's (no gait of its own)
  const lab = /** @type {any} */ ({ defaults: { quick: { seconds: 10 }, gait: page },
    walk: async (/** @type {any} */ w) => { walks.push(w); return { speed: walks.length }; } });
  const key = await ex.key(lab);
  const clock = yours.gait ?? page;
  assert.deepEqual(walks.map((w) => w.gait), [clock, clock], 'both walked on this chapter\'s clock');
  assert.deepEqual(walks.map((w) => w.rows), [yours.rows, first.rows]);
  assert.ok(key.why.includes(`f ${clock.frequency} Hz, φ ${clock.phase}`), key.why);
  const body = CHAPTERS[chapterIndex('A body')].task;
  assert.match(taskOf('A body').ask, /^Erase the third column of the biped/);
  assert.match(body, /^Erase the third column of the biped\b/, 'the Do starts with the question\'s cut, before any voxel is drawn');
});

test('the lesson plan, chapter 8 and docs/teaching.md say the same about a run\'s time; the plan links the teachers\' guide', () => {
  const teaching = readFileSync(path.join(ROOT, 'docs/teaching.md'), 'utf8');
  const chapter8 = CHAPTERS[chapterIndex('Transplant a module')].notice;
  for (const [where, text] of [['the lesson plan', lessonPlan()], ['chapter 8', chapter8], ['docs/teaching.md', teaching.replace(/\s+/g, ' ')]]) {
    assert.doesNotMatch(text, /a minute or (two|so)/, `${where}: a run's time as the page says it`);
    assert.ok(text.includes('under a minute on most computers'), `${where}: ${RUN_TIME}`);
  }
  assert.ok(lessonPlan().includes(RUN_TIME) && chapter8.includes(RUN_TIME), 'one set of words');
  const made = /** @type {any[]} */ ([]);
  const doc = /** @type {any} */ ({ createElement: (/** @type {string} */ tag) => { const el = { tag }; made.push(el); return el; } });
  const nodes = lessonPlanNodes(doc);
  const link = nodes.find((n) => typeof n !== 'string');
  assert.deepEqual(link, { tag: 'a', href: 'docs/teaching.html', target: '_blank', rel: 'noopener', textContent: GUIDE.text });
  assert.ok(existsSync(path.join(ROOT, GUIDE.href.replace(/\.html$/, '.md'))), 'the guide the link points to exists (docs/teaching.md, served as a web page)');
  assert.equal(nodes.map((n) => (typeof n === 'string' ? n : n.textContent)).join(''), lessonPlan(), 'the link\'s words are the plan\'s');
});
