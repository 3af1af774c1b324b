// @ts-check
/**
 * What the tests of the page's numbers share (numbers.test.mjs, agree.test.mjs): the viewer's
 * speed over its episode, the speed note, the shared link, the pretrained biped on its own body.
 */
import { byTestId, clickCells, figure, openPage, waitForText } from './harness.mjs';

export const ATTENTION = 'pretrained/biped-4x3-attention.json';
export const TERRAIN = 'hilly-1-10-7';

/** Clears the drawing, draws a 5-voxel worm and transplants the biped's attention module onto it. @param {import('playwright-core').Page} page */
export async function attentionOnWorm(page) {
  await page.locator('#clear').click();
  await clickCells(page, [[0, 0], [1, 0], [2, 0], [3, 0], [4, 0]]);
  await byTestId(page, 'pretrained').selectOption(ATTENTION);
  await byTestId(page, 'load-pretrained').click();
  await waitForText(page, 'status', /^5 voxels, attention$/);
}

/** Waits until the viewer's episode ended and returns its speed. @param {import('playwright-core').Page} page */
export async function episodeSpeed(page) {
  await page.waitForFunction(() => document.getElementById('robot-speed')?.dataset.ended === 'true', undefined, { timeout: 120_000 });
  return figure(page, 'robot-speed');
}

/** The speed note once measured. @param {import('playwright-core').Page} page */
export async function speedNote(page) {
  await page.waitForFunction(() => Number.isFinite(Number(document.getElementById('speed-note')?.dataset.value)), undefined, { timeout: 60_000 });
  return String(await byTestId(page, 'speed-note').textContent());
}

/** The link the page shares now. @param {import('playwright-core').Page} page */
export async function shareLink(page) {
  await byTestId(page, 'share').click();
  await page.waitForFunction(() => (document.getElementById('share-link')?.dataset.value ?? '').includes('#'));
  return new URL(String(await page.locator('#share-link').getAttribute('data-value')));
}

/**
 * A new page walking the pretrained biped module on its own body, on TERRAIN.
 * @param {{browser: import('playwright-core').Browser, url: string}} env
 */
export async function openOwnBody(env) {
  const opened = await openPage(env.browser, env.url);
  await opened.page.locator('#terrain').fill(TERRAIN);
  await opened.page.locator('#terrain').press('Enter');
  await byTestId(opened.page, 'pretrained').selectOption(ATTENTION);
  await opened.page.locator('#module-open').click();
  await waitForText(opened.page, 'status', /^10 voxels, attention$/);
  return opened;
}
