// @ts-check
/**
 * The README's picture of the page, docs/img/playground.png, taken with the browser tests'
 * harness (needs `make wasm`): a table drawn by hand, the pretrained biped attention module
 * transplanted onto it, a short fine-tune with its from-scratch comparison, then the robot
 * walking the fine-tuned result with its attention maps. Run: node scripts/screenshot.mjs
 */
import path from 'node:path';
import { ROOT, byTestId, clickCells, figure, openPage, start, waitForFigure, waitForText } from '../tests/web/harness.mjs';

const OUT = path.join(ROOT, 'docs', 'img', 'playground.png');
const TABLE = [[0, 2], [1, 2], [2, 2], [3, 2], [4, 2], [0, 1], [1, 1], [2, 1], [3, 1], [4, 1], [0, 0], [2, 0], [4, 0]];

const env = await start();
try {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1300, height: 1000 });
  await page.locator('#clear').click();
  await clickCells(page, /** @type {[number, number][]} */ (TABLE));
  await byTestId(page, 'pretrained').selectOption('pretrained/biped-4x3-attention.json');
  await byTestId(page, 'load-pretrained').click();
  await waitForText(page, 'status', /^13 voxels, attention$/);
  const settings = { population: '20', seconds: '10', budget: '300', seed: '1', terrain: 'hilly-1-10', workers: '2' };
  for (const [key, value] of Object.entries(settings)) await page.locator(`#run-${key}`).fill(value);
  await page.locator('#run-compare').check();
  await byTestId(page, 'finetune').click();
  await waitForText(page, 'run-status', /^from scratch: finished$/, 600_000);
  await waitForText(page, 'driver', /the fine-tuned run's result/);
  const t0 = await figure(page, 'sim-time');
  await waitForFigure(page, 'sim-time', `v >= ${t0 + 6}`, 60_000);
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: OUT, fullPage: true });
  if (problems.length > 0) throw new Error(`the page reported problems: ${problems.join('; ')}`);
  console.log(`wrote ${path.relative(ROOT, OUT)}`);
} finally {
  await env.close();
}
