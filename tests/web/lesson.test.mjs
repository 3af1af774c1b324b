// @ts-check
/**
 * Browser test of the 50-minute lesson and the class challenge as a class uses them (node
 * --test): the teacher's "The 50-minute lesson" sheet gives the plan minute by minute (what to
 * project, what students do), the same as docs/teaching.md, with the QR code of the page's
 * address and a warning when that address opens only on this computer; a challenge link made
 * here says the same, and its QR code shows large for the projector; a student's page opened
 * from a challenge link has the run fixed and locked, and a laptop too slow for it (a challenge
 * of 20,000 evaluations of 30-s walks) says so and keeps the challenge's evaluations; after Evolve and Share link
 * the student gets a short code, and the teacher's page, given the code, evolves the same robot
 * again (the same robot as the student's full link), and names a mistyped code.
 * Screenshots: lesson-1400.png, lesson-420.png, challenge-qr-large.png, challenge-code-420.png.
 */
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { LESSON, lessonStepWords, lessonTimes } from '../../www/classroom/lesson-plan.js';
import { ROOT, SCREENSHOTS, byTestId, openPage, start, waitForText } from './harness.mjs';

/** @type {Awaited<ReturnType<typeof start>>} */ let env;

before(async () => { env = await start(); });
after(async () => { await env?.close(); });

test('the 50-minute lesson: minute by minute in the page and in docs/teaching.md, with the QR code of the class\'s address', async () => {
  assert.equal(LESSON.steps.reduce((sum, s) => sum + s.minutes, 0), 50, 'fifty minutes');
  const times = lessonTimes();
  const expected = LESSON.steps.map((s, i) => [times[i], lessonStepWords(s), s.projects, s.students]);
  const guide = [...readFileSync(path.join(ROOT, 'docs/teaching.md'), 'utf8').matchAll(/^\| (\d+–\d+) \| (.+?) \| (.+?) \| (.+?) \|$/gm)].map((m) => m.slice(1));
  assert.deepEqual(guide, expected, 'docs/teaching.md gives the page\'s lesson');
  for (const [width, height] of [[1400, 900], [420, 860]]) {
    const { page, problems, context } = await openPage(env.browser, `${env.url}?chapter=1`, { width, height, touch: width < 800 });
    await byTestId(page, 'tour-teacher').click();
    await byTestId(page, 'lesson-open').click();
    const sheet = byTestId(page, 'lesson');
    await sheet.waitFor();
    const rows = await byTestId(page, 'lesson-table').locator('tbody tr').evaluateAll((trs) => trs.map((tr) => [...tr.children].map((td) => String(td.textContent))));
    assert.deepEqual(rows, expected, `the page's table (${width} px)`);
    const qr = sheet.locator('[data-testid="qr"]');
    assert.equal(await qr.getAttribute('data-link'), env.url, 'a QR code of the page\'s address');
    await qr.locator('svg path').waitFor(); // drawn once uqr is here (fetched when the teacher's box opens, not at start)
    assert.ok(await qr.locator('svg path').count() === 1);
    assert.match(String(await byTestId(page, 'worksheet-address-note').textContent()), /opens only on this computer/, 'served at 127.0.0.1: said');
    assert.equal(await sheet.locator('.sheet-plan').count(), 0, 'one plan on the sheet: not the two lessons\' plan too');
    assert.ok(!String(await sheet.textContent()).includes('if you want one'), 'one plan on the sheet');
    const edges = await page.evaluate(() => [...document.querySelectorAll('[data-testid="lesson"] .sheet-address, [data-testid="lesson"] .sheet-address *')]
      .map((e) => { const b = e.getBoundingClientRect(); return [b.left, b.right]; }));
    assert.ok(edges.length > 0 && edges.every(([l, r]) => l >= 0 && r <= width), `the address, its field and note are not clipped at ${width} px: ${JSON.stringify(edges)}`);
    await qr.locator('[data-testid="qr-large"]').click();
    assert.match(String(await byTestId(page, 'qr-large-note').textContent()), /^This address opens only on this computer/, 'the large view says it too');
    await page.keyboard.press('Escape');
    await byTestId(page, 'worksheet-address').fill('https://school.example/robots/');
    await page.waitForFunction(() => document.querySelector('[data-testid="lesson"] [data-testid="qr"]')?.getAttribute('data-link') === 'https://school.example/robots/');
    assert.equal(String(await byTestId(page, 'worksheet-address-note').textContent()), '', 'the class\'s address: nothing to warn of');
    const sizes = await page.evaluate(() => ({ page: document.documentElement.scrollWidth, table: document.querySelector('.lesson-table')?.getBoundingClientRect().right ?? 0 }));
    assert.ok(sizes.page <= width && sizes.table <= width, `the sheet fits ${width} px: ${JSON.stringify(sizes)}`);
    await page.screenshot({ path: path.join(SCREENSHOTS, `lesson-${width}.png`) });
    assert.deepEqual(problems, []);
    await context.close();
  }
});

test('a challenge link: its QR code large for the projector, a warning on this computer\'s address, the run fixed and never lighter', async () => {
  const { page, problems, context } = await openPage(env.browser, env.url, { width: 1400, height: 900 });
  await byTestId(page, 'challenge').locator('summary').click();
  await page.locator('#challenge-make').click();
  await page.locator('#challenge-qr [data-testid="qr"]').waitFor();
  const link = await page.locator('#challenge-link').inputValue();
  assert.match(link, /\?challenge=1&terrain=hilly-1-10-0&seconds=10&budget=2000&seed=1&population=20&train=hilly-1-10$/);
  await waitForText(page, 'challenge-address-note', /^This link opens only on this computer .*your students cannot open it/);
  const qr = page.locator('#challenge-qr [data-testid="qr"]');
  assert.equal(await qr.getAttribute('data-link'), link);
  await qr.locator('[data-testid="qr-large"]').click();
  const large = byTestId(page, 'qr-large-view');
  assert.match(String(await byTestId(page, 'qr-large-note').textContent()), /opens only on this computer/, 'the large view warns as the small one');
  const box = await large.locator('svg').boundingBox();
  assert.ok(box && box.width >= 500, `large on a projector: ${box?.width} px`);
  await page.screenshot({ path: path.join(SCREENSHOTS, 'challenge-qr-large.png') });
  await page.keyboard.press('Escape');
  assert.equal(await large.count(), 0, 'Escape closes it');
  assert.deepEqual(problems, []);
  await context.close();

  // A challenge too heavy for this computer (20,000 evaluations of 30-s walks; Chromium's CPU throttling does not slow
  // the workers the page measures its speed in): the run is the challenge's, locked, and the page says it is slow for it.
  const heavy = link.replace('seconds=10', 'seconds=30').replace('budget=2000', 'budget=20000');
  const student = await openPage(env.browser, heavy, { width: 1400, height: 900 });
  const form = () => student.page.evaluate(() => ['run-population', 'run-seconds', 'run-budget', 'run-seed', 'run-terrain']
    .map((id) => { const input = /** @type {HTMLInputElement} */ (document.getElementById(id)); return `${input.value}${input.disabled ? ' locked' : ''}`; }));
  assert.deepEqual(await form(), ['20 locked', '30 locked', '20000 locked', '1 locked', 'hilly-1-10 locked']);
  assert.equal(await student.page.locator('#run-quick').isDisabled(), true, 'no lighter quick settings in a challenge');
  await student.page.waitForFunction(() => document.getElementById('run-estimate')?.dataset.slow === 'true', undefined, { timeout: 90_000 });
  assert.match(String(await student.page.locator('#run-estimate').textContent()),
    /This computer is slow for the challenge's run: it runs all 20,000 evaluations all the same/);
  assert.deepEqual(await form(), ['20 locked', '30 locked', '20000 locked', '1 locked', 'hilly-1-10 locked'], 'still the challenge\'s run');
  assert.deepEqual(student.problems, []);
  await student.context.close();
});

test('a short code: the student\'s page shows it after Share link; the teacher\'s page evolves the same robot again from it', async () => {
  // A short run (200 evaluations of 5-s walks), so that the test evolves it twice in seconds.
  const link = `${env.url}?challenge=1&terrain=hilly-1-10-0&seconds=5&budget=200&seed=3&population=10&train=hilly-1-10`;
  const student = await openPage(env.browser, link, { width: 420, height: 860, touch: true });
  await byTestId(student.page, 'share').click();
  await waitForText(student.page, 'challenge-code', /^No short code for this robot \(your robot has no brain yet: press Evolve first\): send your teacher the link\.$/);
  await byTestId(student.page, 'evolve').click();
  await student.page.waitForFunction(() => document.getElementById('run-workers')?.hasAttribute('disabled'));
  await student.page.waitForFunction(() => !document.getElementById('run-workers')?.hasAttribute('disabled'), undefined, { timeout: 120_000 });
  await byTestId(student.page, 'share').click();
  await waitForText(student.page, 'challenge-code', /^Your short code: [0-9A-Z]{4}-[0-9A-Z]{1,4}\. Give your teacher this code/);
  const code = String(await byTestId(student.page, 'challenge-code').getAttribute('data-code'));
  const full = await student.page.locator('#share-link').inputValue();
  await student.page.screenshot({ path: path.join(SCREENSHOTS, 'challenge-code-420.png') });
  assert.deepEqual(student.problems, []);
  await student.context.close();

  const teacher = await openPage(env.browser, link, { width: 1400, height: 900 });
  await byTestId(teacher.page, 'challenge').locator('summary').click();
  const typo = code.replace(/[0-9A-Z]$/, (c) => (c === 'A' ? 'B' : 'A'));
  await byTestId(teacher.page, 'challenge-compare').fill(`Ana ${code.toLowerCase()}\nBen ${full}\nCid ${typo}`);
  await teacher.page.locator('#challenge-rank').click();
  await teacher.page.locator('#challenge-panel[data-state="ranked"]').waitFor({ timeout: 180_000 });
  const rows = await byTestId(teacher.page, 'challenge-table').locator('tbody tr')
    .evaluateAll((trs) => trs.map((tr) => [...tr.children].map((td) => String(td.textContent))));
  const row = (/** @type {string} */ name) => rows.find((r) => r[1] === name) ?? [];
  assert.match(row('Ana')[5], /^handed in as a short code: evolved again here with the challenge's run; the same robot as Ben \(same body and brain\)/);
  assert.equal(row('Ana')[4], row('Ben')[4], 'the code\'s robot is the link\'s, to the bit: the same speed');
  assert.equal(row('Cid')[0], '–', 'a mistyped code has no place');
  assert.match(row('Cid')[5], /short code|check letters/);
  assert.deepEqual(teacher.problems, []);
  await teacher.context.close();
});
