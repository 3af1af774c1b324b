// @ts-check
/**
 * Browser test of drawing and watching (node --test), as a person uses the page: draw a
 * robot cell by cell and see the parameter count change and the robot in the viewer become
 * the drawing; draw a disconnected shape and read the message with Evolve and Fine-tune
 * off; undo and redo by button and keyboard; drag to draw and right-drag to erase; type
 * rows; a bad terrain keeps the robot walking; Hold / Play / Restart; click a voxel of the
 * walking robot to remove it. Saves screenshots/draw.png and screenshots/page.png.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { byTestId, clickCells, dragCells, expectFigure, figure, openPage, screenshot, start, waitForFigure, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;
/** @type {import('playwright-core').Page} */ let page;
/** @type {string[]} */ let problems;

before(async () => {
  env = await start();
  ({ page, problems } = await openPage(env.browser, env.url));
});

after(async () => { await env?.close(); });

/** Waits until the parameter count shown for the chosen controller is `n`. @param {number} n @param {string} [what] */
async function params(n, what) { await expectFigure(page, 'param-count', n, what); }

test('the default biped walks: its x changes and the speed figure appears', async () => {
  await waitForFigure(page, 'sim-time', 'v >= 2', 30_000);
  const x0 = await figure(page, 'robot-x');
  await waitForFigure(page, 'sim-time', 'v >= 5', 30_000);
  const x1 = await figure(page, 'robot-x');
  assert.ok(Math.abs(x1 - x0) > 0.2, `x moved by more than 0.2 m in 3 simulated s (from ${x0} to ${x1})`);
  assert.ok(await figure(page, 'sim-rate') > 0.2);
  await params(73, 'attention on the biped: 73 parameters');
  assert.deepEqual(problems, []);
});

test('draw a robot cell by cell: the parameter count follows and the viewer walks the drawing', async () => {
  await page.locator('#clear').click();
  await waitForText(page, 'shape-message', /draw at least one voxel/);
  assert.equal(await byTestId(page, 'evolve').isDisabled(), true, 'nothing to evolve');
  await clickCells(page, [[0, 0]]);
  await params(32 + 4 + 1);
  await clickCells(page, [[1, 0], [2, 0]]);
  await params(32 + 4 * 3 + 1);
  await byTestId(page, 'controller').selectOption('mlp');
  await params(4 * 3 + 1, 'MLP: 4n + 1');
  await byTestId(page, 'controller').selectOption('mlp-comm');
  await params((8 * 3 + 1) * 5, 'MLP-Comm: (8n + 1) x 5');
  await byTestId(page, 'controller').selectOption('attention');
  await clickCells(page, [[0, 1]]);
  await params(32 + 4 * 4 + 1);
  await waitForText(page, 'status', /^4 voxels, phase gait$/);
  assert.equal(await page.locator('#rows').inputValue(), '100-111');
  assert.equal(await byTestId(page, 'shape-message').isHidden(), true, 'a valid drawing clears the message');
  assert.equal(await byTestId(page, 'evolve').isEnabled(), true);
  assert.deepEqual(problems, []);
});

test('a disconnected drawing names its pieces and turns Evolve off; undo and redo', async () => {
  await clickCells(page, [[5, 0], [7, 3]]);
  await waitForText(page, 'shape-message', /3 separate pieces/);
  assert.match(String(await byTestId(page, 'shape-message').textContent()), /each of its 3 pieces has its own colour/);
  assert.match(String(await page.locator('#shape-status').textContent()), /^Not a robot yet: 3 separate pieces$/);
  assert.equal(await byTestId(page, 'evolve').isDisabled(), true);
  assert.equal(await byTestId(page, 'finetune').isDisabled(), true);
  assert.equal(await byTestId(page, 'load-pretrained').isDisabled(), true);
  assert.match(String(await page.locator('#status').textContent()), /^4 voxels/, 'the last valid robot keeps walking');
  await page.locator('#undo').click();
  await waitForText(page, 'shape-message', /2 separate pieces/);
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => document.querySelector('[data-testid="shape-message"]')?.hasAttribute('hidden'));
  assert.equal(await byTestId(page, 'evolve').isEnabled(), true);
  await page.keyboard.press('Control+Shift+z');
  await waitForText(page, 'shape-message', /2 separate pieces/);
  await page.locator('#redo').click();
  await waitForText(page, 'shape-message', /3 separate pieces/);
  await page.locator('#undo').click();
  await page.locator('#undo').click();
  await page.waitForFunction(() => document.querySelector('[data-testid="shape-message"]')?.hasAttribute('hidden'));
  assert.equal(await page.locator('#rows').inputValue(), '100-111');
  await screenshot(page, 'draw.png');
  assert.deepEqual(problems, []);
});

test('drag draws a row, right-drag erases it, typed rows and presets replace the drawing', async () => {
  await dragCells(page, [0, 2], [3, 2]);
  assert.equal(await page.locator('#rows').inputValue(), '1111-1000-1110');
  await dragCells(page, [0, 2], [3, 2], 'right');
  assert.equal(await page.locator('#rows').inputValue(), '100-111', 'erased again; the drawing is cropped to its cells');
  await page.locator('#erase').click();
  await clickCells(page, [[2, 0]]);
  assert.equal(await page.locator('#rows').inputValue(), '10-11', 'erase mode removes with the left button too');
  await page.locator('#erase').click();
  await page.locator('#rows').fill('111-101');
  await page.locator('#rows').press('Enter');
  await waitForText(page, 'status', /^5 voxels/);
  await page.locator('#rows').fill('1x1');
  await page.locator('#rows').press('Enter');
  await waitForText(page, 'rows-message', /rows hold only 1/);
  assert.equal(await page.locator('#rows').inputValue(), '1x1', 'a refused entry stays typed, to be corrected');
  assert.match(String(await page.locator('#status').textContent()), /^5 voxels/, 'the robot keeps its body');
  await byTestId(page, 'preset').selectOption({ label: 'comb-7x2' });
  await waitForText(page, 'status', /^11 voxels/);
  await params(32 + 4 * 11 + 1);
  assert.deepEqual(problems, []);
});

test('a bad terrain shows a readable message and the robot keeps walking', async () => {
  await page.locator('#terrain').fill('hilly-one');
  await page.locator('#terrain').press('Enter');
  await waitForText(page, 'terrain-message', /^“hilly-one” is not a terrain\. Try flat/);
  const t0 = await figure(page, 'sim-time');
  await waitForFigure(page, 'sim-time', `v >= ${t0 + 0.5}`, 20_000);
  assert.match(String(await page.locator('#status').textContent()), /^11 voxels/, 'still the comb');
  await page.locator('#terrain').fill('hilly-1-10-0');
  await page.locator('#terrain').press('Enter');
  await byTestId(page, 'terrain-message').waitFor({ state: 'hidden' }); // a terrain again: its message went
  assert.deepEqual(problems, []);
});

test('Hold stops the clock, Restart walk begins again, Play resumes', async () => {
  await page.locator('#sim-hold').click();
  await page.waitForFunction(() => document.body.dataset.running === 'false', undefined, { timeout: 5_000 });
  const held = await figure(page, 'sim-time');
  await page.waitForTimeout(500);
  assert.equal(await figure(page, 'sim-time'), held, 'time stands still while held');
  await page.locator('#sim-restart').click();
  await waitForFigure(page, 'sim-time', 'v < 0.1', 5_000);
  await page.locator('#sim-play').click();
  await waitForFigure(page, 'sim-time', 'v >= 1', 20_000);
  assert.deepEqual(problems, []);
});

test('clicking a voxel of the walking robot removes it where it stands, in its posture; the same controller keeps driving it', async () => {
  await byTestId(page, 'preset').selectOption({ label: 'biped-4x3' });
  await waitForText(page, 'status', /^10 voxels/);
  await waitForFigure(page, 'sim-time', 'v > 0.5', 20_000);
  const start = await figure(page, 'robot-x');
  await page.locator('#speed').selectOption('0'); // as fast as possible, to walk away from the start
  await waitForFigure(page, 'robot-x', `Math.abs(v - ${start}) > 4`, 60_000);
  await page.locator('#speed').selectOption('1');
  await page.locator('#sim-hold').click();
  await page.waitForFunction(() => document.body.dataset.running === 'false', undefined, { timeout: 30_000 });
  // Click once the camera has caught up, so that the click hits the voxel it aims at.
  const boxBefore = await settledRobotBox();
  const before = await figure(page, 'robot-x');
  const centre = { x: (boxBefore.left + boxBefore.right) / 2, y: (boxBefore.top + boxBefore.bottom) / 2 };
  await byTestId(page, 'viewer').click({ position: centre });
  await waitForText(page, 'status', /^9 voxels/);
  assert.notEqual(await page.locator('#rows').inputValue(), '1111-1111-1001');
  const after = await figure(page, 'robot-x');
  assert.ok(Math.abs(after - before) < 1, `rebuilt where it stood: x ${before} before, ${after} after (start ${start})`);
  // In its posture, not rebuilt at rest above the ground: the robot's outline stays put.
  const boxAfter = await settledRobotBox();
  const cell = (boxBefore.bottom - boxBefore.top) / 3;
  for (const side of ['left', 'right', 'top', 'bottom']) {
    assert.ok(Math.abs(boxAfter[side] - boxBefore[side]) < 0.2 * cell,
      `the ${side} edge moved from ${boxBefore[side]} to ${boxAfter[side]} px (a voxel is ${cell} px): ${JSON.stringify([boxBefore, boxAfter, before, after])}`);
  }
  await page.locator('#sim-play').click();
  await screenshot(page, 'page.png');
  assert.deepEqual(problems, []);
});

test('clicking next to the robot adds a voxel, a click too far says where to click; an edit that would split it is refused', async () => {
  await page.locator('#rows').fill('111');
  await page.locator('#rows').press('Enter');
  await waitForText(page, 'status', /^3 voxels/);
  await page.locator('#sim-hold').click();
  await page.waitForFunction(() => document.body.dataset.running === 'false', undefined, { timeout: 30_000 });
  const box = await settledRobotBox();
  const cell = (box.right - box.left) / 3;
  await byTestId(page, 'viewer').click({ position: { x: box.right + 0.45 * cell, y: (box.top + box.bottom) / 2 } });
  await waitForText(page, 'status', /^4 voxels/);
  assert.equal(await page.locator('#rows').inputValue(), '1111', 'a voxel added on the right');
  const far = await settledRobotBox();
  await byTestId(page, 'viewer').click({ position: { x: far.right + 2.5 * cell, y: (far.top + far.bottom) / 2 } });
  await waitForText(page, 'message', /Click a voxel to remove it, or a spot right next to one/);
  assert.equal(await page.locator('#rows').inputValue(), '1111', 'a click too far away changes nothing, and says why');
  await page.locator('#undo').click();
  await waitForText(page, 'status', /^3 voxels/);
  await settledRobotBox();
  await byTestId(page, 'viewer').click({ position: await robotCentre() });
  await waitForText(page, 'message', /would split the robot into 2 pieces; not done/);
  assert.equal(await page.locator('#rows').inputValue(), '111', 'the robot is unchanged');
  assert.equal(await page.locator('#redo').isEnabled(), true, 'the refused edit kept the history: the undone addition can be redone');
  // Removing the left voxel moves the bounding box: the other two keep their places, so the
  // centre moves right by half a voxel (3 m), not left as a mapping without the shift gives.
  const x3 = await figure(page, 'robot-x');
  const box3 = await settledRobotBox();
  const cell3 = (box3.right - box3.left) / 3;
  await byTestId(page, 'viewer').click({ position: { x: box3.left + 0.5 * cell3, y: (box3.top + box3.bottom) / 2 } });
  await waitForText(page, 'status', /^2 voxels/);
  const x2 = await figure(page, 'robot-x');
  assert.ok(Math.abs(x2 - x3 - 1.5) < 0.3, `the centre moved from ${x3} to ${x2} m`);
  await page.locator('#sim-play').click();
  assert.deepEqual(problems, []);
});

/**
 * The robot's box once the view of the held robot is settled: two reads in a row, each drawn
 * after the camera reached where it heads (the renderer's data-camera-still; a frame that
 * arrives between them moves it again, and the reads differ).
 */
async function settledRobotBox() {
  const deadline = Date.now() + 60_000;
  let last = '';
  while (Date.now() < deadline) {
    const drawn = await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => resolve(
      /** @type {HTMLElement} */ (document.querySelector('[data-testid="viewer"]')).dataset.cameraStill === 'true')))));
    const box = JSON.stringify(await robotBox());
    if (drawn && box === last) return JSON.parse(box);
    last = drawn ? box : '';
    await page.waitForTimeout(100);
  }
  throw new Error(`the view of the held robot did not settle in 60 s: ${last}`);
}

/** The box around the robot's coloured pixels on the viewer (CSS px). */
async function robotBox() {
  return page.evaluate(() => {
    const canvas = /** @type {HTMLCanvasElement} */ (document.querySelector('[data-testid="viewer"]'));
    const data = canvas.getContext('2d')?.getImageData(0, 0, canvas.width, canvas.height).data ?? [];
    const box = { left: Infinity, right: -Infinity, top: Infinity, bottom: -Infinity };
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
      if (Math.max(r, g) > 140 && b < 100 && Math.abs(r - g) > 20) {
        const p = i / 4;
        const [x, y] = [p % canvas.width, Math.floor(p / canvas.width)];
        box.left = Math.min(box.left, x); box.right = Math.max(box.right, x);
        box.top = Math.min(box.top, y); box.bottom = Math.max(box.bottom, y);
      }
    }
    const scale = canvas.width / canvas.clientWidth;
    return { left: box.left / scale, right: box.right / scale, top: box.top / scale, bottom: box.bottom / scale };
  });
}

/** Where the robot is on the viewer: the centre of its coloured pixels (CSS px). */
async function robotCentre() {
  return page.evaluate(() => {
    const canvas = /** @type {HTMLCanvasElement} */ (document.querySelector('[data-testid="viewer"]'));
    const data = canvas.getContext('2d')?.getImageData(0, 0, canvas.width, canvas.height).data ?? [];
    let [sx, sy, n] = [0, 0, 0];
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
      if (Math.max(r, g) > 140 && b < 100 && Math.abs(r - g) > 20) { const p = i / 4; sx += p % canvas.width; sy += Math.floor(p / canvas.width); n++; }
    }
    const scale = canvas.width / canvas.clientWidth;
    return { x: sx / n / scale, y: sy / n / scale };
  });
}
