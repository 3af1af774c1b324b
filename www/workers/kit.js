// @ts-check
/**
 * The one helper for starting workers, asking them and wording their failures, used by the page
 * (simulation worker, GA coordinator, the core worker that it asks: requester, answerRequests),
 * by the coordinator (evaluation workers) and by `<vsr-robot>` (embed/vsr-robot.js), whose
 * scripts may come from another origin.
 */

/** @typedef {import('./protocol.js').WorkerMessages} WorkerMessages */
/** @typedef {keyof WorkerMessages} WorkerFile  a worker's file, relative to www/ ('workers/simulation-worker.js', 'codesign/coordinator.js') */

/**
 * A worker as the code that started it holds it: only the messages that worker reads can be posted to it.
 * @template {WorkerFile} F
 * @typedef {Omit<Worker, 'postMessage'> & {postMessage(message: WorkerMessages[F]['in'], transfer?: Transferable[]): void}} WorkerOf
 */

/**
 * A worker's own global scope as it sees its messages (the page's DOM types do not describe a
 * worker's scope): it reads `In` and posts `Out`.
 * @template In, Out
 * @typedef {object} Scope
 * @property {(message: Out, transfer?: Transferable[]) => void} postMessage
 * @property {((event: MessageEvent<In>) => unknown) | null} onmessage
 */

/**
 * This worker's global scope (`self`), its messages typed by its file (protocol.js: WorkerMessages).
 * @template {WorkerFile} F
 * @param {F} file this worker's file, relative to www/ (its type names the messages; nothing reads it)
 * @returns {Scope<WorkerMessages[F]['in'], WorkerMessages[F]['out']>}
 */
export function workerScope(file) {
  return /** @type {any} */ (self);
}

/** www/, the folder that a worker's file is named from (this file is in www/workers/). */
const WWW = new URL('../', import.meta.url);

/**
 * Starts a module worker and wires its messages and failures.
 * @template {WorkerFile} F
 * @param {F} file the worker's file, relative to www/, e.g. 'workers/simulation-worker.js'
 * @param {(data: WorkerMessages[F]['out']) => void} onMessage called with each message's data
 * @param {(text: string) => void} onFailure called when the worker dies (an error event)
 * @returns {WorkerOf<F>}
 */
export function spawn(file, onMessage, onFailure) {
  const worker = new Worker(startable(new URL(file, WWW)), { type: 'module' });
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

/**
 * The type of a message that no case of a handler took, as JSON text for the words that say so
 * (its type is `never` there when the handler takes every type of its protocol).
 * @param {{type: unknown}} msg @returns {string}
 */
export function typeText(msg) {
  return JSON.stringify(msg.type);
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
 * @template In, Out
 * @param {Scope<In, Out>} scope the worker's ({@link workerScope})
 * @param {Promise<unknown>} ready @param {(message: string) => void} fail
 * @param {(msg: In) => void} handle
 */
export function onReadyMessage(scope, ready, fail, handle) {
  scope.onmessage = async (event) => {
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
 * @param {'workers/core-worker.js' | 'classroom/lab-worker.js'} file the worker's file, relative to www/ @param {string} what the worker, in words
 * @returns {(name: string, ...args: any[]) => Promise<any>}
 */
export function requester(file, what) {
  /** @type {WorkerOf<typeof file> | null} */
  let worker = null;
  let asked = 0;
  /** @type {Map<number, {resolve: (value: any) => void, reject: (error: Error) => void}>} */
  const waiting = new Map();
  const stop = (/** @type {WorkerOf<typeof file>} */ dead, /** @type {string} */ text) => {
    dead.terminate();
    if (worker === dead) worker = null;
    for (const w of waiting.values()) w.reject(new Error(`${what} stopped (${text}); try again`));
    waiting.clear();
  };
  const start = () => {
    const w = spawn(file, (msg) => {
      const waiter = waiting.get(msg.id);
      waiting.delete(msg.id);
      if (!('error' in msg)) { waiter?.resolve(msg.value); return; }
      waiter?.reject(new Error(msg.error));
      if (msg.fatal) stop(w, msg.error);
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
  const scope = workerScope('workers/core-worker.js'); // (the classroom's lab-worker.js reads and posts the same)
  scope.onmessage = async ({ data: { id, name, args } }) => {
    try {
      await ready;
      if (!Object.hasOwn(answers, name)) throw new Error(`unknown request ${JSON.stringify(name)}`);
      scope.postMessage({ id, value: answers[name](...args) });
    } catch (error) {
      scope.postMessage({ id, error: messageOf(error), fatal: error instanceof WebAssembly.RuntimeError });
    }
  };
}
