// @ts-check
/**
 * Browser test of the teacher's way into the page, as a teacher new to it walks it (node
 * --test): the first screen has “For teachers” in its header, small beside Learn, at 1400 and
 * 420 px; it opens the 50-minute lesson, THE plan, with its way to the lesson's worksheet, the
 * full worksheet, the answer keys and the teachers' guide; the answer keys' sheet names the same
 * plan first and the two-lesson version only as its alternative; the lesson's worksheet prints
 * only the lesson's chapters and the challenge's box (page.pdf: fewer pages than the full one);
 * docs/teaching.md starts with the class's address and leaves the hosting to a later section,
 * and calls the challenge part of the lesson; chapter 10's “Do” does what its question asks;
 * chapter 5's “Do” box is not covered by the teacher's line at 1400 px.
 * Screenshots: teacher-front-1400.png, teacher-front-420.png, teacher-lesson-420.png,
 * teacher-chapter5-1400.png; PDFs: worksheet-lesson.pdf, worksheet-all.pdf.
 */
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { LESSON, LESSONS, lessonChapters, lessonPlan } from '../../www/classroom/lesson-plan.js';
import { CHAPTERS } from '../../www/tour/chapters.js';
import { exerciseOf } from '../../www/classroom/exercises.js';
import { ROOT, SCREENSHOTS, byTestId, openPage, start } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

/** A PDF's page count. @param {Buffer} pdf */
const pagesOf = (pdf) => (pdf.toString('latin1').match(/\/Type\s*\/Page[^s]/g) ?? []).length;

test('“For teachers” on the first screen opens the 50-minute lesson, with the worksheet, the keys and the guide', async () => {
  for (const [width, height] of [[1400, 900], [420, 860]]) {
    const { page, problems, context } = await openPage(env.browser, env.url, { width, height, touch: width < 800 });
    const entry = byTestId(page, 'teacher-open');
    await entry.waitFor();
    const box = await entry.boundingBox();
    assert.ok(box && box.y + box.height <= height && box.x >= 0 && box.x + box.width <= width, `on the first screen at ${width} px: ${JSON.stringify(box)}`);
    const learn = await byTestId(page, 'tour').boundingBox();
    assert.ok(learn && box.height <= learn.height && box.width < 130, `small, for the teacher (${JSON.stringify(box)} against Learn ${JSON.stringify(learn)})`);
    await page.screenshot({ path: path.join(SCREENSHOTS, `teacher-front-${width}.png`) });
    await entry.click();
    const sheet = byTestId(page, 'lesson');
    await sheet.waitFor();
    const text = String(await sheet.textContent());
    assert.ok(text.includes(`${LESSON.name}, for ${LESSON.who}`), 'the 50-minute lesson');
    assert.ok(text.includes('Class challenge'), 'ending with the class challenge');
    assert.ok(!/if you want one|First lesson \(45 min\)/.test(text), 'one plan, not two');
    const links = byTestId(page, 'lesson-links');
    for (const id of ['lesson-worksheet', 'lesson-worksheet-all', 'lesson-keys', 'lesson-guide']) assert.equal(await links.locator(`[data-testid="${id}"]`).isVisible(), true, `${id} at ${width} px`);
    const edges = await links.locator('button, a').evaluateAll((els) => els.map((e) => e.getBoundingClientRect().right));
    assert.ok(edges.every((r) => r <= width), `the links fit ${width} px: ${edges}`);
    const guide = await page.request.get(new URL(String(await byTestId(page, 'lesson-guide').getAttribute('href')), env.url).href);
    assert.equal(guide.status(), 200, 'the guide is served');
    if (width < 800) await page.screenshot({ path: path.join(SCREENSHOTS, `teacher-lesson-${width}.png`) });
    assert.deepEqual(problems, []);
    await context.close();
  }
});

test('the answer keys\' sheet names the 50-minute lesson first, the two lessons as its alternative; the guide says the same', async () => {
  const plan = lessonPlan();
  assert.match(plan, /^The plan: one lesson of 50 minutes .*chapters 1 to 7 and then the class challenge/);
  assert.ok(plan.indexOf('If you have two lessons') > 0, 'the two lessons, as an alternative');
  for (const l of LESSONS) assert.equal(l.steps.reduce((sum, s) => sum + s.minutes, 0), 45, `${l.name}: 45 minutes`);
  const titles = (/** @type {{what: string}[]} */ steps) => steps.map((s) => s.what).filter((w) => CHAPTERS.some((c) => c.title === w));
  assert.deepEqual(titles(LESSONS[0].steps), titles(LESSON.steps), 'the first of two lessons has the 50-minute lesson\'s chapters');
  assert.ok(LESSONS[1].steps.some((s) => s.what === 'Class challenge'), 'and the second its challenge');

  const guide = readFileSync(path.join(ROOT, 'docs/teaching.md'), 'utf8');
  const heads = [...guide.matchAll(/^## (.+)$/gm)].map((m) => m[1]);
  assert.equal(heads[0], 'An address for your class', 'a teacher\'s first section: the address for the class');
  assert.equal(heads[1], 'One lesson of 50 minutes', 'then THE plan');
  assert.equal(heads[heads.length - 1], 'For whoever hosts the site', 'the hosting last');
  assert.ok(heads.includes('If you have two lessons of 45 minutes'), 'the two lessons as an alternative');
  const hosting = guide.indexOf('## For whoever hosts the site');
  for (const word of ['make site', 'pages.yml', 'has not run yet', 'target/site']) assert.ok(guide.indexOf(word) > hosting, `“${word}” only for whoever hosts`);
  assert.ok(!/third lesson/.test(guide), 'the challenge is part of the lesson');
  assert.ok(guide.includes('*For teachers*'), 'the guide names the page\'s entry');

  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  await byTestId(page, 'teacher-open').click();
  await byTestId(page, 'lesson-keys').click();
  const keys = byTestId(page, 'teacher-keys');
  await keys.waitFor();
  const shown = String(await keys.locator('.sheet-plan').textContent());
  assert.ok(shown.startsWith('The plan: one lesson of 50 minutes'), `the keys' sheet: ${shown}`);
  assert.ok(!shown.includes('if you want one'));
  await keys.locator('[data-state="done"]').or(page.locator('[data-testid="teacher-keys"][data-state="done"]')).waitFor({ timeout: 120_000 });
  const key5 = String(await keys.locator('[data-testid="teacher-key"]').nth(4).textContent());
  console.log(`# chapter 5's key: ${key5}`);
  assert.match(key5, /in the study's run of .* evaluations.*what the class will see is nearer \d+\.\d times \(.*\), as the study's run stood after its first [\d,]+ evaluations/, 'the class\'s number beside the study\'s');
  assert.deepEqual(problems, []);
  await context.close();
});

test('the lesson\'s worksheet prints only the lesson\'s chapters and the challenge; the full one every chapter', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, {
    width: 1400, height: 900, init: () => { window.print = () => {}; } });
  /** @type {Record<string, number>} */
  const pages = {};
  for (const [id, name] of [['lesson-worksheet', 'lesson'], ['lesson-worksheet-all', 'all']]) {
    await byTestId(page, 'teacher-open').click();
    await byTestId(page, id).click();
    const sheet = byTestId(page, 'worksheet');
    await sheet.waitFor();
    await byTestId(page, 'worksheet-address').fill('https://school.example/robots/');
    const heads = await sheet.locator('.sheet-task h2').allTextContents();
    const expected = (name === 'lesson' ? lessonChapters() : CHAPTERS.map((_, i) => i)).map((i) => `Chapter ${i + 1}. ${CHAPTERS[i].title}`);
    assert.deepEqual(heads, expected, `the ${name} worksheet's chapters`);
    const links = await sheet.locator('.sheet-task .sheet-link').allTextContents();
    assert.deepEqual(links, expected.map((_, k) => `https://school.example/robots/?chapter=${(name === 'lesson' ? lessonChapters()[k] : k) + 1}`), 'each chapter\'s own link');
    assert.equal(await byTestId(page, 'worksheet-challenge').count(), 1, 'the challenge\'s box');
    await page.emulateMedia({ media: 'print' });
    const pdf = await page.pdf({ path: path.join(SCREENSHOTS, `worksheet-${name}.pdf`), format: 'A4', margin: { top: '15mm', bottom: '15mm', left: '15mm', right: '15mm' } });
    pages[name] = pagesOf(pdf);
    await page.emulateMedia({ media: 'screen' });
    await sheet.getByRole('button', { name: 'Close' }).click();
  }
  console.log(`# worksheet pages: ${JSON.stringify(pages)}`);
  assert.ok(pages.lesson < pages.all && pages.lesson <= 3, `the lesson's worksheet is shorter: ${JSON.stringify(pages)}`);
  assert.deepEqual(problems, []);
  await context.close();
});

test('the class\'s address typed once, in the lesson\'s sheet, is the one its worksheet prints', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, {
    width: 1400, height: 900, init: () => { window.print = () => {}; } });
  await byTestId(page, 'teacher-open').click();
  await byTestId(page, 'lesson').waitFor();
  await byTestId(page, 'lesson').locator('[data-testid="worksheet-address"]').fill('https://school.example/vsr/');
  await byTestId(page, 'lesson-worksheet').click();
  const sheet = byTestId(page, 'worksheet');
  await sheet.waitFor();
  assert.equal(await byTestId(page, 'worksheet').locator('[data-testid="worksheet-address"]').inputValue(), 'https://school.example/vsr/');
  const links = await sheet.locator('.sheet-task .sheet-link').allTextContents();
  assert.ok(links.length > 0 && links.every((l) => l.startsWith('https://school.example/vsr/?chapter=')), `the worksheet's links: ${links.join(' ')}`);
  assert.deepEqual(problems, []);
  await context.close();
});

test('chapter 10\'s “Do” does what its question asks; chapter 5\'s “Do” is clear of the teacher\'s line at 1400 px', async () => {
  const ten = CHAPTERS.findIndex((c) => c.title === 'Your turn');
  assert.match(String(exerciseOf(ten)?.ask), /faster or slower than the biped/);
  assert.match(CHAPTERS[ten].task, /table's speed.*biped.*compare/, 'the Do compares the table with the biped');
  assert.match(String(exerciseOf(ten)?.try), /biped/);

  const { page, problems, context } = await openPage(env.browser, `${env.url}?chapter=5`, { width: 1400, height: 900 });
  const task = page.locator('#tour-box .tour-task');
  await task.waitFor();
  await task.scrollIntoViewIfNeeded();
  const [t, line, body] = await Promise.all([task.boundingBox(), byTestId(page, 'tour-teacher').boundingBox(), page.locator('#tour-box .tour-body').boundingBox()]);
  assert.ok(t && line && body, 'all shown');
  assert.ok(t.y + t.height <= line.y && t.y + t.height <= body.y + body.height + 0.5, `the Do box (${JSON.stringify(t)}) ends above the teacher's line (${JSON.stringify(line)})`);
  await page.screenshot({ path: path.join(SCREENSHOTS, 'teacher-chapter5-1400.png') });
  assert.deepEqual(problems, []);
  await context.close();
});
