// @ts-check
/**
 * Browser test of the classroom (node --test): in every tour chapter a task asks before it
 * shows (Reveal waits for an answer; the chapter's “Notice” waits for the reveal), and the
 * reveal's numbers are the page's own (chapter 1's speeds are the viewer's, chapter 3's gene
 * gain is the gene count's); the teacher's answer keys agree with the students' reveals; the
 * worksheet holds every chapter's task and link and prints alone (page.pdf, and a screenshot
 * in print media), and until the reveal the module list's speeds and the study's figures and
 * findings are kept back; after a run, one button races its first, middle and last generations' bests;
 * no answer is in the text a pair reads before its reveal (the tour's box, the glossary; the
 * chapters' own words: giveaway.test.mjs); chapter 5 reveals only from the pair's own run;
 * the study's figure captions hold no statistics; the lesson plan's guide is served;
 * the simple-words switch hides formulas and statistics, says labels in plain words, hides a
 * drawing's code and explains terrain names and glossary words where they stand (and the
 * expert's words come back when it is off), and stays on after a reload, and the
 * glossary explains the issue's newcomer words, linked where they appear, with the voxel's
 * width the core's (the plain results: results.test.mjs; the class challenge: challenge.test.mjs). Screenshots:
 * screenshots/classroom-*.png, worksheet.pdf.
 */
import assert from 'node:assert/strict';
import { readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { EVOLVE_FIRST, EXERCISES, TASKS, exerciseOf } from '../../www/classroom/exercises.js';
import { GUIDE, LESSONS } from '../../www/classroom/lesson-plan.js';
import { EXAMPLE_CODE } from '../../www/classroom/challenge/code.js';
import { CHAPTERS, RUN_TIME } from '../../www/tour/chapters.js';
import { ROOT, SCREENSHOTS, byTestId, figure, openPage, screenshot, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

/** @param {import('playwright-core').Page} page */
async function ready(page) {
  await page.locator('#tour-box[data-state="ready"]').waitFor({ timeout: 20_000 });
}

/**
 * Whether a chapter's task can be asked now: a chapter about the study's brain for any body asks only once pretrained/'s manifest
 * lists it (until then it says “not yet”: tour-any-body.test.mjs tests both states with a routed manifest).
 */
const STUDY_ANY_BODY = (JSON.parse(readFileSync(path.join(ROOT, 'pretrained', 'manifest.json'), 'utf8')).modules ?? [])
  .some((/** @type {{controller: string}} */ m) => m.controller === 'attention-any');
/** @param {number} i a chapter's index (0-based) */
const asked = (i) => exerciseOf(i) !== null && (STUDY_ANY_BODY || !CHAPTERS[i].setup.anyBody);

const WORDS = ['zero', 'one', 'two', 'three', 'four', 'five', 'six', 'seven', 'eight', 'nine', 'ten'];
/**
 * What would state a revealed answer in the text read before it: a number of genes, weights or
 * values (in figures or words), and the reviewer's cases (most values at ±1, a one-shot that walks badly).
 * @param {string} shown the page's answer
 */
function giveaway(shown) {
  const n = Math.round(Number(/^(?:about )?([\d.]+) (?:genes|of 16)/.exec(shown)?.[1] ?? NaN));
  const number = Number.isFinite(n) ? `\\b(${n}|${WORDS[n] ?? n}) (genes|weights|output weights)\\b|\\b${n} of 16\\b|` : '';
  return new RegExp(`${number}\\bmost (squares|values) (sit|are) at|walks? badly|hardly moves|\\b32 (genes|numbers)\\b`, 'i');
}

/** A tiny run of chapter 5's (its Reveal answers only from the pair's own run). @param {import('playwright-core').Page} page */
async function tinyRun(page) {
  for (const [key, value] of Object.entries({ population: '4', seconds: '2', budget: '40', seed: '3', workers: '2' })) {
    await page.locator(`#run-${key}`).fill(value);
  }
  await byTestId(page, 'evolve').click();
  await waitForText(page, 'run-status', /^finished$/, 90_000);
}

/** Answers chapter `n`'s task (the first choice, or the number 4) and reveals it. @param {import('playwright-core').Page} page @param {number} n */
async function answerAndReveal(page, n) {
  const task = byTestId(page, 'tour-exercise');
  assert.equal(await task.count(), 1, `chapter ${n}: one task`);
  assert.equal(await byTestId(page, 'tour-reveal').isDisabled(), true, `chapter ${n}: no reveal before an answer`);
  assert.equal(await page.locator('.tour-notice').isVisible(), false, `chapter ${n}: the Notice waits for the reveal`);
  const { figure: shows, setup } = CHAPTERS[n - 1];
  if (shows) assert.equal(await page.locator('#tour-body figure').isVisible(), false, `chapter ${n}: the study's figure waits for the reveal`);
  if (setup.race) assert.equal(await page.locator('#race-panel').getAttribute('data-state'), 'waiting', `chapter ${n}: the race waits at the start line`);
  // Unless its question is not about speeds (chapter 9's genes), nor does the rest of the page give it away: no speed in the module list, the study's figures and findings kept back.
  const speeds = () => page.locator('#module option').evaluateAll((os) => os.filter((o) => /m\/s/.test(o.textContent + o.title)).length);
  // A number kept back is not readable, and something stands in its place ("hidden", "?"), not an empty grey box.
  const keptBack = (/** @type {Element} */ e) => getComputedStyle(e).fontSize === '0px' && /^"(hidden|\?)"$/.test(getComputedStyle(e, '::after').content);
  const covered = () => page.locator('#driver .speed-figure').evaluateAll((els, fn) => els.map((e) => Function(`return ${fn}`)()(e)), keptBack.toString());
  if (exerciseOf(n - 1)?.speedsShown) assert.ok(await speeds() > 0, `chapter ${n}: a question about genes holds no speed back`);
  else {
    assert.equal(await speeds(), 0, `chapter ${n}: the module list keeps its speeds back`);
    assert.ok(await page.locator('#robot-speed').evaluate((e, fn) => Function(`return ${fn}`)()(e), keptBack.toString()), `chapter ${n}: so does the viewer, saying so`);
    assert.doesNotMatch(String(await page.locator('#module-details').textContent()), /m\/s/, `chapter ${n}: so do its details`);
    assert.ok((await covered()).every(Boolean), `chapter ${n}: the speeds in "Driven by" are covered`);
    assert.equal(await page.locator('#attention-why').isVisible(), false, `chapter ${n}: why most attention values are ±1 waits too`);
    for (const [shown, kept] of [['#study-image', '#study-panel'], ['#results-plain-body', '#results-plain']]) {
      assert.equal(await page.locator(shown).isVisible(), false, `chapter ${n}: ${shown} waits for the reveal`);
      assert.equal(await page.locator(`${kept} [data-testid="answer-held-note"]`).isVisible(), true, `chapter ${n}: ${kept} says why`);
    }
  }
  if (exerciseOf(n - 1)?.choices) await task.locator('input[type=radio]').first().check();
  else await task.locator('input[type=number]').fill('4');
  // What the pair reads before the reveal: the tour's box, and the glossary, open beside it.
  const before = `${await page.locator('#tour-box').innerText()} ${await page.locator('#glossary dl').textContent()}`;
  await byTestId(page, 'tour-reveal').click();
  if (exerciseOf(n - 1)?.wait) { // chapter 5: never graded against another run than the pair's own
    await waitForText(page, 'tour-box', /Press Evolve first/);
    assert.equal(await byTestId(page, 'tour-answer').textContent(), EVOLVE_FIRST);
    assert.notEqual(await task.getAttribute('data-state'), 'revealed', `chapter ${n}: nothing revealed before the run`);
    await tinyRun(page);
    await byTestId(page, 'tour-reveal').click();
  }
  await page.locator('[data-testid="tour-exercise"][data-state="revealed"]').waitFor({ timeout: 60_000 });
  const text = (await byTestId(page, 'tour-answer').locator('p').allTextContents()).join(' ');
  const shown = /The page's answer: (.*?)\. /.exec(text)?.[1] ?? '';
  const found = giveaway(shown).exec(before);
  assert.equal(found, null, `chapter ${n}: “${found?.[0]}” read before the reveal gives its answer (${shown}) away`);
  assert.match(text, /You said: .* The page's answer: /, `chapter ${n}: the answer beside the student's`);
  assert.equal(await page.locator('.tour-notice').isVisible(), true, `chapter ${n}: the Notice after the reveal`);
  if (shows) assert.equal(await page.locator('#tour-body figure').isVisible(), true, `chapter ${n}: the figure after the reveal`);
  if (setup.race) await page.locator('#race-panel:not([data-state="waiting"])').waitFor({ timeout: 10_000 });
  assert.ok(await speeds() > 0, `chapter ${n}: the module list's speeds after the reveal`);
  await byTestId(page, 'study').scrollIntoViewIfNeeded(); // the study panel reads its files once in sight
  await page.waitForFunction(() => (/** @type {HTMLImageElement} */ (document.getElementById('study-image'))).naturalWidth > 0);
  assert.equal(await page.locator('#study-image').isVisible(), true, `chapter ${n}: the study's figure after the reveal`);
  assert.equal(await page.locator('#robot-speed').isVisible(), true, `chapter ${n}: the viewer's speed after the reveal`);
  assert.ok((await covered()).every((c) => !c), `chapter ${n}: the speeds in "Driven by" after the reveal`);
  assert.equal(await page.locator('[data-testid="answer-held-note"]:visible').count(), 0, `chapter ${n}: no note after the reveal`);
  return text;
}

test('every chapter asks before it shows: an answer, then the reveal with why', async () => {
  assert.deepEqual(EXERCISES, TASKS, 'every task\'s chapter is in the tour');
  const without = CHAPTERS.filter((c, i) => !exerciseOf(i)).map((c) => c.title);
  console.log(`# chapters without a task: ${JSON.stringify(without)}`);
  assert.deepEqual(without, [], 'a task in every chapter');
  for (let n = 1; n <= CHAPTERS.length; n++) {
    if (!asked(n - 1)) continue;
    const { page, problems } = await openPage(env.browser, `${env.url}?chapter=${n}`, { width: 1400, height: 900 });
    await ready(page);
    const text = await answerAndReveal(page, n);
    console.log(`# chapter ${n}: ${text}`);
    if (CHAPTERS[n - 1].title === 'One small brain in every voxel') {
      const genes = await figure(page, 'param-count');
      assert.match(text, new RegExp(`The page's answer: 4 genes\\..*${genes} genes for 10 voxels`), 'chapter 3: the gene count the page shows');
    }
    if (CHAPTERS[n - 1].title === 'Evolution') assert.match(text, /From this page's latest run: generation 0's best walked/, 'chapter 5: from the pair\'s run');
    if (CHAPTERS[n - 1].title === 'Your turn') { // the key walks both on the clock the question names: the one under the robot
      const [frequency, phase] = [await page.locator('#frequency').inputValue(), await page.locator('#phase').inputValue()];
      assert.ok(text.includes(`phase gait (f ${frequency} Hz, φ ${phase.replace('-', '−')})`), `chapter ${n}: the clock under the robot (f ${frequency}, φ ${phase}): ${text}`);
    }
    if (n === 1) { // the chapter 1 that the exercises name
      // The speed quoted for φ 1.5 is the one the viewer shows when its episode ends.
      await page.waitForFunction(() => document.getElementById('robot-speed')?.dataset.ended === 'true', undefined, { timeout: 40_000 });
      const shown = await figure(page, 'robot-speed');
      const quoted = Number(/([-\d.]+) m\/s at φ 1\.5/.exec(text)?.[1]);
      assert.equal(quoted, Number(shown.toFixed(2)), `chapter 1: the reveal's speed is the viewer's (${shown})`);
      // In the tour the walk holds where its speed was measured, and says how to go on.
      await waitForText(page, 'sim-time', /episode is over; Play walks on, Restart walks it again/);
      const held = Number(await page.locator('#sim-time').getAttribute('data-value'));
      // Thirty frames drawn (the viewer steps once a frame: a clock that ran on would have moved), not a time a busy machine may not draw in.
      await page.evaluate(() => new Promise((resolve) => { let frames = 0; const next = () => (++frames >= 30 ? resolve(undefined) : requestAnimationFrame(next)); requestAnimationFrame(next); }));
      assert.equal(Number(await page.locator('#sim-time').getAttribute('data-value')), held, 'the clock stands at the episode\'s end');
      await page.locator('#sim-restart').click();
      await page.waitForFunction(() => Number(document.getElementById('sim-time')?.dataset.value) < 5, undefined, { timeout: 10_000 });
    }
    if (n === 1 || n === 5) await page.screenshot({ path: path.join(SCREENSHOTS, `classroom-reveal-${n}.png`) });
    assert.deepEqual(problems, [], `chapter ${n}`);
    await page.context().close();
  }
});

test('the teacher\'s answer keys: every chapter\'s, the same as a student\'s reveal', async () => {
  const { page, problems } = await openPage(env.browser, `${env.url}?chapter=2`, { width: 1400, height: 900 });
  await ready(page);
  const student = await answerAndReveal(page, 2);
  assert.equal(await byTestId(page, 'teacher-keys-open').isVisible(), false, 'the keys are folded away from a student');
  await byTestId(page, 'tour-teacher').click();
  await byTestId(page, 'teacher-keys-open').click();
  const keys = byTestId(page, 'teacher-keys');
  await keys.waitFor();
  await page.locator('[data-testid="teacher-keys"][data-state="done"]').waitFor({ timeout: 120_000 });
  const rows = await byTestId(page, 'teacher-key').allTextContents();
  assert.equal(rows.length, CHAPTERS.length);
  for (const [i, row] of rows.entries()) {
    if (asked(i)) assert.match(row, /^Answer: /, `chapter ${i + 1}: ${row}`);
    else if (exerciseOf(i)) assert.match(row, /: not yet: the study is still training it\. Its task is not asked yet\.$/, `chapter ${i + 1}: ${row}`);
  }
  const shown = /The page's answer: (.*?)\. The page's check/.exec(student)?.[1] ?? '';
  assert.ok(shown.length > 0);
  assert.ok(rows[1].startsWith(`Answer: ${shown}.`), `the key of chapter 2 is the student's reveal: ${rows[1]} / ${shown}`);
  assert.match(rows[2], /^Answer: 4 genes\./);
  const plan = String(await keys.locator('.sheet-plan').textContent());
  assert.match(plan, /^The plan: one lesson of 50 minutes .*If you have two lessons of 45 minutes instead.*First lesson \(45 min\): Open the page.*; chapter 1 \(A voxel and its colours\), 5 min;/, `the 50-minute lesson first, the two lessons as its alternative: ${plan}`);
  assert.ok(plan.includes(`each take ${RUN_TIME}`), 'a run\'s time as chapter 8 and docs/teaching.md say it');
  const guide = await page.request.get(new URL(GUIDE.href, env.url.replace(/\/?$/, '/')).href);
  assert.equal(guide.status(), 200, `the teachers' guide the plan links is served (${GUIDE.href})`);
  // docs/teaching.md's table says the same plan.
  const table = [...readFileSync(path.join(ROOT, 'docs/teaching.md'), 'utf8').matchAll(/^\| (First|Second) lesson \| (.+?) \| (\d+) \|/gm)]
    .map((m) => `${m[1]} lesson: ${m[2]}, ${m[3]}`);
  assert.deepEqual(table, LESSONS.flatMap((l) => l.steps.map((s) => `${l.name}: ${s.what}, ${s.minutes}`)), 'docs/teaching.md gives the page\'s plan');
  await byTestId(page, 'teacher-keys').screenshot({ path: path.join(SCREENSHOTS, 'classroom-keys-sheet.png') });
  await screenshot(page, 'classroom-keys.png');
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('Print worksheet: every chapter\'s task, room to write and its link, printed alone', async () => {
  const { page, problems } = await openPage(env.browser, `${env.url}?chapter=1`, {
    width: 1400, height: 900, init: () => { window.print = () => { /** @type {any} */ (window).printed = true; }; } });
  await ready(page);
  await byTestId(page, 'tour-teacher').click();
  await byTestId(page, 'worksheet-open').click();
  const sheet = byTestId(page, 'worksheet');
  await sheet.waitFor();
  // Opened at 127.0.0.1, its links would open on no student's device: the sheet says so and
  // waits for the class's address before printing.
  const address = byTestId(page, 'worksheet-address');
  assert.equal(await address.inputValue(), `${env.url}/`.replace(/\/\/$/, '/'));
  assert.match(String(await byTestId(page, 'worksheet-address-note').textContent()), /opens only on this computer/);
  assert.equal(await page.evaluate(() => /** @type {any} */ (window).printed), undefined, 'no print dialog yet');
  await address.fill('not an address');
  assert.match(String(await byTestId(page, 'worksheet-address-note').textContent()), /is not an address/);
  await address.fill('https://class.example.org/vsr/?chapter=4#x');
  assert.equal(await byTestId(page, 'worksheet-address-note').isVisible(), false, 'a class address: no note');
  await sheet.getByRole('button', { name: 'Print', exact: true }).click();
  await page.waitForFunction(() => /** @type {any} */ (window).printed === true);
  const tasks = sheet.locator('.sheet-task');
  assert.equal(await tasks.count(), CHAPTERS.length);
  for (let i = 0; i < CHAPTERS.length; i++) {
    const text = String(await tasks.nth(i).textContent());
    assert.ok(text.includes(CHAPTERS[i].title), `chapter ${i + 1}'s title`);
    assert.ok(text.includes(exerciseOf(i)?.ask ?? CHAPTERS[i].task), `chapter ${i + 1}'s task`);
    assert.ok(text.includes(`https://class.example.org/vsr/?chapter=${i + 1}`) && !text.includes('#x'), `chapter ${i + 1}'s link at the class's address: ${text}`);
    assert.equal(await tasks.nth(i).locator('.sheet-write').count(), 1, 'room to write');
  }
  // The class challenge's box: the short code a letter a box, in the code's groups of four, with the page's real example.
  const box = byTestId(page, 'worksheet-challenge');
  assert.match(String(await box.textContent()), new RegExp(`^Class challenge: my robotAfter “Share link”, my page shows my robot's short code \\(like ${EXAMPLE_CODE}\\)\\. I copy it here`));
  assert.equal(await box.locator('.sheet-code-box').count(), 16, 'sixteen boxes, four groups of four');
  const boxSize = await box.locator('.sheet-code-box').first().boundingBox();
  assert.ok(boxSize && boxSize.width >= 20 && boxSize.height >= 24, `a box a hand can write a letter in: ${JSON.stringify(boxSize)}`);
  await page.emulateMedia({ media: 'print' });
  assert.equal(await page.locator('main').isVisible(), false, 'printed, the playground is away');
  assert.equal(await page.locator('#tour-box').isVisible(), false, 'and the tour');
  assert.equal(await sheet.isVisible(), true, 'the worksheet prints');
  await page.screenshot({ path: path.join(SCREENSHOTS, 'classroom-worksheet-print.png'), fullPage: true });
  assert.equal(await box.isVisible(), true, 'the challenge box prints');
  await box.screenshot({ path: path.join(SCREENSHOTS, 'worksheet-challenge-box.png') });
  const pdf = path.join(SCREENSHOTS, 'worksheet.pdf');
  await page.pdf({ path: pdf, format: 'A4', margin: { top: '15mm', bottom: '15mm', left: '15mm', right: '15mm' } });
  const bytes = readFileSync(pdf, 'latin1');
  const pages = (bytes.match(/\/Type\s*\/Page[^s]/g) ?? []).length;
  console.log(`# worksheet.pdf: ${pages} pages, ${statSync(pdf).size} bytes`);
  assert.ok(pages >= 2 && pages <= 6, `a few pages: ${pages}`);
  await page.emulateMedia({ media: 'screen' });
  await page.getByRole('button', { name: 'Close' }).click();
  assert.equal(await sheet.count(), 0);
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('after a run, one button races its first, middle and last generations side by side', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1400, height: 1000 });
  assert.equal(await byTestId(page, 'race-first-last').isDisabled(), true, 'no run yet');
  for (const [key, value] of Object.entries({ population: '4', seconds: '2', budget: '40', seed: '3', workers: '2' })) {
    await page.locator(`#run-${key}`).fill(value);
  }
  await byTestId(page, 'evolve').click();
  await waitForText(page, 'run-status', /^finished$/, 90_000);
  const last = await figure(page, 'run-generation');
  await byTestId(page, 'race-first-last').click();
  await page.waitForFunction(() => document.querySelectorAll('[data-testid="race-robot"]').length === 3);
  const names = await page.locator('.race-name').allTextContents();
  assert.match(names[0], /generation 0's best/);
  assert.match(names[1], new RegExp(`generation ${Math.floor(last / 2)}'s best`));
  assert.match(names[2], new RegExp(`generation ${last}'s best`));
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid="race-speed"]')]
    .every((o) => Number(/** @type {HTMLElement} */ (o).dataset.time) > 2), undefined, { timeout: 30_000 });
  await byTestId(page, 'race').screenshot({ path: path.join(SCREENSHOTS, 'classroom-first-last.png') });
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('simple words: formulas and statistics hidden, kept after a reload; the newcomer\'s words explained', async () => {
  const { page, problems } = await openPage(env.browser, `${env.url}?chapter=6`, { width: 1400, height: 900 });
  await ready(page);
  await answerAndReveal(page, 6); // the figure shows after the reveal
  // Its caption in a newcomer's words, simple words or not: no statistics (they stay folded in
  // “What our study found”), and the five runs drawn told apart from the ten tested.
  const caption = String(await page.locator('#tour-box figcaption').innerText());
  assert.doesNotMatch(caption, /\bp\b \d|Holm|results page/, `the figure's caption: ${caption}`);
  assert.match(caption, /only our first five runs[^.]*"no difference detected"[^.]*too few[^.]*\. We then ran ten of each/);
  await byTestId(page, 'simple-words').check();
  await page.reload();
  await waitForText(page, 'status', /voxels/);
  assert.equal(await byTestId(page, 'simple-words').isChecked(), true, 'kept');
  assert.equal(await page.locator('#attention-reader details.formula').evaluate((el) => getComputedStyle(el).display), 'none');
  assert.equal(await page.locator('#results-plain details.stats').isVisible(), false);
  // Labels in plain words where they have them, the expert's figures hidden (issue 46's list: f (Hz), φ (rad / column), ...).
  const labels = () => page.evaluate(() => [...document.querySelectorAll('[data-simple]')]
    .map((e) => ({ text: e.textContent, simple: /** @type {HTMLElement} */ (e).dataset.simple, expert: /** @type {HTMLElement} */ (e).dataset.expert })));
  const simple = await labels();
  assert.ok(simple.every((l) => l.text === l.simple), `every label in its plain words: ${JSON.stringify(simple)}`);
  for (const words of ['The drawing as text (1: a voxel)', 'beats per second', 'delay from column to column', 'Training hills (new ones every walk)',
    'rows: the reading that asks; columns: the readings it listens to (area, vx, vy, touch)', 'Save this run (a file)', 'Open a run saved before (its file)']) {
    assert.ok(simple.some((l) => l.text === words), `simple words say “${words}”`);
  }
  for (const expert of ['#engine-rate', '#run-workers']) assert.equal(await page.locator(expert).isVisible(), false, `${expert} hidden in simple words`);
  // What the page writes as it goes: a drawing's code gone (the status, the module's details), a terrain's name and a glossary word explained where they stand.
  await page.waitForFunction(() => /rows 1111-1111-1001/.test(document.getElementById('module-details')?.textContent ?? ''));
  // The module's training terrain is written (and marked) once its run file has loaded: wait for it, on a busy machine too.
  await page.waitForFunction(() => [...document.querySelectorAll('#robot-speed [data-explain], #speed-note [data-explain]')].some((e) => e.textContent === 'hilly-1-10'));
  const marked = await page.evaluate(() => ({
    hidden: [...document.querySelectorAll('#shape-status .simpler.expert, #module-details .simpler.expert')].map((e) => [e.textContent, getComputedStyle(e).display]),
    explained: [...document.querySelectorAll('#robot-speed [data-explain], #speed-note [data-explain], #param-count a.term[data-explain]')]
      .map((e) => [e.textContent, getComputedStyle(e, '::after').content]),
  }));
  assert.deepEqual(marked.hidden, [[' · 1111-1111-1001', 'none'], [' (rows 1111-1111-1001)', 'none']], 'the drawing\'s code is gone');
  for (const [word, after] of [['hilly-1-10-0', 'the same hills every time'], ['hilly-1-10', 'new hills drawn for every walk'], ['bias', 'one more number, added in']]) {
    assert.ok(marked.explained.some(([text, shown]) => text === word && String(shown).includes(after)), `${word} explained: ${JSON.stringify(marked.explained)}`);
  }
  await byTestId(page, 'simple-words').uncheck();
  const expert = await labels();
  assert.ok(expert.every((l) => l.text === l.expert), 'the expert\'s words back');
  for (const words of ['Rows (top first)', 'f (Hz)', 'φ (rad / column)', 'Training terrain', 'rows: query, columns: key (area, vx, vy, touch)', 'Export run', 'Import run file']) {
    assert.ok(expert.some((l) => l.text === words), `the expert's “${words}”`);
  }
  assert.equal(await page.locator('#shape-status').innerText(), '10 voxels · 1111-1111-1001', 'the code back');
  // The speed line is written again every moment: find it and read its style in one turn of the page (a located span may be gone by the time it is read).
  const explained = () => page.evaluate(() => {
    const e = document.querySelector('#robot-speed [data-explain]');
    return e ? getComputedStyle(e, '::after').content : 'no explained word';
  });
  await page.waitForFunction(() => document.querySelector('#robot-speed [data-explain]') !== null);
  assert.equal(await explained(), 'none', 'no explanation for the expert');
  await byTestId(page, 'simple-words').check();

  // The glossary explains the words, and a word in the page links to its entry.
  const glossary = String(await page.locator('#glossary dl').textContent());
  for (const word of ['VSR', 'GECCO', 'MLP', 'network', 'weights', 'bias', 'tanh', 'softmax', 'dot product', 'saturate', 'a, b, c, d', 'Holm', 'IQR', 'JSON', '20000 + 10000']) {
    assert.ok(glossary.includes(word), `the glossary explains ${word}`);
  }
  const side = Number(/VOXEL_SIDE: f64 = ([\d.]+);/.exec(readFileSync(path.join(ROOT, 'crate/engine/src/simulation/constants.rs'), 'utf8'))?.[1]);
  assert.match(glossary, new RegExp(`voxel[^.]*${side} m wide`), `a voxel's width is the core's (${side} m)`);
  await ready(page);
  await page.locator('#tour-close').click(); // the tour points at its controls no more
  await screenshot(page, 'classroom-simple-words.png');
  // A word of the expert's view links to its entry (simple words hides the header's GECCO).
  assert.equal(await page.locator('header a.term[href="#g-gecco"]').isVisible(), false, 'no GECCO in simple words');
  await byTestId(page, 'simple-words').uncheck();
  await page.locator('header a.term[href="#g-gecco"]').click();
  assert.equal(await page.locator('#glossary').getAttribute('open'), '');
  await page.waitForFunction(() => { const r = document.getElementById('g-gecco')?.getBoundingClientRect(); return r && r.top >= 0 && r.bottom <= innerHeight; });
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('numbers that agree: the race says how long it lasts, the budget and the modules\' 30,100, who talks, a chapter\'s rows', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  const seconds = await page.locator('#race-seconds').inputValue();
  const explain = String(await page.locator('#race-panel .explain').textContent());
  assert.doesNotMatch(explain, /one\s+training episode/, 'the race does not claim a training episode\'s length');
  assert.match(explain, new RegExp(`\\(${seconds} s`), `the race says the ${seconds} s it runs`);
  const modules = await byTestId(page, 'pretrained').locator('option').allTextContents();
  const glossary = String(await page.locator('#glossary').textContent());
  if (modules.some((m) => /30,100/.test(m))) assert.match(glossary, /30,000 evaluations counted 30,100/, 'the 30,100 of the modules is explained');
  assert.match(glossary, /20,000 evaluations on its first body, then fine-tuned 10,000/, 'the figures\' (20000 + 10000) is explained');
  assert.match(String(await page.locator('header p').textContent()), /no voxel talks to another \(in one of the brains it is compared with, mlp-comm, they do\)/);
  const attention = CHAPTERS.find((c) => c.title === 'Attention, read on one voxel');
  assert.doesNotMatch(String(attention?.notice), /stay there/, 'chapter 4 no longer says the values stay');
  assert.deepEqual(problems, []);
  await page.context().close();
});
