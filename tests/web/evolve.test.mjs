// @ts-check
/**
 * Browser test of evolving in the page (node --test): serves www/, opens it in headless
 * Debian Chromium through playwright-core and checks that
 *  - a tiny evolution gives the same run (every generation's statistics and the best genome)
 *    with 1 and with 2 evaluation workers, talking to coordinator.js through protocol.js,
 *    and the same run, bit for bit (every generation's statistics, the best genome and its
 *    fitness), as `vsr evolve` with those settings (needs target/release/vsr; VSR_BIN);
 *  - bad settings (zero budget, a disconnected shape, an empty shape) show a readable message
 *    and start nothing;
 *  - the Evolve button runs a tiny budget: the generation and evaluation figures change, the
 *    run finishes, the best individual drives the robot, and Export downloads a run file
 *    (format "vsr-run") that the page loads back from disk.
 * Saves tests/web/screenshots/evolve.png. Needs `make wasm` (www/pkg) first.
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdir, mkdtemp, readFile, rm } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { serve } from '../../scripts/serve.mjs';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const SCREENSHOT = path.join(HERE, 'screenshots', 'evolve.png');
const ROOT = path.resolve(HERE, '..', '..');
const BIN = path.resolve(process.env.VSR_BIN
  ?? path.join(process.env.CARGO_TARGET_DIR ?? path.join(ROOT, 'target'), 'release', 'vsr'));
const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic',
  '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'];

/** @type {import('node:http').Server} */ let server;
/** @type {import('playwright-core').Browser} */ let browser;
/** @type {import('playwright-core').Page} */ let page;
/** Temporary folders to remove at the end. @type {string[]} */
const temporary = [];
/** @returns {Promise<string>} a new temporary folder */
async function tempDir() {
  const dir = await mkdtemp(path.join(os.tmpdir(), 'vsr-evolve-'));
  temporary.push(dir);
  return dir;
}
/** Console errors and page errors seen so far. @type {string[]} */
const problems = [];

before(async () => {
  const served = await serve({ port: 0 });
  server = served.server;
  browser = await chromium.launch({ executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium', args: CHROMIUM_ARGS });
  page = await browser.newPage({ viewport: { width: 1200, height: 1100 }, acceptDownloads: true });
  page.on('console', (msg) => { if (msg.type() === 'error') problems.push(`console: ${msg.text()}`); });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  await page.goto(served.url);
  await page.waitForFunction(() => /voxels/.test(document.getElementById('status')?.textContent ?? ''),
    undefined, { timeout: 20_000 });
});

after(async () => {
  await browser?.close();
  server?.close();
  await Promise.all(temporary.map((dir) => rm(dir, { recursive: true, force: true })));
});

/**
 * Runs a whole evolution in a coordinator worker with `workers` evaluation workers.
 * @param {number} workers
 * @returns {Promise<any>} the final run file, parsed
 */
function evolveInWorkers(workers) {
  return page.evaluate(async (workers) => {
    const { FromCoordinator, ToCoordinator } = await import('./protocol.js');
    const coordinator = new Worker('./coordinator.js', { type: 'module' });
    const settings = { shape: 'biped-4x3', controller: 'attention', seed: 3, seconds: 2,
      terrain: 'flat', ga: { population: 6, budget_evals: 18 } };
    const text = await new Promise((resolve, reject) => {
      coordinator.onmessage = ({ data }) => {
        if (data.type === FromCoordinator.DONE) resolve(data.runFile);
        if (data.type === FromCoordinator.ERROR) reject(new Error(data.message));
      };
      coordinator.postMessage({ type: ToCoordinator.START, settings, workers });
    });
    coordinator.terminate();
    return JSON.parse(text);
  }, workers);
}

test('a tiny evolution gives the same run with 1 and with 2 evaluation workers', async () => {
  const one = await evolveInWorkers(1);
  const two = await evolveInWorkers(2);
  assert.equal(one.format, 'vsr-run');
  assert.equal(one.generations.length, 2, 'population 6, 18 evaluations: generations 0 and 1');
  assert.deepEqual([one.timing.threads, two.timing.threads], [1, 2]);
  const statistics = (/** @type {any} */ run) => run.generations.map((/** @type {any} */ g) => ({ ...g, wall_seconds: 0 }));
  assert.deepEqual(statistics(two), statistics(one));
  assert.equal(two.best.fitness, one.best.fitness);
  assert.ok(Number.isFinite(one.best.fitness), `best fitness ${one.best.fitness}`);
  assert.deepEqual(two.best.genome, one.best.genome);
  const out = path.join(await tempDir(), 'native.json');
  execFileSync(BIN, ['evolve', '--shape', 'biped-4x3', '--controller', 'attention', '--evals', '18',
    '--seed', '3', '--seconds', '2', '--terrain', 'flat', '--population', '6', '--threads', '1', '--out', out]);
  const native = JSON.parse(await readFile(out, 'utf8'));
  assert.deepEqual(statistics(native), statistics(one), 'every generation as vsr evolve runs it');
  assert.deepEqual(native.best.genome, one.best.genome, 'the best genome as vsr evolve finds it');
  assert.equal(native.best.fitness, one.best.fitness);
  assert.deepEqual(problems, []);
});

/** Fills the Evolve form. @param {Record<string, string>} values by id suffix */
async function fillEvolve(values) {
  for (const [key, value] of Object.entries(values)) await page.locator(`#evolve-${key}`).fill(value);
}

/** Clicks Evolve and expects `pattern` in the message, with no run started. @param {RegExp} pattern */
async function expectRefused(pattern) {
  await page.locator('#evolve-start').click();
  await page.waitForFunction((source) => new RegExp(source, 'i').test(document.getElementById('message')?.textContent ?? ''),
    pattern.source, { timeout: 10_000 });
  await page.waitForFunction(() => !(/** @type {HTMLButtonElement} */ (document.getElementById('evolve-start'))).disabled,
    undefined, { timeout: 10_000 });
  assert.equal(await page.locator('#evolve-generation').textContent(), '–', 'no generation was run');
}

test('bad settings show a readable message and start nothing', async () => {
  await fillEvolve({ population: '6', seconds: '2', budget: '0', terrain: 'flat' });
  await expectRefused(/budget must be a whole number/);
  await fillEvolve({ budget: '24', seconds: '' }); // a number field holds '' for NaN
  await expectRefused(/episode seconds must be a positive number/);
  await fillEvolve({ seconds: '2' });
  await page.locator('#shape').fill('101');
  await expectRefused(/shape/);
  await page.locator('#shape').fill('');
  await expectRefused(/shape/); // the panel's 'type a shape', or the simulation's 'no voxels'
  await page.locator('#shape').fill('biped-4x3');
  await page.locator('#shape').press('Enter');
  await page.waitForFunction(() => /^10 voxels/.test(document.getElementById('status')?.textContent ?? ''),
    undefined, { timeout: 10_000 });
  assert.ok(problems.every((p) => !/page error/.test(p)), problems.join('\n'));
});

test('Evolve runs a tiny budget live, the best walks, Export downloads its run file', async () => {
  await fillEvolve({ population: '6', seconds: '2', budget: '60', seed: '5', terrain: 'hilly-1-10' });
  await page.locator('#evolve-start').click();
  await page.waitForFunction(() => Number(document.getElementById('evolve-generation')?.dataset.value) >= 1,
    undefined, { timeout: 60_000, polling: 50 });
  const midway = Number(await page.locator('#evolve-evaluations').getAttribute('data-value'));
  await page.waitForFunction(() => document.body.dataset.evolve === 'finished', undefined, { timeout: 120_000 });
  const evaluations = Number(await page.locator('#evolve-evaluations').getAttribute('data-value'));
  assert.ok(midway >= 18 && midway <= evaluations, `evaluations went from ${midway} to ${evaluations}`);
  assert.equal(evaluations, 66, 'population 6 + 5 generations of 12 for a budget of 60');
  assert.equal(await page.locator('#evolve-generation').getAttribute('data-value'), '5');
  assert.match(String(await page.locator('#evolve-evaluations').textContent()), /^66 \/ 66$/);
  assert.match(String(await page.locator('#evolve-rate').textContent()), /evaluations\/s/);
  assert.ok(Number.isFinite(Number(await page.locator('#evolve-best').getAttribute('data-value'))));
  await page.waitForFunction(() => /^10 voxels, attention$/.test(document.getElementById('status')?.textContent ?? ''),
    undefined, { timeout: 10_000 });
  assert.match(await page.locator('#source option:checked').innerText(), /evolved best/);
  await page.locator('#attention-panel').waitFor({ state: 'visible', timeout: 10_000 });

  const [download] = await Promise.all([page.waitForEvent('download'), page.locator('#evolve-export').click()]);
  assert.equal(download.suggestedFilename(), 'evolved-attention-seed5.json');
  const file = path.join(await tempDir(), download.suggestedFilename());
  await download.saveAs(file);
  const run = JSON.parse(await readFile(file, 'utf8'));
  assert.equal(run.format, 'vsr-run');
  assert.equal(run.version, 1);
  assert.equal(run.generations.length, 6);
  assert.equal(run.config.seed, 5);
  assert.equal(run.best.genome.length, 73);

  await page.locator('#source').selectOption('gait');
  await page.waitForFunction(() => /phase gait$/.test(document.getElementById('status')?.textContent ?? ''));
  await page.locator('#run-file').setInputFiles(file);
  await page.waitForFunction(() => /^10 voxels, attention$/.test(document.getElementById('status')?.textContent ?? ''),
    undefined, { timeout: 10_000 });
  await page.waitForTimeout(1500);
  await mkdir(path.dirname(SCREENSHOT), { recursive: true });
  await page.screenshot({ path: SCREENSHOT, fullPage: true });
  assert.deepEqual(problems, []);
});

test('Pause holds the evaluations, Resume goes on, Stop ends the run and keeps its run file', async () => {
  await fillEvolve({ population: '20', seconds: '10', budget: '30000', seed: '2' });
  await page.locator('#evolve-start').click();
  await page.waitForFunction(() => Number(document.getElementById('evolve-generation')?.dataset.value) >= 0,
    undefined, { timeout: 60_000, polling: 50 });
  await page.locator('#evolve-pause').click();
  await page.waitForFunction(() => document.body.dataset.evolve === 'paused', undefined, { timeout: 10_000 });
  await page.waitForTimeout(3000); // jobs under way finish; no new ones start
  const held = await page.locator('#evolve-evaluations').getAttribute('data-value');
  await page.waitForTimeout(1500);
  assert.equal(await page.locator('#evolve-evaluations').getAttribute('data-value'), held, 'no generation while paused');
  assert.equal(await page.locator('#evolve-pause').textContent(), 'Resume');
  await page.locator('#evolve-pause').click();
  await page.waitForFunction((held) => document.getElementById('evolve-evaluations')?.dataset.value !== held,
    held, { timeout: 60_000 });
  await page.locator('#evolve-stop').click();
  await page.waitForFunction(() => document.body.dataset.evolve === 'stopped', undefined, { timeout: 10_000 });
  assert.equal(await page.locator('#evolve-export').isEnabled(), true, 'the stopped run can be exported');
  assert.equal(await page.locator('#evolve-start').isEnabled(), true);
  assert.deepEqual(problems, []);
});
