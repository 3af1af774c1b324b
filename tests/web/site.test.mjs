// @ts-check
/**
 * Browser test of the site a school hosts (node --test): `make site`'s folder (scripts/site.mjs,
 * built here into a temporary folder) served by a plain static server, `python3 -m http.server`,
 * from the folder above it, so the page lives at a sub-path (/site/), as on GitHub Pages or a
 * school's server. The page opens with no console error and no missing file, asks only for
 * addresses under /site/, fetches none of the study's files before its panel is in sight (nor the
 * QR codes' library before a teacher's box opens), has a
 * description and a preview image for link previews, and a robot walks; a chapter opens by its
 * link; the guides the page links are readable web pages (no raw Markdown) whose links all lead
 * somewhere. The key path of a lesson, walked as a student does: open, draw, load a module,
 * evolve a few generations, make a share link and open it, open a tour chapter by its link,
 * open the study panel and watch a run's best, open the teachers' guide; online after a first
 * visit, then the same with the network cut (Chromium's offline emulation). axe-core's WCAG 2.1
 * A and AA rules at 1400 and 420 px: no serious or critical violation. Printed, not asserted:
 * the site folder's size, the bytes before the first robot walks and the time to it with the
 * CPU slowed 4 times.
 * Saves screenshots/site-1400.png, site-420.png, site-guide-1400.png, site-guide-420.png,
 * site-path-1400.png and site-offline-1400.png.
 */
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { mkdtemp, readFile, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { buildSite } from '../../scripts/site.mjs';
import { ROOT, byTestId, launchChromium, clickCells, figure, openBare, screenshot, waitForFigure, waitForText } from './harness.mjs';

/** axe-core's script, injected into the page (an npm dev dependency). */
const AXE = readFileSync(path.join(ROOT, 'node_modules', 'axe-core', 'axe.min.js'), 'utf8');
/** A four-legged table, 11111-11111-10101, drawn cell by cell (x from the left, y from the bottom). */
const TABLE = [[0, 2], [1, 2], [2, 2], [3, 2], [4, 2], [0, 1], [1, 1], [2, 1], [3, 1], [4, 1], [0, 0], [2, 0], [4, 0]];

/** @type {string} */ let folder;
/** @type {import('node:child_process').ChildProcess} */ let server;
/** @type {import('playwright-core').Browser} */ let browser;
/** The site's address: a sub-path of the server. */ let site = '';
/** @type {Awaited<ReturnType<typeof buildSite>>} */ let built;

/** Serves `root` with Python's static server on a free port; resolves with its address. @param {string} root */
function pythonServer(root) {
  const child = spawn('python3', ['-u', '-m', 'http.server', '0', '--bind', '127.0.0.1', '--directory', root], { stdio: ['ignore', 'pipe', 'pipe'] });
  return new Promise((resolve, reject) => {
    let said = '';
    child.stdout?.on('data', (chunk) => {
      said += chunk;
      const port = /port (\d+)/.exec(said)?.[1];
      if (port) resolve({ child, url: `http://127.0.0.1:${port}/` });
    });
    child.stderr?.resume(); // its request log
    child.once('exit', (code) => reject(new Error(`python3 -m http.server stopped (${code}): ${said}`)));
  });
}

before(async () => {
  folder = await mkdtemp(path.join(tmpdir(), 'vsr-site-'));
  built = await buildSite({ out: path.join(folder, 'site'), log: () => {} });
  const served = /** @type {{child: import('node:child_process').ChildProcess, url: string}} */ (await pythonServer(folder));
  server = served.child;
  site = `${served.url}site/`;
  browser = await launchChromium();
});

after(async () => {
  await browser?.close();
  server?.kill();
  if (folder) await rm(folder, { recursive: true, force: true });
});

/**
 * Opens `url` in a new page, its problems collected, with every answer of 400 or more and every
 * address asked outside the site added to them.
 * @param {string} url @param {{width?: number, height?: number}} [size]
 */
async function open(url, size = {}) {
  const opened = await openBare(browser, 'about:blank', size);
  opened.page.on('response', (r) => { if (r.status() >= 400) opened.problems.push(`HTTP ${r.status()}: ${r.url()}`); });
  opened.page.on('request', (r) => {
    if (/^https?:/.test(r.url()) && !r.url().startsWith(site)) opened.problems.push(`asked outside the site: ${r.url()}`);
  });
  await opened.page.goto(url);
  return opened;
}

/** Waits until the robot has walked a few simulated seconds and moved. @param {import('playwright-core').Page} page */
async function walks(page) {
  await waitForText(page, 'status', /voxels/, 30_000);
  await waitForFigure(page, 'sim-time', 'v >= 1', 30_000);
  const x0 = await figure(page, 'robot-x');
  await waitForFigure(page, 'sim-time', 'v >= 4', 30_000);
  const x1 = await figure(page, 'robot-x');
  assert.ok(Math.abs(x1 - x0) > 0.2, `the robot walks: x from ${x0} to ${x1}`);
}

test('make site: one folder with the page, its versioned code, the modules, the study files and the guides as pages', async () => {
  const files = new Set(built.files);
  const app = `app-${built.version}/`;
  for (const f of ['index.html', 'sw.js', `${app}main.js`, `${app}pkg/vsr.js`, `${app}pkg/vsr_bg.wasm`, `${app}vendor/uqr.js`,
    'pretrained/manifest.json', 'pretrained/biped-4x3-attention.json', 'study/campaign.csv', 'study/report/fig4-rq1-biped-4x3-30000-unseen.svg',
    'docs/teaching.html', 'docs/RESULTS.html']) assert.ok(files.has(f), `the site has ${f}`);
  for (const f of built.files) {
    assert.ok(/^(index\.html|sw\.js|app-[0-9a-f]{12}\/.+|pretrained\/.+\.json|study\/.+\.(csv|svg|json)|docs\/.+\.(html|png))$/.test(f), `nothing else: ${f}`);
    assert.ok(!/\.md$/.test(f) && !f.startsWith(`${app}embed/`) && !f.endsWith('.d.ts'), `not a page file: ${f}`);
  }
  const index = await readFile(path.join(folder, 'site', 'index.html'), 'utf8');
  for (const m of index.matchAll(/\b(?:href|src)="([^"]+)"/g)) {
    assert.ok(!m[1].startsWith('/') && !/^https?:\/\/(127\.0\.0\.1|localhost)/.test(m[1]), `a relative address in index.html: ${m[1]}`);
  }
  assert.match(index, new RegExp(`src="${app}main\\.js"`), 'the page loads its versioned code');
  // What a link preview shows: a description, and an image of the site (not kept for offline use: only a preview reads it).
  assert.match(index, /<meta name="description" content="[^"]{80,300}">/, 'a description for link previews');
  const image = /<meta property="og:image" content="([^"]+)"/.exec(index)?.[1] ?? '';
  assert.ok(files.has(image) && image.endsWith('.png'), `the preview image is a file of the site: ${image}`);
  assert.equal(/<meta name="twitter:image" content="([^"]+)"/.exec(index)?.[1], image);
  assert.ok(!built.precache.includes(image), 'the preview image is not kept offline');
  const kept = built.precache.reduce((sum, f) => sum + (f === './' ? 0 : readFileSync(path.join(folder, 'site', f)).length), 0);
  console.log(`site ${built.version}: ${built.files.length} files, ${(built.bytes / 1e6).toFixed(1)} MB (${built.bytes} bytes); `
    + `kept offline on the first visit: ${(kept / 1e6).toFixed(1)} MB`);
});

test('served at a sub-path by python3 -m http.server: the page loads with no error or missing file, a robot walks, the study\'s files wait for their panel, a chapter opens by its link', async () => {
  for (const width of [1400, 420]) {
    /** @type {string[]} */
    const study = [];
    const { page, problems, context } = await open('about:blank', { width, height: 900 });
    /** The QR library, asked for by the teacher's boxes only. */
    let qr = false;
    page.on('request', (r) => {
      if (r.url().startsWith(`${site}study/`)) study.push(r.url().slice(site.length));
      if (r.url().endsWith('/vendor/uqr.js')) qr = true;
    });
    await page.goto(site);
    await walks(page);
    await page.waitForFunction(() => (/** @type {HTMLSelectElement} */ (document.getElementById('module'))).options.length > 3, undefined, { timeout: 20_000 });
    await screenshot(page, `site-${width}.png`);
    await page.waitForTimeout(1000);
    assert.deepEqual(study, [], `at ${width} px the first screen fetches none of the study's files`);
    assert.equal(qr, false, `at ${width} px the first screen fetches no QR library`);
    // Scrolled to, the study panel fetches its tables and figure.
    await byTestId(page, 'study').scrollIntoViewIfNeeded();
    await page.waitForFunction(() => { const img = /** @type {HTMLImageElement} */ (document.getElementById('study-image')); return img.complete && img.naturalWidth > 0; },
      undefined, { timeout: 20_000 });
    assert.ok(await byTestId(page, 'study-run').locator('option').count() >= 5, 'its runs are listed');
    assert.ok(study.includes('study/campaign.csv') && study.some((f) => f.endsWith('.svg')), `then: ${study}`);
    assert.deepEqual(problems, [], `at ${width} px`);
    await context.close();
  }
  const { page, problems, context } = await open(`${site}?chapter=4`);
  await page.locator('#tour-box[data-chapter="4"]').waitFor({ timeout: 30_000 });
  await walks(page);
  assert.deepEqual(problems, []);
  await context.close();
});

test('the guides the page links open as readable pages, and every link in them leads somewhere', async () => {
  const { page, problems, context } = await open(site, { width: 1400, height: 900 });
  await waitForText(page, 'status', /voxels/, 30_000);
  const results = await page.locator('a[href="docs/RESULTS.html"]').first().evaluate((a) => /** @type {HTMLAnchorElement} */ (a).href);
  assert.ok(results.startsWith(site), `the page links the results at the site: ${results}`);
  for (const [url, width] of /** @type {[string, number][]} */ ([[results, 1400], [`${site}docs/teaching.html`, 1400], [`${site}docs/teaching.html`, 420]])) {
    await page.setViewportSize({ width, height: 900 });
    await page.goto(url);
    const doc = byTestId(page, 'doc');
    const text = String(await doc.innerText());
    assert.ok(text.length > 1000, 'a whole guide');
    assert.ok(await doc.locator('h1').count() === 1 && await doc.locator('table').count() > 0, 'headings and tables are HTML');
    for (const raw of [/^#{1,6} /m, /\*\*/, /^\|.*\|$/m, /\]\(/]) assert.doesNotMatch(text, raw, `no raw Markdown (${raw}) in ${url}`);
    if (url.endsWith('teaching.html')) await screenshot(page, `site-guide-${width}.png`);
  }
  assert.deepEqual(problems, []);
  await context.close();
  // Every link and image of every guide, fetched: none leads to a missing file.
  for (const file of built.files.filter((f) => /^docs\/.+\.html$/.test(f))) {
    const html = await readFile(path.join(folder, 'site', file), 'utf8');
    for (const m of html.matchAll(/\b(?:href|src)="([^"#]+)(#[^"]*)?"/g)) {
      if (/^(https?:|mailto:|data:)/.test(m[1]) && !m[1].startsWith(site)) continue;
      const url = new URL(m[1], `${site}${file}`).href;
      const response = await fetch(url, { method: 'HEAD' });
      assert.equal(response.status, 200, `${file} links ${m[1]}`);
    }
  }
});

/**
 * The key path of a lesson, as a student walks it: open the page, draw a table, load a
 * pretrained module onto it, evolve a few generations, make a share link and open it, open a
 * tour chapter by its link, open the study panel and watch a run's best, open the teachers'
 * guide. Each step checks what the student sees; the page's problems are the caller's.
 * @param {import('playwright-core').Page} page @param {string} when for the messages and the screenshot
 */
async function keyPath(page, when) {
  await page.goto(site);
  await walks(page);
  // Draw.
  await page.locator('#clear').click();
  await clickCells(page, /** @type {[number, number][]} */ (TABLE));
  await waitForText(page, 'shape-status', /^13 voxels · 11111-11111-10101$/);
  // A module onto the drawing.
  await page.waitForFunction(() => (/** @type {HTMLSelectElement} */ (document.getElementById('module'))).options.length > 3, undefined, { timeout: 20_000 });
  await byTestId(page, 'pretrained').selectOption('pretrained/biped-4x3-attention.json');
  await byTestId(page, 'load-pretrained').click();
  await waitForText(page, 'status', /^13 voxels, attention$/, 30_000);
  await waitForFigure(page, 'sim-time', 'v >= 2', 30_000); // its walk goes on (one-shot, a transplant barely moves)
  // Evolve a few generations: 6 brains, 2-s walks on flat ground, 30 evaluations (generations 0, 1 and 2).
  for (const [key, value] of Object.entries({ population: '6', seconds: '2', budget: '30', seed: '4', terrain: 'flat', workers: '2' })) {
    await page.locator(`#run-${key}`).fill(value);
  }
  await byTestId(page, 'evolve').click();
  await page.waitForFunction(() => document.body.dataset.run === 'finished', undefined, { timeout: 120_000 });
  assert.equal(await figure(page, 'run-generation'), 2, `${when}: three generations`);
  await waitForText(page, 'driver', /the evolved run's result/, 30_000);
  // A share link, opened as a classmate would.
  await byTestId(page, 'share').click();
  await page.waitForFunction(() => (document.getElementById('share-link')?.dataset.value ?? '').includes('#'));
  const link = String(await page.locator('#share-link').getAttribute('data-value'));
  assert.ok(link.startsWith(site), `${when}: the link is the site's: ${link}`);
  await page.goto('about:blank');
  await page.goto(link);
  await waitForText(page, 'status', /^13 voxels, attention$/, 30_000);
  await waitForText(page, 'shape-status', /^13 voxels · 11111-11111-10101$/);
  await waitForFigure(page, 'sim-time', 'v >= 2', 30_000); // the evolved robot's walk (30 evaluations make no fast walker)
  // A tour chapter by its link.
  await page.goto(`${site}?chapter=4`);
  await page.locator('#tour-box[data-chapter="4"]').waitFor({ timeout: 30_000 });
  await walks(page);
  await page.locator('#tour-close').click();
  // The study panel: its figure, its runs, one run's best walking.
  await byTestId(page, 'study').scrollIntoViewIfNeeded();
  await page.waitForFunction(() => { const img = /** @type {HTMLImageElement} */ (document.getElementById('study-image')); return img.complete && img.naturalWidth > 0; },
    undefined, { timeout: 20_000 });
  assert.ok(await byTestId(page, 'study-run').locator('option').count() >= 5, `${when}: the study's runs are listed`);
  const run = await byTestId(page, 'study-run').inputValue();
  await byTestId(page, 'study-watch').click();
  await waitForText(page, 'driver', new RegExp(run.startsWith('biped-4x3-attention') ? 'study: attention on biped-4x3' : 'study:'), 30_000);
  await walks(page);
  await screenshot(page, `site-${when}-1400.png`);
  // The teachers' guide, readable.
  await page.goto(`${site}docs/teaching.html`);
  const doc = byTestId(page, 'doc');
  assert.match(String(await doc.locator('h1').textContent()), /Teaching/);
  assert.ok(await doc.locator('table').count() > 0, `${when}: the lesson's table is a table`);
  assert.doesNotMatch(String(await doc.innerText()), /\*\*|^#{1,6} /m, `${when}: no raw Markdown`);
}

test('the key path of a lesson, online after a first visit and then with the network cut: no missing file, no error', async () => {
  const { page, problems, context } = await open(site, { width: 1400, height: 900 });
  // The first visit keeps the site on the device.
  await walks(page);
  await waitForText(page, 'offline-status', /Kept on this device/, 60_000);
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null, undefined, { timeout: 20_000 });
  await keyPath(page, 'path');
  assert.deepEqual(problems, [], 'online');
  await context.setOffline(true);
  await page.goto(site);
  // (Chromium's offline emulation leaves navigator.onLine true: the page's "No network" line is not asked for.)
  await keyPath(page, 'offline');
  assert.deepEqual(problems, [], 'offline');
  await context.close();
});

/**
 * axe-core's WCAG 2.1 A and AA rules on the page as it is now: its violations whose impact is
 * serious or critical, each with the elements it names.
 * @param {import('playwright-core').Page} page @returns {Promise<string[]>}
 */
async function axeViolations(page) {
  await page.addScriptTag({ content: AXE });
  return page.evaluate(async () => {
    const axe = /** @type {any} */ (window).axe;
    const result = await axe.run(document, { runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] } });
    return result.violations.filter((/** @type {any} */ v) => v.impact === 'serious' || v.impact === 'critical')
      .map((/** @type {any} */ v) => `${v.id} (${v.impact}): ${v.nodes.map((/** @type {any} */ n) => n.target.join(' ')).join(', ')}`);
  });
}

test('accessible: axe-core\'s WCAG 2.1 A and AA rules find no serious or critical violation at 1400 and 420 px', async () => {
  for (const width of [1400, 420]) {
    const { page, problems, context } = await open(site, { width, height: 900 });
    await walks(page);
    assert.deepEqual(await axeViolations(page), [], `the page as it opens, at ${width} px`);
    // Every fold open (the glossary, the teacher's boxes, the statistics), in simple words, scrolled to the end: the study panel filled.
    await page.evaluate(() => { for (const d of document.querySelectorAll('details')) d.open = true; });
    await byTestId(page, 'simple-words').check();
    await byTestId(page, 'study').scrollIntoViewIfNeeded();
    await page.waitForFunction(() => (/** @type {HTMLSelectElement} */ (document.getElementById('study-run'))).options.length > 0, undefined, { timeout: 20_000 });
    assert.deepEqual(await axeViolations(page), [], `every fold open, at ${width} px`);
    // A tour chapter, its box over the page.
    await page.goto(`${site}?chapter=4`);
    await page.locator('#tour-box[data-chapter="4"]').waitFor({ timeout: 30_000 });
    await walks(page);
    assert.deepEqual(await axeViolations(page), [], `the tour's chapter 4, at ${width} px`);
    assert.deepEqual(problems, []);
    await context.close();
  }
});

test('printed, not asserted: the bytes before the first robot walks, and the time to it with the CPU slowed 4 times', async () => {
  const { page, problems, context } = await open('about:blank', { width: 1400, height: 900 });
  // The moment the page first shows a walking robot (its clock past 0), in the page's own time from the start of its navigation.
  await page.addInitScript(() => {
    const tick = () => {
      if (Number(document.getElementById('sim-time')?.dataset.value) > 0) /** @type {any} */ (window).firstWalk = performance.now();
      else requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  const cdp = await context.newCDPSession(page);
  await cdp.send('Emulation.setCPUThrottlingRate', { rate: 4 });
  /** Every request of the page and its workers that finished, when, and the bytes it received (body and headers). @type {Promise<{at: number, bytes: number}>[]} */
  const finished = [];
  page.on('requestfinished', (r) => {
    const at = Date.now();
    finished.push(r.sizes().then((s) => ({ at, bytes: s.responseBodySize + s.responseHeadersSize }), () => ({ at, bytes: 0 })));
  });
  await page.goto(site);
  await page.waitForFunction(() => /** @type {any} */ (window).firstWalk !== undefined, undefined, { timeout: 120_000, polling: 50 });
  const walkedAt = Date.now();
  const ms = await page.evaluate(() => /** @type {any} */ (window).firstWalk);
  const before = (await Promise.all(finished)).filter((f) => f.at <= walkedAt);
  const bytes = before.reduce((sum, f) => sum + f.bytes, 0);
  const files = before.length;
  console.log(`first visit, before the first robot walks: ${files} files, ${(bytes / 1e6).toFixed(2)} MB (${bytes} bytes); `
    + `the first walking robot at ${(ms / 1000).toFixed(1)} s with the CPU slowed 4 times (CDP Emulation.setCPUThrottlingRate 4; no network throttling)`);
  await walks(page);
  assert.deepEqual(problems, []);
  await context.close();
});

test('a new version replaces the kept copy as a whole: the page offers it, switches on a click, and only its files stay kept', async () => {
  const { page, problems, context } = await open(site, { width: 1400, height: 900 });
  await walks(page);
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null, undefined, { timeout: 60_000 });
  const before = built.version;
  const next = await buildSite({ out: path.join(folder, 'site'), salt: 'a later build', log: () => {} });
  assert.notEqual(next.version, before);
  await page.evaluate(async () => { await (await navigator.serviceWorker.getRegistration())?.update(); });
  await waitForText(page, 'offline-status', /A new version of this page is ready/, 60_000);
  assert.equal(await page.evaluate(() => document.querySelector('meta[name="vsr-site"]')?.getAttribute('content')), before, 'the old page goes on until asked');
  await Promise.all([page.waitForEvent('load', { timeout: 60_000 }), byTestId(page, 'offline-update').click()]);
  await walks(page);
  assert.equal(await page.evaluate(() => document.querySelector('meta[name="vsr-site"]')?.getAttribute('content')), next.version, 'the page is the new one');
  const scripts = await page.evaluate(() => performance.getEntriesByType('resource').map((e) => e.name).filter((n) => /\/app-[0-9a-f]+\//.test(n)));
  assert.ok(scripts.length > 0 && scripts.every((n) => n.includes(`/app-${next.version}/`)), 'every script of the new page from the new version');
  assert.deepEqual(await page.evaluate(() => caches.keys()), [`vsr-site-${next.version}`], 'one kept copy, the new one');
  assert.deepEqual(problems, []);
  await context.close();
  built = next;
});
