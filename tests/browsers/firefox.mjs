// @ts-check
/**
 * Firefox (Debian firefox-esr), headless, through puppeteer-core over WebDriver BiDi.
 * FIREFOX overrides /usr/bin/firefox-esr. Console errors and page errors fail the page
 * (`problems`).
 */
import puppeteer from 'puppeteer-core';

/** @returns {Promise<import('./tab.mjs').Tab & {problems: string[]}>} */
export async function launchFirefox() {
  const browser = await puppeteer.launch({ browser: 'firefox', executablePath: process.env.FIREFOX ?? '/usr/bin/firefox-esr', headless: true });
  const page = await browser.newPage();
  await page.setViewport({ width: 1300, height: 1100 });
  /** @type {string[]} */
  const problems = [];
  page.on('console', (msg) => { if (msg.type() === 'error') problems.push(`console: ${msg.text()}`); });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  return {
    name: `Firefox ${(await browser.version()).replace(/^firefox\//, '')}`,
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
