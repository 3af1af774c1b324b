// @ts-check
/**
 * Browser test of the guided tour and the study panel (node --test): every chapter opened
 * from its own link (?chapter=N) sets the playground up as chapters.js says: the body, the
 * brain (bit for bit: a module on its own body is its run file's best genome; a transplant
 * keeps the module's attention block), the viewer's terrain, the run settings, the race; the
 * viewer walks that robot. Back and Next step through the chapters and the address follows;
 * leaving the tour keeps the playground. The time to open each chapter is printed (from a
 * click on Next to the robot walking; a figure, not a pass mark). The study panel shows its
 * figures and walks a run's best. On a phone a touch on the page folds the tour's text away
 * (a new chapter shows it again), and a study figure fits the phone's width (a tap opens it
 * full size). A link to a chapter the tour does not have says how many it has. Screenshots:
 * screenshots/tour-N-{1400,420}.png, study-{1400,420}.png.
 */
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { CHAPTERS } from '../../www/tour/chapters.js';
import { FIGURES } from '../../www/tour/figures.js';
import { NOT_YET } from '../../www/shared/families.js';
import { ROOT, SCREENSHOTS, byTestId, openPage, start, waitForText } from './harness.mjs';

const STORAGE_KEY = 'vsr-playground/state/v1';
/**
 * The study's brain for any body in pretrained/ (its run file), as the manifest lists it, or '' while the study trains it: a
 * chapter with `anyBody` puts it on its body then, else says “not yet” (tour-any-body.test.mjs tests both with a routed manifest).
 */
const STUDY_ANY_BODY = (JSON.parse(readFileSync(path.join(ROOT, 'pretrained', 'manifest.json'), 'utf8')).modules ?? [])
  .filter((/** @type {{controller: string}} */ m) => m.controller === 'attention-any').map((/** @type {{file: string}} */ m) => `pretrained/${m.file}`)[0] ?? '';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

/** @param {string} file a run file of the repository @returns {{shape: string, genome: number[]}} its best */
function best(file) {
  return JSON.parse(readFileSync(path.join(ROOT, file), 'utf8')).best;
}

/** @param {string} text base64url of little-endian float32 @returns {number[]} */
function genomeOf(text) {
  const bytes = Buffer.from(text, 'base64url');
  return Array.from({ length: bytes.length / 4 }, (_, i) => bytes.readFloatLE(i * 4));
}

/** @param {import('playwright-core').Page} page */
async function ready(page) {
  await page.locator('#tour-box[data-state="ready"]').waitFor({ timeout: 20_000 });
}

/**
 * The page's state as it keeps it (the share link's format), once it shows `rows` on
 * `terrain`, with a brain or without.
 * @param {import('playwright-core').Page} page @param {string} rows @param {string | null} terrain
 * @param {boolean} brain
 */
async function kept(page, rows, terrain, brain) {
  const handle = await page.waitForFunction(([key, rows, terrain, brain]) => {
    const text = localStorage.getItem(key);
    const p = new URLSearchParams(text ?? '');
    return p.get('shape') === rows && (terrain === null || p.get('view') === terrain) && p.has('genome') === brain ? text : null;
  }, [STORAGE_KEY, rows, terrain, brain], { timeout: 5_000, polling: 50 });
  return new URLSearchParams(String(await handle.jsonValue()));
}

/**
 * Checks that the playground is set up as chapter `n` (1-based) says.
 * @param {import('playwright-core').Page} page @param {number} n
 */
async function checkSetup(page, n) {
  const { setup, title } = CHAPTERS[n - 1];
  assert.equal(await byTestId(page, 'tour-chapter').textContent(), title);
  const rows = setup.brain?.on === 'own' ? best(setup.brain.module).shape : /** @type {string} */ (setup.rows);
  const anyBody = setup.anyBody ? STUDY_ANY_BODY : ''; // the study's brain for any body, on the chapter's body with all its genes
  const state = await kept(page, rows, setup.terrain, setup.brain !== null || anyBody !== '');
  assert.equal(await page.locator('#rows').inputValue(), rows, `chapter ${n}: the body`);
  assert.equal(await page.locator('#terrain').inputValue(), setup.terrain, `chapter ${n}: the terrain`);
  const voxels = rows.split('').filter((c) => c === '1').length;
  const controller = setup.brain ? best(setup.brain.module).controller : anyBody ? 'attention, any body' : 'phase gait';
  await page.waitForFunction((text) => document.getElementById('status')?.textContent === text, `${voxels} voxels, ${controller}`);
  if (setup.anyBody && !anyBody) {
    assert.match(String(await byTestId(page, 'tour-pending').textContent()), new RegExp(`^The study's brain for any body: ${NOT_YET}\\.`), `chapter ${n}: not yet`);
  }
  if (anyBody) {
    assert.deepEqual(genomeOf(String(state.get('genome'))), best(anyBody).genome.map((g) => Math.fround(g)), `chapter ${n}: all the module's genes`);
  } else if (!setup.brain) {
    assert.equal(state.get('genome'), null, `chapter ${n}: no brain, the phase gait`);
  } else {
    const genome = genomeOf(String(state.get('genome')));
    const module = best(setup.brain.module).genome.map((g) => Math.fround(g));
    if (setup.brain.on === 'own') assert.deepEqual(genome, module, `chapter ${n}: the module's own genome`);
    else {
      assert.deepEqual(genome.slice(0, 32), module.slice(0, 32), `chapter ${n}: the transplant keeps the attention block`);
      assert.equal(genome.length, 32 + 4 * voxels + 1, `chapter ${n}: output weights for every voxel of the new body`);
    }
  }
  if (setup.gait) {
    assert.equal(await page.locator('#frequency').inputValue(), String(setup.gait.frequency), `chapter ${n}: the gait's f`);
    assert.equal(await page.locator('#phase').inputValue(), String(setup.gait.phase), `chapter ${n}: the gait's φ`);
  }
  for (const [key, value] of Object.entries(setup.run ?? {})) {
    assert.equal(await page.locator(`#run-${key}`).inputValue(), value, `chapter ${n}: run setting ${key}`);
  }
  if (setup.compare !== undefined) assert.equal(await page.locator('#run-compare').isChecked(), setup.compare);
  if (setup.controller) assert.equal(await byTestId(page, 'controller').inputValue(), setup.controller);
  if (setup.race) {
    await page.waitForFunction((n) => document.querySelectorAll('[data-testid="race-robot"]').length === n, setup.race.length);
    const raced = await byTestId(page, 'race-robot').evaluateAll((els) => els.map((e) => /** @type {HTMLElement} */ (e).dataset.controller));
    assert.deepEqual(raced, setup.race.map((m) => best(m).controller), `chapter ${n}: the race`);
  }
  assert.ok(await page.locator('.tour-target').count() >= 1, `chapter ${n}: the control it asks about is outlined`);
  // In view, above the tour's sheet on a phone: the control to use (the last outlined) whole, once the
  // page has settled (the tour points again a second after the chapter opens).
  const inView = () => {
    const sheet = /** @type {HTMLElement} */ (document.getElementById('tour-box')).getBoundingClientRect();
    const bottom = sheet.top > innerHeight / 3 ? sheet.top : innerHeight;
    const rects = [...document.querySelectorAll('.tour-target')].map((el) => el.getBoundingClientRect());
    const last = rects[rects.length - 1];
    return { bottom, tops: rects.map((r) => Math.round(r.top)), ends: rects.map((r) => Math.round(r.bottom)),
      ok: last.top >= -1 && (last.bottom <= bottom || last.top < bottom - 100) };
  };
  let seen = await page.evaluate(inView);
  for (let waited = 0; !seen.ok && waited < 3000; waited += 100) {
    await page.waitForTimeout(100);
    seen = await page.evaluate(inView);
  }
  assert.ok(seen.ok, `chapter ${n}: the control it asks about is in view (${JSON.stringify(seen)})`);
}

for (const [width, height] of [[1400, 900], [420, 860]]) {
  test(`every chapter from its own link sets the playground up as it says (${width} px)`, async () => {
    for (let n = 1; n <= CHAPTERS.length; n++) {
      const { page, problems } = await openPage(env.browser, `${env.url}?chapter=${n}`, { width, height, touch: width < 800 });
      await ready(page);
      await checkSetup(page, n);
      await page.waitForTimeout(1500); // a moment of walking in the screenshot
      await page.screenshot({ path: path.join(SCREENSHOTS, `tour-${n}-${width}.png`) });
      assert.deepEqual(problems, [], `chapter ${n}`);
      await page.context().close();
    }
  });
}

test('Learn opens chapter 1; Next and Back step, the address follows; leaving keeps the playground', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  await byTestId(page, 'tour').click();
  await ready(page);
  await checkSetup(page, 1);
  assert.equal(await byTestId(page, 'tour-back').isDisabled(), true);
  /** @type {number[]} */
  const times = [];
  /** @type {number[]} */
  const inPage = [];
  for (let n = 2; n <= CHAPTERS.length; n++) {
    const clicked = Date.now();
    await byTestId(page, 'tour-next').click();
    await page.waitForFunction((n) => document.getElementById('tour-box')?.dataset.chapter === String(n)
      && document.getElementById('tour-box')?.dataset.state === 'ready', n, { polling: 10, timeout: 20_000 });
    times.push(Date.now() - clicked);
    inPage.push(Number(await page.locator('#tour-box').getAttribute('data-opened-ms')));
    assert.equal(new URL(page.url()).searchParams.get('chapter'), String(n));
    await checkSetup(page, n);
  }
  const median = (/** @type {number[]} */ v) => v.slice().sort((a, b) => a - b)[v.length >> 1];
  console.log(`# opening chapters 2-${CHAPTERS.length} with Next, click to the robot walking (ms): ${times.join(', ')}; `
    + `max ${Math.max(...times)}, median ${median(times)}; measured in the page: ${inPage.join(', ')}`);
  assert.equal(await byTestId(page, 'tour-next').isDisabled(), true);
  await byTestId(page, 'tour-back').click();
  await page.waitForFunction((n) => document.getElementById('tour-box')?.dataset.chapter === String(n), CHAPTERS.length - 1);
  await ready(page);
  await checkSetup(page, CHAPTERS.length - 1);
  const rows = await page.locator('#rows').inputValue();
  await page.locator('#tour-close').click();
  assert.equal(await page.locator('#tour-box').isHidden(), true);
  assert.equal(new URL(page.url()).searchParams.get('chapter'), null, 'the address leaves the tour');
  assert.equal(await page.locator('#rows').inputValue(), rows, 'the playground stays as the chapter set it');
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('the study panel shows its figures, and one click walks a run\'s best robot', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  const figures = await byTestId(page, 'study-figure').locator('option').evaluateAll((os) => os.map((o) => /** @type {HTMLOptionElement} */ (o).value));
  for (const id of figures) {
    await byTestId(page, 'study-figure').selectOption(id);
    await page.waitForFunction(() => {
      const img = /** @type {HTMLImageElement} */ (document.getElementById('study-image'));
      return img.complete && img.naturalWidth > 0;
    });
    const fig = FIGURES.find((f) => f.id === id);
    if (fig?.runs.length === 0) { // runs the panel does not list (the body search's, the brains for any body's): it says where to look
      assert.equal(await page.locator('#study-run-bar').isHidden(), true, `${id}: no empty list of runs`);
      assert.ok(fig.elsewhere, `${id}: says where its results are`);
      assert.equal(await byTestId(page, 'study-run-note').textContent(), fig.elsewhere);
      assert.match(String(fig.elsewhere), /in the list of modules/);
      continue;
    }
    assert.ok(await byTestId(page, 'study-run').locator('option').count() >= 5, `${id}: its runs are listed`);
  }
  await byTestId(page, 'study-figure').selectOption('finetune-biped-large');
  const run = await byTestId(page, 'study-run').inputValue();
  assert.match(run, /^biped-4x3-attention-20000-to-biped-6x4-10000-s\d+$/, 'the fastest fine-tuned run is offered first');
  const words = await byTestId(page, 'study-run').locator('option:checked').textContent();
  assert.match(String(words), /^attention on biped-6x4, fine-tuned from biped-4x3-attention, seed \d+: /, 'the run in words, its seed once');
  await byTestId(page, 'study-watch').click();
  const runBest = best(`study/runs/${run}.json`);
  const state = await kept(page, runBest.shape, null, true);
  assert.deepEqual(genomeOf(String(state.get('genome'))), runBest.genome.map((g) => Math.fround(g)), 'that run\'s best genome walks');
  await page.waitForFunction(() => document.getElementById('status')?.textContent === '18 voxels, attention');
  await byTestId(page, 'study').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(SCREENSHOTS, 'study-1400.png') });
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('on a phone a touch on the page folds the tour\'s text away, and the next chapter shows it again', async () => {
  const { page, problems } = await openPage(env.browser, `${env.url}?chapter=1`, { width: 420, height: 860, touch: true });
  const box = page.locator('#tour-box');
  await page.locator('#tour-box[data-state="ready"]').waitFor();
  assert.equal(await page.locator('#tour-body').isVisible(), true, 'the chapter\'s text shows');
  const header = await page.locator('header h1').boundingBox();
  assert.ok(header);
  await page.touchscreen.tap(header.x + 20, header.y + 10);
  await page.locator('#tour-box.folded').waitFor();
  assert.equal(await page.locator('#tour-body').isVisible(), false, 'folded: the text is away');
  assert.equal(await page.locator('#tour-fold').textContent(), 'Show text');
  const sheet = await box.boundingBox();
  assert.ok(sheet && sheet.height < 200, `the folded sheet is small: ${sheet?.height} px`);
  await byTestId(page, 'tour-next').click();
  await page.locator('#tour-box[data-chapter="2"]').waitFor();
  assert.equal(await page.locator('#tour-body').isVisible(), true, 'a new chapter shows its text');
  assert.equal(await page.locator('#tour-fold').textContent(), 'Hide text');
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('on a phone a study figure fits the screen\'s width, and a tap opens it full size', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 420, height: 860, touch: true });
  await byTestId(page, 'study-figure').selectOption('finetune-biped-large');
  await page.waitForFunction(() => {
    const img = /** @type {HTMLImageElement} */ (document.getElementById('study-image'));
    return img.complete && img.naturalWidth > 0;
  });
  await byTestId(page, 'study-image').scrollIntoViewIfNeeded();
  const sizes = await page.evaluate(() => ({
    image: document.getElementById('study-image')?.getBoundingClientRect().right ?? Infinity,
    box: document.getElementById('study-full')?.getBoundingClientRect().right ?? 0,
    page: document.documentElement.scrollWidth,
  }));
  assert.ok(sizes.image <= sizes.box + 0.5 && sizes.page <= 420, `the figure fits its box and the page: ${JSON.stringify(sizes)}`);
  assert.equal(await page.locator('#study-full').getAttribute('href'), await byTestId(page, 'study-image').getAttribute('src'), 'a tap opens it full size');
  assert.equal(await page.locator('.figure-hint').isVisible(), true, 'the phone is told to tap it');
  await page.screenshot({ path: path.join(SCREENSHOTS, 'study-420.png') });
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('a link to a chapter the tour does not have says how many it has', async () => {
  const { page, problems } = await openPage(env.browser, `${env.url}?chapter=12`, { width: 1400, height: 900 });
  await waitForText(page, 'message', new RegExp(`no chapter “12”: the tour has ${CHAPTERS.length} chapters`));
  assert.equal(await page.locator('#tour-box').isVisible(), false);
  assert.deepEqual(problems, []);
  await page.context().close();
});
