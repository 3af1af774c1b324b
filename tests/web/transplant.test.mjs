// @ts-check
/**
 * Browser test of the paper's RQ2 in the page (node --test): a pretrained attention module
 * loads onto a body drawn by hand (not its own) and walks at once; Fine-tune runs live on
 * the workers and the exported run keeps the module's 32 attention genes bit for bit; with
 * "run from scratch for comparison" a second line follows on the chart; the page's
 * fine-tuning equals `vsr finetune` bit for bit; an MLP module is refused on another body.
 * Saves screenshots/transplant.png.
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtemp, readFile, rm } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { BIN, ROOT, byTestId, clickCells, figure, openPage, screenshot, start, waitForFigure, waitForText } from './harness.mjs';

const ATTENTION = 'pretrained/biped-4x3-attention.json';
const MLP = 'pretrained/biped-4x3-mlp.json';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;
/** @type {import('playwright-core').Page} */ let page;
/** @type {string[]} */ let problems;
/** @type {string} */ let tmp;
/** @type {any} */ let pretrained;

before(async () => {
  env = await start();
  ({ page, problems } = await openPage(env.browser, env.url));
  tmp = await mkdtemp(path.join(os.tmpdir(), 'vsr-transplant-'));
  pretrained = JSON.parse(await readFile(path.join(ROOT, ATTENTION), 'utf8'));
});

after(async () => {
  await env?.close();
  await rm(tmp, { recursive: true, force: true });
});

/** A table with four legs, drawn cell by cell: 11111-11111-10101 (13 voxels). */
const TABLE = [[0, 2], [1, 2], [2, 2], [3, 2], [4, 2], [0, 1], [1, 1], [2, 1], [3, 1], [4, 1], [0, 0], [2, 0], [4, 0]];

test('a pretrained attention module loads onto a drawn body and walks at once', async () => {
  await page.locator('#clear').click();
  await clickCells(page, /** @type {[number, number][]} */ (TABLE));
  assert.equal(await page.locator('#rows').inputValue(), '11111-11111-10101');
  await byTestId(page, 'pretrained').selectOption(ATTENTION);
  await byTestId(page, 'load-pretrained').click();
  await waitForText(page, 'status', /^13 voxels, attention$/);
  await waitForText(page, 'driver', /^Driven by: a module transplanted from biped-4x3: its attention as evolved there, the rest of its brain new for this body, drawn with seed \d+ \(attention, 85 genes\)\.$/);
  assert.equal(await byTestId(page, 'finetune').isEnabled(), true);
  const t0 = await figure(page, 'sim-time');
  await waitForFigure(page, 'sim-time', `v >= ${t0 + 3}`, 30_000);
  assert.ok(Number.isFinite(await figure(page, 'robot-x')));
  await page.locator('#attention-panel').waitFor({ state: 'visible', timeout: 10_000 });
  assert.deepEqual(problems, []);
});

test('Fine-tune runs live, keeps the 32 attention genes, and the from-scratch line follows', async () => {
  for (const [key, value] of Object.entries({ population: '6', seconds: '2', budget: '30', seed: '4', terrain: 'hilly-1-10', workers: '2' })) {
    await page.locator(`#run-${key}`).fill(value);
  }
  await page.locator('#run-compare').check();
  const started = Date.now();
  await byTestId(page, 'finetune').click();
  await waitForText(page, 'run-status', /^fine-tuning on 2 workers$/);
  await waitForFigure(page, 'run-generation', 'v >= 1');
  await waitForText(page, 'run-status', /^from scratch/, 60_000);
  const finetuneSeconds = (Date.now() - started) / 1000;
  assert.match(String(await byTestId(page, 'evaluations').textContent()), /\/ 30$/, 'the same budget from scratch');
  assert.match(String(await byTestId(page, 'run-phase').textContent()),
    /^From scratch, the comparison \(fine-tuning ended at [−-]?\d+\.\d\d m\/s, its last generation's best, the brain it keeps, after 30 evaluations\):$/, 'the fine-tuning\'s result stays beside the comparison\'s figures');
  await waitForText(page, 'run-status', /^from scratch: finished$/, 120_000);
  assert.equal(await byTestId(page, 'fitness-chart').getAttribute('data-series'), 'finetune,scratch');
  await waitForText(page, 'driver', /the fine-tuned run's result/);
  const kept = /the best of its last generation, ([−-]?\d+\.\d\d) m\/s/.exec(String(await page.locator('#driver').textContent()))?.[1];
  assert.ok(kept && String(await byTestId(page, 'run-phase').textContent()).includes(`ended at ${kept} m/s`), 'one number for the fine-tuned brain, beside the comparison and under the robot');
  console.log(`# a 30-evaluation fine-tune in the page took ${finetuneSeconds.toFixed(1)} s`);

  const [download] = await Promise.all([page.waitForEvent('download'), byTestId(page, 'export').click()]);
  assert.equal(download.suggestedFilename(), 'finetuned-attention-seed4.json');
  const file = path.join(tmp, download.suggestedFilename());
  await download.saveAs(file);
  const run = JSON.parse(await readFile(file, 'utf8'));
  assert.equal(run.config.shape, '11111-11111-10101');
  assert.equal(run.config.source.shape, '1111-1111-1001');
  assert.equal(run.best.genome.length, 32 + 4 * 13 + 1);
  assert.deepEqual(run.best.genome.slice(0, 32), pretrained.best.genome.slice(0, 32), 'the attention block is unchanged');
  await screenshot(page, 'transplant.png');
  assert.deepEqual(problems, []);
});

test('the page\'s fine-tuning equals vsr finetune bit for bit', async () => {
  const settings = { shape: '11111-11111-10101', seed: 4, seconds: 2, terrain: 'flat', population: 6, budget: 18 };
  const text = await page.evaluate(async ([settings, url]) => {
    const { FromCoordinator, ToCoordinator } = await import('./workers/protocol.js');
    const source = await fetch(url).then((r) => r.text());
    const coordinator = new Worker('./runs/coordinator.js', { type: 'module' });
    const runFile = await new Promise((resolve, reject) => {
      coordinator.onmessage = ({ data }) => {
        if (data.type === FromCoordinator.DONE) resolve(data.runFile);
        if (data.type === FromCoordinator.ERROR) reject(new Error(data.message));
      };
      coordinator.postMessage({ type: ToCoordinator.START, settings, workers: 2, source: { text: source, entry: null } });
    });
    coordinator.terminate();
    return runFile;
  }, /** @type {const} */ ([settings, ATTENTION]));
  const inPage = JSON.parse(text);
  const out = path.join(tmp, 'native-finetune.json');
  execFileSync(BIN, ['finetune', '--from', path.join(ROOT, ATTENTION), '--shape', settings.shape, '--evals', '18',
    '--seed', '4', '--seconds', '2', '--terrain', 'flat', '--population', '6', '--threads', '1', '--out', out]);
  const native = JSON.parse(await readFile(out, 'utf8'));
  const statistics = (/** @type {any} */ run) => run.generations.map((/** @type {any} */ g) => ({ ...g, wall_seconds: 0 }));
  assert.deepEqual(statistics(inPage), statistics(native), 'every generation as vsr finetune runs it');
  assert.deepEqual(inPage.best.genome, native.best.genome);
  assert.equal(inPage.best.fitness, native.best.fitness);
  assert.deepEqual(inPage.config, native.config);
  assert.deepEqual(problems, []);
});

test('choosing another controller family sets the brain aside; choosing it again brings it back', async () => {
  await byTestId(page, 'controller').selectOption('mlp');
  await waitForText(page, 'status', /phase gait$/);
  await waitForText(page, 'message', /attention brain is set aside/);
  assert.equal(await page.locator('#param-count').getAttribute('data-value'), String(4 * 13 + 1));
  assert.equal(await byTestId(page, 'finetune').isDisabled(), true, 'no module on the robot now');
  await byTestId(page, 'controller').selectOption('attention');
  await waitForText(page, 'status', /^13 voxels, attention$/);
  await waitForText(page, 'driver', /fine-tuned run's result/);
  assert.deepEqual(problems, []);
});

test('an MLP module is refused on another body and the robot keeps its brain', async () => {
  const before = await page.locator('#driver').textContent();
  await byTestId(page, 'pretrained').selectOption(MLP);
  await byTestId(page, 'load-pretrained').click();
  await waitForText(page, 'message', /only attention modules transfer to another body/);
  assert.equal(await page.locator('#driver').textContent(), before);
  assert.deepEqual(problems, []);
});
