// @ts-check
/**
 * Browser test of the CSV downloads (node --test): a run's table (a row per generation: its
 * best, its median, the evaluations so far, speeds to 4 decimals) parses and holds the run file's own figures, the
 * same run Export run downloads; a race's table (every half second, each robot's distance from
 * the start line) parses, starts at 0 m and ends at the distance and speed the lanes show at
 * the finish. The buttons are `run-csv` and `race-csv`. Saves screenshots/csv-run.png and csv-race.png.
 */
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { SCREENSHOTS, byTestId, openPage, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

/**
 * Parses CSV (RFC 4180: quoted cells may hold commas, quotes and line breaks).
 * @param {string} text @returns {string[][]}
 */
function parseCsv(text) {
  /** @type {string[][]} */ const rows = [];
  let row = /** @type {string[]} */ ([]);
  let cell = '';
  let quoted = false;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (quoted) {
      if (c === '"' && text[i + 1] === '"') { cell += '"'; i++; } else if (c === '"') quoted = false; else cell += c;
    } else if (c === '"') quoted = true;
    else if (c === ',') { row.push(cell); cell = ''; } else if (c === '\n') { row.push(cell.replace(/\r$/, '')); rows.push(row); row = []; cell = ''; } else cell += c;
  }
  if (cell || row.length) { row.push(cell); rows.push(row); }
  return rows;
}

/**
 * Clicks `button` and gives the file it downloads, read and parsed.
 * @param {import('playwright-core').Page} page @param {import('playwright-core').Locator} button
 */
async function download(page, button) {
  const [file] = await Promise.all([page.waitForEvent('download'), button.click()]);
  const saved = path.join(SCREENSHOTS, file.suggestedFilename());
  await file.saveAs(saved);
  const text = await readFile(saved, 'utf8');
  assert.ok(text.endsWith('\r\n'), 'CSV lines end in CRLF');
  return { name: file.suggestedFilename(), rows: parseCsv(text) };
}

test('a run\'s CSV: per generation its best, median and evaluations, as in its run file', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  const csvButton = byTestId(page, 'run-csv');
  assert.equal(await csvButton.isDisabled(), true, 'nothing to download before a run');
  for (const [key, value] of Object.entries({ population: '6', seconds: '2', budget: '30', seed: '7', terrain: 'flat', workers: '2' })) {
    await page.locator(`#run-${key}`).fill(value);
  }
  await byTestId(page, 'evolve').click();
  await page.waitForFunction(() => document.body.dataset.run === 'finished', undefined, { timeout: 120_000 });
  const { name, rows } = await download(page, csvButton);
  assert.equal(name, 'evolved-attention-seed7-generations.csv');
  assert.deepEqual(rows[0], ['run', 'generation', 'evaluations', 'best (m/s)', 'median (m/s)', 'best so far (m/s)']);
  const [runFile] = await Promise.all([page.waitForEvent('download'), byTestId(page, 'export').click()]);
  const run = JSON.parse(await readFile(String(await runFile.path()), 'utf8'));
  assert.equal(rows.length - 1, run.generations.length, 'a row per generation');
  let bestSoFar = -Infinity;
  run.generations.forEach((/** @type {any} */ g, /** @type {number} */ i) => {
    const [what, generation, evaluations, best, median, soFar] = rows[i + 1];
    bestSoFar = Math.max(bestSoFar, g.best);
    assert.equal(what, 'evolve');
    const four = (/** @type {number} */ v) => Math.round(v * 1e4) / 1e4; // 0.1 mm/s: a spreadsheet's speeds, not 17 digits
    assert.deepEqual([Number(generation), Number(evaluations), Number(best), Number(median), Number(soFar)],
      [g.generation, g.evaluations, four(g.best), four(g.median), four(bestSoFar)], `generation ${g.generation}: the run file's figures to 4 decimals`);
    for (const v of [best, median, soFar]) assert.match(v, /^-?\d+(\.\d{1,4})?$/, 'at most 4 decimals');
  });
  await page.locator('#run-progress').screenshot({ path: path.join(SCREENSHOTS, 'csv-run.png') });
  assert.deepEqual(problems, []);
  await context.close();
});

test('a race\'s CSV: every half second each robot\'s distance, ending where the lanes end', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  const race = page.locator('#race-panel');
  const csvButton = byTestId(page, 'race-csv');
  assert.equal(await csvButton.isDisabled(), true, 'no race, nothing to download');
  await page.locator('#race-seconds').fill('4');
  for (const module of ['pretrained/biped-4x3-attention.json', 'pretrained/biped-4x3-mlp.json']) {
    await byTestId(page, 'pretrained').selectOption(module);
    await byTestId(page, 'race-add').click();
  }
  await race.locator('[data-testid="race-robot"]').nth(1).waitFor();
  await page.locator('#race-panel[data-state="finished"]').waitFor({ timeout: 60_000 });
  await waitForText(page, 'race-status', /finished/);
  const { name, rows } = await download(page, csvButton);
  assert.equal(name, 'race-hilly-1-10-0-4s.csv');
  assert.equal(rows[0][0], 'time (s)');
  assert.match(rows[0][1], /^1\. attention on biped-4x3.*: distance \(m\)$/);
  assert.match(rows[0][2], /^2\. mlp on biped-4x3.*: distance \(m\)$/);
  const times = rows.slice(1).map((r) => Number(r[0]));
  const finish = times[times.length - 1]; // where the race stops, at the step vsr evaluate's episode ends on
  assert.ok(finish >= 4 && finish < 4.05, `the last row at the finish: ${finish} s`);
  assert.deepEqual(times.filter((t) => t !== finish || t === 4), [0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4], 'a row every half second');
  assert.deepEqual(rows[1].slice(1).map(Number), [0, 0], 'both at the start line at 0 s');
  const lanes = await race.locator('[data-testid="race-robot"]').evaluateAll((els) => els.map((el) => ({
    distance: Number(/(−?\d+\.\d) m in/.exec(el.querySelector('.race-distance')?.textContent ?? '')?.[1].replace('−', '-')),
    speed: Number(/** @type {HTMLElement} */ (el.querySelector('[data-testid="race-speed"]')).dataset.value),
  })));
  lanes.forEach((lane, i) => {
    const end = Number(rows[rows.length - 1][i + 1]);
    assert.ok(Math.abs(end - lane.distance) <= 0.05 + 1e-9, `robot ${i + 1}: ${end} m in the CSV, ${lane.distance} m on its lane`);
    // The fitness divides by the episode's seconds (the race's 4), its last step just past them.
    assert.ok(Math.abs(end / 4 - lane.speed) < 1e-6, `robot ${i + 1}: ${end} m over the race's 4 s is its speed ${lane.speed} m/s`);
  });
  await race.screenshot({ path: path.join(SCREENSHOTS, 'csv-race.png') });
  assert.deepEqual(problems, []);
  await context.close();
});
