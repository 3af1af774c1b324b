// @ts-check
/**
 * Firefox (Debian firefox-esr), headless, through puppeteer-core over WebDriver BiDi.
 * FIREFOX overrides /usr/bin/firefox-esr.
 */
import { launchPuppeteer } from './puppeteer.mjs';

/** @returns {Promise<import('./tab.mjs').Tab & {problems: string[]}>} */
export function launchFirefox() {
  return launchPuppeteer({ browser: 'firefox', executablePath: process.env.FIREFOX ?? '/usr/bin/firefox-esr' },
    (version) => `Firefox ${version.replace(/^firefox\//, '')}`);
}
