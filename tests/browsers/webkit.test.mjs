// @ts-check
/** The page in WebKitGTK (MiniBrowser, WebKitWebDriver, under xvfb-run): checks.mjs. `make test-browsers`. */
import { test } from 'node:test';
import { checkBrowser } from './checks.mjs';
import { launchWebKit } from './webkit.mjs';

test('the page works in WebKitGTK, with the same results as vsr', { timeout: 900_000 }, () => checkBrowser(launchWebKit));
