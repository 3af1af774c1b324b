// @ts-check
/**
 * Browser test of the class challenge (node --test): before any challenge link the class is
 * ranked by the form's rules, and the table says so; a challenge link made with "everyone uses
 * the robot drawn now" keeps its body when the drawing changes afterwards (the class is ranked
 * by the link's rules, and the table says the form differs); the entries are measured again by
 * the page and ranked, a damaged, a foreign and a linkless line named, the same link pasted
 * again counted once, the same robot under two names placed but said and raced once, a budget
 * over the challenge's said and left out of the places; the table's header stays on one line at
 * 1400 px; a reload brings back the made link, its rules and the pasted links. A student opening
 * the link gets its rules, its run shown in the Run fieldset (locked, said why) and that run is
 * the one the page makes (its run file's settings); the teacher's form on that page shows the
 * link's rules, not the form's defaults; a drawing over the voxel limit is told at once.
 * Screenshots: screenshots/challenge-table-1400.png, classroom-challenge.png, challenge-evolve-off-1400.png,
 * challenge-run-fixed-1400.png.
 */
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { SCREENSHOTS, byTestId, openPage, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

/** The share link of what `page` shows now. @param {import('playwright-core').Page} page @param {RegExp} holds */
async function shareLink(page, holds) {
  await page.locator('#share-link').evaluate((el) => { /** @type {HTMLInputElement} */ (el).value = ''; });
  await page.locator('#share').click();
  await page.waitForFunction((source) => new RegExp(source).test(/** @type {HTMLInputElement} */ (document.getElementById('share-link')).value), holds.source);
  return page.locator('#share-link').inputValue();
}

/** Ranks the compare box's lines and reads the table. @param {import('playwright-core').Page} page */
async function rank(page) {
  await page.locator('#challenge-rank').click();
  await page.locator('#challenge-panel[data-state="ranked"]').waitFor({ timeout: 120_000 });
  const table = byTestId(page, 'challenge-table');
  const rows = await table.locator('tbody tr').evaluateAll((trs) => trs.map((tr) => [...tr.children].map((td) => String(td.textContent))));
  return { rows, caption: String(await table.locator('caption').textContent()) };
}

test('a class challenge: ranked by the link the teacher made, duplicates, the same robot and a budget over the limit said, kept after a reload', async () => {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1400, height: 1000 });
  /** @type {string[]} */
  const links = [];
  for (const file of ['pretrained/biped-4x3-attention.json', 'pretrained/biped-4x3-mlp.json']) {
    await byTestId(page, 'pretrained').selectOption(file);
    await page.locator('#module-open').click();
    await waitForText(page, 'driver', /on its own body/);
    links.push(await shareLink(page, /genome=/));
  }
  const fresh = await openPage(env.browser, env.url); // a new visitor: the first preset on the phase gait
  await waitForText(fresh.page, 'status', /phase gait/);
  links.push(await shareLink(fresh.page, /shape=/));
  await fresh.page.context().close();
  assert.match(links[0], /view=hilly-1-10-0.*budget=2000/, 'a share link holds its view and its run budget');
  assert.match(links[2], /gait=/, 'a share link holds its phase gait');
  const damaged = links[0].replace(/genome=[^&]{12}/, 'genome=!!!!');
  const otherTerrain = links[0].replace(/view=[^&]*/, 'view=flat'); // the same robot, only the terrain changed
  const overBudget = links[1].replace(/budget=\d+/, 'budget=5000');

  // No challenge link yet: the form's rules, and the table says so. Nothing pasted: said what to do.
  await byTestId(page, 'challenge').locator('.challenge-teacher > summary').click();
  await page.locator('#challenge-rank').click();
  await waitForText(page, 'challenge-status', /^Paste your students' links in the box first/);
  assert.equal(await page.locator('#challenge-link-box').isVisible(), false, 'no link field before a link');
  await byTestId(page, 'challenge-compare').fill('Eve not-a-link');
  let { caption } = await rank(page);
  assert.match(caption, /^No challenge link made yet, so ranked by the rules in the form above: any body; /);

  // Defect 1: the link's body is the one drawn when it was made, whatever is drawn when the class is ranked.
  const drawn = await page.locator('#rows').inputValue();
  assert.equal(drawn, '1111-1111-1001');
  // A terrain the core refuses: said in words, and no link made (a class would work on a broken challenge).
  await page.locator('#challenge-terrain').fill('hilly');
  await page.locator('#challenge-make').click();
  await waitForText(page, 'challenge-status', /^No challenge link made: “hilly” is not a terrain\. Try flat/);
  assert.equal(await page.locator('#challenge-link-box').isVisible(), false);
  await page.locator('#challenge-terrain').fill('hilly-1-10-0');
  await page.locator('#challenge-fixed').check();
  await page.locator('#challenge-make').click();
  await waitForText(page, 'challenge-status', /^Challenge link made/);
  const challengeUrl = await page.locator('#challenge-link').inputValue();
  assert.match(challengeUrl, /\?challenge=1&terrain=hilly-1-10-0&seconds=10&body=1111-1111-1001&budget=2000&seed=1&population=20&train=hilly-1-10$/);
  await page.locator('#rows').fill('11111-11111-10101');
  await page.locator('#rows').press('Enter');
  await waitForText(page, 'shape-status', /^13 voxels/);
  const pasted = [`Ana ${links[0]}`, `Ben: ${links[1]}`, links[2], `Cleo ${damaged}`, 'Dan https://example.com/#shape=1', 'Eve not-a-link',
    `Fay ${links[0]}`, `Gus ${otherTerrain}`, `Hal ${overBudget}`, `Ivy ${challengeUrl}`, `Jo ${links[2].replace(/gait=[^&]*/, 'gait=2%2C-1')}`].join('\n');
  await byTestId(page, 'challenge-compare').fill(pasted);
  let rows;
  ({ rows, caption } = await rank(page));
  console.log(`# challenge table: ${JSON.stringify(rows)}`);
  assert.match(caption, /^Ranked by the rules of the challenge link you made: the body 1111-1111-1001; speeds measured again by this page over 10 s on hilly-1-10-0; at most 2,000 evaluations\. The form above \(or the robot drawn now\) differs from your link/);
  assert.match(String(await page.locator('#challenge-rules').textContent()), /^What your students will see: Challenge: the body 1111-1111-1001,/, 'the rules line keeps the link\'s body');
  assert.deepEqual(rows.filter((r) => /not the challenge's body/.test(r[5])).map((r) => r[1]), ['Dan'], 'no entry rejected for the new drawing (Dan\'s is one voxel)');

  // The places: the fastest first, the same robot under two names placed and said; the rest after them.
  assert.equal(rows.length, 11, 'every line has a row');
  const placed = rows.filter((r) => r[0] !== '–');
  assert.deepEqual(placed.map((r) => r[0]), ['1', '2', '3', '4', '5']);
  assert.deepEqual(placed.map((r) => r[1]).sort(), ['Ana', 'Ben', 'Gus', 'Jo', 'line 3 (no name)']);
  assert.ok(rows.slice(5).every((r) => r[0] === '–'), 'the others have no place');
  const row = (/** @type {string} */ name) => rows.find((r) => r[1] === name) ?? [];
  assert.equal(row('Ana')[3], 'attention');
  assert.match(row('Ana')[5], /^the pretrained module biped-4x3-attention, unchanged: not evolved here; the same robot as Gus \(same body and brain\) under another name$/);
  assert.match(row('Gus')[5], /the same robot as Ana \(same body and brain\) under another name; raced once, as Ana$/);
  assert.equal(row('Gus')[4], row('Ana')[4], 'the same robot, the same speed');
  assert.equal(row('line 3 (no name)')[3], 'no brain (phase gait)');
  assert.equal(row('line 3 (no name)')[5], 'no brain: the clock of the phase gait drives it, nothing evolved');
  // Jo's own clock (f 2, φ −1), walked as Jo's page walked it: another robot than line 3's, another speed.
  assert.equal(row('Jo')[5], 'no brain: the clock of the phase gait drives it, nothing evolved');
  assert.notEqual(row('Jo')[4], row('line 3 (no name)')[4]);
  const speeds = placed.map((r) => Number.parseFloat(r[4].replace('−', '-')));
  assert.ok(speeds.every((s, i) => i === 0 || speeds[i - 1] >= s), `ranked by speed: ${speeds}`);
  assert.match(row('Cleo')[5], /^its brain did not come through whole \(.*\): the link seems cut short; ask Cleo to copy it again with “Share link”$/);
  assert.equal(row('Cleo')[3], '–', 'no brain shown for a brain that did not come through');
  assert.match(row('Dan')[5], /made at another address \(example\.com\/\), read all the same/);
  assert.match(row('Ivy')[5], /^this is the challenge link, not a robot: ask Ivy to press “Share link”/);
  assert.match(row('Eve')[5], /not a share link/, 'a line without a link keeps its name');
  assert.equal(row('Fay')[5], 'the same link as Ana: counted once, in Ana\'s row', 'a link pasted again is counted once');
  assert.match(row('Hal')[5], /^evolved with 5,000 evaluations \(as its link says\), more than the challenge's 2,000; .*the same robot as Ben \(same body and brain\) under another name$/);
  assert.match(row('Hal')[4], /m\/s$/, 'measured all the same, for the teacher to see');

  // Defect 4: the header on one line at 1400 px.
  await byTestId(page, 'challenge-table').screenshot({ path: path.join(SCREENSHOTS, 'challenge-table-1400.png') });
  const lines = await byTestId(page, 'challenge-table').locator('th').evaluateAll((ths) => ths.map((th) => {
    const range = document.createRange();
    range.selectNodeContents(th);
    return new Set([...range.getClientRects()].map((r) => Math.round(r.top))).size;
  }));
  assert.deepEqual(lines, [1, 1, 1, 1, 1, 1], 'every header word on one line');

  // Racing: the best four with a brain, each robot once (Gus is Ana's robot).
  await byTestId(page, 'challenge-race').click();
  await page.waitForFunction(() => document.querySelectorAll('[data-testid="race-robot"]').length === 2);
  assert.deepEqual(await page.locator('.race-name').allTextContents(), ['Ana', 'Ben']);
  await byTestId(page, 'challenge').screenshot({ path: path.join(SCREENSHOTS, 'classroom-challenge.png') });

  // Defect 2: a reload brings back the made link, its rules (the body as it was) and the pasted links.
  await page.reload();
  await waitForText(page, 'status', /voxels/);
  assert.equal(await page.locator('.challenge-teacher').getAttribute('open'), '', 'the teacher\'s part opens on what was kept');
  assert.equal(await page.locator('#challenge-link').inputValue(), challengeUrl);
  assert.equal(await page.locator('#challenge-link').isVisible(), true, 'the link box shown again at once');
  await page.waitForFunction(() => document.querySelectorAll('#challenge-qr svg path').length === 1); // its QR code drawn again
  assert.equal(await page.locator('#challenge-qr').isVisible(), true, 'the QR code shown again at once');
  assert.match(String(await page.locator('#challenge-rules').textContent()), /^What your students will see: Challenge: the body 1111-1111-1001,/);
  assert.equal(await page.locator('#challenge-fixed').isChecked(), true);
  assert.equal(await byTestId(page, 'challenge-compare').inputValue(), pasted);
  assert.match(String(await byTestId(page, 'challenge-status').textContent()), /^Back from your last visit: the challenge link you made, the class's 11 links and codes\. Press “Rank the class” to rank them again, or “Clear the class's entries”/);
  await byTestId(page, 'challenge-compare').fill(`Ana ${links[0]}`);
  ({ rows, caption } = await rank(page));
  assert.match(caption, /^Ranked by the rules of the challenge link you made: the body 1111-1111-1001;/, 'ranked by the kept rules');
  assert.deepEqual(rows.map((r) => r[0]), ['1']);
  // The teacher opens their own challenge link (on the projector's laptop): the link and its QR code are in sight at once.
  await page.goto(challengeUrl.replace(/^https?:\/\/[^/]+\//, env.url));
  await waitForText(page, 'status', /voxels/);
  assert.equal(await page.locator('.challenge-teacher').getAttribute('open'), '', 'the teacher\'s part open on their own link');
  await page.waitForFunction(() => document.querySelectorAll('#challenge-qr svg path').length === 1);
  assert.equal(await page.locator('#challenge-qr').isVisible(), true, 'its QR code in sight');
  assert.deepEqual(problems, []);
  await page.context().close();

  const student = await openPage(env.browser, `${challengeUrl.replace(/^https?:\/\/[^/]+\//, env.url)}`, { width: 1400, height: 900 });
  // The rules, short: the goal, three numbered steps, the run's details folded.
  await waitForText(student.page, 'challenge-rules', /^Challenge: the body 1111-1111-1001, as fast as it can over 10 s on hilly-1-10-0\./);
  assert.deepEqual(await student.page.locator('#challenge-rules ol > li').allTextContents(), ['Your body is drawn for you.',
    'Press Evolve: the run is set for you, the same on every computer.', 'Press “Share link” and give your teacher the short code it shows.']);
  assert.match(String(await student.page.locator('#challenge-rules details').textContent()), /The run: 2,000 evaluations, seed 1, 10-s walks\./);
  assert.equal(await student.page.locator('#challenge-rules details > p').isVisible(), false, 'the details folded');
  await waitForText(student.page, 'message', /^Challenge: .*over 10 s on hilly-1-10-0\. .*further down/); // at the top, where a student looks first
  assert.equal(await student.page.locator('#terrain').inputValue(), 'hilly-1-10-0');
  assert.equal(await student.page.locator('#run-budget').inputValue(), '2000');
  assert.equal(await student.page.locator('#run-seconds').inputValue(), '10', 'trained over the walks the teacher measures');
  assert.equal(await byTestId(student.page, 'challenge-status').isVisible(), false, 'a student\'s page keeps no teacher\'s challenge');
  assert.deepEqual(student.problems, []);
  await student.page.context().close();
});

test('a challenge of at most 12 voxels: its run shown (locked) is the run the page makes, the teacher\'s form shows the challenge; a drawing of 13 is told at once, and Evolve is off until it keeps the rules', async () => {
  // Every setting other than the page's own defaults (20, 10 s, 2,000, seed 1, hilly-1-10), so that a default shown is seen.
  const query = '?challenge=1&terrain=hilly-1-10-0&seconds=5&voxels=12&budget=200&seed=3&population=10&train=flat';
  const small = await openPage(env.browser, `${env.url}${query}`, { width: 1400, height: 900 });
  await waitForText(small.page, 'challenge-rules', /any body of at most 12 voxels, as fast as it can over 5 s on hilly-1-10-0\..*The run: 200 evaluations, seed 3, 5-s walks\./);
  /** The Run fieldset as a student sees it: each field's value, and whether it is locked. */
  const runForm = () => small.page.evaluate(() => Object.fromEntries(['population', 'seconds', 'budget', 'seed', 'terrain'].map((k) => {
    const input = /** @type {HTMLInputElement} */ (document.getElementById(`run-${k}`));
    return [k, `${input.value}${input.disabled ? ' locked' : ''}`];
  })));
  const challengeRun = { population: '10 locked', seconds: '5 locked', budget: '200 locked', seed: '3 locked', terrain: 'flat locked' };
  assert.deepEqual(await runForm(), challengeRun, 'the Run fieldset shows the challenge\'s run, locked');
  assert.match(String(await byTestId(small.page, 'run-fixed').textContent()), /^Set by the challenge \(greyed out\): the same on every computer/, 'and says why, in words (no hover on a touch screen)');
  // The teacher's part of this page: the form shows the challenge in force, not its defaults, and its link and QR code.
  await byTestId(small.page, 'challenge').locator('.challenge-teacher > summary').click();
  const teacherForm = await small.page.evaluate(() => ['terrain', 'seconds', 'voxels', 'budget', 'seed'].map((k) => /** @type {HTMLInputElement} */ (document.getElementById(`challenge-${k}`)).value));
  assert.deepEqual(teacherForm, ['hilly-1-10-0', '5', '12', '200', '3'], 'the challenge-making form holds the link\'s rules');
  assert.equal(await small.page.locator('#challenge-fixed').isChecked(), false);
  assert.equal(await small.page.locator('#challenge-link').inputValue(), `${env.url}?challenge=1&terrain=hilly-1-10-0&seconds=5&voxels=12&budget=200&seed=3&population=10&train=flat`,
    'the link in force, for the projector (its population and training terrain kept, though the form has no field for them)');
  await small.page.locator('#challenge-qr [data-testid="qr"]').waitFor();
  await byTestId(small.page, 'challenge').locator('.challenge-teacher > summary').click();
  await small.page.locator('#rows').fill('11111-11111-11100');
  await small.page.locator('#rows').press('Enter');
  const grid = await small.page.locator('#editor').boundingBox();
  await waitForText(small.page, 'rule-warning', /breaks the challenge's rules: 13 voxels, more than the challenge's 12\. Your teacher's ranking will not count it/, 5_000);
  assert.deepEqual(await small.page.locator('#editor').boundingBox(), grid, 'the warning does not move the grid under the student\'s finger');
  assert.equal(await small.page.locator('#editor.breaks-rules').count(), 1, 'the grid itself is outlined (the line under it may be off a phone\'s screen)');
  // Evolve is off while it does, said beside it (and the line stays: it is not a message that goes).
  assert.equal(await byTestId(small.page, 'evolve').isDisabled(), true, 'Evolve is off');
  await waitForText(small.page, 'run-blocked', /^Evolve is off: your robot breaks the challenge's rules \(13 voxels, more than the challenge's 12\)\. Change the drawing/, 5_000);
  assert.match(String(await byTestId(small.page, 'evolve').getAttribute('title')), /^Evolve is off: your robot breaks the challenge's rules/);
  await byTestId(small.page, 'evolve').scrollIntoViewIfNeeded();
  await small.page.screenshot({ path: path.join(SCREENSHOTS, 'challenge-evolve-off-1400.png') });
  assert.equal(await byTestId(small.page, 'run-blocked').isVisible(), true, 'still said');
  await small.page.locator('#rows').fill('11111-11111-11000');
  await small.page.locator('#rows').press('Enter');
  await byTestId(small.page, 'rule-warning').waitFor({ state: 'hidden', timeout: 5_000 }); // 12 voxels: within the rules again
  assert.equal(await small.page.locator('#editor.breaks-rules').count(), 0);
  await small.page.waitForFunction(() => !(/** @type {HTMLButtonElement} */ (document.getElementById('run-evolve'))).disabled, undefined, { timeout: 5_000 });
  assert.equal(await byTestId(small.page, 'run-blocked').isVisible(), false, 'within the rules: Evolve on, nothing said');

  // The run the page makes is the one shown: its run file's settings are the challenge's.
  await byTestId(small.page, 'evolve').click();
  await waitForText(small.page, 'run-evaluations', /^210 \/ 210$/, 300_000); // 200 evaluations, the last generation finished
  await small.page.waitForFunction(() => !(/** @type {HTMLInputElement} */ (document.getElementById('run-workers'))).disabled, undefined, { timeout: 60_000 });
  const [download] = await Promise.all([small.page.waitForEvent('download'), byTestId(small.page, 'export').click()]);
  const config = JSON.parse(await readFile(String(await download.path()), 'utf8')).config;
  assert.deepEqual({ population: `${config.ga.population} locked`, seconds: `${config.seconds} locked`, budget: `${config.ga.budget_evals} locked`,
    seed: `${config.seed} locked`, terrain: `${config.terrain} locked` }, challengeRun, `the run made is the challenge's: ${JSON.stringify(config)}`);
  assert.equal(config.shape, '11111-11111-11000');
  assert.deepEqual(await runForm(), challengeRun, 'and the form still shows it');
  await small.page.locator('#run-settings').scrollIntoViewIfNeeded();
  await small.page.screenshot({ path: path.join(SCREENSHOTS, 'challenge-run-fixed-1400.png') });
  assert.deepEqual(small.problems, []);
  await small.page.context().close();
});
