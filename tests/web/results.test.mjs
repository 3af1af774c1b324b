// @ts-check
/**
 * Browser test of the study's results in plain words (node --test): no Markdown and no file
 * paths, every number in them is in docs/RESULTS.md, the tests behind a fold, and the test of
 * the paper's own claim as `vsr report` wrote its state (study/report-noninferiority/
 * noninferiority.json), never an interim answer; with a complete file served in its place, the
 * answer on each body in words; the study panel says the same. Screenshot: screenshots/classroom-results-plain.png.
 */
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { ROOT, SCREENSHOTS, byTestId, openPage, start } from './harness.mjs';
import { CLAIM_TABLE, FIGURES, STUDY_DIR, figureSrc } from '../../www/tour/figures.js';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

test('the study\'s results in plain words: no Markdown, no file paths, every number from RESULTS.md, the tests behind a fold', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  const section = byTestId(page, 'results-plain');
  await page.locator('header a[href="#results-plain"]').click();
  await page.waitForFunction(() => { const r = document.getElementById('results-plain')?.getBoundingClientRect(); return r && r.top < innerHeight && r.bottom > 0; });
  assert.equal(new URL(page.url()).hash, '', 'the address (the share link\'s #...) is left alone');
  const plain = String(await section.evaluate((el) => {
    const copy = /** @type {HTMLElement} */ (el.cloneNode(true));
    copy.querySelector('details')?.remove();
    return copy.textContent;
  }));
  assert.doesNotMatch(plain, /\*\*|`|\||^#|\[[^\]]*\]\(/m, 'no Markdown characters');
  assert.doesNotMatch(plain, /[\w-]+\/[\w.-]+\.(md|json|csv|toml|svg)\b|docs\/|study\//, 'no file paths');
  assert.doesNotMatch(plain, /\bRQ\d|A12|Hodges|Mann-Whitney|CCD|dyn4j|SPEC|latched/, 'none of the researchers\' terms');
  assert.match(plain, /No difference detected” means/);
  const results = readFileSync(path.join(ROOT, 'docs/RESULTS.md'), 'utf8');
  const words = await section.evaluate((el) => { // every text node apart, so that table cells do not run together
    const walk = document.createTreeWalker(el, NodeFilter.SHOW_TEXT);
    const out = [];
    while (walk.nextNode()) out.push(walk.currentNode.textContent);
    return out.join(' ');
  });
  const numbers = [...words.matchAll(/[+-]?\d[\d,]*\.\d+|\d{1,3}(?:,\d{3})+/g)].map((m) => m[0]);
  assert.ok(numbers.length >= 10, `numbers: ${numbers}`);
  for (const n of numbers) assert.ok(results.includes(n.replace(/^\+/, '')), `${n} is in docs/RESULTS.md`);
  // The test of the paper's own claim: its state as `vsr report` wrote it, never an interim answer.
  const claim = JSON.parse(readFileSync(path.join(ROOT, 'study/report-noninferiority/noninferiority.json'), 'utf8'));
  await page.waitForFunction(() => !/reading its state/.test(document.querySelector('[data-testid="claim"]')?.textContent ?? 'reading its state'));
  const said = String(await section.locator('[data-testid="claim"]').textContent());
  const row7 = results.split('\n').find((line) => line.startsWith('| 7 |')) ?? '';
  if (claim.complete) {
    for (const fig of FIGURES.filter((f) => f.claim)) assert.ok(existsSync(path.join(ROOT, figureSrc(fig))), `${figureSrc(fig)} is drawn`);
    assert.ok(existsSync(path.join(ROOT, STUDY_DIR, CLAIM_TABLE)), `${CLAIM_TABLE} is merged`);
    for (const s of claim.shapes) {
      assert.ok(said.includes(s.shape) && s.answer, `the answer on ${s.shape}: ${said}`);
      const interval = `[${s.answer.interval.map((/** @type {number} */ v) => (v < 0 ? '' : '+') + v.toFixed(2)).join(', ')}]`;
      assert.ok(row7.includes(s.shape) && row7.includes(interval), `RESULTS.md's row 7 gives ${s.shape}'s interval ${interval}: ${row7}`);
    }
  } else {
    assert.match(row7, /no result yet/, 'RESULTS.md gives no answer before the page has one');
    assert.match(said, new RegExp(`under way: ${claim.finished_runs} of the ${claim.planned_runs} runs have finished`), said);
    assert.doesNotMatch(said, /allow a difference between/, 'no interim answer');
  }
  await byTestId(page, 'study').scrollIntoViewIfNeeded(); // the study panel reads its files once in sight
  await page.waitForFunction(() => document.querySelector('[data-testid="study-claim"]')?.textContent !== '');
  assert.equal(await page.locator('[data-testid="study-claim"]').textContent(), said, 'the study panel says the same');
  const figures = await byTestId(page, 'study-figure').locator('option').evaluateAll((os) => os.map((o) => /** @type {HTMLOptionElement} */ (o).value));
  assert.equal(figures.some((id) => id.startsWith('claim-')), claim.complete, `the claim's figures only once it is complete: ${figures}`);
  const fold = section.locator('details.stats');
  assert.equal(await fold.getAttribute('open'), null, 'the tests are folded');
  assert.equal(await section.locator('table.tests').isVisible(), false);
  await fold.locator('summary').click();
  assert.equal(await section.locator('table.tests tbody tr').count(), 6);
  await section.screenshot({ path: path.join(SCREENSHOTS, 'classroom-results-plain.png') });
  await section.locator('button', { hasText: 'See the figure' }).first().click();
  await page.waitForFunction(() => /fig4-rq1-biped/.test(/** @type {HTMLImageElement} */ (document.getElementById('study-image')).src));
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('once every run of the claim\'s test is in, the page gives its answer on each body (a complete file, served in place of the real one)', async () => {
  const answer = (/** @type {string} */ verdict, /** @type {string | null} */ superiority) => ({
    medians: [3.9, 3.4], shift: 0.45, interval: [-0.12, 1.03], p: 0.004, holm_p: 0.008, verdict, superiority });
  const complete = { group: 'noninferiority', treatment: 'attention', control: 'mlp-comm', margin: 0.5, set: 'unseen', planned_runs: 120,
    finished_runs: 120, complete: true, shapes: [
      { shape: 'biped-4x3', evals: 30000, planned: 30, finished: [30, 30], answer: answer('not worse', 'better') },
      { shape: 'comb-7x2', evals: 30000, planned: 30, finished: [30, 30], answer: answer('not shown', null) },
      { shape: 'biped-6x4', evals: 30000, planned: 30, finished: [30, 30], answer: answer('not worse', 'not shown better') }] };
  const row = (/** @type {string} */ shape, /** @type {string} */ controller, /** @type {number} */ unseen) =>
    `${shape}-${controller}-30000-s11,scratch,${shape},${controller},30000,30100,11,,${unseen}`;
  const table = ['run,kind,shape,controller,evals,evaluations,seed,source,unseen_mean',
    row('biped-4x3', 'mlp-comm', 3.1), row('biped-4x3', 'attention', 3.7), row('comb-7x2', 'attention', 2.9), row('comb-7x2', 'mlp-comm', 3.0)].join('\n');
  const { page, problems } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  await page.route('**/report-noninferiority/noninferiority.json', (route) => route.fulfill({ json: complete }));
  await page.route('**/study/noninferiority.csv', (route) => route.fulfill({ body: table, contentType: 'text/csv' }));
  await page.route('**/report-noninferiority/intervals-noninferiority-unseen.svg', (route) => route.fulfill({
    body: '<svg xmlns="http://www.w3.org/2000/svg" width="80" height="50"><text y="20">intervals</text></svg>', contentType: 'image/svg+xml' }));
  await page.reload();
  // The findings read the claim's file once it is in sight: scroll to the claim itself (the list above it may still be growing).
  await byTestId(page, 'claim').scrollIntoViewIfNeeded();
  await page.waitForFunction(() => /On the comb/.test(document.querySelector('[data-testid="claim"]')?.textContent ?? ''));
  const said = String(await page.locator('[data-testid="claim"]').textContent());
  assert.match(said, /On the biped \(biped-4x3\), attention is not slower than mlp-comm by 0\.5 m\/s or more, and is faster \(median speeds 3\.90 against 3\.40 m\/s, the middle ones of this test's own runs; the runs allow a difference between −0\.12 and \+1\.03 m\/s, with 95% confidence\)\./);
  assert.match(said, /On the comb \(comb-7x2\), not settled: the runs still allow attention being more than 0\.5 m\/s slower/);
  assert.match(said, /On the biped \(biped-6x4\), attention is not slower than mlp-comm by 0\.5 m\/s or more, though these runs do not show it faster either \(/);
  assert.doesNotMatch(said, /under way/);
  await byTestId(page, 'study').scrollIntoViewIfNeeded();
  await page.waitForFunction(() => /On the comb/.test(document.querySelector('[data-testid="study-claim"]')?.textContent ?? ''));
  assert.equal(await page.locator('[data-testid="study-claim"]').textContent(), said, 'the study panel says the same');
  // The study panel now lists the test's figures, drawn from its own table of runs only.
  const pick = byTestId(page, 'study-figure');
  await page.waitForFunction(() => !!document.querySelector('#study-figure option[value="claim-intervals"]'));
  await pick.selectOption('claim-intervals');
  await page.waitForFunction(() => /intervals-noninferiority-unseen\.svg$/.test(/** @type {HTMLImageElement} */ (document.getElementById('study-image')).src));
  const runs = await byTestId(page, 'study-run').locator('option').evaluateAll((os) => os.map((o) => /** @type {HTMLOptionElement} */ (o).value));
  assert.deepEqual(runs, ['biped-4x3-attention-30000-s11', 'biped-4x3-mlp-comm-30000-s11', 'comb-7x2-attention-30000-s11', 'comb-7x2-mlp-comm-30000-s11']);
  assert.match(String(await page.locator('#study-caption').textContent()), /dashed line at −0\.5/);
  await pick.selectOption('validation-biped');
  const paperRuns = await byTestId(page, 'study-run').locator('option').evaluateAll((os) => os.map((o) => /** @type {HTMLOptionElement} */ (o).value));
  assert.ok(paperRuns.length > 0 && paperRuns.every((r) => !r.endsWith('-s11')), `the paper study's figure lists its own runs only: ${paperRuns}`);
  assert.deepEqual(problems, []);
  await page.context().close();
});
