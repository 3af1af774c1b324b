// @ts-check
/**
 * Browser test of issue 46's third part as a class reads it (node --test): in simple words,
 * chapters 4 and 6 are told in short sentences and everyday words (and the expert's words come
 * back with the switch off); the words a 14-year-old did not know are explained where they
 * stand or gone from the simple view; a number that could seem to disagree says which
 * measurement it is (the module list's mean over ten new terrains, a race's own walk); the
 * attention maps show at once after a voxel is added while the robot is held; the teachers'
 * lesson table fits 420 px (the page's sheet and the guide), with nothing covering it.
 * Screenshots: simple-words-4.png, simple-words-6.png, simple-words-held-maps.png,
 * simple-words-lesson-420.png, simple-words-guide-420.png; PDFs: simple-words-lesson.pdf,
 * simple-words-guide.pdf.
 */
import assert from 'node:assert/strict';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { CHAPTERS } from '../../www/tour/chapters.js';
import { SCREENSHOTS, byTestId, openBare, openPage, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

const SIMPLE = () => localStorage.setItem('vsr-playground/simple-words', '1');

/** What a word's explanation shows after it (its ::after), as a person sees it. @param {import('playwright-core').Page} page @param {string} selector */
const after_ = (page, selector) => page.locator(selector).first().evaluate((e) => getComputedStyle(e, '::after').content);

/** @param {import('playwright-core').Page} page */
const chapterReady = (page) => page.waitForFunction(() => document.getElementById('tour-box')?.dataset.state === 'ready', undefined, { timeout: 60_000 });

test('chapters 4 and 6 in simple words: the same facts in short sentences; the expert\'s words back with the switch off', async () => {
  for (const n of [4, 6]) {
    const { page, problems, context } = await openPage(env.browser, `${env.url}?chapter=${n}`, { width: 1400, height: 900, init: SIMPLE });
    await chapterReady(page);
    const chapter = CHAPTERS[n - 1];
    const simple = /** @type {NonNullable<typeof chapter.simple>} */ (chapter.simple);
    assert.ok(simple, `chapter ${n} has simple words`);
    const shown = await page.locator('#tour-body').innerText();
    for (const t of [...simple.text, simple.task]) assert.ok(shown.includes(t.slice(0, 60)), `chapter ${n} says in simple words: ${t.slice(0, 60)}`);
    for (const t of [...chapter.text, chapter.task]) assert.ok(!shown.includes(t.slice(0, 60)), `chapter ${n} hides the expert's: ${t.slice(0, 60)}`);
    // Short sentences: none over 30 words in the simple text.
    for (const sentence of [...simple.text, simple.task, simple.notice].join(' ').split(/(?<=[.?!])\s+/)) {
      assert.ok(sentence.split(/\s+/).length <= 30, `a short sentence: ${sentence}`);
    }
    assert.doesNotMatch(shown, /\bquery\b|\bkeys?\b|attention matrix/, `chapter ${n}: no query, key or matrix in simple words`);
    await page.screenshot({ path: path.join(SCREENSHOTS, `simple-words-${n}.png`) });
    await byTestId(page, 'simple-words').uncheck();
    const expert = await page.locator('#tour-body').innerText();
    assert.ok(expert.includes(chapter.text[0].slice(0, 60)), `chapter ${n}: the expert's words back`);
    assert.ok(!expert.includes(simple.text[0].slice(0, 60)), `chapter ${n}: the simple words gone`);
    assert.deepEqual(problems, []);
    await context.close();
  }
});

test('simple words: the words a class did not know are explained where they stand, or gone; the numbers say which measurement they are', async () => {
  const { page, problems, context } = await openPage(env.browser, `${env.url}?chapter=6`, { width: 1400, height: 900, init: SIMPLE });
  await chapterReady(page);
  // Explained where they appear (in brackets after them).
  for (const [selector, words] of [
    ['header dfn:has-text("fine-tune")', 'train a little more'], ['header a.term[href="#g-mlp"]', 'voxels send messages'],
    ['label:has(#run-population) > span', 'brains tried in each round'], ['.figures span.speed > span', 'the average since this walk began'],
    ['.figures span:has(#robot-v) > span', 'only the last second'],
  ]) {
    assert.match(await after_(page, selector), new RegExp(words), `${selector} explained`);
  }
  // Said in plain words, or hidden.
  assert.equal(await page.locator('header h1 small').innerText(), 'robots made of soft blocks');
  assert.equal(await page.locator('label:has(#preset) > span').innerText(), 'Example bodies');
  assert.equal(await page.locator('header a.term[href="#g-vsr"]').isVisible(), false, 'VSR, voxel-based: gone from the simple view');
  assert.equal(await page.locator('#attention-matrix th.corner').innerText(), 'asks ↓ · listens to →');
  await page.waitForFunction(() => /genes/.test(document.getElementById('param-count')?.textContent ?? ''));
  assert.equal(await page.locator('#param-count .gene-detail').isVisible(), false, 'the genes\' breakdown is the expert\'s');
  await page.waitForFunction(() => document.querySelector('#param-count [data-explain]') !== null);
  assert.match(await after_(page, '#param-count [data-explain]'), /the numbers evolution tunes/, '73 genes explained');
  // The module list's speed says it is the mean over ten new terrains.
  await byTestId(page, 'tour-exercise').locator('input[type=radio]').first().check();
  await byTestId(page, 'tour-reveal').click();
  await page.waitForFunction(() => [...document.querySelectorAll('#module option')].some((o) => /m\/s/.test(o.textContent ?? '')));
  const options = await page.locator('#module option').evaluateAll((os) => os.map((o) => o.textContent ?? '').filter((t) => /m\/s/.test(t)));
  assert.ok(options.length > 3 && options.every((t) => /\d m\/s (average over 10 new terrains|in training)$/.test(t)), `each listed speed says what it is: ${options.join(' | ')}`);
  // The race's speeds say they are this race's, and its brains what they are.
  await waitForText(page, 'race-status', /Speeds: this race only \(one walk on this ground\), not the list's average over 10 new terrains/);
  await page.waitForFunction(() => document.querySelector('#race-lanes [data-explain]') !== null);
  const names = await page.locator('#race-lanes [data-explain]').evaluateAll((es) => es.map((e) => [e.textContent, getComputedStyle(e, '::after').content]));
  assert.ok(names.some(([t, a]) => t === 'mlp-comm' && /voxels send messages/.test(String(a))), `mlp-comm explained in the race: ${JSON.stringify(names)}`);
  await page.locator('#race-panel').screenshot({ path: path.join(SCREENSHOTS, 'simple-words-race.png') });
  assert.deepEqual(problems, []);
  await context.close();
});

test('the attention maps show at once after a voxel is added to the held robot', async () => {
  const { page, problems, context } = await openPage(env.browser, `${env.url}?chapter=4`, { width: 1400, height: 900 });
  await chapterReady(page);
  await page.locator('#tour-close').click();
  await page.locator('#sim-hold').click();
  await page.waitForFunction(() => document.body.dataset.running === 'false', undefined, { timeout: 30_000 });
  const box = await page.evaluate(async () => {
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const canvas = /** @type {HTMLCanvasElement} */ (document.querySelector('[data-testid="viewer"]'));
    const data = canvas.getContext('2d')?.getImageData(0, 0, canvas.width, canvas.height).data ?? [];
    const b = { left: Infinity, right: -Infinity, top: Infinity, bottom: -Infinity };
    /** @type {number[]} */ let atRight = []; // the rows of the robot's rightmost pixels
    for (let i = 0; i < data.length; i += 4) {
      if (Math.max(data[i], data[i + 1]) > 140 && data[i + 2] < 100 && Math.abs(data[i] - data[i + 1]) > 20) {
        const p = i / 4; const x = p % canvas.width; const y = Math.floor(p / canvas.width);
        if (x > b.right) atRight = [y]; else if (x === b.right) atRight.push(y);
        b.left = Math.min(b.left, x); b.right = Math.max(b.right, x); b.top = Math.min(b.top, y); b.bottom = Math.max(b.bottom, y);
      }
    }
    const s = canvas.width / canvas.clientWidth;
    return { left: b.left / s, right: b.right / s, top: b.top / s, bottom: b.bottom / s, rightY: atRight[atRight.length >> 1] / s };
  });
  const cell = (box.right - box.left) / 4;
  // Just right of the robot's rightmost point, at its height: held mid-stride the body leans, and a
  // point beside its box's corner or middle could lie nearer a voxel whose neighbour there is taken
  // (nothing added); beside the rightmost point, the nearest voxel is a right-hand one, its right free.
  await byTestId(page, 'viewer').click({ position: { x: box.right + 0.3 * cell, y: box.rightY } });
  await waitForText(page, 'status', /^11 voxels/);
  assert.equal(await page.evaluate(() => document.body.dataset.running), 'false', 'still held');
  // The maps, as a person sees them: shown, with strong reds and blues (not white, blank squares).
  await page.waitForFunction(() => {
    const section = document.getElementById('attention-panel');
    const canvas = /** @type {HTMLCanvasElement} */ (document.getElementById('attention'));
    if (!section || section.hidden) return false;
    const data = canvas.getContext('2d')?.getImageData(0, 0, canvas.width, canvas.height).data ?? [];
    let strong = 0;
    for (let i = 0; i < data.length; i += 4) {
      if ((data[i] > 150 && data[i + 1] < 90 && data[i + 2] < 90) || (data[i + 2] > 150 && data[i] < 90)) strong++;
    }
    return strong > 500;
  }, undefined, { timeout: 20_000 });
  await page.locator('#watch-panel').screenshot({ path: path.join(SCREENSHOTS, 'simple-words-held-maps.png') });
  assert.deepEqual(problems, []);
  await context.close();
});

test('the lesson table fits 420 px, in the page\'s sheet (its bar covers nothing) and in the teachers\' guide; printed whole', async () => {
  const { page, problems, context } = await openPage(env.browser, `${env.url}?chapter=1`, { width: 420, height: 860, touch: true });
  await byTestId(page, 'tour-teacher').click();
  await byTestId(page, 'lesson-open').click();
  await byTestId(page, 'lesson').waitFor();
  const table = byTestId(page, 'lesson-table');
  await table.evaluate((t) => t.scrollIntoView({ block: 'start' }));
  // What is on screen at the table's head is the table's head, not the sheet's bar.
  const covered = await page.evaluate(() => {
    const head = /** @type {HTMLElement} */ (document.querySelector('[data-testid="lesson-table"] thead'));
    const r = head.getBoundingClientRect();
    return [0.1, 0.5, 0.9].map((f) => document.elementFromPoint(r.left + f * r.width, r.top + r.height / 2)?.closest('thead') !== head);
  });
  assert.deepEqual(covered, [false, false, false], 'the table\'s head is not covered');
  const fits = await table.evaluate((t) => ({ right: t.getBoundingClientRect().right, scroll: t.scrollWidth, client: t.clientWidth, page: document.documentElement.scrollWidth }));
  assert.ok(fits.right <= 420 && fits.scroll <= fits.client && fits.page <= 420, `the sheet's table fits: ${JSON.stringify(fits)}`);
  await page.screenshot({ path: path.join(SCREENSHOTS, 'simple-words-lesson-420.png') });
  await page.emulateMedia({ media: 'print' });
  assert.equal(await page.locator('.class-sheet-bar').isVisible(), false, 'printed: no bar');
  await page.pdf({ path: path.join(SCREENSHOTS, 'simple-words-lesson.pdf'), format: 'A4' });
  assert.deepEqual(problems, []);
  await context.close();

  const guide = await openBare(env.browser, `${env.url}docs/teaching.html`, { width: 420, height: 860, touch: true });
  const tables = await guide.page.evaluate(() => [...document.querySelectorAll('table')].map((t) => ({ scroll: t.scrollWidth, client: t.clientWidth, head: t.rows[0]?.textContent?.trim().slice(0, 30) })));
  assert.ok(tables.length > 0);
  for (const t of tables) assert.ok(t.scroll <= t.client, `the guide's table “${t.head}” fits 420 px: ${JSON.stringify(t)}`);
  await guide.page.locator('table').first().evaluate((t) => t.scrollIntoView({ block: 'start' }));
  await guide.page.screenshot({ path: path.join(SCREENSHOTS, 'simple-words-guide-420.png') });
  await guide.page.emulateMedia({ media: 'print' });
  const printed = await guide.page.evaluate(() => [...document.querySelectorAll('table')].map((t) => t.scrollWidth <= t.clientWidth + 1 && t.getBoundingClientRect().right <= document.documentElement.clientWidth + 1));
  assert.ok(printed.every(Boolean), `printed, every table whole: ${printed}`);
  await guide.page.pdf({ path: path.join(SCREENSHOTS, 'simple-words-guide.pdf'), format: 'A4' });
  assert.deepEqual(guide.problems, []);
  await guide.context.close();
});
