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
import { ROOT, SCREENSHOTS, byTestId, openBare, openPage, start, waitForText } from './harness.mjs';

/** What a person sees of `selector` in simple words: its text with each explanation in brackets after its word (::after). @param {import('playwright-core').Page} page @param {string} selector */
const seen = (page, selector) => page.locator(selector).first().evaluate((root) => {
  const out = [];
  const walk = (/** @type {Node} */ n) => {
    if (n.nodeType === Node.TEXT_NODE) { out.push(n.textContent); return; }
    if (!(n instanceof Element) || getComputedStyle(n).display === 'none') return;
    for (const c of n.childNodes) walk(c);
    const after = getComputedStyle(n, '::after').content;
    if (after && after !== 'none' && after !== 'normal') out.push(after.replace(/^"|"$/g, ''));
  };
  walk(root);
  return out.join('').replace(/\s+/g, ' ');
});

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
  assert.equal(await page.locator('#param-count .gene-detail.expert').isVisible(), false, 'the genes\' breakdown is the expert\'s');
  await page.waitForFunction(() => document.querySelector('#param-count [data-explain]') !== null);
  assert.match(await after_(page, '#param-count [data-explain]'), /the numbers evolution tunes/, '73 genes explained');
  // The module list's speed says which it is: the mean over ten new terrains (a brain for any body: the middle of the new bodies' speeds).
  await byTestId(page, 'tour-exercise').locator('input[type=radio]').first().check();
  await byTestId(page, 'tour-reveal').click();
  await page.waitForFunction(() => [...document.querySelectorAll('#module option')].some((o) => /m\/s/.test(o.textContent ?? '')));
  const options = await page.locator('#module option').evaluateAll((os) => os.map((o) => o.textContent ?? '').filter((t) => /m\/s/.test(t)));
  assert.ok(options.length > 3 && options.every((t) => /\d m\/s (on new ground|in training|on a typical new body)$/.test(t)), `each listed speed says what it is, in simple words: ${options.join(' | ')}`);
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

test('a teacher\'s review in simple words: the header, the brain\'s words, the settings, the three speeds, the glossary and the findings said plainly (1400 and 420 px)', async () => {
  for (const width of [1400, 420]) {
    const { page, problems, context } = await openPage(env.browser, env.url, { width, height: 900, init: SIMPLE, touch: width < 800 });
    // 1. The header: no mlp-comm, GECCO, paper title or fine-tune; the same said in everyday words.
    const header = await page.locator('header > p').innerText();
    assert.doesNotMatch(header, /mlp-comm|GECCO|Evolving Modular|fine-tune/, `the header in simple words: ${header}`);
    assert.match(header, /learn a little more for its new body/);
    assert.match(header, /a study by four scientists, shown at a science meeting in 2022/);
    await page.screenshot({ path: path.join(SCREENSHOTS, `simple-words-header-${width}.png`) });
    // 2. The gene count's breakdown and the module list in plain words.
    await page.waitForFunction(() => document.querySelector('#param-count .gene-plain[data-plain]') !== null);
    const genes = await seen(page, '#param-count');
    assert.match(genes, /^\d+ genes \(the numbers evolution tunes\): 32 shared by all the voxels \(how each one listens\), \d+ that belong to one voxel each \(4 for every voxel\), and 1 more$/, genes);
    assert.doesNotMatch(genes, /attention block|weights|bias/);
    await page.waitForFunction(() => [...document.querySelectorAll('#module option')].some((o) => /on new ground/.test(o.textContent ?? '')));
    const names = await page.locator('#module option').allTextContents();
    assert.ok(names.some((t) => /^a brain trained on the small walker, moved to the big walker: \d+\.\d\d m\/s on new ground$/.test(t)), names.join(' | '));
    assert.ok(names.some((t) => /^an attention brain, trained on the small walker: \d+\.\d\d m\/s on new ground$/.test(t)), names.join(' | '));
    assert.ok(!names.some((t) => /→|average over 10 new terrains/.test(t)), `no expert's name in simple words: ${names.join(' | ')}`);
    // 3. The ground and the run's settings explained where they stand; the workers are the expert's.
    for (const [selector, words] of [['label:has(#terrain) > span', 'hilly-1-10-0: hills about 1 m high every 10 m; the last number picks one ground, always the same'],
      ['label:has(#run-terrain) > span', 'hilly-1-10: hills about 1 m high every 10 m'], ['label:has(#run-seed) > span:first-child', 'the same number gives the same run'],
      ['label:has(#run-budget) > span', 'how many test walks the run may use']]) {
      assert.ok((await seen(page, selector)).includes(words), `${selector}: ${await seen(page, selector)}`);
    }
    // The plan line under the settings: rounds and test walks, no generations or evaluations.
    await page.waitForFunction(() => /test walks/.test(document.getElementById('run-plan')?.innerText ?? ''));
    const plan = await page.locator('#run-plan').innerText();
    assert.match(plan, /^The run may use [\d,]+ test walks\. First \d+ random brains walk; then come \d+ rounds\./, plan);
    assert.doesNotMatch(plan, /generation|evaluation|budget/, plan);
    assert.equal(await page.locator('#run-export').innerText(), 'Save this run (a file)');
    assert.equal(await page.locator('#run-csv').innerText(), 'Save the run as a table (for a spreadsheet)');
    assert.equal(await page.locator('#run-workers').isVisible(), false);
    // 4. Your robot's speed, said as the one that counts; training's two speeds said as not it (a module on its own body: both speeds).
    await byTestId(page, 'pretrained').selectOption('pretrained/biped-4x3-attention.json');
    await page.locator('#module-open').click();
    await waitForText(page, 'speed-note', /^Your robot's speed: \d+\.\d\d m\/s .*the short code and the class ranking use this one\)\. In training: /, 30_000);
    const note = await seen(page, '#speed-note');
    assert.match(note, /^Your robot's speed \(the one that counts: your short code and the class ranking use it\): /, note);
    assert.match(note, /In training \(how fast it walked while it learned, on other hills: not your robot's speed\): /, note);
    assert.match(await seen(page, 'span:has(> #run-best)'), /best so far \(its one fastest walk while it learned, often a lucky one: not your robot's speed\)/);
    // 5. The run's figures: the median explained, the computer's pace hidden.
    assert.match(await seen(page, 'span:has(> #run-median)'), /median \(the middle one of this round: half walked faster, half slower\)/);
    assert.equal(await page.locator('#engine-rate').isVisible(), false);
    assert.equal(await page.locator('#run-gen-best').isVisible(), false, 'one speed fewer: this generation\'s best is the expert\'s (best so far and the median stay)');
    await page.locator('#watch-panel').screenshot({ path: path.join(SCREENSHOTS, `simple-words-speeds-${width}.png`) });
    await page.locator('#brain-panel').screenshot({ path: path.join(SCREENSHOTS, `simple-words-brain-${width}.png`) });
    // 6. The glossary's attention, tanh and saturate in everyday words.
    await page.locator('#glossary-open').click();
    const glossary = await page.locator('#glossary dl').innerText();
    for (const word of ['attention matrix', 'query', 'keys', 'squashing function']) assert.ok(!glossary.includes(word), `the glossary in simple words: no “${word}”`);
    assert.match(glossary, /The answers make a small table, 4 rows by 4 columns/);
    // 7. The findings: the claim's test told without intervals or confidence.
    await page.locator('#glossary').evaluate((d) => { /** @type {HTMLDetailsElement} */ (d).open = false; });
    await byTestId(page, 'results-plain').scrollIntoViewIfNeeded();
    await page.waitForFunction(() => /On the comb/.test(document.querySelector('[data-testid="claim-simple"]')?.textContent ?? ''), undefined, { timeout: 20_000 });
    const found = await byTestId(page, 'results-plain').innerText();
    assert.doesNotMatch(found, /95% confidence|allow a difference between|margin fixed in advance/, 'the exact statement is the expert\'s');
    assert.match(found, /we wrote down a rule before we ran anything: attention passes if it is not slower than mlp-comm by 0\.5 m\/s or more/);
    // Findings 2 and 5 in everyday words too (a teacher's review found them in the expert's): the same numbers, no jargon.
    for (const n of [2, 5]) {
      const said = await page.locator(`#results-plain ol.findings > li:nth-child(${n}) > p.simple-only:not(.claim)`).innerText();
      assert.doesNotMatch(said, /mlp-comm|evaluations|module|detected/, `finding ${n} in simple words: ${said}`);
      assert.match(said, n === 2 ? /3\.28 m\/s.*still we could not tell them apart/s : /3\.14 m\/s.*2\.03 m\/s: we could not tell them apart/s, `finding ${n}: ${said}`);
    }
    await byTestId(page, 'claim-simple').screenshot({ path: path.join(SCREENSHOTS, `simple-words-claim-${width}.png`) });
    await byTestId(page, 'simple-words').uncheck();
    assert.match(await byTestId(page, 'results-plain').innerText(), /with 95% confidence/, 'the exact statement back for the expert');
    assert.match(await page.locator('#results-plain ol.findings > li:nth-child(5)').innerText(), /the 30,100 that made the module/, 'finding 5 in the expert\'s words back');
    assert.ok((await page.locator('#module option').allTextContents()).some((t) => /^biped-4x3 → biped-6x4 · \d+\.\d\d m\/s average over 10 new terrains$/.test(t)), 'the expert\'s names back');
    assert.match(await page.locator('header > p').innerText(), /GECCO/);
    assert.match(await page.locator('#run-plan').innerText(), /^A budget of [\d,]+ evaluations: generation 0 measures/, 'the plan in the expert\'s words back');
    assert.deepEqual(problems, []);
    await context.close();
  }
});

test('Share link: the note that Fine-tune stays behind only for a transplanted brain, in plain words', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1400, height: 900, init: SIMPLE });
  await byTestId(page, 'share').click();
  await waitForText(page, 'message', /Link copied|Here is the link/);
  assert.doesNotMatch(String(await byTestId(page, 'message').textContent()), /Fine-tune will be off/, 'a brain on its own body: nothing said');
  // A pretrained module's file travels in a link by its name: a module imported from a file does not.
  await page.locator('#run-import').setInputFiles(path.join(ROOT, 'pretrained/biped-6x4-attention.json'));
  await page.waitForFunction(() => /** @type {HTMLSelectElement} */ (document.getElementById('module')).value.startsWith('disk:'));
  await byTestId(page, 'load-pretrained').click();
  await waitForText(page, 'driver', /a module transplanted from biped-6x4/);
  await byTestId(page, 'share').click();
  await waitForText(page, 'message', /The robot and its brain open the same there, but Fine-tune will be off: the file its attention came from does not travel in a link\./);
  assert.deepEqual(problems, []);
  await context.close();
});

test('a student\'s challenge rules on a phone: the goal, three numbered steps, the details folded', async () => {
  const url = `${env.url}?challenge=1&terrain=hilly-1-10-0&seconds=10&budget=2000&seed=1&population=20&train=hilly-1-10`;
  const { page, problems, context } = await openPage(env.browser, url, { width: 420, height: 860, touch: true });
  await waitForText(page, 'challenge-rules', /^Challenge: any body, as fast as it can over 10 s on hilly-1-10-0\./);
  const rules = page.locator('#challenge-rules');
  assert.equal(await rules.locator('ol > li').count(), 3);
  assert.equal(await rules.locator('details').getAttribute('open'), null, 'the details folded');
  const height = await rules.evaluate((e) => e.getBoundingClientRect().height);
  assert.ok(height < 200, `short on a 420-px screen: ${height} px`);
  await rules.scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(SCREENSHOTS, 'simple-words-challenge-rules-420.png') });
  await rules.locator('summary').click();
  assert.match(await rules.locator('details').innerText(), /The run: 2,000 evaluations, seed 1, 10-s walks\./);
  assert.deepEqual(problems, []);
  await context.close();
});
