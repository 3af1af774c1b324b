// @ts-check
/**
 * Browser test of messages about an input (node --test), as a person fixes what they typed:
 * rows or a terrain refused stay typed, marked (aria-invalid, red), said right under their field
 * (the page does not move away from it, on a phone either), while the robot keeps the last valid
 * ones; the terrain in a student's words, the core's exact rule folded under them; a field's
 * message is replaced by its next one and goes once the field holds a valid value (typed, or
 * the drawing's rows after a stroke on the grid), the other field's staying; run settings that are not valid say so at once in the plan line, with
 * Evolve off, one problem at a time, until they are fixed; a run file that cannot be read
 * replaces the previous one's message and goes when a good file is imported. Messages sit
 * in the page's flow, covering no control, at 1400 and at 420 px wide. Share link is off, its
 * tooltip saying why, while the drawing is not a robot (empty, in pieces) or a setting would
 * make a link that cannot be opened; it never makes such a link, and is on again once fixed. Saves
 * screenshots/input-message.png, input-message-phone.png, terrain-message.png and terrain-message-phone.png.
 */
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { ROOT, byTestId, clickCells, openPage, screenshot, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

/** The texts of the messages on screen, oldest first. @param {import('playwright-core').Page} page */
async function shown(page) {
  return byTestId(page, 'message').locator('.message:visible > span').allTextContents();
}

/** Types `text` in the field #id, as a person does (then Enter). @param {import('playwright-core').Page} page @param {string} id @param {string} text */
async function type(page, id, text) {
  await page.locator(`#${id}`).fill(text);
  await page.locator(`#${id}`).press('Enter');
}

/** @param {import('playwright-core').Page} page @param {string} text */
const typeRows = (page, text) => type(page, 'rows', text);

/**
 * The field #id keeps `typed`, marked as not valid (aria-invalid and a red border), and it and
 * its message are on screen. @param {import('playwright-core').Page} page @param {string} id @param {string} typed
 */
async function refusedInView(page, id, typed) {
  const field = page.locator(`#${id}`);
  assert.equal(await field.inputValue(), typed, `#${id} keeps what was typed`);
  assert.equal(await field.getAttribute('aria-invalid'), 'true', `#${id} is marked`);
  assert.equal(await field.evaluate((f) => getComputedStyle(f).borderTopColor), 'rgb(180, 35, 24)', `#${id} is red`);
  const height = page.viewportSize()?.height ?? 0;
  for (const box of [await field.boundingBox(), await byTestId(page, `${id}-message`).boundingBox()]) {
    assert.ok(box && box.y >= 0 && box.y + box.height <= height + 1, `#${id} and its message on screen: ${JSON.stringify(box)}`);
  }
}

/** The field #id is unmarked and says nothing. @param {import('playwright-core').Page} page @param {string} id */
async function accepted(page, id) {
  await page.waitForFunction((i) => !document.getElementById(i)?.hasAttribute('aria-invalid'), id, { timeout: 5_000 });
  assert.equal(await byTestId(page, `${id}-message`).isHidden(), true, `no message under #${id}`);
}

/** The page with the example robot walking. @param {number} [width] */
async function fresh(width) {
  const opened = await openPage(env.browser, env.url, width ? { width, height: 900 } : {});
  await waitForText(opened.page, 'status', /^10 voxels/);
  return opened;
}

/** No message left and nothing went wrong: the page closes. @param {Awaited<ReturnType<typeof openPage>>} opened */
async function closeClean({ page, problems, context }) {
  assert.equal(await page.locator('.message').count(), 0, 'no message left');
  assert.deepEqual(problems, []);
  await context.close();
}

/** The visible controls a message box overlaps (none expected). @param {import('playwright-core').Page} page @param {string} [id] the box */
async function covered(page, id = 'message') {
  return page.evaluate((id) => {
    const box = /** @type {HTMLElement} */ (document.getElementById(id)).getBoundingClientRect();
    const controls = [...document.querySelectorAll('button, input, select, canvas, summary, a')];
    return controls.filter((c) => {
      const r = c.getBoundingClientRect();
      const visible = r.width > 0 && r.height > 0 && getComputedStyle(c).visibility !== 'hidden' && !c.closest(`#${id}`);
      return visible && r.left < box.right && r.right > box.left && r.top < box.bottom && r.bottom > box.top;
    }).map((c) => c.id || c.textContent?.trim().slice(0, 30) || c.tagName);
  }, id);
}

test('refused rows stay typed and marked under their field; the next refusal replaces the message, good rows take it away', async () => {
  for (const [width, name] of /** @type {[number, string][]} */ ([[1400, 'input-message.png'], [420, 'input-message-phone.png']])) {
    const opened = await fresh(width);
    const { page } = opened;
    await page.locator('#rows').scrollIntoViewIfNeeded();
    await typeRows(page, '11a1-1111');
    await waitForText(page, 'rows-message', /^rows hold only 1 \(voxel\) and 0 \(empty\), separated by -/);
    await page.waitForTimeout(500); // nothing puts the old rows back
    await refusedInView(page, 'rows', '11a1-1111');
    assert.match(String(await page.locator('#status').textContent()), /^10 voxels/, 'the robot keeps its body');
    assert.deepEqual(await covered(page, 'rows-message'), [], `at ${width} px the message covers no control`);
    await screenshot(page, name);
    await typeRows(page, '11-1');
    await waitForText(page, 'rows-message', /^every row needs the same number of cells/);
    assert.deepEqual(await shown(page), [], 'nothing about the rows at the top');
    assert.equal((await byTestId(page, 'rows-message').locator('.message').count()), 1, 'one message about the rows, the newest');
    await typeRows(page, '111-101');
    await waitForText(page, 'status', /^5 voxels/);
    await accepted(page, 'rows');
    await closeClean(opened); // well-formed rows: the message went
  }
});

test('a refused terrain stays typed and marked, said in a student\'s words under its field; the robot walks on the last one', async () => {
  for (const [width, name] of /** @type {[number, string][]} */ ([[1400, 'terrain-message.png'], [420, 'terrain-message-phone.png']])) {
    const opened = await fresh(width);
    const { page } = opened;
    const terrain = page.locator('#terrain');
    await terrain.scrollIntoViewIfNeeded();
    await type(page, 'terrain', 'hily');
    const says = byTestId(page, 'terrain-message').locator('.message');
    await says.waitFor();
    const words = String(await says.locator('> span').textContent());
    assert.match(words, /^“hily” is not a terrain\. Try flat \(level ground\); hilly-1-10-0 \(hills: about every 10 m the ground goes up or down by about 1 m; the last number picks one of many such grounds/);
    assert.match(words, /uphill-10 or downhill-10 \(a slope of 10°\)/);
    assert.doesNotMatch(words, /\bsd\b|SEED|DEG|>=|\(-89/, 'no programmer\'s notation in the words');
    await page.waitForTimeout(500);
    await refusedInView(page, 'terrain', 'hily');
    await screenshot(page, name);
    const rule = says.locator('details');
    assert.equal(await rule.evaluate((d) => /** @type {HTMLDetailsElement} */ (d).open), false, 'the exact rule is folded');
    await rule.locator('summary').click();
    assert.match(String(await rule.textContent()), /'hily': unknown terrain; accepted forms: flat, hilly-H-W-SEED/, 'the core\'s exact words');
    await rule.locator('summary').click();
    // The robot walks on hilly-1-10-0, and that is what is measured and kept.
    await waitForText(page, 'robot-speed', /on hilly-1-10-0/);
    await typeRows(page, '11a1'); // a mistake in the other field: its own message
    await waitForText(page, 'rows-message', /^rows hold only 1/);
    await byTestId(page, 'editor').scrollIntoViewIfNeeded();
    await clickCells(page, [[4, 0]]); // a stroke on the grid: the rows field holds the drawing's rows again
    await page.waitForFunction(() => /** @type {HTMLInputElement} */ (document.getElementById('rows')).value === '11110-11110-10011');
    await accepted(page, 'rows');
    await page.waitForFunction(() => (localStorage.getItem('vsr-playground/state/v1') ?? '').includes('shape=11110-11110-10011'));
    assert.match(String(await page.evaluate(() => localStorage.getItem('vsr-playground/state/v1'))), /view=hilly-1-10-0/, 'the kept terrain is the one walked on');
    assert.equal(await terrain.inputValue(), 'hily', 'the terrain typed stays');
    assert.equal(await terrain.getAttribute('aria-invalid'), 'true');
    assert.match(String(await says.textContent()), /^“hily” is not a terrain/, 'the message about the terrain stays');
    await type(page, 'terrain', 'flat');
    await accepted(page, 'terrain');
    await waitForText(page, 'robot-speed', /on flat/);
    await closeClean(opened);
  }
});

test('run settings that are not valid say so at once in the plan line, with Evolve off until fixed', async () => {
  const opened = await fresh();
  const { page } = opened;
  const evolve = page.locator('#run-evolve');
  await waitForText(page, 'run-plan', /^A budget of/);
  assert.equal(await evolve.isEnabled(), true);
  await page.locator('#run-population').fill('0');
  await waitForText(page, 'run-plan', /^Not valid yet: population must be a whole number of at least 1, not "0"/);
  assert.equal(await evolve.isDisabled(), true, 'Evolve is off');
  await page.locator('#run-seconds').fill('-3');
  await waitForText(page, 'run-plan', /^Not valid yet: population/);
  await page.locator('#run-population').fill('20');
  await waitForText(page, 'run-plan', /^Not valid yet: episode seconds must be a positive number, not "-3"/);
  assert.equal(await evolve.isDisabled(), true, 'still off');
  await page.locator('#run-terrain').fill('moon');
  await page.locator('#run-seconds').fill('10');
  await waitForText(page, 'run-plan', /^Not valid yet: training terrain:/);
  await page.locator('#run-terrain').fill('hilly-1-10');
  await waitForText(page, 'run-plan', /^A budget of/);
  assert.equal(await evolve.isEnabled(), true, 'fixed: Evolve is on');
  await closeClean(opened); // no message piled up
});

test('an unreadable run file: the next one replaces its message, a good one takes it away', async () => {
  const opened = await fresh();
  const { page } = opened;
  const file = page.locator('#run-import');
  const bad = (/** @type {string} */ name) => ({ name, mimeType: 'application/json', buffer: Buffer.from('{"not": "a run"}') });
  await file.setInputFiles(bad('one.json'));
  await waitForText(page, 'message', /one\.json is not a run file/);
  await file.setInputFiles(bad('two.json'));
  await waitForText(page, 'message', /two\.json is not a run file/);
  assert.equal((await shown(page)).length, 1, 'the second file\'s message replaced the first');
  const good = path.join(ROOT, 'pretrained', 'biped-4x3-mlp.json');
  await file.setInputFiles({ name: 'good.json', mimeType: 'application/json', buffer: fs.readFileSync(good) });
  await page.waitForFunction(() => document.getElementById('message')?.hasAttribute('hidden'), undefined, { timeout: 20_000 });
  await closeClean(opened);
});

test('Share link is off while the drawing is not a robot or a setting is not valid, says why, and never makes a broken link', async () => {
  const opened = await fresh();
  const { page } = opened;
  const share = byTestId(page, 'share');
  const title = await share.getAttribute('title');
  const off = async (/** @type {RegExp} */ why) => {
    await page.waitForFunction(() => /** @type {HTMLButtonElement} */ (document.getElementById('share')).disabled);
    assert.match(String(await share.getAttribute('title')), why);
  };
  await page.locator('#clear').click();
  await off(/^Share link is off: a link opens your drawing, and it is empty: draw a robot \(or Undo\) to share it\.$/);
  await share.evaluate((b) => { /** @type {HTMLButtonElement} */ (b).disabled = false; }); // clicked before the button turned off
  await share.click();
  await waitForText(page, 'message', /^No link was made: a link opens your drawing, and it is empty/);
  assert.equal(await page.locator('#share-link').isHidden(), true, 'no link shown');
  assert.equal(await page.evaluate(() => location.hash), '', 'no link in the address bar');
  await byTestId(page, 'message').getByTestId('message-close').click();
  await typeRows(page, '1101-1101-1001');
  await off(/^Share link is off: a link opens your drawing, and it is in 2 separate pieces: make it one whole robot \(or Undo\) to share it\.$/);
  await typeRows(page, '1111-1101-1001');
  await page.waitForFunction(() => !(/** @type {HTMLButtonElement} */ (document.getElementById('share')).disabled));
  assert.equal(await share.getAttribute('title'), title, 'its own tooltip back');
  await page.locator('#run-population').fill('0');
  await page.locator('#run-population').dispatchEvent('change');
  await off(/^Share link is off: its link would not open \(population "0" is not a whole number from 1\)/);
  await page.locator('#run-population').fill('20');
  await page.locator('#run-population').dispatchEvent('change');
  await share.click(); // on again: its link opens the robot it shares
  await page.waitForFunction(() => (document.getElementById('share-link')?.dataset.value ?? '').includes('#'));
  const link = String(await page.locator('#share-link').getAttribute('data-value'));
  await byTestId(page, 'message').getByTestId('message-close').click(); // the note that the link is ready
  const other = await openPage(env.browser, link);
  await waitForText(other.page, 'status', /^9 voxels/);
  assert.equal(await other.page.locator('#rows').inputValue(), '1111-1101-1001');
  await closeClean(other);
  await closeClean(opened);
});

test('what was kept from the last visit and can no longer be opened is said, not dropped in silence', async () => {
  const opened = await openPage(env.browser, env.url);
  const { page } = opened;
  const key = 'vsr-playground/state/v1';
  await page.waitForFunction((k) => !!localStorage.getItem(k), key);
  await page.evaluate((k) => { // a kept state with a run setting no link would open
    const state = String(localStorage.getItem(k));
    localStorage.setItem(k, /population=\d+/.test(state) ? state.replace(/population=\d+/, 'population=0') : `${state}&population=0`);
  }, key);
  await page.reload();
  await waitForText(page, 'message', /^What this page kept from your last visit could not be opened \(.*population.*\): the example robot .* is shown instead\./);
  await byTestId(page, 'message').getByTestId('message-close').click(); // it stays until read
  await closeClean(opened);
});
