// @ts-check
/**
 * Keeps the page's state across reloads in the browser's localStorage, in the link format
 * of share.js, and the modules made on the page (runs, imported files) beside it. Storage can
 * be full or switched off: then nothing is kept, and the page says so once instead of failing.
 */

const KEY = 'vsr-playground/state/v1';
const MODULES_KEY = 'vsr-playground/modules/v1';
/** Most modules made on the page kept for the next visit (the newest). */
export const KEPT_MODULES = 12;

/** @returns {string | null} the kept state, or null */
export function loadKept() {
  try {
    return localStorage.getItem(KEY);
  } catch {
    return null;
  }
}

/** @param {string} text the state to keep @returns {string} '' or why it was not kept */
export function keep(text) {
  try {
    localStorage.setItem(KEY, text);
    return '';
  } catch (error) {
    return `your drawing could not be kept for the next visit (${error instanceof Error ? error.message : error})`;
  }
}

/** Forgets the kept state. */
export function forget() {
  try { localStorage.removeItem(KEY); } catch { /* nothing kept anyway */ }
}

/**
 * The modules kept from earlier visits, oldest first (each checked by the module list).
 * @returns {{key: string, label: string, short?: string, text: string}[]}
 */
export function loadKeptModules() {
  try {
    const list = JSON.parse(localStorage.getItem(MODULES_KEY) ?? '[]');
    return Array.isArray(list) ? list.filter((m) => m && typeof m.key === 'string' && typeof m.text === 'string'
      && typeof m.label === 'string') : [];
  } catch {
    return [];
  }
}

/**
 * Keeps the newest {@link KEPT_MODULES} of `modules` (oldest first), fewer if storage is full.
 * @param {{key: string, label: string, short?: string, text: string}[]} modules
 * @returns {string} '' or what was not kept, and why
 */
export function keepModules(modules) {
  let kept = modules.slice(-KEPT_MODULES);
  let why = '';
  while (kept.length > 0) {
    try {
      localStorage.setItem(MODULES_KEY, JSON.stringify(kept));
      const dropped = modules.length - kept.length;
      return dropped > 0 && why ? `the ${dropped} oldest module${dropped === 1 ? '' : 's'} made on this page will not be there on your next visit (${why})` : '';
    } catch (error) {
      why = error instanceof Error ? error.message : String(error);
      kept = kept.slice(1);
    }
  }
  try { localStorage.removeItem(MODULES_KEY); } catch { /* nothing kept anyway */ }
  return modules.length > 0 ? `the modules made on this page could not be kept for your next visit (${why || 'storage is off'})` : '';
}
