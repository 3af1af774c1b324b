// @ts-check
/**
 * Browser test: a body the body search found fine-tunes in the page (node --test). A small
 * search whose attention evolves with each body (brain "every gene evolving from the
 * module"); a click on a body of its gallery loads it; Fine-tune is on, and its run keeps
 * that body's 32 attention genes (not the module's) and equals `vsr finetune --from
 * bodies.json --entry I` bit for bit (needs target/release/vsr; VSR_BIN). A link to the result
 * says that Fine-tune will be off where it opens (the file does not travel), and there the
 * button says why.
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { BIN, ROOT, byTestId, openPage, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;
/** @type {string} */ let tmp;

const MODULE = 'pretrained/biped-4x3-attention.json';
const ATTENTION_GENES = 32;
/** The fine-tune's run settings (the run panel's fields). */
const RUN = Object.freeze({ population: '6', seconds: '2', budget: '12', seed: '3', terrain: 'hilly-1-10', workers: '2' });

before(async () => {
  env = await start();
  tmp = await mkdtemp(path.join(os.tmpdir(), 'vsr-found-finetune-'));
});

after(async () => {
  await env?.close();
  await rm(tmp, { recursive: true, force: true });
});

/** Downloads what `testid`'s button exports. @param {import('playwright-core').Page} page @param {string} testid */
async function exported(page, testid) {
  const [download] = await Promise.all([page.waitForEvent('download'), byTestId(page, testid).click()]);
  return readFile(/** @type {string} */ (await download.path()), 'utf8');
}

test('a body the search found fine-tunes with its own attention, as vsr finetune --entry does', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1300, height: 1500 });
  await page.locator(`#module option[value="${MODULE}"]`).waitFor({ state: 'attached' });
  await byTestId(page, 'pretrained').selectOption(MODULE);
  await page.locator('#run-seed').fill('7');
  await page.locator('#run-workers').fill('2');
  await byTestId(page, 'codesign-brain').selectOption('finetune');
  await page.locator('#codesign-from').selectOption('box');
  await page.locator('#codesign-budget').fill('80');
  await page.locator('#codesign-seconds').fill('2');
  await byTestId(page, 'codesign').click();
  await page.waitForFunction(() => document.body.dataset.codesign === 'finished', undefined, { timeout: 120_000 });
  const searchFile = path.join(tmp, 'bodies.json');
  const search = await exported(page, 'codesign-export');
  await writeFile(searchFile, search);
  const archive = JSON.parse(search).archive;

  // A body whose attention is neither the module's nor the search's best body's (every gene evolved with it).
  const block = (/** @type {{genome: number[]}} */ b) => b.genome.slice(0, ATTENTION_GENES).join();
  const others = [block(JSON.parse(await readFile(path.join(ROOT, MODULE), 'utf8')).best), block(JSON.parse(search).best)];
  const index = archive.findIndex((/** @type {any} */ e) => !others.includes(block(e)));
  assert.ok(index >= 0, 'the search evolved some body\'s attention away from the module and its best');
  const entry = archive[index];
  await page.locator(`[data-testid="codesign-body"][data-cell="${entry.cell.join(',')}"]`).click();
  await waitForText(page, 'driver', /a body found by the body search/);
  await waitForText(page, 'shape-status', new RegExp(`· ${entry.shape}$`));
  await waitForText(page, 'watch-message', /Fine-tune, under “Run”, can train its attention for this body or one you draw/);
  assert.equal(await byTestId(page, 'finetune').isEnabled(), true, 'Fine-tune is on for a found attention brain');
  assert.match(String(await byTestId(page, 'finetune').getAttribute('title')), /its attention stays as it is and the rest of its brain is evolved anew .* at first it walks worse than now/,
    'what Fine-tune does to a found body, said before it is pressed');

  for (const [key, value] of Object.entries(RUN)) await page.locator(`#run-${key}`).fill(value);
  if (await page.locator('#run-compare').isChecked()) await page.locator('#run-compare').uncheck();
  await byTestId(page, 'finetune').click();
  await page.waitForFunction(() => document.body.dataset.run === 'finished', undefined, { timeout: 120_000 });
  const inPage = JSON.parse(await exported(page, 'export'));
  assert.deepEqual(inPage.best.genome.slice(0, ATTENTION_GENES), entry.genome.slice(0, ATTENTION_GENES), 'its own attention kept');

  const out = path.join(tmp, 'native.json');
  execFileSync(BIN, ['finetune', '--from', searchFile, '--entry', String(index), '--shape', entry.shape, '--evals', RUN.budget,
    '--seed', RUN.seed, '--seconds', RUN.seconds, '--terrain', RUN.terrain, '--population', RUN.population, '--threads', '1', '--out', out]);
  const native = JSON.parse(await readFile(out, 'utf8'));
  const generations = (/** @type {any} */ run) => run.generations.map((/** @type {any} */ g) => ({ ...g, wall_seconds: 0 }));
  assert.deepEqual(generations(inPage), generations(native), 'every generation as vsr finetune --entry runs it');
  assert.deepEqual(inPage.best, native.best);
  assert.deepEqual(inPage.config, native.config);

  // A link keeps the robot, not the file its attention came from: said when it is made; reopened, Fine-tune is off and says why.
  await byTestId(page, 'share').click();
  await waitForText(page, 'message', /The robot and its brain open the same there, but Fine-tune will be off: the file its attention came from does not travel in a link/);
  const reopened = await openPage(env.browser, await page.locator('#share-link').inputValue());
  await waitForText(reopened.page, 'driver', /fine-tuned/);
  assert.equal(await byTestId(reopened.page, 'finetune').isDisabled(), true);
  assert.match(String(await byTestId(reopened.page, 'finetune').getAttribute('title')), /^The file this brain’s attention came from is not in the page/);
  assert.deepEqual(reopened.problems, []);
  await reopened.context.close();
  assert.deepEqual(problems, []);
  await context.close();
});
