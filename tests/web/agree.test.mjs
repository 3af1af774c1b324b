// @ts-check
/**
 * Browser test of numbers that agree (issue 31; node --test): the biped-6x4 module, stopped
 * at 20,100 evaluations, says beside it what the same run's best at 30,100 walks (the study's
 * table), and so does that run in the study panel; a drawing in pieces counts its genes and
 * voxels beside the robot that still walks; the clock past the episode says the episode is
 * over; the freeze verdict keeps one wording while the frozen robot rocks; during a fine-tune
 * the training figure beside the walking best is its own, with why the viewer's speed
 * differs; at 375 px every figure fits. Saves screenshots/numbers-phone.png.
 */
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { ROOT, SCREENSHOTS, byTestId, figure, openPage, screenshot, start, waitForFigure, waitForText } from './harness.mjs';
import { ATTENTION, attentionOnWorm, episodeSpeed, openOwnBody, speedNote } from './viewer-numbers.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

function studyUnseen() {
  const [head, ...lines] = readFileSync(path.join(ROOT, 'study/campaign.csv'), 'utf8').trim().split('\n');
  const names = head.split(',');
  return new Map(lines.map((l) => l.split(',')).map((v) => [v[names.indexOf('run')], Number(v[names.indexOf('unseen_mean')])]));
}

test('numbers that agree: a module stopped at 20,100 evaluations and the same run at 30,100, each beside the other', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  const manifest = JSON.parse(readFileSync(path.join(ROOT, 'pretrained/manifest.json'), 'utf8'));
  const module = manifest.modules.find((/** @type {any} */ m) => m.file === 'biped-6x4-attention.json');
  const unseen = studyUnseen();
  const stop20 = unseen.get('biped-6x4-attention-20000-s1');
  const stop30 = unseen.get('biped-6x4-attention-30000-s1');
  assert.equal(module.validation.unseen.mean, stop20, 'the module is the 20,000-evaluation run of seed 1');
  await byTestId(page, 'pretrained').selectOption('pretrained/biped-6x4-attention.json');
  const chosen = byTestId(page, 'pretrained').locator('option:checked');
  assert.equal(await chosen.textContent(), `attention on biped-6x4 · ${Number(stop20).toFixed(2)} m/s average over 10 new terrains`, 'the list shows what it is, its speed and which speed that is: the mean over the unseen terrains');
  assert.equal(await chosen.evaluate((o) => /** @type {HTMLOptGroupElement} */ (o.parentElement).label), 'from scratch, 20,000 evaluations');
  const label = String(await chosen.getAttribute('title'));
  assert.match(label, new RegExp(`evolved with a budget of 20,000 evaluations, on average ${Number(stop20).toFixed(2)} m/s`));
  // Beside it: the same run's best at 30,100, the number the study panel lists, and why it is slower.
  const details = page.locator('#module-details');
  await waitForText(page, 'module-details', /evolved on biped-6x4[^]*The study ran this seed once/); // this module's, not the first one's
  const said = String(await details.textContent());
  assert.ok(said.includes(`${Number(stop20).toFixed(2)} m/s (this one) and ${Number(stop30).toFixed(2)} m/s`), said);
  assert.match(said, /a longer run can end on a robot that walks worse on terrains it never saw/);
  await page.locator('#study-figure').selectOption('finetune-biped-large');
  const option = page.locator('#study-run option[value="biped-6x4-attention-30000-s1"]');
  assert.match(String(await option.textContent()), new RegExp(`seed 1: on average ${Number(stop30).toFixed(2)} m/s`));
  await page.locator('#study-run').selectOption('biped-6x4-attention-30000-s1');
  assert.ok(String(await byTestId(page, 'study-run-note').textContent()).includes(`${Number(stop20).toFixed(2)} m/s and ${Number(stop30).toFixed(2)} m/s (this one)`));
  // Every run from scratch in that list faster than the module on the unseen terrains would need no reason; none is.
  const listed = (await page.locator('#study-run option').allTextContents()).filter((t) => /from scratch, 30,000/.test(t));
  assert.ok(listed.every((t) => Number(/on average (\d+\.\d\d)/.exec(t)?.[1]) < Number(stop20)), 'the module is faster than every 30,000 run: the reason is needed');
  assert.deepEqual(problems, []);
  await context.close();
});

test('numbers that agree: the same best biped\'s speeds, each beside what it measures', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  await byTestId(page, 'pretrained').selectOption(ATTENTION);
  await page.locator('#module-open').click();
  await waitForText(page, 'status', /^10 voxels, attention$/);
  const module = JSON.parse(readFileSync(path.join(ROOT, 'pretrained/manifest.json'), 'utf8')).modules
    .find((/** @type {any} */ m) => `pretrained/${m.file}` === ATTENTION);
  const note = await speedNote(page);
  const here = await figure(page, 'speed-note');
  const driver = String(await page.locator('#driver').textContent());
  await waitForText(page, 'module-details', /The study ran this seed once/);
  const [details, lineage] = String(await page.locator('#module-details').textContent()).split(/(?=The study ran this seed once)/);
  // Its other stop in the study is another robot (the same run's earlier best), said as such; this one's number is the driver's.
  assert.ok(lineage.includes(`${module.validation.unseen.mean.toFixed(2)} m/s (this one)`), lineage);
  // Each speed on screen, and the words that say what it measures right after it.
  const said = [...`${driver} ${note} ${details}`.matchAll(/([−-]?\d+\.\d\d) m\/s([^.;]*)/g)].map((m) => ({ speed: m[1].replace('−', '-'), what: m[2] }));
  const expected = [
    [module.validation.unseen.mean, /^ on ten terrains it never trained on/],
    [here, /^ over a 30-s episode on hilly-1-10-0/],
    [module.training_best, /^ \(its latest evaluation, on a hilly-1-10 terrain drawn fresh/],
  ];
  for (const [speed, what] of expected) {
    const found = said.find((s) => s.speed === Number(speed).toFixed(2));
    assert.ok(found, `${Number(speed).toFixed(2)} m/s is on screen: ${JSON.stringify(said)}`);
    assert.match(found.what, what, `${found.speed} m/s says what it measures`);
  }
  for (const s of said) assert.ok(expected.some(([speed]) => Number(speed).toFixed(2) === s.speed), `${s.speed} m/s is one of the three: ${JSON.stringify(said)}`);
  assert.match(note, /Training draws a fresh terrain for every evaluation.*so the two differ/, 'why training\'s and the viewer\'s differ');
  assert.deepEqual(problems, []);
  await context.close();
});

test('numbers that agree: a drawing in pieces, the robot still walking, the clock past its episode', async () => {
  const { page, problems, context } = await openOwnBody(env);
  await page.locator('#speed').selectOption('0');
  await episodeSpeed(page);
  const seconds = JSON.parse(await readFile(path.join(ROOT, ATTENTION), 'utf8')).config.seconds;
  await waitForFigure(page, 'sim-time', `v > ${seconds + 1}`);
  const time = String(await page.locator('#sim-time').textContent());
  assert.match(time, new RegExp(`^\\d+\\.\\d\\d s \\(its ${seconds}-s episode is over; it walks on\\)$`), 'the clock past the episode says so');
  assert.match(String(await byTestId(page, 'viewer-speed').textContent()), new RegExp(`over its ${seconds}-s episode`));

  await page.locator('#rows').fill('1101-1101-1001'); // the biped cut in two: 8 voxels
  await page.locator('#rows').press('Enter');
  await waitForText(page, 'shape-status', /2 separate pieces/);
  await waitForText(page, 'driver', /is not a robot yet/);
  const driver = String(await page.locator('#driver').textContent());
  const genes = String(await page.locator('#param-count').textContent());
  const walking = Number(/^(\d+) voxels/.exec(String(await page.locator('#status').textContent()))?.[1]);
  const drivenGenes = Number(/\(attention, (\d+) genes\)/.exec(driver)?.[1]);
  assert.equal(walking, 10, 'the robot walking is the last whole body');
  assert.match(driver, new RegExp(`Your drawing \\(8 voxels\\) is not a robot yet, so the robot walking is your last whole drawing: ${walking} voxels, ${drivenGenes} genes\\.$`));
  assert.equal(Number(/^(\d+) genes/.exec(genes)?.[1]), await figure(page, 'param-count'));
  assert.match(genes, new RegExp(`^\\d+ genes \\(for your drawing of 8 voxels, once it is one piece; the robot walking is your last whole drawing: ${walking} voxels, ${drivenGenes} genes\\)`));
  await page.locator('#clear').click(); // empty: the same words for the robot that walks on
  await waitForText(page, 'shape-status', /no voxels/);
  await waitForText(page, 'driver', /Your drawing is empty, so the robot walking is your last whole drawing: 10 voxels/);
  assert.deepEqual(problems, []);
  await context.close();
});

test('numbers that agree: the freeze verdict keeps one wording while the frozen robot rocks', async () => {
  const { page, problems, context } = await openOwnBody(env);
  await waitForFigure(page, 'sim-time', 'v >= 5', 60_000);
  await byTestId(page, 'freeze-attention').click();
  const verdicts = new Set();
  const until = Date.now() + 12_000;
  while (Date.now() < until) {
    const text = String(await byTestId(page, 'freeze-report').textContent());
    const verdict = text.slice(text.lastIndexOf(' s. ') + 4); // after the speeds, the words
    if (!/Watch a few seconds more/.test(verdict) && /^Frozen/.test(verdict)) verdicts.add(verdict);
    await page.waitForTimeout(100);
  }
  assert.equal(verdicts.size, 1, `one verdict while frozen: ${[...verdicts].join(' | ')}`);
  assert.match([...verdicts][0], /^Frozen, it nearly stops/);
  assert.deepEqual(problems, []);
  await context.close();
});

test('numbers that agree: during a fine-tune the walking best shows its own training figure, and why the viewer\'s differs', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url);
  await attentionOnWorm(page); // the biped's attention on a 5-voxel worm
  for (const [key, value] of Object.entries({ population: '6', seconds: '2', budget: '600', seed: '2', terrain: 'hilly-1-10', workers: '2' })) {
    await page.locator(`#run-${key}`).fill(value);
  }
  await byTestId(page, 'finetune').click();
  await waitForText(page, 'driver', /the run's best when it began walking \(fine-tuning\)/, 60_000);
  // The note measures the walking best (asynchronously) and a newer best can take over: paused,
  // the best stays (a loaded machine can otherwise end the run first), and both are read once they agree.
  await byTestId(page, 'pause').click();
  await waitForText(page, 'run-pause', /^Resume$/);
  const agreed = await page.waitForFunction(() => {
    const driver = document.getElementById('driver')?.textContent ?? '';
    const note = document.querySelector('[data-testid="speed-note"]')?.textContent ?? '';
    const best = /\(fine-tuning\): ([−-]?\d+\.\d\d) m\/s in one evaluation/.exec(driver)?.[1];
    return best && note.startsWith(`In training: ${best} m/s`) ? [driver, note] : false;
  }, undefined, { timeout: 60_000 });
  const [driver, note] = /** @type {string[]} */ (await agreed.jsonValue());
  const best = /\(fine-tuning\): ([−-]?\d+\.\d\d) m\/s in one evaluation/.exec(driver)?.[1];
  assert.ok(best, driver);
  assert.match(note, new RegExp(`^In training: ${best} m/s \\(its best single evaluation, on a hilly-1-10 terrain drawn fresh for that evaluation, 2-s episodes\\)\\. `
    + 'The viewer measures its speed as it walks, over a 2-s episode on hilly-1-10-0 \\(under the robot, once the episode is over\\)\\. Training draws a fresh terrain'), note);
  await byTestId(page, 'pause').click();
  await page.waitForFunction(() => document.body.dataset.run === 'finished', undefined, { timeout: 120_000 });
  assert.match(String(await page.locator('#run-rate').textContent()), /evaluations\/s · took \d+ s$/, 'how long it took, on screen');
  assert.deepEqual(problems, []);
  await context.close();
});

test('numbers that agree: at 375 px every figure fits the phone\'s width', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 375, height: 800, touch: true });
  await page.locator('#study-panel').scrollIntoViewIfNeeded();
  await page.waitForFunction(() => /** @type {HTMLImageElement} */ (document.getElementById('study-image')).complete);
  for (const id of ['validation-biped', 'finetune-biped-large', 'budget-comb']) {
    await page.locator('#study-figure').selectOption(id);
    await page.waitForFunction(() => { const img = /** @type {HTMLImageElement} */ (document.getElementById('study-image')); return img.complete && img.naturalWidth > 0; });
    const widths = await page.evaluate(() => ({
      page: document.documentElement.scrollWidth,
      images: [...document.querySelectorAll('img, canvas, svg')].filter((e) => e.getClientRects().length > 0)
        .map((e) => ({ what: e.id || e.tagName, right: e.getBoundingClientRect().right, box: e.parentElement?.getBoundingClientRect().right ?? 0 })),
    }));
    assert.ok(widths.page <= 375, `the page is ${widths.page} px wide at 375`);
    for (const image of widths.images) assert.ok(image.right <= 375.5, `${image.what} ends at ${image.right} px (figure ${id})`);
  }
  await page.locator('#study-panel').screenshot({ path: path.join(SCREENSHOTS, 'numbers-phone.png') });
  assert.deepEqual(problems, []);
  await context.close();
});
