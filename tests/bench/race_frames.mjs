// @ts-check
/**
 * Frame rate and main-thread tasks of the side-by-side race (a benchmark that prints
 * figures, not a test): the page in headless Chromium at 1400 x 900, four pretrained
 * robots (attention, MLP-Comm, MLP on biped-4x3 and attention on comb-7x2) racing in real
 * time, each in its own simulation worker, the main thread only drawing. Over WINDOW_S
 * seconds of the race it counts animation frames and collects every main-thread task over
 * 50 ms (PerformanceObserver 'longtask') and how busy the main thread was (Chromium's
 * Performance metrics).
 *
 *   node tests/bench/race_frames.mjs [--seconds S]
 * Needs www/pkg (`make wasm`). Headless Chromium without a GPU draws in software, so a
 * real browser does at least as well.
 */
import os from 'node:os';
import { openPage, start } from '../web/harness.mjs';

const args = process.argv.slice(2);
const at = args.indexOf('--seconds');
const WINDOW_S = at >= 0 ? Number(args[at + 1]) : 10;
const MODULES = ['biped-4x3-attention', 'biped-4x3-mlp-comm', 'biped-4x3-mlp', 'comb-7x2-attention'];

/**
 * Frames, the longest gap between two, main-thread tasks over 50 ms (registered once on the
 * page) and each racer's simulated seconds per wall second, over `seconds` of wall time.
 * @param {import('playwright-core').Page} page @param {number} seconds
 */
async function measure(page, seconds) {
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Performance.enable');
  const metrics = async () => Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map((m) => [m.name, m.value]));
  const before = await metrics();
  const result = await page.evaluate((seconds) => new Promise((resolve) => {
    const w = /** @type {any} */ (window);
    const from = performance.now();
    /** @type {number[]} */
    const gaps = [];
    let last = from;
    const times = () => [...document.querySelectorAll('[data-testid="race-speed"]')].map((o) => Number(/** @type {HTMLElement} */ (o).dataset.time));
    const simFrom = times();
    requestAnimationFrame(function tick(now) {
      gaps.push(now - last);
      last = now;
      if (now - from < seconds * 1000) { requestAnimationFrame(tick); return; }
      resolve({ frames: gaps.length, wall: (now - from) / 1000, worstGap: Math.max(...gaps.slice(1)),
        longTasks: w.longTasks.filter((/** @type {any} */ t) => t.start >= from).map((/** @type {any} */ t) => t.ms),
        simRates: times().map((t, i) => (t - simFrom[i]) / ((now - from) / 1000)) });
    });
  }), seconds);
  const after = await metrics();
  const busy = (/** @type {string} */ key) => (after[key] - before[key]) / /** @type {any} */ (result).wall;
  return { ...result, busy: { task: busy('TaskDuration'), script: busy('ScriptDuration'), layout: busy('LayoutDuration') + busy('RecalcStyleDuration') } };
}

/** @param {string} what @param {any} r */
function report(what, r) {
  console.log(`${what}, ${r.wall.toFixed(1)} s of wall time (load average ${os.loadavg()[0].toFixed(1)} on ${os.cpus().length} cores):`);
  console.log(`  ${r.frames} frames (${(r.frames / r.wall).toFixed(1)} frames/s), longest gap between frames ${r.worstGap.toFixed(1)} ms`);
  console.log(`  main-thread tasks over 50 ms: ${r.longTasks.length}${r.longTasks.length ? ` (longest ${Math.max(...r.longTasks).toFixed(0)} ms)` : ''}`);
  console.log(`  main thread busy ${(100 * r.busy.task).toFixed(0)}% of the time (scripts ${(100 * r.busy.script).toFixed(0)}%, style and layout ${(100 * r.busy.layout).toFixed(0)}%)`);
  if (r.simRates.length) console.log(`  simulated s per wall s, per robot: ${r.simRates.map((/** @type {number} */ v) => v.toFixed(2)).join(', ')}`);
}

const env = await start();
try {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  await page.evaluate(() => {
    /** @type {any} */ (window).longTasks = [];
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) /** @type {any} */ (window).longTasks.push({ start: e.startTime, ms: e.duration });
    }).observe({ type: 'longtask' });
  });
  report('the page alone (the viewer walking the default robot), 1400 x 900', await measure(page, WINDOW_S));
  for (const m of MODULES) {
    await page.locator('[data-testid="pretrained"]').selectOption(`pretrained/${m}.json`);
    await page.locator('[data-testid="race-add"]').click();
  }
  await page.waitForFunction(() => [...document.querySelectorAll('[data-testid="race-speed"]')]
    .filter((o) => Number(/** @type {HTMLElement} */ (o).dataset.time) > 1).length === 4, undefined, { timeout: 30_000 });
  await page.locator('#race-panel').scrollIntoViewIfNeeded();
  report('a race of 4 robots in real time (and the viewer walking), 1400 x 900', await measure(page, WINDOW_S));
  if (problems.length) console.log(`problems: ${problems.join('; ')}`);
} finally {
  await env.close();
}
