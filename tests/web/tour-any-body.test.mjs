// @ts-check
/**
 * Browser test of the tour's chapter “One brain for every body” (node --test), in its two states:
 *  - while pretrained/'s manifest lists no brain for any body of the study (served here as the
 *    committed manifest without one), the chapter says “not yet: the study is still training it”,
 *    asks nothing, holds no speed back, and its body walks on the phase gait; Back and Next work;
 *  - with one (a module made on the fly by `vsr evolve --bodies`, listed in a routed manifest with an
 *    `any_body` record as `vsr campaign export` writes it, served in place of pretrained/'s files,
 *    never written there): the chapter loads it onto its body with all its genes, asks first and holds
 *    the page's speeds back; a new body typed in “Rows” walks with the same genes; after the
 *    answer, Reveal walks the module on that body and shows the speed beside the student's answer: the
 *    number “Your robot's speed” shows once revealed, and the study's figures of the manifest.
 * Needs target/release/vsr (VSR_BIN). Screenshots: screenshots/tour-any-body-{pending,revealed}-{1400,420}.png.
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtemp, readFile, rm } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { NOT_YET } from '../../www/shared/families.js';
import { CHAPTERS } from '../../www/tour/chapters.js';
import { BIN, ROOT, SCREENSHOTS, byTestId, openBare, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;
/** @type {string} */ let tmp;
/** The brain for any body made for this test: its file's text and its run. */
const made = { text: '', run: /** @type {any} */ (null) };
/** Where the made module is served (pretrained/ holds no such file: the routes answer for it). */
const MADE_KEY = 'pretrained/any-test-attention-any.json';
/** The chapter's number (1-based). */
const N = CHAPTERS.findIndex((c) => c.title === 'One brain for every body') + 1;
/** The body typed in “Rows” in place of the chapter's: a worm with four legs (11 voxels). */
const WORM = '1111111-1010101';
/**
 * The routed manifest's figures for the held-out random bodies: this test's numbers, not the study's (the page
 * must quote whatever the manifest says): four bodies, two above 1 m/s; the median over the runs it was chosen from 0.7.
 */
const HELDOUT = { name: 'heldout-random', file: 'bodies/heldout-random.txt', heldout: true, set: 'unseen', seconds: 2,
  median: 1.1, walking_share: 0.5, means: [0.2, 0.8, 1.4, 1.6], median_of_runs: 0.7 };

before(async () => {
  env = await start();
  tmp = await mkdtemp(path.join(os.tmpdir(), 'vsr-tour-any-body-'));
  const file = path.join(tmp, 'any.json');
  execFileSync(BIN, ['evolve', '--bodies', path.join(ROOT, 'campaigns/bodies/train-32.txt'), '--controller', 'attention-any',
    '--evals', '20', '--population', '10', '--seconds', '2', '--bodies-per-evaluation', '2', '--seed', '1', '--threads', '1',
    '--out', file], { stdio: 'pipe' });
  made.text = await readFile(file, 'utf8');
  made.run = JSON.parse(made.text);
});

after(async () => {
  await env?.close();
  await rm(tmp, { recursive: true, force: true });
});

/** The committed manifest, without any brain for any body of the study's. */
async function manifestWithout() {
  const manifest = JSON.parse(await readFile(path.join(ROOT, 'pretrained', 'manifest.json'), 'utf8'));
  manifest.modules = manifest.modules.filter((/** @type {any} */ m) => m.controller !== 'attention-any');
  return manifest;
}

/**
 * The genome the page keeps for its robot (float32 values; null with no brain), once it keeps the body `rows`.
 * @param {import('playwright-core').Page} page @param {string} rows @param {boolean} brain whether a brain is expected
 */
async function keptGenome(page, rows, brain) {
  const handle = await page.waitForFunction(([rows, brain]) => {
    const p = new URLSearchParams(localStorage.getItem('vsr-playground/state/v1') ?? '');
    return p.get('shape') === rows && p.has('genome') === brain ? String(p.get('genome')) : null;
  }, /** @type {[string, boolean]} */ ([rows, brain]), { timeout: 10_000, polling: 50 });
  if (!brain) return null;
  const bytes = Buffer.from(String(await handle.jsonValue()), 'base64url');
  return Array.from({ length: bytes.length / 4 }, (_, i) => bytes.readFloatLE(i * 4));
}

/**
 * Saves what the screen shows at 1400 and at 420 px (the tour's sheet at the bottom), `testid` brought into view in the tour's box.
 * @param {import('playwright-core').Page} page @param {string} name @param {string} testid
 */
async function shoot(page, name, testid) {
  const show = () => byTestId(page, testid).evaluate((e) => e.scrollIntoView({ block: 'nearest', behavior: 'instant' }));
  await show();
  await page.screenshot({ path: path.join(SCREENSHOTS, `${name}-1400.png`) });
  await page.setViewportSize({ width: 420, height: 860 });
  await page.waitForTimeout(300);
  await show();
  await page.screenshot({ path: path.join(SCREENSHOTS, `${name}-420.png`) });
  await page.setViewportSize({ width: 1400, height: 900 });
}

test('while the study trains its brain for any body, the chapter says “not yet” and asks nothing; the tour goes on', async () => {
  const { page, problems } = await openBare(env.browser, 'about:blank', { width: 1400, height: 900 });
  const manifest = await manifestWithout();
  await page.route('**/pretrained/manifest.json', (route) => route.fulfill({ json: manifest }));
  await page.goto(`${env.url}?chapter=${N}`);
  await page.locator('#tour-box[data-state="ready"]').waitFor({ timeout: 30_000 });
  assert.equal(await byTestId(page, 'tour-chapter').textContent(), 'One brain for every body');
  const pending = String(await byTestId(page, 'tour-pending').innerText());
  assert.ok(pending.startsWith(`The study's brain for any body: ${NOT_YET}. Until it is, this chapter has no brain to walk`), pending);
  assert.equal(await byTestId(page, 'tour-exercise').count(), 0, 'no task without its module');
  assert.equal(await page.locator('.tour-task, .tour-notice').count(), 0, 'no “Do” and no “Notice” about a walk that cannot be');
  assert.equal(await page.evaluate(() => document.body.hasAttribute('data-answer-held')), false, 'no question: no speed held back');
  const { rows } = CHAPTERS[N - 1].setup;
  await waitForText(page, 'status', new RegExp(`^${String(rows).split('').filter((c) => c === '1').length} voxels, phase gait$`));
  assert.equal(await page.locator('#rows').inputValue(), rows);
  assert.equal(await keptGenome(page, String(rows), false), null, 'no brain: no made-up module');
  await page.waitForTimeout(1000);
  await shoot(page, 'tour-any-body-pending', 'tour-pending');
  // The tour goes on: Back to the chapter before, Next to this one again.
  await byTestId(page, 'tour-back').click();
  await page.locator(`#tour-box[data-chapter="${N - 1}"][data-state="ready"]`).waitFor({ timeout: 30_000 });
  await byTestId(page, 'tour-next').click();
  await page.locator(`#tour-box[data-chapter="${N}"][data-state="ready"]`).waitFor({ timeout: 30_000 });
  assert.equal(await byTestId(page, 'tour-pending').isVisible(), true);
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('with the study\'s brain for any body: predict, draw, then Reveal walks it on that body and shows the measured speed '
  + 'beside the answer and the study\'s figures', async () => {
  const { page, problems } = await openBare(env.browser, 'about:blank', { width: 1400, height: 900 });
  const manifest = await manifestWithout();
  manifest.modules.push({ file: path.basename(MADE_KEY), shape: 'train-32', rows: made.run.best.shape, controller: 'attention-any', bodies: 32,
    seed: 1, budget: 20, evaluations: 20, training_best: made.run.best.fitness, chosen_from: 3,
    any_body: { group: 'any-train32', training_set: 'bodies/train-32.txt', per_evaluation: 2, chosen_by: 'this test', sets: [HELDOUT] } });
  await page.route('**/pretrained/manifest.json', (route) => route.fulfill({ json: manifest }));
  await page.route(`**/${MADE_KEY}`, (route) => route.fulfill({ body: made.text, contentType: 'application/json' }));
  await page.goto(`${env.url}?chapter=${N}`);
  await page.locator('#tour-box[data-state="ready"]').waitFor({ timeout: 30_000 });
  const genome = made.run.best.genome.map((/** @type {number} */ g) => Math.fround(g));
  const { rows } = CHAPTERS[N - 1].setup;
  await waitForText(page, 'status', new RegExp(`^${String(rows).split('').filter((c) => c === '1').length} voxels, attention, any body$`));
  assert.deepEqual(await keptGenome(page, String(rows), true), genome, 'the module on the chapter\'s body, all its genes');
  assert.equal(await byTestId(page, 'tour-pending').count(), 0);
  const task = byTestId(page, 'tour-exercise');
  assert.equal(await task.count(), 1, 'it asks first');
  assert.equal(await page.locator('.tour-notice').isVisible(), false, 'the Notice waits for the reveal');
  assert.equal(await page.evaluate(() => document.body.hasAttribute('data-answer-held')), true, 'the page holds its speeds back');
  assert.equal(await page.locator('#speed-note').isVisible(), false, '“Your robot\'s speed” waits for the reveal');

  // A body of the student's own, typed in “Rows”: the same genes walk it.
  await page.locator('#rows').fill(WORM);
  await page.locator('#rows').press('Enter');
  await waitForText(page, 'status', /^11 voxels, attention, any body$/);
  assert.deepEqual(await keptGenome(page, WORM, true), genome, 'the same genes on the new body');
  assert.equal(await page.locator('#speed-note').isVisible(), false, 'still held back');
  await task.locator('input[type=radio]').nth(1).check(); // 0.5 to 1 m/s
  await byTestId(page, 'tour-reveal').click();
  await page.locator('[data-testid="tour-exercise"][data-state="revealed"]').waitFor({ timeout: 60_000 });
  const text = (await byTestId(page, 'tour-answer').locator('p').allTextContents()).join(' ');
  console.log(`# ${text}`);
  const said = /The page's answer: (faster than 1 m\/s|from 0\.5 to 1 m\/s|slower than 0\.5 m\/s): (-?[\d.]+) m\/s on your body \(([01-]+), (\d+) voxels\)\./.exec(text);
  assert.ok(said, text);
  assert.equal(said[3], WORM, 'measured on the body drawn');
  const speed = Number(said[2]);
  const band = speed > 1 ? 'faster than 1 m/s' : speed >= 0.5 ? 'from 0.5 to 1 m/s' : 'slower than 0.5 m/s';
  assert.equal(said[1], band, 'the range the measured speed falls in');
  assert.match(text, /You said: from 0\.5 to 1 m\/s\./, 'the prediction beside the measurement');
  assert.equal(await task.getAttribute('data-right'), String(band === 'from 0.5 to 1 m/s'));
  assert.match(text, /The study walked it on 4 random bodies it never trained on, each on 10 new terrains: the median of those bodies' mean speeds is 1\.10 m\/s, and 2 of the 4 \(50%\) averaged more than 1 m\/s\./,
    'the study\'s figures, from the manifest');
  assert.match(text, /This brain is the one the study chose of its 3 runs of this kind \(by their speed on their own training bodies\); the middle run's brain walked 0\.70 m\/s there, below the 1 m\/s the study calls walking\./,
    'the typical run beside the chosen one');
  // Revealed: the page shows its own measure of the same walk, the number the answer gave.
  assert.equal(await page.locator('.tour-notice').isVisible(), true);
  assert.equal(await page.evaluate(() => document.body.hasAttribute('data-answer-held')), false);
  await page.waitForFunction(() => Number.isFinite(Number(document.getElementById('speed-note')?.dataset.value)), undefined, { timeout: 30_000 });
  const note = Number(await page.locator('#speed-note').getAttribute('data-value'));
  assert.equal(note.toFixed(2), speed.toFixed(2), `“Your robot's speed” (${note}) is the answer's`);
  assert.match(String(await page.locator('#speed-note').textContent()), new RegExp(`^Your robot's speed: ${speed.toFixed(2)} m/s`));
  // The module list names it with the same held-out median (it has no one body: no mean over the unseen terrains).
  const option = page.locator(`#module option[value="${MADE_KEY}"]`);
  assert.equal(await option.textContent(), 'attention, any body, trained on 32 bodies · 1.10 m/s median on new bodies');
  assert.match(String(await option.getAttribute('title')), /a median of 1\.10 m\/s over 4 bodies it never trained on \(each body's mean on 10 new terrains\), 2 of the 4 above 1 m\/s\)$/);
  await shoot(page, 'tour-any-body-revealed', 'tour-answer');
  assert.deepEqual(problems, []);
  await page.context().close();
});
