// @ts-check
/**
 * WebKitGTK (Debian webkit2gtk-driver): WebKitWebDriver on a free port, driving its
 * MiniBrowser in automation mode. MiniBrowser has a window: run under an X display
 * (`xvfb-run -a`, as `make test-browsers` does). WEBKIT_DRIVER and MINIBROWSER override the
 * Debian paths.
 */
import { spawn } from 'node:child_process';
import { createServer } from 'node:net';
import { openSession } from './webdriver.mjs';

const DRIVER = process.env.WEBKIT_DRIVER ?? '/usr/bin/WebKitWebDriver';
const MINIBROWSER = process.env.MINIBROWSER ?? '/usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser';

/** @returns {Promise<import('./tab.mjs').Tab>} */
export async function launchWebKit() {
  if (!process.env.DISPLAY) throw new Error('WebKitGTK needs an X display: run under xvfb-run -a (make test-browsers)');
  const port = await freePort();
  const driver = spawn(DRIVER, [`--port=${port}`], { stdio: ['ignore', 'ignore', 'inherit'] });
  const exited = new Promise((resolve) => driver.once('exit', resolve));
  try {
    const base = `http://127.0.0.1:${port}`;
    await untilListening(base);
    const tab = await openSession(base, {
      browserName: 'MiniBrowser', 'webkitgtk:browserOptions': { binary: MINIBROWSER, args: ['--automation'] },
    });
    return { ...tab, name: `WebKitGTK ${tab.name}`, close: async () => { await tab.close().finally(() => driver.kill()); await exited; } };
  } catch (error) {
    driver.kill();
    throw error;
  }
}

/** A port nobody listens on now. @returns {Promise<number>} */
function freePort() {
  return new Promise((resolve, reject) => {
    const server = createServer().once('error', reject).listen(0, '127.0.0.1', () => {
      const { port } = /** @type {import('node:net').AddressInfo} */ (server.address());
      server.close(() => resolve(port));
    });
  });
}

/** Waits until the driver answers its status. @param {string} base */
async function untilListening(base) {
  for (let tries = 0; ; tries++) {
    try {
      if ((await fetch(`${base}/status`)).ok) return;
    } catch (error) {
      if (tries > 100) throw new Error(`${DRIVER} did not start: ${error}`);
    }
    await new Promise((resolve) => setTimeout(resolve, 100));
  }
}
