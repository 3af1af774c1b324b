// @ts-check
/**
 * Browser test of the page's messages (node --test): an error stays until the person closes
 * it. The core worker dies while the page asks it to check a drawing, and the simulation
 * worker crashes: each says so, and both messages are still on screen 16 s later (the page
 * once hid errors after 15 s), after a successful action and a note ("Link copied") that came
 * and went by itself. Each closes with its own button. Saves screenshots/messages.png.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { byTestId, clickCells, openPage, screenshot, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

/** The texts of the messages on screen, oldest first. @param {import('playwright-core').Page} page */
async function shown(page) {
  return byTestId(page, 'message').locator('.message:visible > span').allTextContents();
}

test('a failed request and a crashed worker keep their messages until closed; a note goes by itself', async () => {
  const { page, problems } = await openPage(env.browser, env.url);
  const worker = (/** @type {string} */ file) => page.workers().find((w) => w.url().endsWith(`/${file}`));
  const core = worker('core-worker.js');
  assert.ok(core, 'a core worker runs');
  // The core worker dies on the next question it is asked: a click on the editor asks it to check the drawing.
  // Under load the worker may still be loading its imports, and its module would then install
  // its own handler after ours: wait until it has, then wrap it. Only the check of a drawing
  // fails, and only once armed: other questions the page may still be asking (it is starting
  // up; the Share button asks whether the state can be shared) are answered.
  await core.evaluate(() => new Promise((resolve) => {
    const replace = () => {
      const answer = self.onmessage;
      if (!answer) { setTimeout(replace, 10); return; }
      self.onmessage = (/** @type {MessageEvent} */ event) => {
        if (event.data?.name === 'checkShape' && /** @type {any} */ (self).armed) throw new Error('the core worker fails on purpose');
        return answer.call(self, event);
      };
      resolve(undefined);
    };
    replace();
  }));
  await page.waitForTimeout(1000); // the page's own questions at start-up answered
  await core.evaluate(() => { /** @type {any} */ (self).armed = true; });
  await clickCells(page, [[6, 0]]);
  await waitForText(page, 'message', /the drawing could not be checked: the core worker stopped \(.*fails on purpose.*\); try again/);
  const failed = Date.now();
  const simulation = worker('simulation-worker.js');
  assert.ok(simulation, 'a simulation worker runs');
  await simulation.evaluate(() => { setTimeout(() => { throw new Error('the simulation worker fails on purpose'); }); });
  await waitForText(page, 'message', /The simulation worker crashed; a new one took over/);

  // Later successes: the drawing is a robot again (checked by a new core worker), a link is copied.
  await page.locator('#undo').click();
  await waitForText(page, 'shape-status', /^10 voxels · 1111-1111-1001$/);
  await byTestId(page, 'share').click();
  await waitForText(page, 'message', /Link copied|Here is the link/);
  assert.equal((await shown(page)).length, 3, 'two errors and the note');

  await page.waitForTimeout(Math.max(0, failed + 16_000 - Date.now()));
  const texts = await shown(page);
  assert.equal(texts.length, 2, `the note went by itself, both errors stayed: ${JSON.stringify(texts)}`);
  assert.match(texts[0], /^the drawing could not be checked: the core worker stopped/);
  assert.match(texts[1], /^The simulation worker crashed; a new one took over\.$/);
  await waitForText(page, 'status', /^10 voxels/); // the new simulation worker walks the robot
  await screenshot(page, 'messages.png');

  const closers = byTestId(page, 'message').locator('[data-testid="message-close"]');
  await closers.first().click();
  assert.deepEqual((await shown(page)).length, 1, 'one closed, the other stays');
  await closers.first().click();
  assert.equal(await byTestId(page, 'message').isHidden(), true, 'both closed: the box is gone');
  console.log(`# problems seen (the failures on purpose): ${JSON.stringify(problems)}`);
  assert.ok(problems.every((p) => /fails on purpose/.test(p)), `nothing else went wrong: ${problems}`);
  await page.context().close();
});
