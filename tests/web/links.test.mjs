// @ts-check
/**
 * Browser test of what a visitor meets first (node --test): a link that cannot be opened
 * keeps its message on screen (3 s later it is still there, saying what is shown instead)
 * until it is closed; a link whose brain is damaged opens its robot and settings without the
 * brain, and says so; after Share, a later edit survives a reload (the shared link never
 * brings back an older robot); Evolve and Fine-tune are on the first screen at 1400 x 900,
 * and on a 420 px phone within one screen of the robot.
 * Saves screenshots/first-screen.png and screenshots/first-screen-phone.png.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { byTestId, clickCells, openPage, screenshot, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

test('a damaged link keeps its message, saying what is shown instead, until it is closed', async () => {
  for (const hash of ['#shape=1111-1111-1001&controller=quantum', '#x7Qp!!random', '#shape=101-000-101&controller=attention']) {
    const { page, problems, context } = await openPage(env.browser, `${env.url}${hash}`);
    await waitForText(page, 'message', /could not be opened/);
    await page.waitForTimeout(3000); // the robot loads and walks meanwhile
    const box = byTestId(page, 'message');
    assert.equal(await box.isVisible(), true, `the message of ${hash} is still on screen 3 s later`);
    assert.match(String(await box.textContent()), /Shown instead: the example robot biped-4x3, 1111-1111-1001/);
    assert.equal(new URL(page.url()).hash, '', 'the link left the address bar: a reload shows the kept robot');
    await box.locator('[data-testid="message-close"]').click();
    assert.equal(await box.isHidden(), true, 'closed');
    assert.deepEqual(problems, []);
    await context.close();
  }
});

test('a link whose brain is damaged opens its robot and settings without the brain, and says so', async () => {
  const settings = 'shape=1111111-1010101&controller=attention&view=hilly-1-10-3&population=12&seconds=12&budget=240&seed=7&train=hilly-1-10';
  for (const [genome, why] of [['AAAAAAAAAAA', /genome has 2 genes/], ['%%%', /not valid base64/]]) {
    const { page, problems, context } = await openPage(env.browser, `${env.url}#${settings}&brain=attention&genome=${genome}`);
    await waitForText(page, 'message', /The brain in this link is damaged/);
    const text = String(await byTestId(page, 'message').textContent());
    assert.match(text, new RegExp(`The brain in this link is damaged \\(.*${why.source}.*\\): the robot and settings are opened without it`));
    await waitForText(page, 'status', /^11 voxels, phase gait$/);
    assert.equal(await page.locator('#rows').inputValue(), '1111111-1010101', 'the link\'s comb, not the example');
    const values = await page.evaluate(() => ['terrain', 'run-population', 'run-seconds', 'run-budget', 'run-seed', 'run-terrain']
      .map((id) => /** @type {HTMLInputElement} */ (document.getElementById(id))?.value));
    assert.deepEqual(values, ['hilly-1-10-3', '12', '12', '240', '7', 'hilly-1-10'], 'its terrain and run settings');
    await page.waitForTimeout(3000);
    assert.equal(await byTestId(page, 'message').isVisible(), true, 'the message stays');
    assert.deepEqual(problems, []);
    await context.close();
  }
});

test('after Share, an edit survives a reload: the shared link does not bring back the older robot', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url);
  await byTestId(page, 'preset').selectOption({ label: 'comb-7x2' });
  await waitForText(page, 'status', /^11 voxels/);
  await byTestId(page, 'share').click();
  await page.waitForFunction(() => location.hash.includes('shape=1111111-1010101'));
  await clickCells(page, [[0, 2]]); // an edit after sharing
  await waitForText(page, 'status', /^12 voxels/);
  await page.waitForTimeout(600); // kept after a short delay
  await page.reload();
  await waitForText(page, 'status', /^12 voxels/);
  assert.equal(await page.locator('#rows').inputValue(), '1000000-1111111-1010101');
  assert.deepEqual(problems, []);
  await context.close();
});

/** The page box of a test id. @param {import('playwright-core').Page} page @param {string} id */
async function boxOf(page, id) {
  const box = await byTestId(page, id).boundingBox();
  if (!box) throw new Error(`${id} is not visible`);
  return box;
}

test('Evolve and Fine-tune: on the first screen at 1400 x 900, within one screen of the robot on a phone', async () => {
  const wide = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  for (const id of ['evolve', 'finetune']) {
    const box = await boxOf(wide.page, id);
    assert.ok(box.y >= 0 && box.y + box.height <= 900, `${id} is at y ${box.y}..${box.y + box.height}, not within 900 px`);
  }
  await screenshot(wide.page, 'first-screen.png');
  assert.deepEqual(wide.problems, []);
  await wide.context.close();

  const phone = await openPage(env.browser, env.url, { width: 420, height: 860, touch: true });
  const robot = await boxOf(phone.page, 'viewer');
  for (const id of ['evolve', 'finetune']) {
    const box = await boxOf(phone.page, id);
    const below = box.y + box.height - robot.y;
    assert.ok(below <= 860, `${id} ends ${below} px under the top of the robot's view: more than one 860 px screen`);
  }
  await screenshot(phone.page, 'first-screen-phone.png');
  assert.deepEqual(phone.problems, []);
  await phone.context.close();
});

test('a glossary explains every word of the page; the paper and the study are linked; no internal names', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url);
  const glossary = byTestId(page, 'glossary');
  assert.equal(await glossary.evaluate((d) => /** @type {HTMLDetailsElement} */ (d).open), false);
  await page.locator('#glossary-open').click();
  assert.equal(await glossary.evaluate((d) => /** @type {HTMLDetailsElement} */ (d).open), true, 'the Glossary button opens it');
  const terms = (await glossary.locator('dt').allTextContents()).join(' | ');
  for (const word of ['voxel', 'module', 'attention', 'sensor', 'fitness', 'generation', 'evaluation', 'population', 'episode',
    'transplant', 'fine-tune', 'from scratch', 'phase gait', 'seed', 'terrain', 'budget', 'playing at']) {
    assert.match(terms, new RegExp(word), `the glossary explains "${word}"`);
  }
  assert.match(String(await glossary.textContent()), /query.*keys/s);
  const paper = page.locator('header .expert a[href="https://arxiv.org/abs/2204.06547"]'); // simple words has its own, “their paper”
  assert.match(String(await paper.textContent()), /Evolving Modular Soft Robots without Explicit Inter-Module Communication using Local Self-Attention/);
  assert.equal(await page.locator('header a', { hasText: 'what our study found' }).getAttribute('href'), '#results-plain',
    'the header opens the results in plain words');
  const researchers = await page.locator('#results-plain a', { hasText: 'researchers' }).getAttribute('href');
  const response = await page.request.get(new URL(String(researchers), env.url).href);
  assert.equal(response.status(), 200, 'the study\'s results for researchers are served with the page');
  assert.match(String(response.headers()['content-type']), /^text\/html/, 'as a web page (docs/RESULTS.md rendered)');
  const results = await response.text();
  assert.match(results, /<h1[^>]*>Results/);
  assert.doesNotMatch(results, /^#+ /m, 'no raw Markdown');
  const visible = await page.evaluate(() => document.body.innerText + [...document.querySelectorAll('[title]')].map((e) => e.getAttribute('title')).join(' '));
  for (const internal of [/SPEC \d/, /downstream/i, /\bengine\b/i, /sim s \/ wall s/, /\.js\b/, /\bevals\b/]) {
    assert.doesNotMatch(visible, internal, `the page shows ${internal}`);
  }
  assert.deepEqual(problems, []);
  await context.close();
});
