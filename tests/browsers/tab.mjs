// @ts-check
/**
 * What the cross-browser checks need of a browser, whichever drives it (puppeteer-core for
 * Firefox, W3C WebDriver for WebKit): one page (a tab) to open, act on as a person does and
 * read. Every driver gives a {@link Tab}; the checks (checks.mjs) use nothing else.
 */

/**
 * @typedef {object} Tab
 * @property {string} name the browser and its version
 * @property {(url: string) => Promise<void>} goto opens `url` and waits until it has loaded
 * @property {<A, T>(fn: (arg: A) => T | Promise<T>, arg: A) => Promise<T>} run runs `fn(arg)`
 *   in the page (`fn` is sent as its source: no closure) and gives its JSON-able result
 * @property {(selector: string) => Promise<void>} click clicks the element
 * @property {(selector: string, text: string) => Promise<void>} fill replaces an input's text
 *   by `text` and presses Enter
 * @property {(selector: string, value: string) => Promise<void>} select picks the option of
 *   that value in a <select>
 * @property {() => Promise<void>} close ends the browser
 */

/**
 * Waits until `fn(arg)`, run in the page, is truthy, and gives it; else fails saying `what`.
 * @template A, T
 * @param {Tab} tab @param {(arg: A) => T} fn @param {A} arg @param {string} what
 * @param {number} [timeout] ms
 * @returns {Promise<T>}
 */
export async function waitFor(tab, fn, arg, what, timeout = 60_000) {
  const end = Date.now() + timeout;
  for (;;) {
    const value = await tab.run(fn, arg);
    if (value) return value;
    if (Date.now() > end) throw new Error(`${tab.name}: waited ${timeout / 1000} s for ${what}`);
    await new Promise((resolve) => setTimeout(resolve, 100));
  }
}
