// @ts-check
/**
 * Browser test of the brains for any body in the page (node --test):
 *  - the family menu names them for a newcomer ("attention, any body", ...), their gene count
 *    is the same for any drawing, and, while the manifest lists no brain for any body of the
 *    study's (served here as the committed manifest without one), where the page would need it
 *    (the module list, the note under the menu) it says "not yet: the study is still training
 *    it", and offers nothing in its place;
 *  - "attention, any body" evolves on the drawn body in the run panel; the walking robot edited
 *    (a click beside it in the viewer, a cell drawn in the editor) keeps walking with the SAME
 *    genome; Fine-tune from it starts from its whole genome, its attention block kept, as `vsr
 *    finetune` does bit for bit;
 *  - a manifest entry for a brain for any body lists it among the modules (a module made on the
 *    fly by `vsr evolve --bodies`, served in place of pretrained/'s files, never written there):
 *    it loads onto a drawing with all its genes, and the body search with it kept whole
 *    evolves bodies only (every entry's genome is the module's), as `vsr codesign` does bit for
 *    bit; a search from scratch of a family for any body runs too;
 *  - the study's own brain for any body, as pretrained/ holds it (the committed manifest, not
 *    routed): listed with its held-out median, it walks at once on a drawing it never trained
 *    on, at the speed `vsr evaluate --shape` gives that body, keeps walking, with the same
 *    genes, through an erased and an added voxel, and fine-tunes from all its genes.
 * Needs target/release/vsr (VSR_BIN). Saves screenshots/any-body-1400.png, any-body-420.png,
 * any-body-search-1400.png, any-body-search-420.png, any-body-study-1400.png and any-body-study-420.png
 * (whole pages; in /tmp, the screen at the part they show).
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtemp, readFile, rm } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { BIN, ROOT, byTestId, clickCells, expectFigure, figure, openBare, screenshot, start, waitForFigure, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;
/** @type {string} */ let tmp;
/** The brain for any body made for this test, its file's text and its run. */
let made = { text: '', run: /** @type {any} */ (null), file: '' };

/** A table with four legs, drawn cell by cell: 11111-11111-10101 (13 voxels). */
const TABLE = [[0, 2], [1, 2], [2, 2], [3, 2], [4, 2], [0, 1], [1, 1], [2, 1], [3, 1], [4, 1], [0, 0], [2, 0], [4, 0]];
/** Where the made module is served (pretrained/ holds no such file: the test's routes answer for it). */
const MADE_KEY = 'pretrained/attention-any-test.json';

before(async () => {
  env = await start();
  tmp = await mkdtemp(path.join(os.tmpdir(), 'vsr-any-body-'));
  made.file = path.join(tmp, 'any.json');
  execFileSync(BIN, ['evolve', '--bodies', path.join(ROOT, 'campaigns/bodies/train-32.txt'), '--controller', 'attention-any',
    '--evals', '20', '--population', '10', '--seconds', '2', '--bodies-per-evaluation', '2', '--seed', '1', '--threads', '1',
    '--out', made.file], { stdio: 'pipe' });
  made.text = await readFile(made.file, 'utf8');
  made.run = JSON.parse(made.text);
});

after(async () => {
  await env?.close();
  await rm(tmp, { recursive: true, force: true });
});

/** The committed manifest, without any brain for any body (the page as it was before the study exported one). */
async function manifestWithout() {
  const manifest = JSON.parse(await readFile(path.join(ROOT, 'pretrained', 'manifest.json'), 'utf8'));
  manifest.modules = manifest.modules.filter((/** @type {any} */ m) => !m.any_body);
  return manifest;
}

/** Float32 values of a run file's genome (its JSON numbers are f32 values written out). @param {number[]} genes */
const f32 = (genes) => Array.from(Float32Array.from(genes));

/**
 * The brain the page shares now, as its link holds it: its family and genome (float32 values).
 * @param {import('playwright-core').Page} page
 */
async function sharedBrain(page) {
  await byTestId(page, 'share').click();
  await page.waitForFunction(() => /genome=/.test(document.getElementById('share-link')?.dataset.value ?? ''));
  const link = String(await page.locator('#share-link').getAttribute('data-value'));
  const p = new URLSearchParams(new URL(link).hash.slice(1));
  const bytes = Buffer.from(String(p.get('genome')), 'base64url');
  const genome = Array.from(new Float32Array(bytes.buffer, bytes.byteOffset, bytes.byteLength / 4));
  return { controller: p.get('brain'), genome, shape: p.get('shape') };
}

/** Waits for the viewer's clock to pass `seconds` more than now: the robot walks. @param {import('playwright-core').Page} page */
async function walksOn(page, seconds = 1) {
  const t0 = await figure(page, 'sim-time');
  await waitForFigure(page, 'sim-time', `v >= ${t0 + seconds}`, 30_000);
}

/** Fills the run form. @param {import('playwright-core').Page} page @param {Record<string, string>} values */
async function runForm(page, values) {
  for (const [key, value] of Object.entries(values)) await page.locator(`#run-${key}`).fill(value);
}

/** Downloads what `button` gives, parsed as JSON, and keeps a copy at `keep`. @param {import('playwright-core').Page} page @param {string} button @param {string} keep */
async function downloadJson(page, button, keep) {
  const [download] = await Promise.all([page.waitForEvent('download'), byTestId(page, button).click()]);
  await download.saveAs(keep);
  return { name: download.suggestedFilename(), json: JSON.parse(await readFile(keep, 'utf8')) };
}

/**
 * The robot's box on the viewer once the held robot's view is settled (CSS px), as page.test.mjs reads it.
 * @param {import('playwright-core').Page} page
 */
async function settledRobotBox(page) {
  const box = () => page.evaluate(() => {
    const canvas = /** @type {HTMLCanvasElement} */ (document.querySelector('[data-testid="viewer"]'));
    const data = canvas.getContext('2d')?.getImageData(0, 0, canvas.width, canvas.height).data ?? [];
    const b = { left: Infinity, right: -Infinity, top: Infinity, bottom: -Infinity };
    for (let i = 0; i < data.length; i += 4) {
      if (Math.max(data[i], data[i + 1]) > 140 && data[i + 2] < 100 && Math.abs(data[i] - data[i + 1]) > 20) {
        const p = i / 4;
        const [x, y] = [p % canvas.width, Math.floor(p / canvas.width)];
        b.left = Math.min(b.left, x); b.right = Math.max(b.right, x); b.top = Math.min(b.top, y); b.bottom = Math.max(b.bottom, y);
      }
    }
    const s = canvas.width / canvas.clientWidth;
    return JSON.stringify({ left: b.left / s, right: b.right / s, top: b.top / s, bottom: b.bottom / s });
  });
  let last = '';
  for (const deadline = Date.now() + 60_000; Date.now() < deadline;) {
    const still = await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => resolve(
      /** @type {HTMLElement} */ (document.querySelector('[data-testid="viewer"]')).dataset.cameraStill === 'true')))));
    const now = await box();
    if (still && now === last) return JSON.parse(now);
    last = still ? now : '';
    await page.waitForTimeout(100);
  }
  throw new Error('the view of the held robot did not settle');
}

/**
 * Saves a full-page screenshot under screenshots/, and what the screen shows with `selector` at its top in /tmp (to look at).
 * @param {import('playwright-core').Page} page @param {string} name @param {string} selector
 */
async function shoot(page, name, selector) {
  await screenshot(page, name);
  await page.locator(selector).evaluate((e) => e.scrollIntoView({ block: 'start', behavior: 'instant' }));
  await page.screenshot({ path: path.join(os.tmpdir(), name) });
}

test('“attention, any body”: named for a newcomer, one gene count for any drawing, the study\'s module “not yet”; it evolves, '
  + 'keeps its genome through edits of the walking robot, and fine-tunes from its whole genome as vsr finetune does', async () => {
  const { page, problems } = await openBare(env.browser, 'about:blank', { width: 1400, height: 1000 });
  const without = await manifestWithout();
  await page.route('**/pretrained/manifest.json', (route) => route.fulfill({ json: without }));
  await page.goto(env.url);
  await waitForText(page, 'status', /voxels/);
  const names = await byTestId(page, 'controller').locator('option').allTextContents();
  for (const name of ['attention, any body', 'MLP, any body', 'MLP-Comm, any body']) assert.ok(names.includes(name), `${name} in ${names}`);
  await byTestId(page, 'controller').selectOption('attention-any');
  const genes = made.run.best.genome.length; // attention for any body, as vsr makes it
  await expectFigure(page, 'param-count', genes, 'the genes of attention for any body');
  await waitForText(page, 'param-count', new RegExp(`^${genes} genes, the same number for any body you draw, all shared by every voxel: 32 for the attention block`));
  // The study's brain for any body is not in pretrained/ yet: said where the page would need it, nothing in its place.
  await waitForText(page, 'any-body-note', /^The study's brain for any body \(attention, trained on many bodies\): not yet: the study is still training it\. Evolve trains one on your drawing/);
  const pending = page.locator('#module option[value="pending:attention-any"]');
  assert.equal(await pending.isDisabled(), true, 'it cannot be chosen');
  assert.equal(await pending.textContent(), 'attention, any body: not yet: the study is still training it');
  assert.equal(await pending.evaluate((o) => /** @type {HTMLOptGroupElement} */ (o.parentElement).label), 'one brain for any body');
  await page.locator('#clear').click();
  await clickCells(page, /** @type {[number, number][]} */ (TABLE));
  await waitForText(page, 'shape-status', /^13 voxels · 11111-11111-10101$/);
  await expectFigure(page, 'param-count', genes, 'the same for a drawing of 13 voxels');

  // Evolve it on the drawing, a few generations.
  await runForm(page, { population: '6', seconds: '2', budget: '24', seed: '3', terrain: 'hilly-1-10', workers: '2' });
  await byTestId(page, 'evolve').click();
  await waitForText(page, 'run-status', /^evolving on 2 workers$/);
  await waitForText(page, 'run-status', /^finished$/, 120_000);
  assert.ok(await figure(page, 'run-generation') >= 2, 'a few generations');
  await waitForText(page, 'driver', new RegExp(`the evolved run's result: .* \\(attention, any body, ${genes} genes\\)\\.$`));
  await waitForText(page, 'status', /^13 voxels, attention, any body$/);
  const evolved = await downloadJson(page, 'export', path.join(tmp, 'evolved.json'));
  assert.equal(evolved.name, 'evolved-attention-any-seed3.json');
  assert.equal(evolved.json.best.genome.length, genes);
  const walking = await sharedBrain(page);
  assert.equal(walking.controller, 'attention-any');
  assert.deepEqual(walking.genome, f32(evolved.json.best.genome), 'the run\'s result walks');

  // The walking robot edited: a voxel added beside it in the viewer, then one drawn in the editor. It walks on, the same genes.
  await page.locator('#sim-hold').click();
  await page.waitForFunction(() => document.body.dataset.running === 'false', undefined, { timeout: 30_000 });
  const box = await settledRobotBox(page);
  const cell = (box.right - box.left) / 5;
  await byTestId(page, 'viewer').click({ position: { x: box.right + 0.45 * cell, y: (box.top + box.bottom) / 2 } });
  await waitForText(page, 'status', /^14 voxels, attention, any body$/);
  await waitForText(page, 'driver', new RegExp(`· edited \\(the same genes drive the new body\\).*\\(attention, any body, ${genes} genes\\)\\.$`));
  await page.locator('#sim-play').click();
  await walksOn(page);
  const afterClick = await sharedBrain(page);
  assert.notEqual(afterClick.shape, walking.shape, 'a new body');
  assert.deepEqual(afterClick.genome, walking.genome, 'the same genome after the walking edit');
  await clickCells(page, [[0, 3]]);
  await waitForText(page, 'status', /^15 voxels, attention, any body$/);
  await walksOn(page);
  const afterStroke = await sharedBrain(page);
  assert.deepEqual(afterStroke.genome, walking.genome, 'the same genome after a drawn voxel');
  await shoot(page, 'any-body-1400.png', 'body');

  // Fine-tune from it: its whole genome the start, its attention block kept; vsr finetune's run, bit for bit.
  assert.equal(await byTestId(page, 'finetune').isEnabled(), true);
  assert.match(String(await byTestId(page, 'finetune').getAttribute('title')), /starts from all its genes/);
  await runForm(page, { population: '6', seconds: '2', budget: '18', seed: '4', terrain: 'hilly-1-10' });
  await byTestId(page, 'finetune').click();
  await waitForText(page, 'run-status', /^fine-tuning on 2 workers$/);
  await waitForText(page, 'run-status', /^finished$/, 120_000);
  const tuned = await downloadJson(page, 'export', path.join(tmp, 'tuned.json'));
  assert.equal(tuned.name, 'finetuned-attention-any-seed4.json');
  assert.equal(tuned.json.config.controller, 'attention-any');
  assert.equal(tuned.json.config.source.controller, 'attention-any');
  assert.deepEqual(tuned.json.best.genome.slice(0, 32), evolved.json.best.genome.slice(0, 32), 'the attention block kept');
  const out = path.join(tmp, 'native-tuned.json');
  execFileSync(BIN, ['finetune', '--from', path.join(tmp, 'evolved.json'), '--shape', tuned.json.config.shape, '--evals', '18',
    '--seed', '4', '--seconds', '2', '--terrain', 'hilly-1-10', '--population', '6', '--threads', '1', '--out', out], { stdio: 'pipe' });
  const native = JSON.parse(await readFile(out, 'utf8'));
  const generations = (/** @type {any} */ run) => run.generations.map((/** @type {any} */ g) => ({ ...g, wall_seconds: 0 }));
  assert.deepEqual(generations(tuned.json), generations(native), 'every generation as vsr finetune runs it');
  assert.deepEqual(tuned.json.best, native.best);
  await page.setViewportSize({ width: 420, height: 900 });
  await shoot(page, 'any-body-420.png', '#brain-panel');
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('a brain for any body in a manifest is listed with the modules, loads onto a drawing whole, and a body search with it '
  + 'kept whole evolves bodies only, as vsr codesign does bit for bit', async () => {
  const { page, problems } = await openBare(env.browser, 'about:blank', { width: 1400, height: 1100 });
  // The study's manifest with one more module, as `vsr campaign export` would list a brain for any body; its file the one made above.
  const manifest = await manifestWithout();
  // Its any_body record names the plan's primary group, as the export writes it (no body set's figures: the list shows no speed).
  manifest.modules.push({ file: path.basename(MADE_KEY), shape: 'train-32', rows: made.run.best.shape, controller: 'attention-any', bodies: 32,
    seed: 1, budget: 20, evaluations: 20, training_best: made.run.best.fitness,
    any_body: { group: 'any-train32', training_set: 'bodies/train-32.txt', per_evaluation: 2, chosen_by: 'this test', sets: [] } });
  await page.route('**/pretrained/manifest.json', (route) => route.fulfill({ json: manifest }));
  await page.route(`**/${MADE_KEY}`, (route) => route.fulfill({ body: made.text, contentType: 'application/json' }));
  await page.goto(env.url);
  await waitForText(page, 'status', /voxels/);
  const option = page.locator(`#module option[value="${MADE_KEY}"]`);
  await option.waitFor({ state: 'attached' });
  assert.equal(await option.textContent(), 'attention, any body, trained on 32 bodies');
  assert.match(String(await option.getAttribute('title')), /^a brain for any body \(attention, any body\), trained on 32 bodies at once \(evolved with a budget of 20 evaluations\)$/);
  assert.equal(await option.evaluate((o) => /** @type {HTMLOptGroupElement} */ (o.parentElement).label), 'one brain for any body');
  assert.equal(await page.locator('#module option[value="pending:attention-any"]').count(), 0, 'no “not yet” once it is there');
  await byTestId(page, 'controller').selectOption('attention-any');
  await waitForText(page, 'any-body-note', /is in the module list, under “one brain for any body”/);

  await byTestId(page, 'pretrained').selectOption(MADE_KEY);
  const genes = made.run.best.genome.length;
  await waitForText(page, 'module-details', new RegExp(`^This brain for any body \\(attention, any body\\), ${genes} genes for every body, was evolved on 32 bodies at once \\(the body set .*train-32\\.txt\\) with seed 1`));
  // Trained on many bodies, it has no body of its own: it opens on the first of them, its training speed not that body's.
  await page.locator('#module-open').click();
  await waitForText(page, 'driver', /, on the first of the 32 bodies it was trained on \(attention, any body, \d+ genes\)\.$/);
  await waitForText(page, 'shape-status', new RegExp(` · ${made.run.best.shape}$`));
  await page.locator('#clear').click();
  await clickCells(page, /** @type {[number, number][]} */ (TABLE));
  await waitForText(page, 'shape-status', /^13 voxels · 11111-11111-10101$/);
  await byTestId(page, 'load-pretrained').click();
  await waitForText(page, 'driver', new RegExp(`^Driven by: a brain for any body trained on 32 bodies, on your drawing, every gene as trained \\(attention, any body, ${genes} genes\\)\\.$`));
  await waitForText(page, 'speed-note', /with no training for it: a brain for any body keeps all its genes on every body/, 30_000);
  assert.deepEqual((await sharedBrain(page)).genome, f32(made.run.best.genome), 'all its genes, as trained');
  await walksOn(page);

  // The body search with it kept whole: bodies only.
  await page.locator('#run-seed').fill('5');
  await page.locator('#run-workers').fill('2');
  await byTestId(page, 'codesign-brain').selectOption('frozen');
  assert.equal(await byTestId(page, 'codesign-brain').locator('option[value="frozen"]').textContent(), 'the chosen module, kept whole: only the bodies evolve');
  await page.locator('#codesign-from').selectOption('box');
  await page.locator('#codesign-budget').fill('30');
  await page.locator('#codesign-seconds').fill('2');
  await waitForText(page, 'codesign-estimate', /^Brain: the module “attention, any body, trained on 32 bodies”, kept whole \(only the bodies evolve\)\./);
  await byTestId(page, 'codesign').click();
  await page.waitForFunction(() => document.body.dataset.codesign === 'finished', undefined, { timeout: 180_000 });
  await waitForText(page, 'codesign-summary', /^Brain: a brain for any body \(attention, any body\), trained on 32 bodies at once, kept whole \(only the bodies evolve\), bodies from a 3 × 3 box · /);
  const search = await downloadJson(page, 'codesign-export', path.join(tmp, 'search.json'));
  assert.equal(search.json.config.controller, 'attention-any');
  assert.ok(search.json.archive.length >= 2, `bodies of several kinds: ${search.json.archive.length}`);
  for (const e of search.json.archive) {
    assert.deepEqual(e.genome, made.run.best.genome, `entry ${e.cell}: the module's genome`);
    assert.deepEqual(e.design.genes, made.run.best.genome, `entry ${e.cell}: no other gene`);
  }
  assert.equal(new Set(search.json.archive.map((/** @type {any} */ e) => e.shape)).size, search.json.archive.length, 'a body per cell');
  const out = path.join(tmp, 'native-search.json');
  execFileSync(BIN, ['codesign', '--brain', 'frozen', '--from', made.file, '--start', '111-111-111', '--evals', '30', '--seed', '5',
    '--seconds', '2', '--terrain', 'hilly-1-10', '--batch', '20', '--threads', '1', '--checkpoint-every', '0', '--out', out], { stdio: 'pipe' });
  const native = JSON.parse(await readFile(out, 'utf8'));
  const result = (/** @type {any} */ run) => ({ history: run.history.map((/** @type {any} */ r) => ({ ...r, wall_seconds: 0 })),
    archive: run.archive, best: run.best, evaluations: run.evaluations });
  assert.deepEqual(result(search.json), result(native), 'the page\'s search is vsr codesign\'s');
  // A body of the gallery walks with the same brain.
  const bodies = byTestId(page, 'codesign-body');
  await bodies.nth((await bodies.count()) - 1).click();
  await waitForText(page, 'driver', /a body found by the body search/);
  assert.deepEqual((await sharedBrain(page)).genome, f32(made.run.best.genome));
  await shoot(page, 'any-body-search-1400.png', '#codesign-panel');
  await page.setViewportSize({ width: 420, height: 900 });
  await shoot(page, 'any-body-search-420.png', '#codesign-panel');
  await page.setViewportSize({ width: 1400, height: 1100 });

  // From scratch, a brain for any body of the chosen family evolves with the bodies.
  await byTestId(page, 'codesign-brain').selectOption('scratch');
  await page.locator('#codesign-budget').fill('20');
  await page.locator('#codesign-seconds').fill('1');
  await byTestId(page, 'codesign').click();
  await page.waitForFunction(() => document.body.dataset.codesign === 'finished', undefined, { timeout: 120_000 });
  await waitForText(page, 'codesign-summary', /^Brain: attention, any body from scratch, bodies from a 3 × 3 box · /);
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('the study\'s brain for any body, as pretrained/ holds it: listed with its held-out median, it walks at once on a drawing it '
  + 'never trained on, at vsr evaluate\'s speed for that body, keeps walking with the same genes through an erased and an added voxel, and fine-tunes', async () => {
  const manifest = JSON.parse(await readFile(path.join(ROOT, 'pretrained', 'manifest.json'), 'utf8'));
  const study = manifest.modules.find((/** @type {any} */ m) => m.controller === 'attention-any' && m.any_body?.group === 'any-train32');
  assert.ok(study, 'pretrained/manifest.json lists the study\'s brain for any body (vsr campaign export campaigns/any-body.toml)');
  const key = `pretrained/${study.file}`;
  const run = JSON.parse(await readFile(path.join(ROOT, key), 'utf8'));
  const heldout = study.any_body.sets.find((/** @type {any} */ s) => s.name === 'heldout-random');
  const { page, problems } = await openBare(env.browser, env.url, { width: 1400, height: 1000 });
  await waitForText(page, 'status', /voxels/);
  const terrain = 'hilly-1-10-7';
  await page.locator('#terrain').fill(terrain);
  await page.locator('#terrain').press('Enter');
  const option = page.locator(`#module option[value="${key}"]`);
  await option.waitFor({ state: 'attached' });
  assert.equal(await option.textContent(), `attention, any body, trained on ${study.bodies} bodies · ${heldout.median.toFixed(2)} m/s median on new bodies`);
  assert.equal(await page.locator('#module option[value="pending:attention-any"]').count(), 0, 'no “not yet”');
  await byTestId(page, 'controller').selectOption('attention-any');
  await waitForText(page, 'any-body-note', /is in the module list, under “one brain for any body”: choose it and press “Load onto my robot”, and it walks on your drawing at once/);

  // A table with four legs: not in its training set nor in any held-out set.
  const bodySets = ['train-32', 'train-128', 'heldout-random', 'heldout-mutants', 'heldout-combs', 'heldout-paper'];
  for (const set of bodySets) {
    const text = await readFile(path.join(ROOT, 'campaigns', 'bodies', `${set}.txt`), 'utf8');
    assert.ok(!text.split('\n').some((l) => l.trim() === '11111-11111-10101'), `the table is not in ${set}`);
  }
  await page.locator('#clear').click();
  await clickCells(page, /** @type {[number, number][]} */ (TABLE));
  await waitForText(page, 'shape-status', /^13 voxels · 11111-11111-10101$/);
  await byTestId(page, 'pretrained').selectOption(key);
  const set = `${heldout.means.length} bodies it never trained on, each on 10 new terrains: the median of their mean speeds is ${heldout.median.toFixed(2)} m/s`;
  await waitForText(page, 'module-details', new RegExp(`The study walked it on ${set}, the speed beside it in the list; \\d+ of the ${heldout.means.length} averaged more than 1 m/s\\. `
    + `It is the study's choice of ${study.chosen_from} runs \\(by their speed on their own training bodies\\): the middle run's brain walked ${heldout.median_of_runs.toFixed(2)} m/s there\\.$`));
  await byTestId(page, 'load-pretrained').click();
  const genes = run.best.genome.length;
  await waitForText(page, 'driver', new RegExp(`^Driven by: a brain for any body trained on ${study.bodies} bodies, on your drawing, every gene as trained \\(attention, any body, ${genes} genes\\)\\.$`));
  await waitForText(page, 'status', /^13 voxels, attention, any body$/);
  await waitForText(page, 'any-body-note', /^Your robot walks with the study's brain for any body \(attention, trained on many bodies\), every gene as trained/);
  assert.deepEqual((await sharedBrain(page)).genome, f32(run.best.genome), 'all its genes, as trained');
  await walksOn(page);
  /** vsr's speed for the module on `rows` over its 30-s episode, on the viewer's terrain. @param {string} rows */
  const native = (rows) => JSON.parse(execFileSync(BIN, ['evaluate', '--genome', path.join(ROOT, key), '--shape', rows,
    '--terrain', terrain], { encoding: 'utf8' })).velocity;
  /** “Your robot's speed” once measured for `rows`. @param {string} rows */
  const measured = async (rows) => {
    await page.waitForFunction((r) => document.getElementById('speed-note')?.dataset.rows === r
      && Number.isFinite(Number(document.getElementById('speed-note')?.dataset.value)), rows, { timeout: 60_000 });
    return figure(page, 'speed-note');
  };
  const onTable = native('11111-11111-10101');
  assert.ok(Math.abs(await measured('11111-11111-10101') - onTable) <= 1e-9, `the page's speed on the table is vsr evaluate's (${onTable} m/s)`);
  console.log(`# the study's brain for any body on a table it never saw: ${onTable.toFixed(2)} m/s on ${terrain}`);
  await shoot(page, 'any-body-study-1400.png', '#brain-panel');

  // Erase a leg, then add a voxel, while it walks: the same genes walk on, at vsr's speed for each new body.
  await byTestId(page, 'editor').scrollIntoViewIfNeeded();
  await clickCells(page, [[2, 0]], 'right');
  await waitForText(page, 'status', /^12 voxels, attention, any body$/);
  await walksOn(page);
  assert.deepEqual((await sharedBrain(page)).genome, f32(run.best.genome), 'the same genes after an erased voxel');
  assert.ok(Math.abs(await measured('11111-11111-10001') - native('11111-11111-10001')) <= 1e-9, 'three legs: vsr evaluate\'s speed');
  await clickCells(page, [[0, 3]]);
  await waitForText(page, 'status', /^13 voxels, attention, any body$/);
  await walksOn(page);
  assert.deepEqual((await sharedBrain(page)).genome, f32(run.best.genome), 'the same genes after an added voxel');

  // Fine-tuned on this body: from all its genes, its attention block kept.
  await runForm(page, { population: '6', seconds: '2', budget: '18', seed: '2', terrain: 'hilly-1-10' });
  await byTestId(page, 'finetune').click();
  await waitForText(page, 'run-status', /^finished$/, 120_000);
  const tuned = await downloadJson(page, 'export', path.join(tmp, 'study-tuned.json'));
  assert.equal(tuned.json.config.source.controller, 'attention-any');
  assert.deepEqual(tuned.json.config.source.genome, run.best.genome, 'it started from the study\'s module');
  assert.deepEqual(tuned.json.best.genome.slice(0, 32), run.best.genome.slice(0, 32), 'the attention block kept');
  await page.setViewportSize({ width: 420, height: 900 });
  await shoot(page, 'any-body-study-420.png', '#brain-panel');
  assert.deepEqual(problems, []);
  await page.context().close();
});
