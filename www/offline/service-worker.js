// @ts-check
/**
 * The site's service worker: the page keeps working when a class's network drops. `make site`
 * (scripts/site.mjs) writes it at the site's root as sw.js, after one line that names the
 * site's version and its files: `self.VSR_SITE = {version, precache}`. It is not used by the
 * developer's server (offline.js registers it only on a built site).
 *
 * - On the first visit it keeps every file of the site in one cache named after the version
 *   (the page, the wasm core, the modules, the study's tables and figures, the guides), each
 *   fetched past the browser's own cache; if one cannot be fetched nothing is kept, and the
 *   page works online as before. The study's run files are kept once opened.
 * - Every request of the site is answered from that cache first, so a page and its core always
 *   come from the same build; an address with a query (`?chapter=4`, a challenge link) is the
 *   page itself.
 * - A new build is a new sw.js: it fills its own cache while the old one goes on serving, waits
 *   until no page of the old version is open (or a page asks it to take over: offline.js's
 *   Update button, which then reloads), and only then deletes the old cache. Never a new core
 *   under an old page.
 */

/** @typedef {{version: string, precache: string[]}} Site */

const sw = /** @type {any} */ (self);
/** @type {Site} */
const SITE = sw.VSR_SITE ?? { version: 'unbuilt', precache: [] };
const PREFIX = 'vsr-site-';
const CACHE = `${PREFIX}${SITE.version}`;
/** The site's root (the folder sw.js is in): its scope. */
const ROOT = new URL('./', sw.location.href);

/** Files that are kept once fetched (not on the first visit: the study's run files). @param {URL} url */
const keptWhenOpened = (url) => url.pathname.startsWith(`${ROOT.pathname}study/runs/`);

sw.addEventListener('install', (/** @type {any} */ event) => {
  event.waitUntil(caches.open(CACHE).then((cache) => cache.addAll(
    SITE.precache.map((file) => new Request(new URL(file, ROOT), { cache: 'reload' })))));
});

sw.addEventListener('activate', (/** @type {any} */ event) => {
  event.waitUntil((async () => {
    for (const name of await caches.keys()) if (name.startsWith(PREFIX) && name !== CACHE) await caches.delete(name);
    await sw.clients.claim();
  })());
});

sw.addEventListener('message', (/** @type {MessageEvent} */ event) => {
  if (event.data?.type === 'take-over') sw.skipWaiting();
  if (event.data?.type === 'version') event.ports[0]?.postMessage({ version: SITE.version, cache: CACHE });
});

sw.addEventListener('fetch', (/** @type {any} */ event) => {
  /** @type {Request} */
  const request = event.request;
  const url = new URL(request.url);
  if (request.method !== 'GET' || url.origin !== ROOT.origin || !url.pathname.startsWith(ROOT.pathname)) return;
  event.respondWith(answer(request, url));
});

/**
 * The cached copy of a request, else the network's answer (kept when it is a run file).
 * @param {Request} request @param {URL} url @returns {Promise<Response>}
 */
async function answer(request, url) {
  const cache = await caches.open(CACHE);
  const page = request.mode === 'navigate' && (url.pathname === ROOT.pathname || url.pathname === `${ROOT.pathname}index.html`);
  const hit = await cache.match(page ? new URL('./', ROOT).href : request, { ignoreSearch: request.mode === 'navigate' });
  if (hit) return hit;
  const response = await fetch(request);
  if (response.ok && keptWhenOpened(url)) await cache.put(request, response.clone());
  return response;
}
