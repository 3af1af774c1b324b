// @ts-check
/**
 * Browser test of a reveal that depends on the page's own run (node --test): chapter 5 asks
 * how much faster the last generation's best will be than generation 0's; while the pair's
 * run is still going, Reveal says to wait for its end (a generation's answer is not the run's)
 * and reveals nothing; once the run ends, it reveals the answer from that run.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { CHAPTERS } from '../../www/tour/chapters.js';
import { byTestId, openPage, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

test('chapter 5: Reveal waits for the run in progress, then answers from it', async () => {
  const n = CHAPTERS.findIndex((c) => c.title === 'Evolution') + 1;
  const { page, problems } = await openPage(env.browser, `${env.url}?chapter=${n}`, { width: 1400, height: 900 });
  await page.locator('#tour-box[data-state="ready"]').waitFor({ timeout: 20_000 });
  for (const [key, value] of Object.entries({ population: '4', seconds: '2', budget: '40', seed: '3', workers: '2' })) {
    await page.locator(`#run-${key}`).fill(value);
  }
  await byTestId(page, 'evolve').click();
  await byTestId(page, 'pause').click(); // the run stays in progress while the pair reveals
  await waitForText(page, 'run-pause', /^Resume$/);
  const task = byTestId(page, 'tour-exercise');
  await task.locator('input[type=radio]').nth(1).check();
  await byTestId(page, 'tour-reveal').click();
  await waitForText(page, 'tour-box', /Your run is still going: reveal once it ends/);
  assert.notEqual(await task.getAttribute('data-state'), 'revealed', 'nothing revealed during the run');
  assert.equal(await page.locator('.tour-notice').isVisible(), false, 'the Notice still waits');
  await byTestId(page, 'pause').click();
  await waitForText(page, 'run-status', /^finished$/, 90_000);
  await byTestId(page, 'tour-reveal').click();
  await page.locator('[data-testid="tour-exercise"][data-state="revealed"]').waitFor({ timeout: 60_000 });
  assert.match(String(await byTestId(page, 'tour-answer').textContent()), /From this page's latest run: generation 0's best walked/);
  assert.deepEqual(problems, []);
  await page.context().close();
});
