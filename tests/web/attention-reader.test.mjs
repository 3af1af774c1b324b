// @ts-check
/**
 * Browser test of two lessons of the paper in the page (node --test): reading attention
 * (a click or tap on a voxel's map opens its matrix enlarged, rows named by query and
 * columns by key in the controller's sensor order, live values in [-1, 1], the value under
 * the pointer spelled out; at 1400 px it takes a row of its own under the robot and the
 * maps, with no blank area) and freezing it (paper Fig. 6, live: the pretrained attention
 * biped, frozen while it walks, loses more than two thirds of its speed; released, it is
 * no longer frozen; the verdict in words follows the two speeds). Saves screenshots/attention-reader-{1400,420}.png.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { byTestId, figure, openPage, screenshot, start, waitForFigure, waitForText } from './harness.mjs';
import { verdict } from '../../www/viewer/freeze.js';

const ATTENTION = 'pretrained/biped-4x3-attention.json';
const NAMES = ['area', 'vx', 'vy', 'touch'];

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

test('the freeze report says in words what the two speeds mean, once it has seen enough', () => {
  assert.equal(verdict(2, 0.1, 1), 'Watch a few seconds more…');
  assert.match(verdict(0.05, 0.04, 6), /^It was hardly walking before/);
  assert.match(verdict(2, -0.1, 6), /^Frozen, it nearly stops \(less than a tenth/);
  assert.equal(verdict(2, 0.05, 6), verdict(2, -0.05, 6), 'rocking on the spot, one wording whichever way it rocks');
  assert.match(verdict(2, 0.2, 6), /^Frozen, it keeps only 10% of its speed: its changing attention is what made it walk\.$/);
  assert.match(verdict(2, 1, 6), /^Frozen, it keeps 50% of its speed: its changing attention helps/);
  assert.match(verdict(2, 1.9, 6), /^Frozen, it keeps 95% of its speed: this robot walks about as well/);
  assert.match(verdict(NaN, NaN, 6), /^It was hardly walking/);
});

/** Opens the pretrained attention biped on its own body. @param {import('playwright-core').Page} page */
async function openAttentionBiped(page) {
  await byTestId(page, 'pretrained').selectOption(ATTENTION);
  await page.locator('#module-open').click();
  await waitForText(page, 'status', /^10 voxels, attention$/);
  await page.locator('#attention-panel').waitFor({ state: 'visible', timeout: 10_000 });
}

/**
 * Where on the screen the map of the voxel at grid (column, row from the top) is, the maps
 * being laid out like the robot's grid.
 * @param {import('playwright-core').Page} page @param {number} column @param {number} fromTop
 */
async function mapPoint(page, column, fromTop, columns = 4, rows = 3) {
  const box = await page.locator('#attention').boundingBox();
  if (!box) throw new Error('no attention maps on screen');
  return { x: box.x + (box.width / columns) * (column + 0.5), y: box.y + (box.height / rows) * (fromTop + 0.5) };
}

/** @param {import('playwright-core').Page} page */
async function readMatrix(page) {
  const table = byTestId(page, 'attention-matrix');
  const columns = await table.locator('thead th[scope="col"]').allTextContents();
  const rows = await table.locator('tbody th[scope="row"]').allTextContents();
  const values = (await table.locator('tbody td').evaluateAll((tds) => tds.map((td) => Number(/** @type {HTMLElement} */ (td).dataset.value))));
  return { columns, rows, values };
}

test('a click on a voxel\'s map shows its matrix enlarged, named and live; freezing stops the robot', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  await openAttentionBiped(page);
  const reader = byTestId(page, 'attention-reader');
  assert.equal(await reader.isVisible(), false, 'closed until a voxel is chosen');
  const point = await mapPoint(page, 3, 0); // the top right voxel: column 4, row 3
  await page.mouse.click(point.x, point.y);
  await reader.waitFor({ state: 'visible' });
  assert.match(String(await page.locator('#attention-reader-title').textContent()), /column 4, row 3/);
  // Laid out without a blank area: a row of its own right under the robot and the maps, as wide as both.
  const [scene, maps, opened] = await Promise.all(['#scene', '#attention-panel', '#attention-reader'].map((s) => page.locator(s).boundingBox()));
  if (!scene || !maps || !opened) throw new Error('the viewer, the maps and the reader are on screen');
  const gap = opened.y - Math.max(scene.y + scene.height, maps.y + maps.height);
  assert.ok(gap >= 0 && gap < 20, `the reader starts ${gap} px under the robot and the maps`);
  assert.ok(Math.abs(opened.x - scene.x) < 2 && Math.abs(opened.x + opened.width - (maps.x + maps.width)) < 2, `as wide as both: ${JSON.stringify([scene, maps, opened])}`);
  const first = await readMatrix(page);
  assert.deepEqual(first.columns, NAMES);
  assert.deepEqual(first.rows, NAMES);
  assert.equal(first.values.length, 16);
  assert.ok(first.values.every((v) => v >= -1 && v <= 1), `values in [-1, 1]: ${first.values}`);
  await page.locator('#attention-matrix tbody tr').nth(3).locator('td').nth(1).hover();
  await waitForText(page, 'attention-hover', /^Row touch \(query\), column vx \(key\): [+−]\d\.\d{3}$/);
  assert.match(String(await page.locator('#attention-terms').textContent()), /a = −?\d/);
  await waitForFigure(page, 'sim-time', 'v >= 1', 30_000);
  const later = await readMatrix(page);
  assert.notDeepEqual(later.values, first.values, 'the enlarged matrix follows the walk');

  // Freeze the attention of the walking robot after 6 s, watch 6 s more.
  await waitForFigure(page, 'sim-time', 'v >= 6', 60_000);
  const freeze = byTestId(page, 'freeze-attention');
  assert.equal(await freeze.isEnabled(), true);
  await freeze.click();
  await page.waitForFunction(() => document.querySelector('[data-testid="freeze-attention"]')?.getAttribute('aria-pressed') === 'true');
  const frozenAt = await figure(page, 'sim-time');
  await waitForFigure(page, 'sim-time', `v >= ${frozenAt + 6}`, 60_000);
  const report = byTestId(page, 'freeze-report');
  const beforeSpeed = Number(await report.getAttribute('data-before'));
  const afterSpeed = Number(await report.getAttribute('data-after'));
  console.log(`# frozen at ${frozenAt.toFixed(1)} s: ${beforeSpeed.toFixed(2)} m/s before, ${afterSpeed.toFixed(2)} m/s over the last 2 of the 6 s after`);
  assert.ok(beforeSpeed > 1, `it walked before: ${beforeSpeed}`);
  assert.ok(Math.abs(afterSpeed) < beforeSpeed / 3, `more than two thirds slower frozen: ${beforeSpeed} -> ${afterSpeed}`);
  assert.match(String(await report.textContent()), /^Before freezing: \d+\.\d\d m\/s over the last \d+\.\d s\. Frozen for \d+\.\d s: −?\d+\.\d\d m\/s over the last [12]\.\d s\. Frozen, it (keeps only \d+% of its speed|nearly stops \(less than a tenth of its speed before, rocking on the spot\)): its changing attention is what made it walk\.$/);
  const held = await readMatrix(page);
  await page.waitForTimeout(500);
  assert.deepEqual((await readMatrix(page)).values, held.values, 'frozen, the matrix holds still');
  await screenshot(page, 'attention-reader-1400.png');
  await freeze.click();
  await page.waitForFunction(() => document.querySelector('[data-testid="freeze-attention"]')?.getAttribute('aria-pressed') === 'false');
  assert.equal(await freeze.textContent(), 'Freeze the attention');
  await page.locator('#attention-reader-close').click();
  assert.equal(await reader.isVisible(), false);
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('on a phone a tap opens the reader; a brain without attention cannot be frozen', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 420, height: 860, touch: true });
  assert.equal(await byTestId(page, 'freeze-attention').isDisabled(), true, 'the phase gait has no attention');
  await openAttentionBiped(page);
  await page.locator('#attention').scrollIntoViewIfNeeded();
  const point = await mapPoint(page, 0, 2); // bottom left voxel: column 1, row 1
  await page.touchscreen.tap(point.x, point.y);
  await byTestId(page, 'attention-reader').waitFor({ state: 'visible' });
  assert.match(String(await page.locator('#attention-reader-title').textContent()), /column 1, row 1/);
  await waitForFigure(page, 'sim-time', 'v >= 2', 30_000);
  await screenshot(page, 'attention-reader-420.png');
  await byTestId(page, 'pretrained').selectOption('pretrained/biped-4x3-mlp.json');
  await page.locator('#module-open').click();
  await waitForText(page, 'status', /^10 voxels, mlp$/);
  assert.equal(await byTestId(page, 'freeze-attention').isDisabled(), true, 'an MLP has no attention');
  assert.deepEqual(problems, []);
  await page.context().close();
});
