// @ts-check
/**
 * Browser test of the page (node --test): serves www/ on a free port, opens it in
 * headless Debian Chromium through playwright-core, and checks that the real wasm
 * simulation runs in the worker and is drawn: the robot's x changes, the speed figure
 * appears, bad input shows a readable message while the previous robot keeps going,
 * and nothing is logged as an error; a pretrained attention controller walks and its
 * attention matrices are drawn, and a malformed run file from disk is refused while it
 * keeps walking. Saves tests/web/screenshots/page.png and attention.png.
 * Needs `make wasm` (www/pkg) first; CHROMIUM overrides /usr/bin/chromium.
 */
import assert from 'node:assert/strict';
import { mkdir } from 'node:fs/promises';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { serve } from '../../scripts/serve.mjs';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const SCREENSHOT = path.join(HERE, 'screenshots', 'page.png');
const ATTENTION_SCREENSHOT = path.join(HERE, 'screenshots', 'attention.png');
const ATTENTION_RUN = 'pretrained/biped-4x3-attention-seed1.json';
const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic',
  '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'];

/** @type {import('node:http').Server} */ let server;
/** @type {import('playwright-core').Browser} */ let browser;
/** @type {import('playwright-core').Page} */ let page;
/** Console errors, page errors and failed requests seen so far. @type {string[]} */
const problems = [];

before(async () => {
  const served = await serve({ port: 0 });
  server = served.server;
  browser = await chromium.launch({ executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium', args: CHROMIUM_ARGS });
  page = await browser.newPage({ viewport: { width: 1200, height: 900 } });
  page.on('console', (msg) => { if (msg.type() === 'error') problems.push(`console: ${msg.text()}`); });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('requestfailed', (req) => problems.push(`request failed: ${req.url()}`));
  page.on('worker', (worker) => worker.on('console', (msg) => {
    if (msg.type() === 'error') problems.push(`worker console: ${msg.text()}`);
  }));
  await page.goto(served.url);
});

after(async () => {
  await browser?.close();
  server?.close();
});

/** @param {string} id @returns {Promise<number>} the raw number behind a live figure */
async function figure(id) {
  return Number(await page.locator(`#${id}`).getAttribute('data-value'));
}

/** Waits until simulated time reaches `t` seconds. @param {number} t */
async function waitForSimTime(t) {
  await page.waitForFunction((t) => Number(document.getElementById('sim-time')?.dataset.value) >= t,
    t, { timeout: 30_000, polling: 100 });
}

test('the biped walks: its x changes and the speed figure appears', async () => {
  await waitForSimTime(2);
  const x0 = await figure('robot-x');
  await waitForSimTime(6);
  const x1 = await figure('robot-x');
  assert.ok(Number.isFinite(x0) && Number.isFinite(x1), `x is a number (${x0}, ${x1})`);
  assert.ok(Math.abs(x1 - x0) > 0.2, `x moved by more than 0.2 m in 4 simulated s (from ${x0} to ${x1})`);
  const rate = await figure('sim-rate');
  assert.ok(rate > 0.2, `sim s / wall s is shown and positive (${rate})`);
  assert.match(await page.locator('#sim-rate').innerText(), /sim s \/ wall s/);
  await mkdir(path.dirname(SCREENSHOT), { recursive: true });
  await page.screenshot({ path: SCREENSHOT });
  assert.deepEqual(problems, []);
});

test('an invalid shape shows a readable message and the previous robot keeps going', async () => {
  await page.locator('#shape').fill('11x1-1001');
  await page.locator('#shape').press('Enter');
  const message = page.locator('#message');
  await message.waitFor({ state: 'visible', timeout: 10_000 });
  assert.match(await message.innerText(), /invalid shape/i);
  const t0 = await figure('sim-time');
  await waitForSimTime(t0 + 1);
  const voxels = await page.evaluate(() => document.getElementById('status')?.textContent);
  assert.match(String(voxels), /^10 voxels/, 'still the 10-voxel biped');
  assert.ok(await canvasHasRobotColours(), 'the canvas still shows the robot');
  assert.deepEqual(problems, []);
});

test('a preset loads, then an invalid terrain shows a readable message and keeps it', async () => {
  await page.locator('#shape').fill('comb-7x2');
  await page.locator('#shape').press('Enter');
  await page.waitForFunction(() => /^11 voxels/.test(document.getElementById('status')?.textContent ?? ''),
    undefined, { timeout: 10_000 });
  assert.equal(await page.locator('#message').isHidden(), true, 'a valid shape clears the message');
  await page.locator('#terrain').fill('hilly-one');
  await page.locator('#terrain').press('Enter');
  await page.waitForFunction(() => /invalid terrain/i.test(document.getElementById('message')?.textContent ?? ''),
    undefined, { timeout: 10_000 });
  const t0 = await figure('sim-time');
  await waitForSimTime(t0 + 0.5);
  assert.match(String(await page.locator('#status').textContent()), /^11 voxels/, 'still the comb');
  assert.deepEqual(problems, []);
});

test('Pause stops the clock, Reset starts the episode again, Start resumes', async () => {
  await page.locator('#pause').click();
  await page.waitForFunction(() => document.body.dataset.running === 'false', undefined, { timeout: 5_000 });
  const paused = await figure('sim-time');
  await page.waitForTimeout(500);
  assert.equal(await figure('sim-time'), paused, 'time stands still while paused');
  await page.locator('#reset').click();
  await page.waitForFunction(() => Number(document.getElementById('sim-time')?.dataset.value) < 0.1,
    undefined, { timeout: 5_000 });
  await page.locator('#start').click();
  await waitForSimTime(1);
  assert.deepEqual(problems, []);
});

test('the pretrained attention biped walks and its attention matrices are drawn', async () => {
  await page.locator('#terrain').fill('hilly-1-10-0'); // the previous test left a bad terrain typed
  await page.locator('#terrain').press('Enter');
  await page.locator('#source').selectOption(ATTENTION_RUN, { timeout: 10_000 });
  await page.waitForFunction(() => /^10 voxels, attention$/.test(document.getElementById('status')?.textContent ?? ''),
    undefined, { timeout: 10_000 });
  assert.equal(await page.locator('#shape').inputValue(), '1111-1111-1001', 'the run file\'s shape is shown');
  assert.equal(await page.locator('#frequency').isDisabled(), true, 'the gait fields are unused');
  await page.locator('#attention-panel').waitFor({ state: 'visible', timeout: 10_000 });
  const t0 = await figure('sim-time');
  const x0 = await figure('robot-x');
  await waitForSimTime(t0 + 3);
  const x1 = await figure('robot-x');
  assert.ok(x1 - x0 > 1, `the evolved biped walks forward more than 1 m in 3 s (from ${x0} to ${x1})`);
  const colours = await attentionColours();
  assert.ok(colours.red > 50 && colours.blue > 50, `the heat maps show both signs (${JSON.stringify(colours)})`);
  await page.screenshot({ path: ATTENTION_SCREENSHOT, fullPage: true });
  assert.deepEqual(problems, []);
});

test('a malformed run file or another shape shows a message and the attention biped keeps going; a valid file loads', async () => {
  await page.locator('#run-file').setInputFiles({ name: 'broken.json', mimeType: 'application/json',
    buffer: Buffer.from('{"format": "vsr-run", "version": 1, "config": {') });
  await page.waitForFunction(() => /not valid JSON/.test(document.getElementById('message')?.textContent ?? ''),
    undefined, { timeout: 10_000 });
  assert.equal(await page.locator('#source').inputValue(), ATTENTION_RUN, 'the running source stays chosen');
  await page.locator('#shape').fill('comb-7x2');
  await page.locator('#shape').press('Enter');
  await page.waitForFunction(() => /needs shape 1111-1111-1001/.test(document.getElementById('message')?.textContent ?? ''),
    undefined, { timeout: 10_000 });
  const t0 = await figure('sim-time');
  const x0 = await figure('robot-x');
  await waitForSimTime(t0 + 2);
  assert.ok(await figure('robot-x') - x0 > 0.5, 'the attention biped still walks');
  assert.match(String(await page.locator('#status').textContent()), /^10 voxels, attention$/);
  assert.equal(await page.locator('#attention-panel').isVisible(), true);
  await page.locator('#run-file').setInputFiles(path.join(HERE, '..', '..', 'pretrained', 'comb-7x2-attention-finetuned-seed1.json'));
  await page.waitForFunction(() => /^11 voxels, attention$/.test(document.getElementById('status')?.textContent ?? ''),
    undefined, { timeout: 10_000 });
  assert.match(await page.locator('#source option:checked').innerText(), /from disk/, 'a valid file from disk drives the robot');
  await page.locator('#source').selectOption('gait');
  await page.locator('#attention-panel').waitFor({ state: 'hidden', timeout: 10_000 });
  assert.deepEqual(problems, []);
});

/** Counts strongly red and strongly blue pixels of the attention canvas. */
async function attentionColours() {
  return page.evaluate(() => {
    const canvas = /** @type {HTMLCanvasElement} */ (document.getElementById('attention'));
    const data = canvas.getContext('2d')?.getImageData(0, 0, canvas.width, canvas.height).data ?? [];
    const counts = { red: 0, blue: 0 };
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b, a] = [data[i], data[i + 1], data[i + 2], data[i + 3]];
      if (a > 200 && r > 150 && g < 120 && b < 120) counts.red++;
      if (a > 200 && b > 150 && r < 120 && g < 160) counts.blue++;
    }
    return counts;
  });
}

/** True when some canvas pixels have a voxel colour (strongly red, yellow or green). */
async function canvasHasRobotColours() {
  return page.evaluate(() => {
    const canvas = /** @type {HTMLCanvasElement} */ (document.getElementById('scene'));
    const data = canvas.getContext('2d')?.getImageData(0, 0, canvas.width, canvas.height).data;
    if (!data) return false;
    let coloured = 0;
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
      if (Math.max(r, g) > 140 && b < 100) coloured++;
    }
    return coloured > 200;
  });
}
