// @ts-check
/**
 * The one helper for starting workers, asking them and wording their failures, used by the page
 * (simulation worker, GA coordinator, the core worker that it asks: requester, answerRequests),
 * by the coordinator (evaluation workers) and by `<vsr-robot>` (embed/vsr-robot.js), whose
 * scripts may come from another origin.
 */

/**
 * Starts a module worker next to this file and wires its messages and failures.
 * @param {string} file the worker's file name, e.g. 'worker.js'
 * @param {(data: any) => void} onMessage called with each message's data
 * @param {(text: string) => void} onFailure called when the worker dies (an error event)
 * @returns {Worker}
 */
export function spawn(file, onMessage, onFailure) {
  const worker = new Worker(startable(new URL(`./${file}`, import.meta.url)), { type: 'module' });
  worker.onmessage = (event) => onMessage(event.data);
  worker.onerror = (event) => {
    event.preventDefault();
    onFailure(event.message || 'it stopped without a message (see the console)');
  };
  worker.onmessageerror = () => onFailure('a message could not be read');
  return worker;
}

/**
 * A worker script's URL as this page may start it: the URL itself on the page's origin; from
 * another origin (the embedded robot's scripts on a CDN), a same-origin module that imports it,
 * since a page may only start workers of its own origin.
 * @param {URL} url @returns {URL | string}
 */
function startable(url) {
  if (url.origin === self.location.origin) return url;
  return URL.createObjectURL(new Blob([`import ${JSON.stringify(url.href)};`], { type: 'text/javascript' }));
}

/**
 * Fetches `url`, throwing on an HTTP error ("WHAT: HTTP 404", or "HTTP 404" without `what`).
 * @param {string} url @param {string} [what] what it is, for the message @returns {Promise<Response>}
 */
export async function fetchOk(url, what) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${what ? `${what}: ` : ''}HTTP ${response.status}`);
  return response;
}

/** The text of a thrown value. @param {unknown} error @returns {string} */
export function messageOf(error) {
  return error instanceof Error ? error.message : String(error);
}

/**
 * Loads the wasm module inside a worker and installs its panic hook; failures are reported
 * once through `report` with a readable message.
 * @param {() => Promise<unknown>} init the module's default export
 * @param {() => void} installPanicHook its `start`
 * @returns {Promise<void>}
 */
export function loadWasm(init, installPanicHook) {
  return init().then(() => installPanicHook(), (error) => {
    throw new Error(`could not load the simulator (wasm): ${messageOf(error)}`);
  });
}

/**
 * A worker's message handler that waits for its wasm module: each message goes to
 * `handle` once `ready` resolved; if the module could not load, `fail` gets why, in words.
 * @param {Promise<unknown>} ready @param {(message: string) => void} fail
 * @param {(msg: any) => void} handle
 */
export function onReadyMessage(ready, fail, handle) {
  self.onmessage = async (/** @type {MessageEvent} */ event) => {
    try {
      await ready;
    } catch (error) {
      fail(messageOf(error));
      return;
    }
    handle(event.data);
  };
}

/**
 * The page's side of a worker that answers requests ({@link answerRequests}): `ask(name, ...args)`
 * posts {id, name, args} and resolves with the answer's value, or rejects with its message as
 * an Error. The worker starts at the first request; when it dies (or its wasm module crashed),
 * the requests waiting fail with a readable message and a new worker takes the next ones.
 * @param {string} file the worker's file name @param {string} what the worker, in words
 * @returns {(name: string, ...args: any[]) => Promise<any>}
 */
export function requester(file, what) {
  /** @type {Worker | null} */
  let worker = null;
  let asked = 0;
  /** @type {Map<number, {resolve: (value: any) => void, reject: (error: Error) => void}>} */
  const waiting = new Map();
  const stop = (/** @type {Worker} */ dead, /** @type {string} */ text) => {
    dead.terminate();
    if (worker === dead) worker = null;
    for (const w of waiting.values()) w.reject(new Error(`${what} stopped (${text}); try again`));
    waiting.clear();
  };
  const start = () => {
    const w = spawn(file, (/** @type {{id: number, value?: any, error?: string, fatal?: boolean}} */ msg) => {
      const waiter = waiting.get(msg.id);
      waiting.delete(msg.id);
      if (msg.error === undefined) waiter?.resolve(msg.value); else waiter?.reject(new Error(msg.error));
      if (msg.fatal) stop(w, String(msg.error));
    }, (text) => stop(w, text));
    return w;
  };
  return (name, ...args) => new Promise((resolve, reject) => {
    worker ??= start();
    waiting.set(++asked, { resolve, reject });
    worker.postMessage({ id: asked, name, args });
  });
}

/**
 * A worker's side of {@link requester}: each request {id, name, args} is answered, once
 * `ready` resolved, with {id, value} from `answers[name](...args)`, or with {id, error} in
 * words; a crash of the wasm module (a Rust panic) adds fatal: true, so that the page starts a
 * fresh worker.
 * @param {Promise<unknown>} ready @param {Record<string, (...args: any[]) => any>} answers
 */
export function answerRequests(ready, answers) {
  self.onmessage = async (/** @type {MessageEvent<{id: number, name: string, args: any[]}>} */ { data: { id, name, args } }) => {
    try {
      await ready;
      if (!Object.hasOwn(answers, name)) throw new Error(`unknown request ${JSON.stringify(name)}`);
      self.postMessage({ id, value: answers[name](...args) });
    } catch (error) {
      self.postMessage({ id, error: messageOf(error), fatal: error instanceof WebAssembly.RuntimeError });
    }
  };
}
