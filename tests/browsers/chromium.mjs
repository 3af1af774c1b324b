// @ts-check
/**
 * Chromium (Debian chromium), headless, through puppeteer-core: the browser of the page tests
 * (tests/web/), here so that the cross-browser checks give its figures in the same sitting as
 * Firefox's and WebKit's (the quick evolution's time above all). CHROMIUM overrides
 * /usr/bin/chromium.
 */
import { CHROMIUM_ARGS } from '../web/harness.mjs';
import { launchPuppeteer } from './puppeteer.mjs';

/** @returns {Promise<import('./tab.mjs').Tab & {problems: string[]}>} */
export function launchChromium() {
  return launchPuppeteer({ browser: 'chrome', executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium', args: CHROMIUM_ARGS },
    (version) => version.replace(/^(Headless)?Chrome\//, 'Chromium '));
}
