// @ts-check
/** The cross-browser checks in Chromium, for figures beside Firefox's and WebKit's: checks.mjs. `make test-browsers`. */
import { test } from 'node:test';
import { checkBrowser } from './checks.mjs';
import { launchChromium } from './chromium.mjs';

test('the page works in Chromium, with the same results as vsr (the figures beside the other browsers)', { timeout: 900_000 }, () => checkBrowser(launchChromium));
