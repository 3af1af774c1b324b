// @ts-check
/**
 * Offline use of a built site (`make site`): registers its service worker (sw.js at the site's
 * root: service-worker.js says what it keeps) and says, in a line under the page's title, what
 * a visitor needs to know: the page is now kept on this device, a new version is ready (with a
 * button that switches to it and reloads), or the page works from the kept copy because the
 * network is gone. On the developer's server (`make run`) there is no site version in the page
 * (the meta tag scripts/site.mjs writes) and nothing is registered.
 */

/** The site's version, written into index.html by `make site` ('' on the developer's server). */
const VERSION = document.querySelector('meta[name="vsr-site"]')?.getAttribute('content') ?? '';

/** The line under the title, once the page has it. @returns {HTMLElement | null} */
function line() {
  return document.getElementById('offline-status');
}

/**
 * Says `text` in the line ('' hides it), with a button when `action` is given.
 * @param {string} text @param {string} state for tests and styles @param {{label: string, run: () => void}} [action]
 */
function say(text, state, action) {
  const out = line();
  if (!out) return;
  out.replaceChildren(text);
  out.dataset.state = state;
  if (action) {
    const button = document.createElement('button');
    button.type = 'button';
    button.textContent = action.label;
    button.dataset.testid = 'offline-update';
    button.addEventListener('click', action.run, { once: true });
    out.append(' ', button);
  }
  out.hidden = text === '';
}

/** Offers the waiting new version: its button lets it take over, and the page reloads into it. @param {ServiceWorker} waiting */
function offerUpdate(waiting) {
  say('A new version of this page is ready.', 'update', { label: 'Update now (reloads the page)', run: () => waiting.postMessage({ type: 'take-over' }) });
}

/** Registers the service worker and follows it. */
async function start() {
  if (!VERSION || !('serviceWorker' in navigator)) return;
  /** Whether a version of the site serves this page (none on a first visit, until the first one is kept). */
  const served = () => navigator.serviceWorker.controller !== null;
  let wasServed = served();
  // A page served by one version and handed to another reloads into it (never an old page with a new core).
  navigator.serviceWorker.addEventListener('controllerchange', () => {
    if (wasServed) location.reload();
    wasServed = true;
  });
  let registration;
  try {
    registration = await navigator.serviceWorker.register('sw.js', { updateViaCache: 'none' });
  } catch (error) {
    say(`This page could not be kept for offline use (${error instanceof Error ? error.message : error}); it works online as before.`, 'failed');
    return;
  }
  if (registration.waiting && served()) offerUpdate(registration.waiting);
  registration.addEventListener('updatefound', () => {
    const installing = registration.installing;
    installing?.addEventListener('statechange', () => {
      if (installing.state === 'installed') {
        if (served()) offerUpdate(installing);
        else say('Kept on this device: the page now opens and runs without the network.', 'kept');
      }
      if (installing.state === 'redundant' && !served()) {
        say('This page could not be kept for offline use (a file could not be fetched); it works online as before.', 'failed');
      }
    });
  });
  if (served() && !navigator.onLine) say('No network: the page runs from its copy on this device.', 'offline');
  addEventListener('offline', () => say('No network: the page runs from its copy on this device.', 'offline'));
  addEventListener('online', () => { if (line()?.dataset.state === 'offline') say('', ''); });
}

// Once the page has loaded: the first visit's copy of the whole site (about 4 MB) is fetched after what the first screen needs, not with it.
if (document.readyState === 'complete') void start();
else addEventListener('load', () => void start(), { once: true });
