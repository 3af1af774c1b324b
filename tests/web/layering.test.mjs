// @ts-check
/**
 * Browser test of the page's layering (node --test): its main thread never loads wasm. Every
 * way to compile or instantiate a wasm module is counted in the page's main realm (an init
 * script, which workers do not run) while a person draws a robot cell by cell, loads a
 * pretrained module onto it (transplant, the module's description) and shares it as a link;
 * the count stays 0 and the main realm fetches no wasm, while the core worker and the
 * simulation worker each fetch it. A core worker that dies is ended and the next question
 * starts a new one. Saves screenshots/core-worker-1400.png.
 */
import assert from 'node:assert/strict';
import { after, before, test } from 'node:test';
import { byTestId, clickCells, expectFigure, openPage, screenshot, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

/** Counts, in the realm it runs in, every call that compiles or instantiates wasm (in `wasmCalls`). */
function countWasm() {
  /** @type {string[]} */
  const calls = [];
  const wasm = /** @type {any} */ (WebAssembly);
  for (const name of ['compile', 'compileStreaming', 'instantiate', 'instantiateStreaming', 'validate']) {
    const real = wasm[name];
    wasm[name] = function (/** @type {any[]} */ ...args) { calls.push(name); return real.apply(this, args); };
  }
  for (const name of ['Module', 'Instance']) {
    wasm[name] = new Proxy(wasm[name], { construct(target, args) { calls.push(name); return Reflect.construct(target, args); } });
  }
  /** @type {any} */ (window).wasmCalls = calls;
}

/** The names of the resources a realm fetched (its own performance timeline). */
const fetched = () => performance.getEntriesByType('resource').map((e) => e.name);

/** A four-legged table, 11111-11111-10101. */
const TABLE = [[0, 2], [1, 2], [2, 2], [3, 2], [4, 2], [0, 1], [1, 1], [2, 1], [3, 1], [4, 1], [0, 0], [2, 0], [4, 0]];

test('the page\'s main thread loads no wasm: drawing, a transplant and a link are the core worker\'s answers', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1400, height: 1000, init: countWasm });
  await page.locator('#clear').click();
  await clickCells(page, /** @type {[number, number][]} */ (TABLE));
  await expectFigure(page, 'param-count', 32 + 4 * 13 + 1, 'the core\'s gene count for the drawing');
  assert.match(String(await page.locator('#param-count').textContent()), /^85 genes: 32 for the attention block, shared by every voxel, 52 for the outputs, .*each voxel adds 4.*and 1 bias shared by every voxel$/);
  await waitForText(page, 'shape-status', /^13 voxels · 11111-11111-10101$/);
  await byTestId(page, 'pretrained').selectOption('pretrained/biped-4x3-attention.json');
  await waitForText(page, 'module-details', /^This attention brain of 73 genes was evolved on biped-4x3 \(rows 1111-1111-1001\) with seed/);
  await byTestId(page, 'load-pretrained').click();
  await waitForText(page, 'driver', /a module transplanted from biped-4x3:/);
  await waitForText(page, 'status', /^13 voxels, attention$/);
  await page.locator('#share').click();
  await page.waitForFunction(() => /genome=/.test(/** @type {HTMLInputElement} */ (document.getElementById('share-link')).value));
  await page.waitForTimeout(1000); // the robot walks a while
  await screenshot(page, 'core-worker-1400.png');

  assert.deepEqual(await page.evaluate(() => /** @type {any} */ (window).wasmCalls), [], 'no wasm compiled or instantiated on the main thread');
  // (Chromium lists the scripts of the page's workers in the page's timeline too, not what they fetch.)
  const onPage = await page.evaluate(fetched);
  assert.deepEqual(onPage.filter((name) => name.endsWith('.wasm')), [], 'the main thread fetched no wasm');
  /** @type {Record<string, number>} */
  const wasmFetches = {};
  for (const worker of page.workers()) {
    const file = new URL(worker.url()).pathname.split('/').pop() ?? worker.url();
    // A short-lived worker (a speed measurement's) can end between the listing and the question: skipped.
    const names = await worker.evaluate(fetched).catch((error) => (/closed/.test(String(error)) ? [] : Promise.reject(error)));
    const n = names.filter((name) => name.endsWith('/pkg/vsr_bg.wasm')).length;
    wasmFetches[file] = (wasmFetches[file] ?? 0) + n;
  }
  console.log(`# vsr_bg.wasm fetched: main thread 0, workers ${JSON.stringify(wasmFetches)}`);
  assert.equal(wasmFetches['core-worker.js'], 1, 'the core worker loads the wasm once');
  assert.ok(wasmFetches['simulation-worker.js'] >= 1, 'the simulation worker loads its own');

  // The count is real: the same hook sees a wasm module instantiated on the main thread.
  await page.evaluate(() => WebAssembly.instantiate(new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0])));
  assert.deepEqual(await page.evaluate(() => /** @type {any} */ (window).wasmCalls), ['instantiate']);
  assert.deepEqual(problems, []);
  await page.context().close();
});

test('when the core worker dies, the next question starts a new one: the drawing is checked again', async () => {
  const { page, problems } = await openPage(env.browser, env.url);
  const core = page.workers().find((w) => w.url().endsWith('/core-worker.js'));
  assert.ok(core, 'a core worker runs');
  const ended = new Promise((resolve) => core.once('close', resolve));
  await core.evaluate(() => { setTimeout(() => { throw new Error('the core worker fails on purpose'); }); });
  await ended; // the page ended the failed worker
  await page.locator('#clear').click();
  await waitForText(page, 'shape-message', /draw at least one voxel/);
  await clickCells(page, [[0, 0], [1, 0]]);
  await waitForText(page, 'shape-status', /^2 voxels · 11$/);
  await expectFigure(page, 'param-count', 32 + 4 * 2 + 1);
  const cores = page.workers().filter((w) => w.url().endsWith('/core-worker.js'));
  assert.equal(cores.length, 1, 'the dead worker was ended and one new core worker answers');
  assert.notEqual(cores[0], core);
  console.log(`# problems seen (the failure on purpose): ${JSON.stringify(problems)}`);
  assert.ok(problems.every((p) => /fails on purpose/.test(p)), `nothing else went wrong: ${problems}`);
  await page.context().close();
});
