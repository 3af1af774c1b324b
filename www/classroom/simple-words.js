// @ts-check
/**
 * Words for a class: the “Simple words” switch in the header hides formulas, statistics and
 * figures for the expert (elements marked `formula`, `stats` or `expert`; classroom.css), says a
 * label in plain words where it has them (`data-simple`: "f (Hz)" becomes "beats per second"),
 * and is kept in the browser; the
 * glossary's words are links where they appear (`a.term`), which open the glossary at their
 * entry, and links within the page (`a.jump`) scroll there without touching the address (its
 * `#...` is the share link's); and {@link withStats} marks a caption's statistics so that the switch can hide them.
 */

import { byId } from '../dom.js';

const KEY = 'vsr-playground/simple-words';

/** A parenthesis that holds a p-value: "(Holm p 0.017)", "(p 0.55; p: see the glossary)". */
const STATS = /\s*\([^()]*\bp\b[^()]*\)/g;

/**
 * Words of the glossary that text made by the page uses (captions, a task's answer, the gene
 * count), each with its entry in index.html's glossary: {@link withTerms} links them.
 */
const TERMS = {
  'see the glossary': 'g-p', Holm: 'g-p', 'mlp-comm': 'g-mlp', mlp: 'g-mlp', tanh: 'g-tanh', softmax: 'g-softmax',
  saturates: 'g-saturate', bias: 'g-network', weights: 'g-network', network: 'g-network', median: 'g-iqr',
};
/** The terms as whole words, the longest first (mlp-comm before mlp). */
const TERM_WORDS = new RegExp(`(?<![\\w-])(${Object.keys(TERMS).sort((a, b) => b.length - a.length).join('|')})(?![\\w-])`, 'g');

/**
 * `text` as nodes, the first use of each glossary word ({@link TERMS}) a link to its entry.
 * @param {Document} doc @param {string} text @param {Set<string>} [done] words already linked (by an earlier part)
 * @returns {(string | HTMLElement)[]}
 */
export function withTerms(doc, text, done = new Set()) {
  /** @type {(string | HTMLElement)[]} */
  const out = [];
  let at = 0;
  for (const m of text.matchAll(TERM_WORDS)) {
    const id = TERMS[/** @type {keyof typeof TERMS} */ (m[1])];
    if (done.has(m[1])) continue;
    done.add(m[1]);
    out.push(text.slice(at, m.index));
    const a = doc.createElement('a');
    a.className = 'term';
    a.href = `#${id}`;
    a.textContent = m[1];
    out.push(a);
    at = (m.index ?? 0) + m[1].length;
  }
  out.push(text.slice(at));
  return out.filter((x) => x !== '');
}

/**
 * `text` as nodes, each parenthesis holding a p-value in a `span.stats` (hidden in simple words),
 * the glossary's words linked ({@link withTerms}).
 * @param {Document} doc @param {string} text @returns {(string | HTMLElement)[]}
 */
export function withStats(doc, text) {
  /** @type {(string | HTMLElement)[]} */
  const out = [];
  const done = new Set();
  let at = 0;
  for (const m of text.matchAll(STATS)) {
    out.push(...withTerms(doc, text.slice(at, m.index), done));
    const span = doc.createElement('span');
    span.className = 'stats';
    span.append(...withTerms(doc, m[0], done));
    out.push(span);
    at = (m.index ?? 0) + m[0].length;
  }
  out.push(...withTerms(doc, text.slice(at), done));
  return out.filter((x) => x !== '');
}

/** Wires the switch and the glossary links. @param {Document} doc */
export function wireWords(doc) {
  const box = byId(doc, 'simple-words', HTMLInputElement);
  const set = (/** @type {boolean} */ on) => {
    if (on) doc.documentElement.dataset.words = 'simple'; else delete doc.documentElement.dataset.words;
    for (const el of doc.querySelectorAll('[data-simple]')) {
      if (!(el instanceof HTMLElement)) continue;
      el.dataset.expert ??= el.textContent ?? '';
      el.textContent = on ? el.dataset.simple ?? '' : el.dataset.expert;
    }
  };
  let kept = false;
  try { kept = localStorage.getItem(KEY) === '1'; } catch { /* storage off: the switch starts off */ }
  box.checked = kept;
  set(kept);
  box.addEventListener('change', () => {
    set(box.checked);
    try { localStorage.setItem(KEY, box.checked ? '1' : '0'); } catch { /* not kept */ }
  });
  // The address's #... is the share link's, so a link within the page scrolls without changing it.
  doc.addEventListener('click', (event) => {
    const link = /** @type {HTMLElement} */ (event.target)?.closest?.('a.term, a.jump');
    if (!(link instanceof HTMLAnchorElement)) return;
    const entry = doc.getElementById(link.hash.slice(1));
    if (!entry) return;
    event.preventDefault();
    const glossary = byId(doc, 'glossary', HTMLDetailsElement);
    if (glossary.contains(entry)) glossary.open = true;
    entry.scrollIntoView({ block: link.classList.contains('term') ? 'center' : 'start' });
    entry.classList.add('term-shown');
    setTimeout(() => entry.classList.remove('term-shown'), 2000);
  });
}
