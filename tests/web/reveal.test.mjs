// @ts-check
/**
 * Browser test of a reveal that depends on the page's own run (node --test): chapter 5 asks
 * how much faster the last generation's best will be than generation 0's; before the pair's
 * run, Reveal says to press Evolve first (it never grades against another run); while the run
 * is still going, it says to wait for its end (a generation's answer is not the run's) and
 * reveals nothing; once the run ends the box says so by itself; then Reveal answers from that run.
 * A guess given before the run is locked once the run shows its first generation (its speeds
 * would otherwise let the pair change their prediction into a reading).
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { EVOLVE_FIRST, RUN_GOING } from '../../www/classroom/exercises.js';
import { LOCKED } from '../../www/classroom/guess-lock.js';
import { CHAPTERS } from '../../www/tour/chapters.js';
import { byTestId, openPage, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

test('chapter 5: Reveal waits for the run in progress, then answers from it', async () => {
  const n = CHAPTERS.findIndex((c) => c.title === 'Evolution') + 1;
  const { page, problems } = await openPage(env.browser, `${env.url}?chapter=${n}`, { width: 1400, height: 900 });
  await page.locator('#tour-box[data-state="ready"]').waitFor({ timeout: 20_000 });
  const task = byTestId(page, 'tour-exercise');
  const said = async () => String(await byTestId(page, 'tour-answer').textContent());
  await task.locator('input[type=radio]').nth(1).check();
  await byTestId(page, 'tour-reveal').click(); // before any run: not graded against the study's
  await waitForText(page, 'tour-box', /Press Evolve first/);
  assert.equal(await said(), EVOLVE_FIRST);
  assert.notEqual(await task.getAttribute('data-state'), 'revealed', 'nothing revealed before the run');
  for (const [key, value] of Object.entries({ population: '4', seconds: '2', budget: '40', seed: '3', workers: '2' })) {
    await page.locator(`#run-${key}`).fill(value);
  }
  await byTestId(page, 'evolve').click();
  await byTestId(page, 'pause').click(); // the run stays in progress while the pair reveals
  await waitForText(page, 'run-pause', /^Resume$/);
  await byTestId(page, 'tour-reveal').click();
  await waitForText(page, 'tour-box', /Reveal waits for the end of your run/);
  assert.equal(await said(), RUN_GOING);
  assert.notEqual(await task.getAttribute('data-state'), 'revealed', 'nothing revealed during the run');
  assert.equal(await page.locator('.tour-notice').isVisible(), false, 'the Notice still waits');
  await byTestId(page, 'pause').click();
  await waitForText(page, 'run-status', /^finished$/, 90_000);
  // The run has ended and Reveal not been pressed again: the box says so by itself.
  await page.waitForFunction(() => document.querySelector('[data-testid="tour-answer"]')?.textContent === 'Your run has ended: press Reveal.', undefined, { timeout: 5_000 });
  // The guess, given before the run, was locked once the run showed its generations.
  assert.equal(await byTestId(page, 'tour-guess-locked').textContent(), LOCKED);
  assert.deepEqual(await task.locator('input[type=radio]').evaluateAll((els) => els.map((e) => /** @type {HTMLInputElement} */ (e).disabled)), [true, true, true]);
  assert.equal(await task.locator('input[type=radio]').nth(1).isChecked(), true, 'the guess kept');
  await byTestId(page, 'tour-reveal').click();
  await page.locator('[data-testid="tour-exercise"][data-state="revealed"]').waitFor({ timeout: 60_000 });
  assert.match(String(await byTestId(page, 'tour-answer').textContent()), /From this page's latest run: generation 0's best walked/);
  assert.deepEqual(problems, []);
  await page.context().close();
});
