// @ts-check
/**
 * Keeps the teacher's challenge across reloads in the browser's localStorage: the rules of the
 * challenge link they made (null before they make one) and the class's links as pasted. Storage
 * can be full or switched off: then nothing is kept, and the caller says so instead of failing
 * (as keep/storage.js does for the page's state).
 */
import { rulesFrom } from './challenge-rules.js';

const KEY = 'vsr-playground/challenge/v1';

/** @typedef {{rules: import('./challenge-rules.js').Rules | null, links: string}} KeptChallenge */

/** The teacher's challenge from an earlier visit (no rules and no links when none was kept). @returns {KeptChallenge} */
export function loadChallenge() {
  try {
    const kept = JSON.parse(localStorage.getItem(KEY) ?? 'null');
    if (!kept || typeof kept !== 'object') return { rules: null, links: '' };
    return { rules: kept.rules && typeof kept.rules === 'object' ? rulesFrom(kept.rules) : null,
      links: typeof kept.links === 'string' ? kept.links : '' };
  } catch {
    return { rules: null, links: '' };
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
