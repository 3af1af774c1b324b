// @ts-check
/**
 * Keeps the teacher's challenge across reloads in the browser's localStorage: the rules of the
 * challenge link they made (null before they make one), the class's links and codes as pasted,
 * and the genomes of the short codes already checked (evolved again here: minutes of the
 * projector's time not spent twice), by challenge and code. Storage can be full or switched off:
 * then nothing is kept, and the caller says so instead of failing (as keep/storage.js does for
 * the page's state). clearEntries forgets the class's entries and checks, not the challenge.
 */
import { rulesFrom } from './rules.js';

const KEY = 'vsr-playground/challenge/v1';

/**
 * @typedef {{rules: import('./rules.js').Rules | null, links: string, checked?: Record<string, string>}} KeptChallenge
 *   checked: a checked code's genome (base64 of its float32 bytes), by checkKey
 */

/** The teacher's challenge from an earlier visit (no rules and no links when none was kept). @returns {KeptChallenge} */
export function loadChallenge() {
  try {
    const kept = JSON.parse(localStorage.getItem(KEY) ?? 'null');
    if (!kept || typeof kept !== 'object') return { rules: null, links: '', checked: {} };
    const checked = kept.checked && typeof kept.checked === 'object'
      ? Object.fromEntries(Object.entries(kept.checked).filter(([, v]) => typeof v === 'string')) : {};
    return { rules: kept.rules && typeof kept.rules === 'object' ? rulesFrom(kept.rules) : null,
      links: typeof kept.links === 'string' ? kept.links : '', checked };
  } catch {
    return { rules: null, links: '', checked: {} };
  }
}

/** @param {KeptChallenge} challenge @returns {string} '' or why it was not kept */
export function keepChallenge(challenge) {
  try {
    localStorage.setItem(KEY, JSON.stringify(challenge));
    return '';
  } catch (error) {
    return `your challenge and the class's links could not be kept for your next visit (${error instanceof Error ? error.message : error})`;
  }
}

/**
 * Which checked genome a code of a challenge names: the run and the walk it was checked with, and the code.
 * @param {import('./rules.js').Rules} r @param {string} code its one spelling
 */
export function checkKey(r, code) {
  return [r.terrain, r.seconds, r.budget, r.seed, r.population, r.train, code].join(' ');
}

/** A genome as text to keep. @param {Float32Array} genome */
export function genomeText(genome) {
  const bytes = new Uint8Array(genome.buffer, genome.byteOffset, genome.byteLength);
  let binary = '';
  for (const b of bytes) binary += String.fromCharCode(b);
  return btoa(binary);
}

/** A kept genome back (null when the text is not one). @param {string} text @returns {Float32Array | null} */
export function genomeOf(text) {
  try {
    const bytes = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
    return bytes.length % 4 === 0 && bytes.length > 0 ? new Float32Array(bytes.buffer) : null;
  } catch {
    return null;
  }
}
