// @ts-check
/**
 * Browser test of the body search in the page (node --test):
 *  - a tiny body search in the page's workers (the body-search coordinator and its evaluation
 *    workers) gives the same archive and best, bit for bit, with 1 and 2 workers, when an
 *    evaluation worker dies mid-search (a new one re-runs its job), and as `vsr codesign` with
 *    those settings (needs target/release/vsr; VSR_BIN);
 *  - the panel runs a small search live: the progress counts evaluations of the planned ones,
 *    the gallery fills, a click on a body loads it with its brain into the editor and it
 *    walks; its exported file's best is `vsr codesign`'s with the same settings; the first and
 *    the last best race side by side, and a link shares the chosen body with its brain;
 *  - the tour's chapter "Which body for this brain?" sets the search up from its link;
 *  - a wrong module (MLP-Comm, frozen) and a drawing that is no body are refused in words that
 *    stay on the page.
 * With VSR_BENCH=1 it also times the panel's quick setting on 2 workers (a figure, printed, not
 * a pass mark). Saves screenshots/codesign.png, codesign-panel.png and codesign-refused.png.
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtemp, readFile, rm } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { BIN, ROOT, SCREENSHOTS, byTestId, figure, openPage, screenshot, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;
/** @type {string} */ let tmp;

const MODULE = 'pretrained/biped-4x3-attention.json';
/** A tiny search: the frozen biped module from a 3 x 3 box, 3 rounds of 10 new bodies, 3-s episodes. */
const TINY = Object.freeze({ brain: 'frozen', start: '111-111-111', seed: 7, seconds: 3, terrain: 'hilly-1-10', budget: 30, batch: 10 });

before(async () => {
  env = await start();
  tmp = await mkdtemp(path.join(os.tmpdir(), 'vsr-codesign-'));
});

after(async () => {
  await env?.close();
  await rm(tmp, { recursive: true, force: true });
});

/**
 * Runs a whole body search in a body-search coordinator worker, as the panel does; runs in the
 * page. @param {[typeof TINY, number, string, boolean]} arg settings, workers, the module's run file
 * text, whether evaluation worker 2 crashes at the start (a new one must re-run its job)
 */
async function searchInPage([settings, workers, module, crash]) {
  const { FromCodesign, ToCodesign } = await import(new URL('workers/codesign-protocol.js', location.href).href);
  const coordinator = new Worker(new URL('codesign/coordinator.js', location.href), { type: 'module' });
  /** @type {number[]} */
  const filled = [];
  /** @type {string[]} */
  const recovered = [];
  const text = await new Promise((resolve, reject) => {
    coordinator.onmessage = ({ data }) => {
      if (data.type === FromCodesign.STARTED && crash) coordinator.postMessage({ type: ToCodesign.CRASH_WORKER, index: 1 });
      if (data.type === FromCodesign.RECOVERED) recovered.push(data.message);
      if (data.type === FromCodesign.ITERATION) filled.push(data.gallery.length);
      if (data.type === FromCodesign.DONE) resolve(data.runFile);
      if (data.type === FromCodesign.ERROR) reject(new Error(data.message));
    };
    coordinator.postMessage({ type: ToCodesign.START, settings, workers, module });
  });
  coordinator.terminate();
  return { run: JSON.parse(text), filled, recovered };
}

/**
 * `vsr codesign` with the same settings on 1 thread. @param {typeof TINY} s @param {string} out
 * @returns {Promise<any>} its run file
 */
async function searchNative(s, out) {
  execFileSync(BIN, ['codesign', '--brain', s.brain, '--from', path.join(ROOT, MODULE), '--start', s.start,
    '--evals', String(s.budget), '--seed', String(s.seed), '--seconds', String(s.seconds), '--terrain', s.terrain,
    '--batch', String(s.batch), '--threads', '1', '--checkpoint-every', '0', '--out', out]);
  return JSON.parse(await readFile(out, 'utf8'));
}

/** What must match between two runs of one search: all but wall times and threads. @param {any} run */
const result = (run) => ({
  history: run.history.map((/** @type {any} */ r) => ({ ...r, wall_seconds: 0 })),
  archive: run.archive, best: run.best, evaluations: run.evaluations,
});

test('a tiny body search in workers is the same with 1 and 2 workers, with a worker that dies, and as vsr codesign, bit for bit', async () => {
  const { page, problems } = await openPage(env.browser, env.url);
  const module = await (await fetch(`${env.url}${MODULE}`)).text();
  const one = await page.evaluate(searchInPage, /** @type {[typeof TINY, number, string, boolean]} */ ([TINY, 1, module, false]));
  const two = await page.evaluate(searchInPage, /** @type {[typeof TINY, number, string, boolean]} */ ([TINY, 2, module, false]));
  const crashed = await page.evaluate(searchInPage, /** @type {[typeof TINY, number, string, boolean]} */ ([TINY, 2, module, true]));
  assert.equal(crashed.recovered.length, 1, `one recovery: ${crashed.recovered.join('; ')}`);
  assert.match(crashed.recovered[0], /worker 2 stopped.*re-runs its job/);
  assert.deepEqual(result(crashed.run), result(one.run), 'a worker that died changed nothing');
  assert.equal(one.run.format, 'vsr-codesign');
  assert.ok(one.filled.length >= 2 && one.filled.every((n) => n >= 1), `the gallery filled, round by round: ${one.filled}`);
  assert.deepEqual(result(two.run), result(one.run), '2 workers as 1');
  const native = await searchNative(TINY, path.join(tmp, 'native.json'));
  assert.deepEqual(result(native), result(one.run), 'the page\'s search is vsr codesign\'s');
  problems.splice(0, problems.length, ...problems.filter((p) => !/crashed on request/.test(p)));
  console.log(`# tiny search: ${one.run.evaluations} evaluations, ${one.run.archive.length} bodies, best ${native.best.shape} at ${native.best.fitness.toFixed(3)} m/s, the same in the page and in vsr codesign`);
  assert.deepEqual(problems, []);
  await page.context().close();
});

/** Chooses a pretrained module in "3 · Give it a brain". @param {import('playwright-core').Page} page @param {string} key */
async function chooseModule(page, key) {
  await page.locator('#module option[value="' + key + '"]').waitFor({ state: 'attached' });
  await byTestId(page, 'pretrained').selectOption(key);
}

test('the panel searches live, the gallery fills, a click loads a body that walks, its best is vsr codesign\'s', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1300, height: 1500 });
  await chooseModule(page, MODULE);
  await page.locator('#run-seed').fill(String(TINY.seed));
  await page.locator('#run-workers').fill('2');
  await byTestId(page, 'codesign-brain').selectOption('frozen');
  await page.locator('#codesign-from').selectOption('box');
  await page.locator('#codesign-budget').fill('60');
  await page.locator('#codesign-seconds').fill(String(TINY.seconds));
  await page.evaluate(() => {
    const w = /** @type {any} */ (window);
    w.longTasks = [];
    new PerformanceObserver((list) => { for (const e of list.getEntries()) w.longTasks.push(e.duration); }).observe({ type: 'longtask' });
  });
  // Before it starts, the panel says about how long it will take (once the page has measured this computer's speed).
  await waitForText(page, 'codesign-estimate', /^Brain: the module .*, its attention kept\. At this computer's speed, about .* on 2 workers \(larger bodies take longer/, 30_000);
  const estimated = Number(await byTestId(page, 'codesign-estimate').getAttribute('data-value'));
  const started = Date.now();
  await byTestId(page, 'codesign').click();
  await waitForText(page, 'codesign-status', /^searching on 2 workers$/);
  await page.waitForFunction(() => document.body.dataset.codesign === 'finished', undefined, { timeout: 120_000 });
  console.log(`# the body search was estimated at ${estimated.toFixed(1)} s and took ${((Date.now() - started) / 1000).toFixed(1)} s (a figure, not a pass mark)`);
  const long = await page.evaluate(() => /** @type {any} */ (window).longTasks);
  const update = Number(await page.locator('#codesign-summary').getAttribute('data-update-ms'));
  console.log(`# the longest gallery update took ${update.toFixed(1)} ms; main-thread tasks over 50 ms meanwhile (the whole page: the viewer walks too): ${long.length ? long.map((/** @type {number} */ d) => d.toFixed(0)).join(', ') + ' ms' : 'none'} (figures on a busy machine, not pass marks)`);
  const progress = String(await byTestId(page, 'codesign-progress').textContent());
  assert.match(progress, /^\d+ of 60 evaluations$/);
  assert.ok(Number(progress.split(' ')[0]) >= 60, progress);
  const bodies = byTestId(page, 'codesign-body');
  const count = await bodies.count();
  assert.ok(count >= 2, `the gallery shows ${count} bodies`);
  assert.equal(count, Number(await page.locator('#codesign-summary').getAttribute('data-filled')));
  assert.match(String(await page.locator('#codesign-summary').textContent()), /kinds? of body found .* fastest: \d+\.\d\d m\/s.* · searched for (\d+ s|under a second), /,
    'once ended, the summary says how long the search took');

  // The exported file's best is vsr codesign's with the panel's settings.
  const [download] = await Promise.all([page.waitForEvent('download'), byTestId(page, 'codesign-export').click()]);
  const exported = JSON.parse(await readFile(/** @type {string} */ (await download.path()), 'utf8'));
  assert.equal(download.suggestedFilename(), `body-search-${exported.config.brain}-seed${exported.config.seed}.json`, 'a name in the panel\'s words');
  const native = await searchNative({ ...TINY, budget: 60, batch: 20 }, path.join(tmp, 'panel.json'));
  assert.deepEqual(result(exported), result(native), 'the panel\'s search is vsr codesign\'s');

  // A click on the last body loads it with its brain; it walks.
  const last = bodies.nth(count - 1);
  const cell = String(await last.getAttribute('data-cell'));
  const entry = native.archive.find((/** @type {any} */ e) => String(e.cell) === cell);
  await last.click();
  await page.waitForFunction((rows) => document.body.dataset.codesignLoaded === rows, entry.shape);
  await waitForText(page, 'shape-status', new RegExp(`· ${entry.shape}$`));
  await waitForText(page, 'driver', /a body found by the body search/);
  // The drawing was replaced: said just above the robot, in view (not at the top of the page).
  await waitForText(page, 'watch-message', /^The body you clicked, with its brain, now stands in “1 · Draw” in place of your drawing/);
  assert.ok(await byTestId(page, 'watch-message').evaluate((e) => e.getBoundingClientRect().top >= 0 && e.getBoundingClientRect().bottom <= innerHeight), 'the note in view');
  const x0 = await figure(page, 'robot-x');
  await page.waitForTimeout(1500);
  assert.notEqual(await figure(page, 'robot-x'), x0, 'it walks');
  await screenshot(page, 'codesign.png');
  await page.locator('#codesign-panel').screenshot({ path: path.join(SCREENSHOTS, 'codesign-panel.png') });

  // The first and the last best race side by side.
  await byTestId(page, 'codesign-race').click();
  await page.waitForFunction(() => document.querySelectorAll('[data-testid="race-robot"]').length === 2);

  // A link to the chosen body with its brain.
  await byTestId(page, 'codesign-share').click();
  await page.waitForFunction((rows) => {
    const link = new URL(/** @type {HTMLInputElement} */ (document.getElementById('share-link')).value, location.href);
    const p = new URLSearchParams(link.hash.slice(1));
    return p.get('shape') === rows && p.get('brain') === 'attention' && (p.get('genome') ?? '').length > 0;
  }, entry.shape);
  // Opened again, it says of its training speed what the page said (the mean of how many walks, not "its latest").
  const inTraining = async (/** @type {import('playwright-core').Page} */ p) => {
    await p.waitForFunction(() => /In training: /.test(document.getElementById('speed-note')?.textContent ?? ''));
    return String(await p.locator('#speed-note').textContent()).match(/In training: [^(]*\([^,]*/)?.[0];
  };
  const said = await inTraining(page);
  assert.match(String(said), /the mean of its \d+ evaluations|one evaluation only/);
  const reopened = await openPage(env.browser, await page.locator('#share-link').inputValue());
  await waitForText(reopened.page, 'driver', /a body found by the body search/);
  assert.equal(await inTraining(reopened.page), said);
  assert.deepEqual(reopened.problems, []);
  await reopened.page.context().close();
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('a wrong module and a drawing that is no body are refused in words that stay; from scratch, any module\'s body is a start', async () => {
  const { page, problems } = await openPage(env.browser, env.url);
  await chooseModule(page, 'pretrained/biped-4x3-mlp-comm.json');
  await byTestId(page, 'codesign-brain').selectOption('frozen');
  await byTestId(page, 'codesign').click();
  // Said under the panel's buttons, in view, not at the top of the page (which would leave the form behind).
  await waitForText(page, 'codesign-message', /The body search did not start: this module is mlp-comm, not attention: only an attention module can be reassembled into other bodies/);
  assert.ok(await byTestId(page, 'codesign-message').evaluate((e) => { const r = e.getBoundingClientRect(); return r.top >= 0 && r.bottom <= innerHeight; }), 'the reason in view');
  assert.equal(await page.locator('#message').textContent(), '', 'nothing at the top of the page');
  await waitForText(page, 'codesign-status', /^The search did not start: the message under the buttons says why\.$/);
  assert.equal(await page.evaluate(() => document.body.dataset.codesign), 'not');
  assert.equal(await byTestId(page, 'codesign-body').count(), 0);
  await page.waitForTimeout(2000);
  assert.match(String(await byTestId(page, 'codesign-message').textContent()), /only an attention module/, 'the words stay');

  await page.locator('#clear').click();
  await page.locator('#codesign-from').selectOption('drawing');
  await byTestId(page, 'codesign').click();
  await waitForText(page, 'codesign-message', /Your drawing is not a body the search can start from.*Draw one piece of touching voxels/);
  await screenshot(page, 'codesign-refused.png');

  // From scratch, any module's body is a start: a new attention brain on the MLP-Comm module's biped.
  await byTestId(page, 'codesign-brain').selectOption('scratch');
  await page.locator('#codesign-from').selectOption('module');
  await page.locator('#codesign-budget').fill('20');
  await page.locator('#codesign-seconds').fill('1');
  await byTestId(page, 'codesign').click();
  await page.waitForFunction(() => document.body.dataset.codesign === 'finished', undefined, { timeout: 60_000 });
  await waitForText(page, 'codesign-summary', /^Brain: attention from scratch, bodies from the module's own body · /);
  assert.equal(await byTestId(page, 'codesign-message').isVisible(), false, 'a search that starts takes the refusal away');
  // Refused now, the gallery below is said to be the last search's (not the refused one's).
  await page.locator('#codesign-budget').fill('0');
  await byTestId(page, 'codesign').click();
  await waitForText(page, 'codesign-message', /evaluations must be a whole number of at least 1, not "0"/);
  await waitForText(page, 'codesign-summary', /^Your last search: Brain: attention from scratch/);
  assert.ok(await byTestId(page, 'codesign-body').count() >= 1);
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('the tour\'s chapter "Which body for this brain?" opens from its link with the search set up', async () => {
  const { CHAPTERS } = await import('../../www/tour/chapters.js');
  const n = CHAPTERS.findIndex((c) => c.title === 'Which body for this brain?') + 1;
  assert.ok(n > 0, 'the chapter is in the tour');
  const { page, problems } = await openPage(env.browser, `${env.url}?chapter=${n}`);
  await page.waitForFunction((n) => document.getElementById('tour-box')?.dataset.chapter === String(n), n);
  await page.waitForFunction(() => /** @type {HTMLSelectElement} */ (document.getElementById('module')).value === 'pretrained/biped-4x3-attention.json');
  assert.equal(await byTestId(page, 'codesign-brain').inputValue(), 'frozen');
  assert.equal(await page.locator('#codesign-from').inputValue(), 'box');
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('benchmark: the quick body search on 2 workers (VSR_BENCH=1)', { skip: !process.env.VSR_BENCH }, async () => {
  const { page } = await openPage(env.browser, env.url, { width: 1300, height: 1500 });
  await chooseModule(page, MODULE);
  await page.locator('#run-workers').fill('2');
  const started = Date.now();
  await byTestId(page, 'codesign').click();
  await page.waitForFunction(() => document.body.dataset.codesign === 'finished', undefined, { timeout: 600_000 });
  const took = (Date.now() - started) / 1000;
  console.log(`# quick body search (${await byTestId(page, 'codesign-progress').textContent()}, ${await page.locator('#codesign-seconds').inputValue()}-s episodes) on 2 workers: ${took.toFixed(1)} s; ${await page.locator('#codesign-summary').textContent()}`);
  await screenshot(page, 'codesign-quick.png');
  await page.context().close();
});

test('a body the study\'s body search found is listed with the modules, described as found by a search, and walks with its own body', async () => {
  const manifest = JSON.parse(await readFile(path.join(ROOT, 'pretrained', 'manifest.json'), 'utf8'));
  const body = manifest.bodies[0];
  const key = `pretrained/${body.file}`;
  const { page, problems } = await openPage(env.browser, env.url);
  await page.locator(`#module option[value="${key}"]`).waitFor({ state: 'attached' });
  const option = page.locator(`#module option[value="${key}"]`);
  assert.match(String(await option.getAttribute('title')), new RegExp(`^a body found by the body search: ${body.voxels} voxels`));
  assert.equal(await option.textContent(), `${body.voxels} voxels, attention module, attention kept · ${Number(body.validation.unseen.mean).toFixed(2)} m/s average over 10 new terrains`,
    'the list shows the body, its brain and its mean speed on the unseen terrains, said as such');
  assert.equal(await option.evaluate((o) => /** @type {HTMLOptGroupElement} */ (o.parentElement).label), 'found by a body search');
  await byTestId(page, 'pretrained').selectOption(key);
  await waitForText(page, 'module-details', new RegExp(`a body of ${body.voxels} voxels \\(rows ${body.rows}\\) found by a body search`));
  await page.locator('#module-open').click();
  await waitForText(page, 'status', new RegExp(`^${body.voxels} voxels, attention$`));
  assert.deepEqual(problems, []);
  await page.context().close();
});
