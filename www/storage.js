// @ts-check
/**
 * Keeps the page's state across reloads in the browser's localStorage, in the link format
 * of share.js. Storage can be full or switched off: then nothing is kept, and the page
 * says so once instead of failing.
 */

const KEY = 'vsr-playground/state/v1';

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
