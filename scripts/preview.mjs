// @ts-check
/**
 * The page's link-preview image, www/preview.png (index.html's og:image: the picture a chat or a
 * school's learning platform shows beside a link to the site), 1200 x 630 as link previews
 * want: the study's best biped walking on hills with each voxel's attention map beside it,
 * taken with the browser tests' harness (needs `make wasm`). Run: node scripts/preview.mjs
 */
import path from 'node:path';
import { ROOT, byTestId, figure, openPage, start, waitForFigure, waitForText } from '../tests/web/harness.mjs';

const OUT = path.join(ROOT, 'www', 'preview.png');

const env = await start();
try {
  const { page, problems } = await openPage(env.browser, env.url, { width: 1200, height: 900 });
  await byTestId(page, 'pretrained').selectOption('pretrained/biped-4x3-attention.json');
  await page.locator('#module-open').click();
  await waitForText(page, 'status', /^10 voxels, attention$/);
  const t0 = await figure(page, 'sim-time');
  await waitForFigure(page, 'sim-time', `v >= ${t0 + 6}`, 60_000);
  const stage = await page.locator('#watch-panel .stage').boundingBox();
  if (!stage) throw new Error('no stage on the page');
  // The header's title and the stage under it, 1200 x 630.
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: OUT, clip: { x: 0, y: Math.max(0, stage.y + stage.height - 630), width: 1200, height: 630 } });
  if (problems.length > 0) throw new Error(`the page reported problems: ${problems.join('; ')}`);
  console.log(`wrote ${path.relative(ROOT, OUT)}`);
} finally {
  await env.close();
}
