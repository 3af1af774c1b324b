// @ts-check
/**
 * Browser test of the side-by-side race (node --test): the three pretrained brains of
 * biped-4x3 race on the viewer's terrain for one 30-s episode, all in their own workers;
 * each ends with exactly the speed `vsr evaluate` gives that module on that terrain (when
 * the native CLI is built), and their order is the study's (attention > MLP-Comm > MLP);
 * a fifth cannot be added, one can be taken out; after a small run, the best of a chosen generation and the best
 * so far join a race; each lane shows its place and its distance against the leader's. Saves screenshots/race-{1400,420,420-panel}.png.
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { standings } from '../../www/viewer/race-lane.js';
import { BIN, ROOT, SCREENSHOTS, byTestId, openPage, robotPixels, screenshot, start, waitForFigure, waitForText } from './harness.mjs';

const BRAINS = ['attention', 'mlp-comm', 'mlp'];
const file = (/** @type {string} */ c) => `pretrained/biped-4x3-${c}.json`;

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

/** @param {import('playwright-core').Page} page @param {string} module */
async function addModule(page, module) {
  const before = await byTestId(page, 'race-robot').count();
  await byTestId(page, 'pretrained').selectOption(module);
  await byTestId(page, 'race-add').click();
  await page.waitForFunction((n) => document.querySelectorAll('[data-testid="race-robot"]').length === n, before + 1);
}

/** @param {import('playwright-core').Page} page @returns {Promise<{controller: string, speed: number, time: number}[]>} */
async function speeds(page) {
  return byTestId(page, 'race-robot').evaluateAll((robots) => robots.map((r) => {
    const out = /** @type {HTMLElement} */ (r.querySelector('[data-testid="race-speed"]'));
    return { controller: String(/** @type {HTMLElement} */ (r).dataset.controller), speed: Number(out.dataset.value), time: Number(out.dataset.time) };
  }));
}

test('places and bars share one scale: ties share a place, a lone robot has none', () => {
  assert.deepEqual(standings([4, 2, NaN, 4]), [{ place: 1, share: 1 }, { place: 3, share: 0.5 }, { place: 0, share: 0 }, { place: 1, share: 1 }]);
  assert.deepEqual(standings([3]), [{ place: 0, share: 1 }]);
  assert.deepEqual(standings([-1, -2]), [{ place: 1, share: 0 }, { place: 2, share: 0 }]);
});

test('three pretrained brains race on biped-4x3: vsr evaluate\'s speeds, in the study\'s order', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  const terrain = await page.locator('#terrain').inputValue();
  await page.locator('#race-speed-select').selectOption('4');
  for (const c of BRAINS) await addModule(page, file(c));
  await waitForText(page, 'race-status', /^3 robots on .+, 30 s\. Speeds: this race only/);
  // The lanes keep in step: the widest gap between their clocks while all three are running,
  // with one lane's worker stalled for 1.5 s on the way (as a loaded machine stalls it).
  const gap = page.evaluate(() => new Promise((resolve) => {
    let widest = 0;
    const timer = setInterval(() => {
      const times = [...document.querySelectorAll('[data-testid="race-speed"]')].map((o) => Number(/** @type {HTMLElement} */ (o).dataset.time));
      if (times.every((t) => t > 0 && t < 30)) widest = Math.max(widest, Math.max(...times) - Math.min(...times));
      if (document.getElementById('race-panel')?.dataset.state === 'finished') { clearInterval(timer); resolve(widest); }
    }, 20);
  }));
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid="race-speed"]')].every((o) => Number(/** @type {HTMLElement} */ (o).dataset.time) > 3));
  const laneWorkers = page.workers().filter((w) => w.url().endsWith('/simulation-worker.js')).slice(-BRAINS.length);
  await laneWorkers[1].evaluate(() => { const end = performance.now() + 1500; while (performance.now() < end); });
  await page.locator('#race-panel[data-state="finished"]').waitFor({ timeout: 90_000 });
  console.log(`# one lane's worker stalled 1.5 s: the lanes' clocks at most ${Number(await gap).toFixed(2)} s apart`);
  assert.ok(Number(await gap) < 0.75, `one lane stalled, the others waited for it: the lanes' clocks were at most ${await gap} s apart`);
  const raced = await speeds(page);
  assert.deepEqual(raced.map((r) => r.controller), BRAINS);
  for (const r of raced) assert.ok(Math.abs(r.time - 1801 / 60) < 1e-9, `${r.controller} ran 1801 steps: ${r.time}`);
  const figures = raced.map((r) => `${r.controller} ${r.speed.toFixed(3)} m/s`).join(', ');
  console.log(`# race on ${terrain}, 30 s: ${figures}`);
  if (existsSync(BIN)) {
    for (const r of raced) {
      const out = execFileSync(BIN, ['evaluate', '--genome', path.join(ROOT, file(r.controller)), '--terrain', terrain, '--seconds', '30'], { encoding: 'utf8' });
      const cli = JSON.parse(out.trim().split('\n').pop() ?? '{}').velocity;
      assert.ok(Math.abs(r.speed - cli) < 1e-9, `${r.controller}: the race's ${r.speed} against vsr evaluate's ${cli}`);
    }
  } else {
    console.log(`# ${BIN} not built: the speeds were not compared with vsr evaluate`);
  }
  const [attention, comm, mlp] = raced.map((r) => r.speed);
  assert.ok(attention > comm && comm > mlp, `the study's order attention > MLP-Comm > MLP: ${figures}`);
  const standing = await byTestId(page, 'race-robot').evaluateAll((robots) => robots.map((r) => ({
    place: String(r.querySelector('[data-testid="race-place"]')?.textContent),
    share: Number(/** @type {HTMLElement} */ (r.querySelector('.race-mark')).dataset.value),
  })));
  assert.deepEqual(standing.map((s) => s.place), ['1st', '2nd', '3rd'], `places by distance: ${JSON.stringify(standing)}`);
  assert.ok(standing[0].share === 1 && standing[1].share < 1 && standing[2].share < standing[1].share,
    `the leader's bar is full, the others shorter in order: ${JSON.stringify(standing)}`);
  const drawn = await Promise.all((await page.locator('.race-robot canvas').all()).map((c) => c.evaluate(robotPixels)));
  assert.ok(drawn.length === 3 && drawn.every((n) => n > 100), `each lane draws its robot in its colours: ${drawn} pixels`);
  await screenshot(page, 'race-1400.png');

  await addModule(page, file('attention'));
  assert.equal(await byTestId(page, 'race-add').isDisabled(), true, 'four robots at most');
  await page.locator('.race-robot .close').first().click();
  await page.waitForFunction(() => document.querySelectorAll('[data-testid="race-robot"]').length === 3);
  assert.equal(await byTestId(page, 'race-add').isEnabled(), true);
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('the bests of a run\'s generations join a race (on a phone)', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 420, height: 860, touch: true });
  for (const [key, value] of Object.entries({ population: '4', seconds: '2', budget: '20', seed: '3', workers: '2' })) {
    await page.locator(`#run-${key}`).fill(value);
  }
  await byTestId(page, 'evolve').click();
  await waitForText(page, 'run-status', /^finished$/, 60_000);
  await waitForFigure(page, 'run-generation', 'v >= 2');
  const options = await byTestId(page, 'race-generation').locator('option').allTextContents();
  assert.ok(options.length >= 3 && /^generation 0 \(/.test(options[0]), `one entry per generation: ${options}`);
  await byTestId(page, 'race-generation').selectOption('0');
  await byTestId(page, 'race-add-generation').click();
  await page.waitForFunction(() => Number(/** @type {HTMLElement} */ (document.querySelector('[data-testid="race-speed"]'))?.dataset.time) > 2);
  await page.locator('#race-best').click(); // 2 s later: the race starts again, both together
  await page.waitForFunction(() => document.querySelectorAll('[data-testid="race-robot"]').length === 2);
  const names = await page.locator('.race-name').allTextContents();
  assert.match(names[0], /generation 0's best/);
  assert.match(names[1], /best so far \(generation \d+\)/);
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid="race-speed"]')]
    .every((o) => Number(/** @type {HTMLElement} */ (o).dataset.time) > 1), undefined, { timeout: 30_000 });
  const times = (await speeds(page)).map((r) => r.time);
  assert.ok(Math.max(...times) - Math.min(...times) < 1, `started together, they walk in step: ${times}`);
  await byTestId(page, 'race').scrollIntoViewIfNeeded();
  await screenshot(page, 'race-420.png');
  await byTestId(page, 'race').screenshot({ path: path.join(SCREENSHOTS, 'race-420-panel.png') });
  assert.deepEqual(problems, []);
  await page.context().close();
});
