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
import { EXAMPLE_CODE, codeLength, readCode, robotCode } from '../../www/classroom/challenge/code.js';
import { decimal } from '../../www/shared/format.js';
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
    // At 1400 px through the tour's teacher line, at 420 px through “For teachers” in the header.
    if (width > 800) {
      await byTestId(page, 'tour-teacher').click();
      await byTestId(page, 'lesson-open').click();
    } else {
      await byTestId(page, 'teacher-open').click();
    }
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
    assert.ok(!/if you want one|First lesson \(45 min\)/.test(String(await sheet.textContent())), 'one plan on the sheet');
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
  await byTestId(page, 'challenge').locator('.challenge-teacher > summary').click();
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

test('every example of a short code in the page and the docs is a real code of the real format; a wrong length says the form', () => {
  assert.ok(!('error' in readCode(EXAMPLE_CODE)), `the page's example reads back: ${JSON.stringify(readCode(EXAMPLE_CODE))}`);
  assert.equal(EXAMPLE_CODE.replace(/-/g, '').length, codeLength(4, 3), 'the example is a 4 × 3 body\'s');
  /** @type {string[]} */
  const found = [];
  for (const file of ['docs/teaching.md', 'docs/playground.md', 'README.md', 'www/index.html', 'www/classroom/challenge/rules.js', 'www/classroom/lesson-plan.js']) {
    const text = readFileSync(path.join(ROOT, file), 'utf8');
    // A code-like word: groups of four of the code's letters; not a body's rows (only 0 and 1) nor a date.
    for (const [word] of text.matchAll(/(?<![\w-])[0-9A-Z]{4}(?:-[0-9A-Z]{1,4})+(?![\w-])/g)) {
      if (/^[01-]+$/.test(word) || /^\d{4}-\d\d-\d\d$/.test(word) || /^[X-]+$/.test(word)) continue; // a body, a date, a code's form
      found.push(`${file}: ${word}`);
      assert.ok(!('error' in readCode(word)), `${file}'s example ${word} reads: ${JSON.stringify(readCode(word))}`);
    }
  }
  console.log(`# short codes shown: ${found.join(', ')}`);
  assert.ok(found.some((f) => f.startsWith('docs/teaching.md')), 'the teachers\' guide shows one');
  const short = readCode('ABCD-1234');
  assert.ok('error' in short && /^too short: 8 letters, .* has \d+: X{4}-X{4}-.*like /.test(short.error), `a wrong length says the form: ${JSON.stringify(short)}`);
  const old = readCode('0SFZ-57R');
  assert.ok('error' in old && old.error.includes(`XXXX-XXXX-XX, like ${EXAMPLE_CODE}`), JSON.stringify(old));
});

test('a short code: the student\'s page shows it after Share link; the teacher\'s page ranks it at once by its claim, checks the best, and keeps the checks', async () => {
  // A short run (200 evaluations of 5-s walks), so that the test evolves it twice in seconds.
  const link = `${env.url}?challenge=1&terrain=hilly-1-10-0&seconds=5&budget=200&seed=3&population=10&train=hilly-1-10`;
  const student = await openPage(env.browser, link, { width: 420, height: 860, touch: true });
  await byTestId(student.page, 'share').click();
  await waitForText(student.page, 'challenge-code', /^No short code for this robot \(your robot has no brain yet: press Evolve first\): send your teacher the link\.$/);
  await byTestId(student.page, 'evolve').click();
  await student.page.waitForFunction(() => document.getElementById('run-workers')?.hasAttribute('disabled'));
  await student.page.waitForFunction(() => !document.getElementById('run-workers')?.hasAttribute('disabled'), undefined, { timeout: 120_000 });
  await byTestId(student.page, 'share').click();
  await waitForText(student.page, 'challenge-code', /^Your short code: [0-9A-Z]{4}-[0-9A-Z]{4}-[0-9A-Z]{2} \(your robot's speed over 5 s on hilly-1-10-0: −?\d+\.\d\d m\/s, in the code\)\. Give your teacher this code/);
  const code = String(await byTestId(student.page, 'challenge-code').getAttribute('data-code'));
  console.log(`# the student's short code: ${code} (${String(await byTestId(student.page, 'challenge-code').textContent())})`);
  const read = readCode(code);
  assert.ok(!('error' in read) && read.rows === '1111-1111-1001' && read.controller === 'attention', JSON.stringify(read));
  assert.equal(code.length, EXAMPLE_CODE.length, 'the form of the page\'s example');
  const full = await student.page.locator('#share-link').inputValue();
  await student.page.screenshot({ path: path.join(SCREENSHOTS, 'challenge-code-420.png') });
  assert.deepEqual(student.problems, []);
  await student.context.close();

  const teacher = await openPage(env.browser, link, { width: 1400, height: 900 });
  await byTestId(teacher.page, 'challenge').locator('.challenge-teacher > summary').click();
  const typo = `${code.slice(0, 6)}${code[6] === 'A' ? 'B' : 'A'}${code.slice(7)}`; // a letter of the body's cells typed wrong
  // Dan's code claims 9.99 m/s for a robot no run of the challenge makes: placed first as claimed, then found out.
  const forged = robotCode('1111-1111-1111', 'attention', new Float32Array([1, 2, 3]), 9.99);
  await byTestId(teacher.page, 'challenge-compare').fill(`Ana ${code.toLowerCase()}\nBen ${full}\nCid ${typo}\nDan ${forged}\nEd ABCD-1234`);
  await teacher.page.waitForFunction(() => !document.getElementById('challenge-estimate')?.hidden);
  console.log(`# estimate: ${String(await byTestId(teacher.page, 'challenge-estimate').textContent())}`);
  await waitForText(teacher.page, 'challenge-estimate', /^5 lines: 4 short codes, 1 link or other line\. “Rank the class” takes seconds to measure the links and place the codes by the speeds their pages claim, then checks the best 2 codes by evolving their robots again here: (about \d|time not known)/);
  await byTestId(teacher.page, 'challenge-rank').click();
  await waitForText(teacher.page, 'challenge-status', /^Checking (Dan|Ana)'s short code: evolving the robot again here with the challenge's run \(1 of 2/, 60_000);
  await teacher.page.locator('#challenge-panel[data-state="ranked"]').waitFor({ timeout: 180_000 });
  const rows = await byTestId(teacher.page, 'challenge-table').locator('tbody tr')
    .evaluateAll((trs) => trs.map((tr) => [...tr.children].map((td) => String(td.textContent))));
  console.log(`# teacher's table: ${JSON.stringify(rows)}`);
  const row = (/** @type {string} */ name) => rows.find((r) => r[1] === name) ?? [];
  assert.match(row('Ana')[5], /^short code: checked \(evolved again here with the challenge's run, the same robot to the bit, measured here\); the same robot as Ben \(same body and brain\)/);
  assert.ok(!row('Ana')[5].includes('claimed'), 'the speed the code claimed is the one measured here');
  assert.equal(row('Ana')[4], row('Ben')[4], 'the code\'s robot is the link\'s, to the bit: the same speed');
  assert.equal(row('Ana')[4], `${decimal(read.speed)} m/s`, 'and the speed the student\'s page put in the code');
  assert.equal(row('Cid')[0], '–', 'a mistyped code has no place');
  assert.match(row('Cid')[5], /^not a short code \(a letter is typed wrong/);
  assert.equal(row('Dan')[0], '–', 'a forged claim, checked: no place');
  assert.match(row('Dan')[5], /its check letters do not match/);
  assert.match(row('Ed')[5], /^not a short code \(too short: 8 letters, .* has 22: XXXX-XXXX-XXXX-XXXX-XXXX-XX .*a 4 × 3 body's code has 10: XXXX-XXXX-XX, like 0SFZ-60MS-0V\)/);
  assert.match(String(await byTestId(teacher.page, 'challenge-status').textContent()), /^2 short codes checked\.$/);
  assert.match(String(await byTestId(teacher.page, 'challenge-table').locator('caption').textContent()), /Speeds: 2 measured by this page\.$/);

  // Kept after a reload: the lines and Ana's check (not evolved again: ranked at once, checked).
  await teacher.page.reload();
  await waitForText(teacher.page, 'status', /voxels/);
  assert.match(await byTestId(teacher.page, 'challenge-compare').inputValue(), /^Ana /);
  await byTestId(teacher.page, 'challenge').locator('.challenge-teacher > summary').click();
  await waitForText(teacher.page, 'challenge-estimate', /^5 lines: 4 short codes \(1 checked before\), 1 link or other line\./);
  await byTestId(teacher.page, 'challenge-rank').click();
  await teacher.page.locator('#challenge-panel[data-state="ranked"]').waitFor({ timeout: 60_000 });
  const again = await byTestId(teacher.page, 'challenge-table').locator('tbody tr')
    .evaluateAll((trs) => trs.map((tr) => [...tr.children].map((td) => String(td.textContent))));
  assert.deepEqual(again.find((r) => r[1] === 'Ana')?.slice(1, 5), row('Ana').slice(1, 5), 'Ana\'s row as before (her place ties with Ben\'s)');
  assert.match(again.find((r) => r[1] === 'Ana')?.[5] ?? '', /^short code: checked /);

  // Cleared, with the teacher's yes: the box, the table and the checks, also for the next visit.
  teacher.page.once('dialog', (dialog) => void dialog.accept());
  await byTestId(teacher.page, 'challenge-clear').click();
  await waitForText(teacher.page, 'challenge-status', /^Cleared: the class's 5 lines and the codes checked are forgotten/);
  assert.equal(await byTestId(teacher.page, 'challenge-compare').inputValue(), '');
  assert.equal(await byTestId(teacher.page, 'challenge-table').isVisible(), false);
  await teacher.page.reload();
  await waitForText(teacher.page, 'status', /voxels/);
  assert.equal(await byTestId(teacher.page, 'challenge-compare').inputValue(), '');
  assert.deepEqual(teacher.problems, []);
  await teacher.context.close();
});

test('ranking a class of codes on a slow challenge: claims at once, the time said before, progress, and Stop keeps the rest claimed', async () => {
  // A challenge of 20,000 evaluations of 30-s walks: a check would take minutes, so Stop is pressed while it runs.
  const link = `${env.url}?challenge=1&terrain=hilly-1-10-0&seconds=30&budget=20000&seed=1&population=20&train=hilly-1-10`;
  const teacher = await openPage(env.browser, link, { width: 1400, height: 1000 });
  await byTestId(teacher.page, 'challenge').locator('.challenge-teacher > summary').click();
  const bodies = ['1111-1111-1001', '1111-1111-1111', '11111-11111-10001', '111-111-101', '1111-1001', '11111-10001'];
  const claims = [3.1, 2.5, 4.2, 1.9, 0.7, 2.2];
  const lines = bodies.map((rows, i) => `Student ${i + 1} ${robotCode(rows, i % 2 ? 'mlp' : 'attention', new Float32Array([i]), claims[i])}`);
  const box = byTestId(teacher.page, 'challenge-compare');
  await box.fill(lines.join('\n'));
  // The time before anything starts (the computer's pace measured a few seconds after the page opened).
  await waitForText(teacher.page, 'challenge-estimate', /checks the best 4 codes by evolving their robots again here: about \d+ (s|min).* Checking every code \(“Check every code”\): about \d/, 30_000);
  console.log(`# estimate: ${String(await byTestId(teacher.page, 'challenge-estimate').textContent())}`);
  await byTestId(teacher.page, 'challenge-rank').click();
  await waitForText(teacher.page, 'challenge-status', /^Checking Student 3's short code: evolving the robot again here with the challenge's run \(1 of 4, about \d+ (s|min)[^)]* left\)… “Stop checking” keeps the rest as claimed\.$/, 60_000);
  // Ranked already, by the claims, each said as claimed.
  const table = byTestId(teacher.page, 'challenge-table');
  const claimed = await table.locator('tbody tr').evaluateAll((trs) => trs.map((tr) => [...tr.children].map((td) => String(td.textContent))));
  assert.deepEqual(claimed.map((r) => [r[0], r[1], r[4]]), [['1', 'Student 3', '4.20 m/s claimed'], ['2', 'Student 1', '3.10 m/s claimed'],
    ['3', 'Student 2', '2.50 m/s claimed'], ['4', 'Student 6', '2.20 m/s claimed'], ['5', 'Student 4', '1.90 m/s claimed'], ['6', 'Student 5', '0.70 m/s claimed']]);
  assert.match(String(await table.locator('caption').textContent()), /Speeds: 0 measured by this page, 6 claimed by the student's page/);
  await teacher.page.screenshot({ path: path.join(SCREENSHOTS, 'challenge-checking-1400.png'), fullPage: false });
  await byTestId(teacher.page, 'challenge-stop').click();
  await teacher.page.locator('#challenge-panel[data-state="ranked"]').waitFor({ timeout: 20_000 });
  assert.match(String(await byTestId(teacher.page, 'challenge-status').textContent()), /^Stopped after 0 checks\. 6 speeds are claimed, not checked: “Check every code” checks them \(about \d/);
  assert.equal(await byTestId(teacher.page, 'challenge-check').isEnabled(), true, 'the rest can be checked later');
  assert.equal(await byTestId(teacher.page, 'challenge-stop').isVisible(), false);
  assert.equal(await table.locator('tr[data-claimed="true"]').count(), 6);
  await byTestId(teacher.page, 'challenge').screenshot({ path: path.join(SCREENSHOTS, 'challenge-claimed-1400.png') });
  assert.deepEqual(teacher.problems, []);
  await teacher.context.close();
});
