// @ts-check
/**
 * What every browser test shares: serve www/ (and pretrained/) on a free port, open it in
 * headless Debian Chromium through playwright-core, collect console errors, page errors
 * and failed requests (from workers too), and act on the page as a person does: draw cells
 * on the editor, read the live figures (their raw numbers in data-value), wait for text.
 * Needs `make wasm` (www/pkg) first; CHROMIUM overrides /usr/bin/chromium.
 */
import assert from 'node:assert/strict';
import { mkdir } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { serve } from '../../scripts/serve.mjs';

const HERE = path.dirname(fileURLToPath(import.meta.url));
export const ROOT = path.resolve(HERE, '..', '..');
export const SCREENSHOTS = path.join(HERE, 'screenshots');
/** The native CLI, for comparisons (VSR_BIN overrides). */
export const BIN = path.resolve(process.env.VSR_BIN
  ?? path.join(process.env.CARGO_TARGET_DIR ?? path.join(ROOT, 'target'), 'release', 'vsr'));
export const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic',
  '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'];

/**
 * Serves the page and opens a browser.
 * @returns {Promise<{url: string, browser: import('playwright-core').Browser, close: () => Promise<void>}>}
 */
export async function start() {
  const served = await serve({ port: 0 });
  let browser;
  try {
    browser = await launchChromium();
  } catch (error) {
    served.server.close(); // an open server would keep this test file's process alive forever
    throw error;
  }
  return {
    url: served.url,
    browser,
    close: async () => { await browser.close(); served.server.close(); },
  };
}

/**
 * Headless Debian Chromium. A launch that crashes before the browser answers (seen once on a
 * fresh CI machine: SIGSEGV at start, before any page) is tried again, up to three times, and
 * said on stderr; a browser that never starts still fails the test.
 * @returns {Promise<import('playwright-core').Browser>}
 */
export async function launchChromium() {
  for (let attempt = 1; ; attempt++) {
    try {
      return await chromium.launch({ executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium', args: CHROMIUM_ARGS });
    } catch (error) {
      if (attempt >= 3) throw error;
      const first = String(error instanceof Error ? error.message : error).split('\n')[0];
      process.stderr.write(`harness: Chromium did not start (attempt ${attempt} of 3: ${first}); trying again\n`);
    }
  }
}

/**
 * A new page (its own storage) at `url`, with its problems collected, once the robot walks.
 * @param {import('playwright-core').Browser} browser @param {string} url
 * @param {Parameters<typeof openBare>[2]} [options] see {@link openBare}
 */
export async function openPage(browser, url, options = {}) {
  const opened = await openBare(browser, url, options);
  await waitForText(opened.page, 'status', /voxels/);
  return opened;
}

/**
 * A new page (its own storage) at `url`, with its problems collected, once it has loaded:
 * any page, not only the playground.
 * @param {import('playwright-core').Browser} browser @param {string} url
 * @param {{width?: number, height?: number, touch?: boolean, init?: () => void}} [options] screen size, a
 *   touch screen, a script run in the page's main realm before the page's own (not in its workers)
 */
export async function openBare(browser, url, options = {}) {
  const context = await browser.newContext({ viewport: { width: options.width ?? 1300, height: options.height ?? 1100 },
    acceptDownloads: true, hasTouch: options.touch ?? false });
  if (options.init) await context.addInitScript(options.init);
  const page = await context.newPage();
  /** @type {string[]} */
  const problems = [];
  page.on('console', (msg) => { if (msg.type() === 'error') problems.push(`console: ${msg.text()}`); });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  // A request the page itself cancelled (a reload, a worker it ended) is aborted, not failed.
  page.on('requestfailed', (req) => {
    const why = req.failure()?.errorText ?? '';
    if (why !== 'net::ERR_ABORTED') problems.push(`request failed: ${req.url()} (${why})`);
  });
  page.on('worker', (worker) => worker.on('console', (msg) => {
    if (msg.type() === 'error') problems.push(`worker console: ${msg.text()}`);
  }));
  await page.goto(url);
  return { page, problems, context };
}

/** @param {import('playwright-core').Page} page @param {string} testid */
export function byTestId(page, testid) {
  return page.locator(`[data-testid="${testid}"]`);
}

/** The raw number behind a figure. @param {import('playwright-core').Page} page @param {string} id an element id */
export async function figure(page, id) {
  return Number(await page.locator(`#${id}`).getAttribute('data-value'));
}

/**
 * Waits until the text of #id matches `pattern`.
 * @param {import('playwright-core').Page} page @param {string} id @param {RegExp} pattern @param {number} [timeout]
 */
export async function waitForText(page, id, pattern, timeout = 20_000) {
  await page.waitForFunction(([id, source, flags]) => new RegExp(source, flags).test(document.getElementById(id)?.textContent ?? ''),
    [id, pattern.source, pattern.flags], { timeout, polling: 50 });
}

/**
 * Waits until the number behind #id is `expected` (the page shows the core's answers a moment
 * after an action), else fails saying what it shows.
 * @param {import('playwright-core').Page} page @param {string} id @param {number} expected @param {string} [what]
 */
export async function expectFigure(page, id, expected, what) {
  try {
    await waitForFigure(page, id, `v === ${expected}`, 5_000);
  } catch {
    assert.equal(await figure(page, id), expected, what);
  }
}

/**
 * Waits until the number behind #id satisfies `test` (evaluated in the page as `v => ...`).
 * @param {import('playwright-core').Page} page @param {string} id @param {string} condition e.g. 'v >= 2'
 * @param {number} [timeout]
 */
export async function waitForFigure(page, id, condition, timeout = 60_000) {
  await page.waitForFunction(([id, condition]) => {
    const v = Number(document.getElementById(id)?.dataset.value);
    return Number.isFinite(v) && Function('v', `return ${condition}`)(v);
  }, [id, condition], { timeout, polling: 50 });
}

/**
 * Clicks grid cells of the editor, x from the left and y from the bottom; `button` 'right'
 * erases.
 * @param {import('playwright-core').Page} page @param {[number, number][]} cells
 * @param {'left' | 'right'} [button]
 */
export async function clickCells(page, cells, button = 'left') {
  const box = await byTestId(page, 'editor').boundingBox();
  if (!box) throw new Error('the editor is not visible');
  const side = box.width / 20;
  for (const [x, y] of cells) {
    await page.mouse.click(box.x + (x + 0.5) * side, box.y + box.height - (y + 0.5) * side, { button });
  }
}

/**
 * Taps grid cells of the editor with a finger, x from the left and y from the bottom.
 * @param {import('playwright-core').Page} page @param {[number, number][]} cells
 */
export async function tapCells(page, cells) {
  const box = await byTestId(page, 'editor').boundingBox();
  if (!box) throw new Error('the editor is not visible');
  const side = box.width / 20;
  for (const [x, y] of cells) await page.touchscreen.tap(box.x + (x + 0.5) * side, box.y + box.height - (y + 0.5) * side);
}

/**
 * Drags across the editor from one cell to another in a straight line.
 * @param {import('playwright-core').Page} page @param {[number, number]} from @param {[number, number]} to
 * @param {'left' | 'right'} [button]
 */
export async function dragCells(page, from, to, button = 'left') {
  const box = await byTestId(page, 'editor').boundingBox();
  if (!box) throw new Error('the editor is not visible');
  const side = box.width / 20;
  const at = (/** @type {[number, number]} */ [x, y]) => [box.x + (x + 0.5) * side, box.y + box.height - (y + 0.5) * side];
  const [x0, y0] = at(from);
  const [x1, y1] = at(to);
  await page.mouse.move(x0, y0);
  await page.mouse.down({ button });
  await page.mouse.move(x1, y1, { steps: 12 });
  await page.mouse.up({ button });
}

/** Saves a full-page screenshot under tests/web/screenshots/. @param {import('playwright-core').Page} page @param {string} name */
export async function screenshot(page, name) {
  await mkdir(SCREENSHOTS, { recursive: true });
  const file = path.join(SCREENSHOTS, name);
  await page.screenshot({ path: file, fullPage: true });
  return file;
}

/**
 * How many pixels of a canvas have a voxel's colour (red, yellow or green by its area; not the
 * sky, the ground or the lines): the robot is drawn. Runs in the page: `locator.evaluate(robotPixels)`.
 * @param {Element} canvas @returns {number}
 */
export function robotPixels(canvas) {
  const c = /** @type {HTMLCanvasElement} */ (canvas);
  const data = c.getContext('2d')?.getImageData(0, 0, c.width, c.height).data ?? [];
  let n = 0;
  for (let i = 0; i < data.length; i += 4) if (Math.max(data[i], data[i + 1]) > 140 && data[i + 2] < 100 && Math.abs(data[i] - data[i + 1]) > 20) n++;
  return n;
}
