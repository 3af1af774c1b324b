// @ts-check
/**
 * A minimal W3C WebDriver client over HTTP (fetch): a session's commands that the checks use,
 * as a {@link import('./tab.mjs').Tab}. Spec: https://www.w3.org/TR/webdriver2/
 */

/** Keys in WebDriver's Send Keys: Enter, and Control (held until the command's end). */
const [ENTER, CONTROL] = ['\uE007', '\uE009'];
/** The key under which WebDriver answers an element reference. */
const ELEMENT = 'element-6066-11e4-a52e-4f735466cecf';

/**
 * Opens a session on the driver at `base` with `capabilities`.
 * @param {string} base e.g. http://127.0.0.1:4444 @param {object} capabilities alwaysMatch
 * @returns {Promise<import('./tab.mjs').Tab>} its one tab (close ends the session)
 */
export async function openSession(base, capabilities) {
  const opened = await command(base, 'POST', '/session', { capabilities: { alwaysMatch: capabilities } });
  const session = `/session/${opened.sessionId}`;
  const at = (/** @type {string} */ method, /** @type {string} */ path, /** @type {object} */ [body] = []) => command(base, method, session + path, body);
  await at('POST', '/timeouts', [{ script: 600_000, pageLoad: 120_000 }]);
  const element = async (/** @type {string} */ selector) =>
    `/element/${(await at('POST', '/element', [{ using: 'css selector', value: selector }]))[ELEMENT]}`;
  return {
    name: `${opened.capabilities.browserName} ${opened.capabilities.browserVersion}`,
    goto: async (url) => { await at('POST', '/url', [{ url }]); },
    run: async (fn, arg) => {
      const script = `const done = arguments[arguments.length - 1];
        Promise.resolve().then(() => (${fn})(arguments[0])).then((value) => done({ value }), (e) => done({ error: String(e?.stack ?? e) }));`;
      const answer = await at('POST', '/execute/async', [{ script, args: [arg] }]);
      if (answer.error) throw new Error(`in the page: ${answer.error}`);
      return answer.value;
    },
    click: async (selector) => { await at('POST', `${await element(selector)}/click`, [{}]); },
    fill: async (selector, text) => {
      // As a person does: select all (Control+A; Element Clear would commit an empty value),
      // then type and press Enter (a second command: the held Control ends with the first).
      const input = await element(selector);
      await at('POST', `${input}/value`, [{ text: `${CONTROL}a` }]);
      await at('POST', `${input}/value`, [{ text: text + ENTER }]);
    },
    select: async (selector, value) => {
      await at('POST', `${await element(`${selector} option[value="${value}"]`)}/click`, [{}]);
    },
    close: async () => { await command(base, 'DELETE', session); },
  };
}

/**
 * One WebDriver command; its value, or an error with the driver's message.
 * @param {string} base @param {string} method @param {string} path @param {object} [body]
 */
async function command(base, method, path, body) {
  const response = await fetch(base + path, {
    method, headers: { 'content-type': 'application/json' }, body: body === undefined ? undefined : JSON.stringify(body),
  });
  const { value } = await response.json();
  if (!response.ok) throw new Error(`WebDriver ${method} ${path}: ${value?.error}: ${value?.message}`);
  return value;
}
