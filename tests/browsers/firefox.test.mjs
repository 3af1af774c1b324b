// @ts-check
/** The page in Firefox (firefox-esr, puppeteer-core): checks.mjs. `make test-browsers`. */
import { test } from 'node:test';
import { checkBrowser } from './checks.mjs';
import { launchFirefox } from './firefox.mjs';

test('the page works in Firefox, with the same results as vsr', { timeout: 900_000 }, () => checkBrowser(launchFirefox));
