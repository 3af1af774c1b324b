// @ts-check
/**
 * Browser test of `<vsr-robot>` (node --test) on the plain example page www/embed/example.html:
 * its three robots walk, each in its own worker (the centre's x grows by metres); a click holds
 * one (its x stays) and plays it again; a wrong attribute (a bad or disconnected shape, a module
 * file missing, malformed or for another body, an unknown terrain, no robot at all) shows its
 * message in place of the robot, and fixing it brings the robot back (a shape alone walks with
 * the phase gait); a robot out of sight pauses. Saves
 * screenshots/embed-{walking,errors}.png.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { openBare, robotPixels, screenshot, start } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

/** @param {import('playwright-core').Page} page @returns {Promise<{id: string, x: number, distance: number, time: number, running: boolean, error: string}[]>} */
function robots(page) {
  return page.$$eval('vsr-robot', (els) => els.map((el) => {
    const r = /** @type {any} */ (el);
    return { id: el.id, x: r.x, distance: r.distance, time: r.time, running: r.running, error: r.error };
  }));
}

/**
 * Waits until every robot of the page has walked `metres` beyond where it was first seen.
 * @param {import('playwright-core').Page} page @param {number} metres
 */
async function waitWalked(page, metres) {
  await page.waitForFunction(() => [...document.querySelectorAll('vsr-robot')].every((el) => Number.isFinite(/** @type {any} */ (el).x)),
    undefined, { timeout: 30_000, polling: 100 });
  const first = await robots(page);
  await page.waitForFunction(([from, metres]) => [...document.querySelectorAll('vsr-robot')]
    .every((el, i) => /** @type {any} */ (el).x > from[i] + metres), [first.map((r) => r.x), metres], { timeout: 60_000, polling: 100 });
  return first;
}

test('the example page: three robots walk, each on its own canvas; a click holds one and plays it again', async () => {
  const { page, problems } = await openBare(env.browser, `${env.url}embed/example.html`, { width: 1000, height: 1400 });
  const first = await waitWalked(page, 2);
  const now = await robots(page);
  assert.deepEqual(now.map((r) => r.id), ['biped', 'comb', 'transplant']);
  for (const r of now) {
    assert.equal(r.error, '', `${r.id} shows no message`);
    assert.ok(r.distance > 2, `${r.id} walked ${r.distance} m from its start`);
  }
  console.log(`# walked: ${now.map((r, i) => `${r.id} ${(r.x - first[i].x).toFixed(1)} m in ${(r.time - first[i].time).toFixed(1)} s`).join(', ')}`);
  const canvases = await page.$$eval('vsr-robot', (els) => els.map((el) => {
    const canvas = /** @type {HTMLCanvasElement} */ (el.shadowRoot?.querySelector('canvas'));
    return { width: canvas.width, height: canvas.height, shown: !canvas.hidden };
  }));
  for (const c of canvases) assert.ok(c.shown && c.width > 100 && c.height > 50, `a canvas of its own, sized by CSS: ${JSON.stringify(c)}`);
  for (const id of ['biped', 'comb', 'transplant']) { // coloured by the core's area limits, sent by its worker
    assert.ok(await page.locator(`#${id} >> canvas`).evaluate(robotPixels) > 100, `${id}'s robot is drawn in its colours`);
  }
  await screenshot(page, 'embed-walking.png');

  const biped = page.locator('#biped');
  await biped.click();
  await page.waitForFunction(() => /** @type {any} */ (document.getElementById('biped')).running === false);
  const held = await biped.evaluate((el) => /** @type {any} */ (el).x);
  await page.waitForTimeout(800);
  assert.equal(await biped.evaluate((el) => /** @type {any} */ (el).x), held, 'a held robot stays');
  assert.equal(await page.locator('#biped >> .held').isVisible(), true, 'it says it is held');
  await biped.click();
  await page.waitForFunction((x) => /** @type {any} */ (document.getElementById('biped')).x > x + 1, held, { timeout: 30_000 });
  assert.deepEqual(problems, []);
  await page.context().close();
});

/** Wrong attributes, each with what its message must say. */
const WRONG = [
  { attrs: { shape: '11x1' }, says: /invalid shape: row 1 has 'x' at column 3/ },
  { attrs: { shape: '101' }, says: /invalid shape: the shape is in 2 separate pieces/ },
  { attrs: { shape: 'biped-4x3', module: '../pretrained/no-such-module.json' }, says: /could not read the module file "..\/pretrained\/no-such-module.json": 404/ },
  { attrs: { module: '../pretrained/manifest.json' }, says: /vsr-robot: .*(run file|format|missing field)/i },
  { attrs: { shape: 'comb-7x2', module: '../pretrained/biped-4x3-attention.json' }, says: /needs shape 1111-1111-1001 \(10 voxels\), not 1111111-1010101/ },
  { attrs: { shape: 'biped-4x3', terrain: 'lava' }, says: /invalid terrain: 'lava'/ },
  { attrs: {}, says: /no robot: give a shape/ },
];

test('a wrong attribute shows its message in place of the robot; fixing it brings the robot back', async () => {
  const { page, problems } = await openBare(env.browser, `${env.url}embed/example.html`, { width: 1000, height: 2400 });
  const ids = await page.evaluate((wrong) => wrong.map((w, i) => {
    const el = document.createElement('vsr-robot');
    el.id = `wrong-${i}`;
    for (const [k, v] of Object.entries(w.attrs)) el.setAttribute(k, v);
    document.body.append(el);
    return el.id;
  }), WRONG.map((w) => ({ attrs: w.attrs })));
  for (const [i, id] of ids.entries()) {
    await page.waitForFunction((id) => /** @type {any} */ (document.getElementById(id)).error !== '', id, { timeout: 30_000 });
    const shown = await page.locator(`#${id}`).evaluate((el) => {
      const box = /** @type {HTMLElement} */ (el.shadowRoot?.querySelector('.error'));
      return { text: box.textContent ?? '', visible: !box.hidden && box.getBoundingClientRect().height > 0,
        canvas: !(/** @type {HTMLCanvasElement} */ (el.shadowRoot?.querySelector('canvas')).hidden) };
    });
    console.log(`# ${JSON.stringify(WRONG[i].attrs)}: ${shown.text}`);
    assert.match(shown.text, WRONG[i].says);
    assert.ok(shown.visible && !shown.canvas, `${id}: the message in place of the robot`);
  }
  await page.locator('#wrong-5').scrollIntoViewIfNeeded();
  await screenshot(page, 'embed-errors.png');

  const fixed = page.locator('#wrong-5');
  await fixed.evaluate((el) => el.setAttribute('terrain', 'flat'));
  await page.waitForFunction(() => {
    const el = /** @type {any} */ (document.getElementById('wrong-5'));
    return el.error === '' && el.running && el.time > 1;
  }, undefined, { timeout: 30_000 });
  assert.equal(await fixed.evaluate((el) => /** @type {HTMLElement} */ (el.shadowRoot?.querySelector('.error')).hidden), true);

  // With a shape and nothing else, the phase gait drives it on the viewer's terrain.
  await page.locator('#wrong-6').evaluate((el) => el.setAttribute('shape', 'biped-4x3'));
  await page.waitForFunction(() => {
    const el = /** @type {any} */ (document.getElementById('wrong-6'));
    return el.error === '' && el.running && el.time > 1;
  }, undefined, { timeout: 30_000 });

  // A robot out of sight pauses, and walks on when scrolled back into view.
  const biped = () => page.evaluate(() => /** @type {any} */ (document.getElementById('biped')).running);
  await page.evaluate(() => window.scrollTo(0, document.body.scrollHeight));
  await page.waitForFunction(() => /** @type {any} */ (document.getElementById('biped')).running === false, undefined, { timeout: 10_000 });
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.waitForFunction(() => /** @type {any} */ (document.getElementById('biped')).running === true, undefined, { timeout: 10_000 });
  assert.equal(await biped(), true);
  assert.deepEqual(problems.filter((p) => !/404/.test(p)), [], 'nothing but the missing file went wrong');
  await page.context().close();
});
