// @ts-check
/**
 * The one helper for starting workers and wording their failures, used by the page
 * (simulation worker, GA coordinator), by the coordinator (evaluation workers) and by
 * `<vsr-robot>` (embed/vsr-robot.js), whose scripts may come from another origin.
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
