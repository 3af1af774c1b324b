// @ts-check
/**
 * Browser test of the site a school hosts (node --test): `make site`'s folder (scripts/site.mjs,
 * built here into a temporary folder) served by a plain static server, `python3 -m http.server`,
 * from the folder above it, so the page lives at a sub-path (/site/), as on GitHub Pages or a
 * school's server. The page opens with no console error and no missing file, asks only for
 * addresses under /site/, and a robot walks; a chapter opens by its link; the guides the page
 * links are readable web pages (no raw Markdown) whose links all lead somewhere; after a first
 * visit, with the network cut (Chromium's offline emulation), a reload draws the page, a robot
 * walks, the teachers' guide opens and the pretrained modules load.
 * Saves screenshots/site-1400.png, site-420.png, site-guide-1400.png and site-guide-420.png.
 */
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { mkdtemp, readFile, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { chromium } from 'playwright-core';
import { buildSite } from '../../scripts/site.mjs';
import { CHROMIUM_ARGS, byTestId, figure, openBare, screenshot, waitForFigure, waitForText } from './harness.mjs';

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
  browser = await chromium.launch({ executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium', args: CHROMIUM_ARGS });
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
  console.log(`site ${built.version}: ${built.files.length} files, ${(built.bytes / 1e6).toFixed(1)} MB`);
});

test('served at a sub-path by python3 -m http.server: the page loads with no error or missing file, a robot walks, a chapter opens by its link', async () => {
  for (const width of [1400, 420]) {
    const { page, problems, context } = await open(site, { width, height: 900 });
    await walks(page);
    await page.waitForFunction(() => (/** @type {HTMLSelectElement} */ (document.getElementById('module'))).options.length > 3, undefined, { timeout: 20_000 });
    await page.waitForFunction(() => { const img = /** @type {HTMLImageElement} */ (document.getElementById('study-image')); return img.complete && img.naturalWidth > 0; },
      undefined, { timeout: 20_000 });
    await screenshot(page, `site-${width}.png`);
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

test('offline after the first visit: with the network cut, a reload draws the page, a robot walks, the modules and the guide open', async () => {
  const { page, problems, context } = await open(site, { width: 1400, height: 900 });
  await walks(page);
  await waitForText(page, 'offline-status', /Kept on this device/, 60_000);
  await page.waitForFunction(() => navigator.serviceWorker.controller !== null, undefined, { timeout: 20_000 });
  await context.setOffline(true);
  await page.reload();
  await walks(page);
  await page.waitForFunction(() => (/** @type {HTMLSelectElement} */ (document.getElementById('module'))).options.length > 3, undefined, { timeout: 20_000 });
  await page.waitForFunction(() => { const img = /** @type {HTMLImageElement} */ (document.getElementById('study-image')); return img.complete && img.naturalWidth > 0; },
    undefined, { timeout: 20_000 });
  // A pretrained module onto the drawn robot, from the kept copy.
  await byTestId(page, 'load-pretrained').click();
  await waitForText(page, 'status', /attention/, 20_000);
  await walks(page);
  await page.screenshot({ path: '/tmp/site-offline-1400.png' });
  // A chapter's link and the teachers' guide, offline too.
  await page.goto(`${site}?chapter=4`);
  await page.locator('#tour-box[data-chapter="4"]').waitFor({ timeout: 30_000 });
  await page.goto(`${site}docs/teaching.html`);
  assert.match(String(await byTestId(page, 'doc').locator('h1').textContent()), /Teaching/);
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
