// @ts-check
/**
 * Browser test of the numbers the page shows (node --test): the viewer measures its own robot
 * as training does. A pretrained module opened on its own body walks an episode of the
 * length it was trained on; the viewer's speed over that episode equals `vsr evaluate` on the
 * same genome, terrain and seconds (to 1e-9; needs target/release/vsr, VSR_BIN), and so does
 * the speed measured at once beside the training figure; the distance counts from the start
 * (0 m at first, not the robot's place on the terrain). A module transplanted onto a drawn
 * robot shows its one-shot speed at once, says what to do next, and the viewer's own measure
 * over the episode agrees with it. A budget says what it becomes (2020 evaluations).
 * Saves screenshots/numbers.png.
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { BIN, ROOT, byTestId, clickCells, figure, openPage, screenshot, start, waitForText } from './harness.mjs';

const ATTENTION = 'pretrained/biped-4x3-attention.json';
const TERRAIN = 'hilly-1-10-7';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

/** Waits until the viewer's episode ended and returns its speed. @param {import('playwright-core').Page} page */
async function episodeSpeed(page) {
  await page.waitForFunction(() => document.getElementById('robot-speed')?.dataset.ended === 'true', undefined, { timeout: 120_000 });
  return figure(page, 'robot-speed');
}

test('the viewer\'s speed over an episode is `vsr evaluate`\'s; the distance counts from the start', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url);
  await page.locator('#terrain').fill(TERRAIN);
  await page.locator('#terrain').press('Enter');
  await byTestId(page, 'pretrained').selectOption(ATTENTION);
  await page.locator('#module-open').click();
  await waitForText(page, 'status', /^10 voxels, attention$/);
  await waitForText(page, 'module-details', /budget 30000 evaluations \(it took 30100: a run finishes its last generation\)/);
  await page.waitForFunction(() => Number(document.getElementById('sim-time')?.dataset.value) < 1);
  const x = await figure(page, 'robot-x');
  assert.ok(Math.abs(x) < 0.5, `the distance from the start reads ${x} m in the first second`);
  await page.locator('#speed').selectOption('0'); // as fast as possible
  const viewed = await episodeSpeed(page);
  const seconds = JSON.parse(await readFile(path.join(ROOT, ATTENTION), 'utf8')).config.seconds;
  const cli = JSON.parse(execFileSync(BIN, ['evaluate', '--genome', path.join(ROOT, ATTENTION), '--terrain', TERRAIN,
    '--seconds', String(seconds)], { encoding: 'utf8' }));
  assert.ok(Math.abs(viewed - cli.velocity) <= 1e-9, `viewer ${viewed} m/s, vsr evaluate ${cli.velocity} m/s`);
  assert.match(String(await byTestId(page, 'viewer-speed').textContent()), new RegExp(`over its ${seconds}-s episode on ${TERRAIN}`));
  await page.waitForFunction(() => Number.isFinite(Number(document.getElementById('speed-note')?.dataset.value)));
  const atOnce = await figure(page, 'speed-note');
  assert.ok(Math.abs(atOnce - cli.velocity) <= 1e-9, `measured at once ${atOnce} m/s, vsr evaluate ${cli.velocity} m/s`);
  assert.match(String(await byTestId(page, 'speed-note').textContent()), /In training: .* drawn fresh/);
  assert.deepEqual(problems, []);
  await context.close();
});

test('a transplant shows its one-shot speed at once and says to fine-tune; a budget says what it becomes', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url);
  await page.locator('#clear').click();
  await clickCells(page, [[0, 0], [1, 0], [2, 0], [3, 0], [4, 0]]); // a 5-voxel worm
  await byTestId(page, 'pretrained').selectOption(ATTENTION);
  await byTestId(page, 'load-pretrained').click();
  await waitForText(page, 'status', /^5 voxels, attention$/);
  await waitForText(page, 'speed-note', /one-shot speed.*the paper found the same.*Fine-tune/, 30_000);
  const oneShot = await figure(page, 'speed-note');
  assert.ok(Number.isFinite(oneShot));
  await page.locator('#speed').selectOption('0');
  const viewed = await episodeSpeed(page);
  assert.equal(viewed, oneShot, 'the viewer measures over the episode what was measured at once');
  assert.match(String(await page.locator('#run-plan').textContent()), /budget of 2000 evaluations.*50 generations.*takes 2020/);
  await screenshot(page, 'numbers.png');
  assert.deepEqual(problems, []);
  await context.close();
});
