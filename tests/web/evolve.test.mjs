// @ts-check
/**
 * Browser test of evolving in the page (node --test):
 *  - a tiny evolution gives the same run (every generation's statistics and the best genome)
 *    with 1 and with 2 evaluation workers, and the same run, bit for bit, as `vsr evolve`
 *    with those settings (needs target/release/vsr; VSR_BIN);
 *  - an evaluation worker that crashes mid-run is replaced, its job re-run, and the run's
 *    result is unchanged;
 *  - bad settings are said at once in the plan line, with Evolve off, and start nothing;
 *  - after a run the page says how long the settings would take at its pace (none before the
 *    first; the estimate and the time the run took are printed, figures, not pass marks);
 *  - Evolve runs a tiny budget live on the chosen number of workers (figures change, the chart
 *    is against evaluations, the best walks), Export downloads its run file and Import lists
 *    it back as a module that opens with its own body;
 *  - Pause holds, Step runs exactly one generation, Stop ends and keeps the run file; the
 *    pace says how long the run has left.
 * Saves screenshots/evolve.png.
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtemp, readFile, rm } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { RunEstimate } from '../../www/runs/estimate.js';
import { timeLeft } from '../../www/runs/progress.js';
import { TINY, evolveInPage, evolveNative, statistics } from './evolution.mjs';
import { BIN, byTestId, figure, openPage, screenshot, start, waitForFigure, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;
/** @type {import('playwright-core').Page} */ let page;
/** @type {string[]} */ let problems;
/** @type {string} */ let tmp;

before(async () => {
  env = await start();
  ({ page, problems } = await openPage(env.browser, env.url));
  tmp = await mkdtemp(path.join(os.tmpdir(), 'vsr-evolve-'));
});

after(async () => {
  await env?.close();
  await rm(tmp, { recursive: true, force: true });
});

/**
 * Runs the tiny evolution in the page's workers. @param {number} workers
 * @param {boolean} crash make worker 1 crash during generation 1
 */
const evolveInWorkers = (workers, crash = false) => page.evaluate(evolveInPage, /** @type {[typeof TINY, number, boolean]} */ ([TINY, workers, crash]));

test('a tiny evolution is the same with 1 and 2 workers and as vsr evolve, bit for bit', async () => {
  const one = (await evolveInWorkers(1)).run;
  const two = (await evolveInWorkers(2)).run;
  assert.equal(one.format, 'vsr-run');
  assert.equal(one.generations.length, 2, 'population 6, 18 evaluations: generations 0 and 1');
  assert.deepEqual([one.timing.threads, two.timing.threads], [1, 2]);
  assert.deepEqual(statistics(two), statistics(one));
  assert.deepEqual(two.best.genome, one.best.genome);
  const native = await evolveNative(path.join(tmp, 'native.json'));
  assert.deepEqual(statistics(native), statistics(one), 'every generation as vsr evolve runs it');
  assert.deepEqual(native.best.genome, one.best.genome, 'the best genome as vsr evolve finds it');
  assert.equal(native.best.fitness, one.best.fitness);
  assert.deepEqual(problems, []);
});

test('an evaluation worker that crashes is replaced and the run ends with the same result', async () => {
  const clean = (await evolveInWorkers(2)).run;
  const crashed = await evolveInWorkers(2, true);
  assert.equal(crashed.recovered.length, 1, `one recovery: ${crashed.recovered.join('; ')}`);
  assert.match(crashed.recovered[0], /worker 2 stopped.*re-runs its job/);
  assert.deepEqual(statistics(crashed.run), statistics(clean));
  assert.deepEqual(crashed.run.best.genome, clean.best.genome);
  assert.deepEqual(problems.filter((p) => !/crashed on request/.test(p)), []);
  problems.length = 0;
});

/** Fills the run form. @param {Record<string, string>} values by id suffix */
async function fillRun(values) {
  for (const [key, value] of Object.entries(values)) await page.locator(`#run-${key}`).fill(value);
}

/** Expects `pattern` in the plan line at once, with Evolve off and no run started. @param {RegExp} pattern */
async function expectRefused(pattern) {
  await waitForText(page, 'run-plan', new RegExp(`^Not valid yet: .*${pattern.source}`));
  assert.equal(await byTestId(page, 'evolve').isDisabled(), true, 'Evolve is off');
  assert.equal(await byTestId(page, 'generation').textContent(), '–', 'no generation was run');
}

test('bad settings are said at once in the plan line, with Evolve off, and start nothing', async () => {
  await fillRun({ population: '6', seconds: '2', budget: '0', terrain: 'flat' });
  await expectRefused(/budget must be a whole number/);
  await fillRun({ budget: '24', seconds: '' });
  await expectRefused(/episode seconds must be a positive number/);
  await fillRun({ seconds: '2', workers: '0' });
  await expectRefused(/workers must be a whole number from 1/);
  await fillRun({ workers: '1', terrain: 'hills' });
  await expectRefused(/neither a terrain family/);
  assert.doesNotMatch(String(await page.locator('#run-plan').textContent()), /line \d+ column/, 'no parser internals');
  await fillRun({ terrain: 'flat' });
  await waitForText(page, 'run-plan', /^A budget of 24 evaluations/);
  assert.equal(await byTestId(page, 'evolve').isEnabled(), true, 'fixed: Evolve is on');
  assert.deepEqual(problems, []);
});

test('Evolve runs live on the chosen workers, the best walks, Export and Import round-trip', async () => {
  await fillRun({ population: '6', seconds: '2', budget: '60', seed: '5', terrain: 'hilly-1-10', workers: '1' });
  // The page's first run: the estimate is from this computer's speed, measured as the page opened.
  await waitForText(page, 'run-estimate', /^At this computer's speed, measured as the page opened, that is about \d+ s on 1 worker\.$/);
  const estimated = await figure(page, 'run-estimate');
  const started = Date.now();
  await byTestId(page, 'evolve').click();
  await waitForText(page, 'run-status', /on 1 worker$/);
  await waitForFigure(page, 'run-generation', 'v >= 1');
  const midway = await figure(page, 'run-evaluations');
  await page.waitForFunction(() => document.body.dataset.run === 'finished', undefined, { timeout: 120_000 });
  const took = (Date.now() - started) / 1000;
  // After it, the same settings are estimated at its pace.
  await waitForText(page, 'run-estimate', /^At the pace of the last run here, that is about \d+ s on 1 worker\.$/);
  console.log(`# a run of 66 evaluations of 2 s on 1 worker took ${took.toFixed(1)} s from the click; estimated at ${estimated.toFixed(1)} s before it `
    + `(the speed measured as the page opened), at ${(await figure(page, 'run-estimate')).toFixed(1)} s after it (its own pace)`);
  assert.ok(midway >= 18 && midway <= 66, `evaluations went from ${midway}`);
  assert.equal(await figure(page, 'run-evaluations'), 66, 'population 6 + 5 generations of 12 for a budget of 60');
  assert.match(String(await byTestId(page, 'evaluations').textContent()), /^66 \/ 66$/);
  const best = await figure(page, 'run-best');
  assert.ok(best >= await figure(page, 'run-gen-best'), 'best so far is at least the last generation\'s best');
  await waitForText(page, 'status', /^10 voxels, attention$/);
  await waitForText(page, 'driver', /the evolved run's result: the best of its last generation/);
  await page.locator('#attention-panel').waitFor({ state: 'visible', timeout: 10_000 });

  const [download] = await Promise.all([page.waitForEvent('download'), byTestId(page, 'export').click()]);
  assert.equal(download.suggestedFilename(), 'evolved-attention-seed5.json');
  const file = path.join(tmp, download.suggestedFilename());
  await download.saveAs(file);
  const run = JSON.parse(await readFile(file, 'utf8'));
  assert.equal(run.format, 'vsr-run');
  assert.equal(run.generations.length, 6);
  assert.equal(run.best.genome.length, 73);
  execFileSync(BIN, ['validate', '--genome', file], { stdio: 'ignore' }); // the CLI reads what the page wrote

  await byTestId(page, 'preset').selectOption({ label: 'comb-7x2' });
  await waitForText(page, 'status', /^11 voxels/);
  await byTestId(page, 'import').setInputFiles(file);
  await waitForText(page, 'module-details', /This attention brain of 73 genes was evolved on biped-4x3 \(rows 1111-1111-1001\) with seed/);
  await page.locator('#module-open').click();
  await waitForText(page, 'status', /^10 voxels, attention$/);
  assert.equal(await page.locator('#rows').inputValue(), '1111-1111-1001');
  await byTestId(page, 'import').setInputFiles({ name: 'broken.json', mimeType: 'application/json', buffer: Buffer.from('{"format": "vsr-run", "version": 1, "config": {') });
  await waitForText(page, 'message', /broken.json is not a run file/);
  assert.match(String(await page.locator('#status').textContent()), /^10 voxels, attention$/, 'the robot keeps walking');
  await screenshot(page, 'evolve.png');
  // The next visit (a new tab, the same browser) lists the modules made here: the run and the imported file, not the broken file.
  const mine = (/** @type {import('playwright-core').Page} */ p) => p.locator('#module optgroup[label="opened, imported or run here"] option')
    .evaluateAll((os) => os.map((o) => o.textContent));
  const before = await mine(page);
  assert.equal(before.length, 2, `the run and the file: ${before}`);
  assert.match(String(before[0]), / m\/s in training$/, 'a run made here says its speed is its training\'s');
  const next = await page.context().newPage();
  await next.goto(env.url);
  await waitForText(next, 'status', /voxels/);
  await next.waitForFunction(() => document.querySelectorAll('#module optgroup[label="opened, imported or run here"] option').length === 2, undefined, { timeout: 10_000 });
  assert.deepEqual(await mine(next), before, 'listed again on the next visit');
  await next.close();
  assert.deepEqual(problems, []);
});

test('the time a run has left is said in seconds, then minutes', () => {
  assert.equal(timeLeft(NaN), '');
  assert.equal(timeLeft(0), '');
  assert.equal(timeLeft(Infinity), '');
  assert.equal(timeLeft(12.2), ' · about 13 s to go');
  assert.equal(timeLeft(125), ' · about 2 min 5 s to go');
  assert.equal(timeLeft(1500), ' · about 25 min to go');
});

test('the quick settings are lighter where this computer would take over 90 s, and the estimate says so', () => {
  const QUICK = { population: 20, seconds: 10, budget: 2000 };
  /** @type {Record<string, number>} */ const form = { workers: 2, seconds: 10, budget: 2000, population: 20 };
  const fake = { quick: (/** @type {any} */ p) => p, number: (/** @type {string} */ k) => form[k], planned: 2020, untouched: true,
    running: false, fixed: new Set(), fixedBy: '', preset: (/** @type {any} */ p) => { form.budget = p.budget; } };
  const out = /** @type {any} */ ({ dataset: {}, textContent: '', hidden: true });
  let pace = NaN; // voxel-seconds per second per worker: 2,020 evaluations of 10 voxels for 10 s on 2 workers take 101,000 / pace s
  const estimate = new RunEstimate(out, /** @type {any} */ (fake), () => pace, () => '1111-1111-1001', QUICK);
  clearInterval(estimate.timer);
  assert.deepEqual(fake.quick(QUICK), QUICK, 'no speed known: the core\'s quick settings');
  pace = 101_000 / 60; // 60 s
  assert.deepEqual(fake.quick(QUICK), QUICK, 'about a minute: as they are');
  pace = 101_000 / 300; // 5 min: 1,000 would take about 2.5 min, 500 about 76 s, 200 about 33 s
  fake.preset(fake.quick(QUICK));
  assert.equal(form.budget, 200, 'the largest lighter budget that takes at most 70 s');
  fake.planned = 220;
  estimate.refresh();
  assert.match(out.textContent, /^At the pace of the last run here, that is about 33 s on 2 workers\. The quick settings are lighter on this computer: 200 evaluations, not 2,000 \(about 5 min 0 s here\)\.$/);
  // A class challenge fixes the run: never lighter, and the same slow computer says so instead.
  fake.fixed = new Set(['budget']);
  fake.fixedBy = 'the challenge';
  form.budget = 2000;
  fake.planned = 2020;
  assert.deepEqual(fake.quick(QUICK), QUICK, 'a challenge\'s run: as it is');
  estimate.refresh();
  assert.match(out.textContent, /^At the pace of the last run here, that is about 5 min 0 s on 2 workers\. This computer is slow for the challenge's run: it runs all 2,000 evaluations all the same/);
});

test('with the from-scratch comparison switched on, the estimate covers the fine-tune and the run after it', () => {
  /** @type {Record<string, number>} */ const form = { workers: 2, seconds: 10, budget: 2000, population: 20 };
  const fake = { quick: (/** @type {any} */ p) => p, number: (/** @type {string} */ k) => form[k], planned: 2020, untouched: false,
    running: false, fixed: new Set(), fixedBy: '', preset: () => {} };
  const out = /** @type {any} */ ({ dataset: {}, textContent: '', hidden: true });
  let compare = false;
  const estimate = new RunEstimate(out, /** @type {any} */ (fake), () => 101_000 / 60, () => '1111-1111-1001', form, () => compare);
  clearInterval(estimate.timer);
  estimate.refresh();
  assert.equal(out.textContent, 'At the pace of the last run here, that is about 1 min 0 s on 2 workers.');
  compare = true;
  estimate.refresh();
  assert.equal(out.textContent, 'At the pace of the last run here, that is about 1 min 0 s a run on 2 workers; '
    + 'Fine-tune with the from-scratch comparison makes two runs, about 2 min 0 s in all.');
  assert.equal(Number(out.dataset.total), 2 * Number(out.dataset.value), 'the two runs\' time, beside one run\'s');
});

test('Pause holds, Step runs one generation, Stop ends the run and keeps its run file', async () => {
  await fillRun({ population: '4', seconds: '1', budget: '30000', seed: '2', workers: '2' });
  await byTestId(page, 'evolve').click();
  // This run's generation 0 (the figures of the run before stay until it starts).
  await page.waitForFunction(() => document.body.dataset.run === 'evolving', undefined, { timeout: 60_000 });
  await waitForFigure(page, 'run-generation', 'v >= 0', 120_000);
  await byTestId(page, 'pause').click();
  // Paused once the evaluations under way are back (they may finish a generation); then no new one starts.
  await page.waitForFunction(() => document.body.dataset.run === 'paused', undefined, { timeout: 60_000 });
  const held = await figure(page, 'run-generation');
  assert.ok(Number.isInteger(held) && held >= 0, `a generation was told: ${held}`);
  await byTestId(page, 'run-estimate').waitFor({ state: 'hidden', timeout: 5_000 }); // no estimate while it runs
  assert.match(String(await page.locator('#run-rate').textContent()),
    /^\d+\.\d evaluations\/s · about (\d+ s|\d+ min \d+ s|\d+ min) to go$/, 'the pace, and the time left at it');
  await page.waitForTimeout(1000);
  assert.equal(await figure(page, 'run-generation'), held, 'no generation while paused');
  assert.equal(await byTestId(page, 'pause').textContent(), 'Resume');
  await byTestId(page, 'step').click();
  await waitForFigure(page, 'run-generation', `v === ${held + 1}`, 120_000);
  await page.waitForFunction(() => document.body.dataset.run === 'paused', undefined, { timeout: 60_000 });
  await page.waitForTimeout(1000);
  assert.equal(await figure(page, 'run-generation'), held + 1, 'one step, one generation');
  await byTestId(page, 'pause').click();
  await waitForFigure(page, 'run-generation', `v > ${held + 1}`, 120_000);
  // Each newer best starts a walk of its own (the clock's note goes, the line under the robot is
  // written again): the lines over the run's buttons keep their room, so Stop never moves up
  // (it did by 50 px each generation, and the run's figures under it took the click).
  const moves = await page.evaluate(() => new Promise((resolve, reject) => {
    const stop = /** @type {HTMLElement} */ (document.getElementById('run-stop'));
    const driver = /** @type {HTMLElement} */ (document.getElementById('driver'));
    const said = driver.textContent;
    let walks = 0; // newer bests that began walking: the line under the robot says each
    /** @type {number[]} */ const tops = [];
    // Measured after every change of the page's text (a line emptied for a moment counts) and every frame.
    const measure = () => tops.push(Math.round(stop.getBoundingClientRect().top + window.scrollY));
    const changes = new MutationObserver((records) => {
      if (records.some((r) => driver.contains(r.target)) && driver.textContent !== said) walks++;
      measure();
    });
    changes.observe(document.body, { subtree: true, childList: true, characterData: true });
    const started = performance.now();
    const frame = () => {
      measure();
      if (walks < 3 && performance.now() - started < 120_000) { requestAnimationFrame(frame); return; }
      changes.disconnect();
      if (walks < 3) reject(new Error(`${walks} newer bests walked in 2 min, not 3`));
      else resolve({ tops: [...new Set(tops)], up: tops.some((t, i) => i > 0 && t < tops[i - 1]) });
    };
    requestAnimationFrame(frame);
  }));
  assert.equal(moves.up, false, `Stop moved up while the run went on: its tops ${moves.tops.join(', ')} px`);
  await byTestId(page, 'stop').click();
  await page.waitForFunction(() => document.body.dataset.run === 'stopped', undefined, { timeout: 60_000 });
  assert.equal(await byTestId(page, 'export').isEnabled(), true, 'the stopped run can be exported');
  assert.equal(await byTestId(page, 'evolve').isEnabled(), true);
  assert.deepEqual(problems, []);
});
