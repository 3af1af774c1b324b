// @ts-check
/**
 * A browser driven by puppeteer-core (Firefox over WebDriver BiDi, Chromium over CDP) as a
 * {@link import('./tab.mjs').Tab}. Console errors and page errors fail the page (`problems`).
 */
import puppeteer from 'puppeteer-core';

/**
 * @param {import('puppeteer-core').LaunchOptions} options puppeteer's launch options (browser, executable, arguments)
 * @param {(version: string) => string} name the browser's name and version, from puppeteer's version string
 * @returns {Promise<import('./tab.mjs').Tab & {problems: string[]}>}
 */
export async function launchPuppeteer(options, name) {
  const browser = await puppeteer.launch({ headless: true, ...options });
  const page = await browser.newPage();
  await page.setViewport({ width: 1300, height: 1100 });
  /** @type {string[]} */
  const problems = [];
  page.on('console', (msg) => { if (msg.type() === 'error') problems.push(`console: ${msg.text()}`); });
  page.on('pageerror', (error) => problems.push(`page error: ${error instanceof Error ? error.message : String(error)}`));
  return {
    name: name(await browser.version()),
    problems,
    goto: async (url) => { await page.goto(url, { waitUntil: 'load' }); },
    run: (fn, arg) => page.evaluate(fn, arg),
    click: async (selector) => { await page.locator(selector).click(); },
    fill: async (selector, text) => {
      await page.locator(selector).fill(text);
      await page.keyboard.press('Enter');
    },
    select: async (selector, value) => { await page.select(selector, value); },
    close: () => browser.close(),
  };
}
